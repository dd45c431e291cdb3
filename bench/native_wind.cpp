// boreas: the native twins of the hot kernels, built with -O3 -march=native -fopenmp (see
// bench/CMakeLists.txt). Each follows its .cl file step by step in float, with the same
// polynomials; the loops are shaped so that GCC vectorizes every inner one (checked with
// -fopt-info-vec-missed: what stops it is noted where the code looks unusual).
#include "native_wind.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shared/fast_math.h"

namespace boreas::bench {

namespace {

struct Vec3 {
  float x, y, z;
};

inline int grid_index(const BoreasGpuGrid& g, int i, int j, int k) {
  return (k * g.ny + j) * g.nx + i;
}

inline int grid_cells(const BoreasGpuGrid& g) { return g.nx * g.ny * g.nz; }

inline float mix(float a, float b, float t) { return a + (b - a) * t; }

// Points per block of the sine-sum loops. The loop over waves runs outside the SIMD loop
// over a block (GCC does not vectorize a loop with a loop inside), and a block's partial
// sums stay in L1.
constexpr int kBlock = kNativeWindBlock;

// boreas_wind_sine_sum (cl/shared/wind_sample.h) for n <= kBlock points, summed over the
// waves in the same order.
void sine_sum_block(const float* x, const float* z, int n, const BoreasGpuWave* waves,
                    int wave_count, float* fx, float* fz) {
#pragma omp simd
  for (int i = 0; i < n; ++i) fx[i] = fz[i] = 0.0f;
  for (int w = 0; w < wave_count; ++w) {
    const BoreasGpuWave wave = waves[w];
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      float u = std::fma(std::fma(wave.dir_x, x[i], wave.dir_z * z[i]), wave.cycles_per_meter,
                         wave.phase_cycles);
      u -= std::floor(u + 0.5f);
      float base = std::fma(boreas_poly_sin_cycle(u), 0.5f, 0.5f);
      float s = wave.amplitude * boreas_poly_pow(base, wave.sharpness);
      fx[i] = std::fma(wave.dir_x, s, fx[i]);
      fz[i] = std::fma(wave.dir_z, s, fz[i]);
    }
  }
}

// boreas_grid_trilinear: c in cell units, clamped to the outermost centers; grid is the 4
// planes. Always inlined: GCC otherwise leaves a call, and a call stops the SIMD loop.
[[gnu::always_inline]] inline Vec3 trilinear(const float* grid, const BoreasGpuGrid& g, float cx,
                                             float cy, float cz) {
  cx = std::min(std::max(cx, 0.0f), float(g.nx - 1));
  cy = std::min(std::max(cy, 0.0f), float(g.ny - 1));
  cz = std::min(std::max(cz, 0.0f), float(g.nz - 1));
  const float x0 = std::floor(cx), y0 = std::floor(cy), z0 = std::floor(cz);
  const float fx = cx - x0, fy = cy - y0, fz = cz - z0;
  const int i0 = int(x0), j0 = int(y0), k0 = int(z0);
  const int di = std::min(i0 + 1, g.nx - 1) - i0;  // 0 on the last cell
  const int dj = (std::min(j0 + 1, g.ny - 1) - j0) * g.nx;
  const int dk = (std::min(k0 + 1, g.nz - 1) - k0) * g.nx * g.ny;
  // Plain int indices: GCC turns them into gathers (pointer arithmetic defeats that).
  const int c000 = grid_index(g, i0, j0, k0), c100 = c000 + di;
  const int c010 = c000 + dj, c110 = c010 + di;
  const int c001 = c000 + dk, c101 = c001 + di;
  const int c011 = c001 + dj, c111 = c011 + di;
  const float w000 = (1.0f - fx) * (1.0f - fy) * (1.0f - fz);
  const float w100 = fx * (1.0f - fy) * (1.0f - fz);
  const float w010 = (1.0f - fx) * fy * (1.0f - fz);
  const float w110 = fx * fy * (1.0f - fz);
  const float w001 = (1.0f - fx) * (1.0f - fy) * fz;
  const float w101 = fx * (1.0f - fy) * fz;
  const float w011 = (1.0f - fx) * fy * fz;
  const float w111 = fx * fy * fz;
  const int n = grid_cells(g);
  // Written out per plane: a loop over planes here would stop the caller's SIMD loop.
  const float* px = grid;
  const float* py = grid + n;
  const float* pz = grid + 2 * n;
  Vec3 r;
  r.x = w000 * px[c000] + w100 * px[c100] + w010 * px[c010] + w110 * px[c110] + w001 * px[c001] +
        w101 * px[c101] + w011 * px[c011] + w111 * px[c111];
  r.y = w000 * py[c000] + w100 * py[c100] + w010 * py[c010] + w110 * py[c110] + w001 * py[c001] +
        w101 * py[c101] + w011 * py[c011] + w111 * py[c111];
  r.z = w000 * pz[c000] + w100 * pz[c100] + w010 * pz[c010] + w110 * pz[c110] + w001 * pz[c001] +
        w101 * pz[c101] + w011 * pz[c011] + w111 * pz[c111];
  return r;
}

// One flow primitive with what the SIMD loop over cells needs precomputed: a uniform
// select or branch inside that loop would stop GCC vectorizing it.
struct FlowTerms {
  BoreasGpuForcing f;
  float radius2;  // radius^2, or infinity when unbounded (coverage 1 everywhere)
  float core;     // radius of the linear core, m
};

FlowTerms flow_terms(const BoreasGpuForcing& f) {
  FlowTerms t{};
  t.f = f;
  t.radius2 = f.radius > 0.0f ? f.radius * f.radius : INFINITY;
  t.core = std::max(0.25f * f.radius, 1e-6f);
  return t;
}

// boreas_flow_add (wind_grid_step.cl) at offset r: adds the primitive's velocity to v and
// returns its coverage. The offset comes as scalars: a Vec3 built inside an omp simd loop
// becomes an in-memory "simd array", which GCC then does not vectorize.
[[gnu::always_inline]] inline float flow_add(const FlowTerms& t, float rx, float ry, float rz,
                                             float& vx, float& vy, float& vz) {
  const BoreasGpuForcing& f = t.f;
  const float d2 = rx * rx + ry * ry + rz * rz;
  const float q = std::max(1.0f - d2 / t.radius2, 0.0f);
  const float coverage = q * q;
  const float d = std::sqrt(d2);
  const float ramp = std::min(d / t.core, 1.0f) * coverage * f.strength;
  // Divisions done unconditionally and then selected, so that GCC if-converts them.
  const float inv_d = d > 1e-6f ? 1.0f / std::max(d, 1e-6f) : 0.0f;
  // axis x r, as the kernel: equal to axis x (the part of r across the axis)
  const float sx = f.dir_y * rz - f.dir_z * ry;
  const float sy = f.dir_z * rx - f.dir_x * rz;
  const float sz = f.dir_x * ry - f.dir_y * rx;
  const float slen = std::sqrt(sx * sx + sy * sy + sz * sz);
  const float inv_s = slen > 1e-6f ? 1.0f / std::max(slen, 1e-6f) : 0.0f;
  const float radial = f.radial_weight * ramp * inv_d;
  const float swirl = f.swirl_weight * ramp * inv_s;
  const float uniform = f.uniform_weight * f.strength * coverage;
  vx += f.dir_x * uniform + rx * radial + sx * swirl;
  vy += f.dir_y * uniform + ry * radial + sy * swirl;
  vz += f.dir_z * uniform + rz * radial + sz * swirl;
  return coverage;
}

// Steps 1-5 of wind_grid_step.cl for the cells of row (j, k), given the forcing's target
// and keep factor per cell. Obstacles are a template parameter because a uniform bool
// inside the SIMD loop stops GCC vectorizing it.
template <bool kSolids>
void grid_step_row(const float* in, float* out, const float* slab, const float* tx, const float* ty,
                   const float* tz, const float* keep, const BoreasGpuGrid& g,
                   const BoreasGpuGridStep& s, int j, int k) {
  const int nx = g.nx, ny = g.ny, nz = g.nz, n = grid_cells(g);
  const float* in_x = in;
  const float* in_y = in + n;
  const float* in_z = in + 2 * n;
  const float* in_solid = in + 3 * n;
  const float* sine_x = slab + size_t(k) * nx;
  const float* sine_z = slab + size_t(nx) * nz + size_t(k) * nx;
  const int row = grid_index(g, 0, j, k);
  // Neighbour rows, clamped at the grid's edge (zero-gradient boundary).
  const int dym = j > 0 ? nx : 0, dyp = j < ny - 1 ? nx : 0;
  const int dzm = k > 0 ? nx * ny : 0, dzp = k < nz - 1 ? nx * ny : 0;
#pragma omp simd
  for (int i = 0; i < nx; ++i) {
    const int c = row + i;
    const int xm = c - (i > 0 ? 1 : 0), xp = c + (i < nx - 1 ? 1 : 0);
    const int ym = c - dym, yp = c + dyp, zm = c - dzm, zp = c + dzp;
    const float sx = sine_x[i], sz = sine_z[i];
    // 1. transport
    Vec3 v =
        trilinear(in, g, float(i) - (sx + in_x[c]) * s.dt_over_cell,
                  float(j) - in_y[c] * s.dt_over_cell, float(k) - (sz + in_z[c]) * s.dt_over_cell);
    // 2. diffusion
    const float mx =
        (in_x[xm] + in_x[xp] + in_x[ym] + in_x[yp] + in_x[zm] + in_x[zp]) * (1.0f / 6.0f);
    const float my =
        (in_y[xm] + in_y[xp] + in_y[ym] + in_y[yp] + in_y[zm] + in_y[zp]) * (1.0f / 6.0f);
    const float mz =
        (in_z[xm] + in_z[xp] + in_z[ym] + in_z[yp] + in_z[zm] + in_z[zp]) * (1.0f / 6.0f);
    // 3. decay, 4. forcing
    float vx = mix(tx[i], mix(v.x, mx, s.diffusion_mix) * s.decay_factor, keep[i]);
    float vy = mix(ty[i], mix(v.y, my, s.diffusion_mix) * s.decay_factor, keep[i]);
    float vz = mix(tz[i], mix(v.z, mz, s.diffusion_mix) * s.decay_factor, keep[i]);
    // 5. obstacles; bitwise | on the comparisons, as short-circuit forms would be branches.
    const float solid = in_solid[c];
    if constexpr (kSolids) {
      const float wx = (in_solid[xp] != 0.0f) | (in_solid[xm] != 0.0f) ? 0.0f : sx + vx;
      const float wy = (in_solid[yp] != 0.0f) | (in_solid[ym] != 0.0f) ? 0.0f : vy;
      const float wz = (in_solid[zp] != 0.0f) | (in_solid[zm] != 0.0f) ? 0.0f : sz + vz;
      const bool is_solid = solid != 0.0f;
      vx = is_solid ? -sx : wx - sx;
      vy = is_solid ? 0.0f : wy;
      vz = is_solid ? -sz : wz - sz;
    }
    out[c] = vx;
    out[n + c] = vy;
    out[2 * n + c] = vz;
    out[3 * n + c] = solid;
  }
}

}  // namespace

void native_copy(const float* in, float* out, size_t count) {
  const long long n = static_cast<long long>(count);
#pragma omp parallel for simd schedule(static)
  for (long long i = 0; i < n; ++i) out[i] = in[i];
}

// As boreas_grid_fade (cl/shared/wind_sample.h): the max norm of the distance outside.
[[gnu::always_inline]] inline float grid_fade(float cx, float cz, int nx, int nz,
                                              float fade_per_cell) {
  const float hx = 0.5f * float(nx), hz = 0.5f * float(nz);
  const float outside = std::max(std::max(std::fabs(cx - hx) - hx, std::fabs(cz - hz) - hz), 0.0f);
  const float s = std::min(std::max(1.0f - outside * fade_per_cell, 0.0f), 1.0f);
  return s * s * (3.0f - 2.0f * s);
}

namespace {

// As boreas_wind_sine_interpolated (cl/shared/wind_sample_width.inc): bilinear in the slab
// within the rectangle of the column centers, handing over to the exact sum in its
// outermost cell; the block's exact sums only where a point lies near the edge or beyond.
void sine_interpolated_block(const float* px, const float* pz, int n, const BoreasGpuWave* waves,
                             int wave_count, const float* grid, const BoreasGpuGrid& g, float* fx,
                             float* fz) {
  const float inv_h = 1.0f / g.cell_size;
  const float* sx = grid + boreas_grid_slab_offset(g);
  const float* sz = sx + size_t(g.nx) * g.nz;
  const float last_x = float(g.nx - 1), last_z = float(g.nz - 1);
  alignas(64) float ux[kBlock], uz[kBlock];
  int any_near = 0;
#pragma omp simd reduction(| : any_near)
  for (int i = 0; i < n; ++i) {
    ux[i] = (px[i] - g.origin_x) * inv_h - 0.5f;
    uz[i] = (pz[i] - g.origin_z) * inv_h - 0.5f;
    const bool deep =
        (ux[i] >= 1.0f) & (ux[i] <= last_x - 1.0f) & (uz[i] >= 1.0f) & (uz[i] <= last_z - 1.0f);
    any_near |= !deep;
    const float cx = std::min(std::max(ux[i], 0.0f), last_x);
    const float cz = std::min(std::max(uz[i], 0.0f), last_z);
    const float x0 = std::floor(cx), z0 = std::floor(cz);
    const float wx = cx - x0, wz = cz - z0;
    const int i0 = int(x0), k0 = int(z0);
    const int di = std::min(i0 + 1, g.nx - 1) - i0;
    const int dk = (std::min(k0 + 1, g.nz - 1) - k0) * g.nx;
    const int c00 = k0 * g.nx + i0, c10 = c00 + di, c01 = c00 + dk, c11 = c01 + di;
    const float w00 = (1.0f - wx) * (1.0f - wz), w10 = wx * (1.0f - wz);
    const float w01 = (1.0f - wx) * wz, w11 = wx * wz;
    fx[i] = w00 * sx[c00] + w10 * sx[c10] + w01 * sx[c01] + w11 * sx[c11];
    fz[i] = w00 * sz[c00] + w10 * sz[c10] + w01 * sz[c01] + w11 * sz[c11];
  }
  if (!any_near) return;
  alignas(64) float ex[kBlock], ez[kBlock];
  sine_sum_block(px, pz, n, waves, wave_count, ex, ez);
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const bool within = (ux[i] >= 0.0f) & (ux[i] <= last_x) & (uz[i] >= 0.0f) & (uz[i] <= last_z);
    const float edge = std::min(std::min(ux[i], last_x - ux[i]), std::min(uz[i], last_z - uz[i]));
    const float d = std::min(std::max(edge, 0.0f), 1.0f);
    const float keep = within ? d * d * (3.0f - 2.0f * d) : 0.0f;
    fx[i] = ex[i] + (fx[i] - ex[i]) * keep;
    fz[i] = ez[i] + (fz[i] - ez[i]) * keep;
  }
}

}  // namespace

void native_wind_block(const float* px, const float* py, const float* pz, int n,
                       const BoreasGpuWave* waves, int wave_count, const float* grid,
                       const BoreasGpuGrid& g, float* fx, float* fy, float* fz, bool interpolated) {
  const float inv_h = 1.0f / g.cell_size;
  const float* flags = grid + 3 * size_t(grid_cells(g));
  if (interpolated)
    sine_interpolated_block(px, pz, n, waves, wave_count, grid, g, fx, fz);
  else
    sine_sum_block(px, pz, n, waves, wave_count, fx, fz);
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const float cx = (px[i] - g.origin_x) * inv_h;
    const float cy = (py[i] - g.origin_y) * inv_h;
    const float cz = (pz[i] - g.origin_z) * inv_h;
    const Vec3 t = trilinear(grid, g, cx - 0.5f, cy - 0.5f, cz - 0.5f);
    const float fade = grid_fade(cx, cz, g.nx, g.nz, g.fade_per_cell);
    const float fi = std::floor(cx), fj = std::floor(cy), fk = std::floor(cz);
    const bool inside = (fi >= 0.0f) & (fj >= 0.0f) & (fk >= 0.0f) & (fi < float(g.nx)) &
                        (fj < float(g.ny)) & (fk < float(g.nz));
    const int ci = std::min(std::max(int(fi), 0), g.nx - 1);
    const int cj = std::min(std::max(int(fj), 0), g.ny - 1);
    const int ck = std::min(std::max(int(fk), 0), g.nz - 1);
    // Loaded unconditionally (the index is clamped) and combined with &, not &&: a
    // short-circuit load would be a branch.
    const bool solid = inside & (g.solid_count > 0) & (flags[grid_index(g, ci, cj, ck)] != 0.0f);
    fx[i] = solid ? 0.0f : fx[i] + fade * t.x;
    fy[i] = solid ? 0.0f : fade * t.y;
    fz[i] = solid ? 0.0f : fz[i] + fade * t.z;
  }
}

void native_sample_points(const float* points, float* force, int count, const BoreasGpuWave* waves,
                          int wave_count, const float* grid, const BoreasGpuGrid& g) {
  const size_t n_points = size_t(count);
#pragma omp parallel for schedule(static)
  for (int start = 0; start < count; start += kBlock) {
    const int n = std::min(kBlock, count - start);
    const float* px = points + start;
    float* fx = force + start;
    native_wind_block(px, px + n_points, px + 2 * n_points, n, waves, wave_count, grid, g, fx,
                      fx + n_points, fx + 2 * n_points);
  }
}

void native_sine_slab(float* slab, const BoreasGpuWave* waves, int wave_count,
                      const BoreasGpuGrid& g) {
  const int blocks_per_row = (g.nx + kBlock - 1) / kBlock;
  const size_t plane = size_t(g.nx) * g.nz;
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < g.nz; ++k) {
    for (int b = 0; b < blocks_per_row; ++b) {
      const int start = b * kBlock;
      const int n = std::min(kBlock, g.nx - start);
      const float z = g.origin_z + (float(k) + 0.5f) * g.cell_size;
      float px[kBlock], pz[kBlock];
#pragma omp simd
      for (int i = 0; i < n; ++i) {
        px[i] = g.origin_x + (float(start + i) + 0.5f) * g.cell_size;
        pz[i] = z;
      }
      float* out = slab + size_t(k) * g.nx + start;
      sine_sum_block(px, pz, n, waves, wave_count, out, out + plane);
    }
  }
}

// Adds count primitives' velocities to the row of cells (j, k) (centers at x = ox + (i +
// 1/2) h, y = py, z = pz) and raises cov to their coverage maximum, one primitive at a
// time so the SIMD loop holds no loop over primitives.
void add_flow_row(const BoreasGpuForcing* forcing, int count, float ox, float h, float py, float pz,
                  int nx, float* tx, float* ty, float* tz, float* cov) {
  for (int m = 0; m < count; ++m) {
    const FlowTerms t = flow_terms(forcing[m]);
    const float ry = py - t.f.pos_y, rz = pz - t.f.pos_z;
#pragma omp simd
    for (int i = 0; i < nx; ++i) {
      const float rx = ox + (float(i) + 0.5f) * h - t.f.pos_x;
      const float c = flow_add(t, rx, ry, rz, tx[i], ty[i], tz[i]);
      cov[i] = cov[i] < c ? c : cov[i];
    }
  }
}

void native_forcing_field(float* field, const BoreasGpuForcing* steady, int count,
                          const BoreasGpuGrid& g) {
  const int nx = g.nx, ny = g.ny, nz = g.nz;
  const size_t plane = size_t(nx) * ny * nz;
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      const float h = g.cell_size, ox = g.origin_x;
      const float py = g.origin_y + (float(j) + 0.5f) * h;
      const float pz = g.origin_z + (float(k) + 0.5f) * h;
      float* tx = field + (size_t(k) * ny + j) * nx;
      float* ty = tx + plane;
      float* tz = ty + plane;
      float* cov = tz + plane;
#pragma omp simd
      for (int i = 0; i < nx; ++i) tx[i] = ty[i] = tz[i] = cov[i] = 0.0f;
      add_flow_row(steady, count, ox, h, py, pz, nx, tx, ty, tz, cov);
    }
  }
}

void native_grid_step(const float* in, float* out, const float* slab, const float* steady,
                      const BoreasGpuForcing* varying, int varying_count, const BoreasGpuGrid& g,
                      const BoreasGpuGridStep& s) {
  const int nx = g.nx, ny = g.ny, nz = g.nz;
  const size_t plane = size_t(nx) * ny * nz;
  const bool solids = g.solid_count > 0;
#pragma omp parallel
  {
    // Per-thread row buffers for the forcing's target and keep factor: the steady field's
    // row plus the gusts, one primitive at a time (no loop over primitives inside a SIMD
    // loop); with no forcing, target 0 and keep 1 leave v exactly as it is, as the
    // kernel's skipped stage does.
    std::vector<float> buffers(4 * size_t(nx));
    float* tx = buffers.data();
    float* ty = tx + nx;
    float* tz = ty + nx;
    float* keep = tz + nx;
    for (int i = 0; i < nx; ++i) keep[i] = 1.0f;
#pragma omp for collapse(2) schedule(static)
    for (int k = 0; k < nz; ++k) {
      for (int j = 0; j < ny; ++j) {
        if (steady || varying_count > 0) {
          // Uniform values in locals: read through g inside the loop they are reloaded per
          // cell (the stores might alias them), which GCC does not vectorize.
          const float h = g.cell_size, ox = g.origin_x;
          const float py = g.origin_y + (float(j) + 0.5f) * h;
          const float pz = g.origin_z + (float(k) + 0.5f) * h;
          if (steady) {
            const float* row = steady + (size_t(k) * ny + j) * nx;
#pragma omp simd
            for (int i = 0; i < nx; ++i) {
              tx[i] = row[i];
              ty[i] = row[plane + i];
              tz[i] = row[2 * plane + i];
              keep[i] = row[3 * plane + i];  // the coverage maximum, for now
            }
          } else {
#pragma omp simd
            for (int i = 0; i < nx; ++i) tx[i] = ty[i] = tz[i] = keep[i] = 0.0f;
          }
          add_flow_row(varying, varying_count, ox, h, py, pz, nx, tx, ty, tz, keep);
#pragma omp simd
          for (int i = 0; i < nx; ++i)
            keep[i] = keep[i] > 0.0f ? boreas_poly_exp2(-keep[i] * s.drive_exponent) : 1.0f;
        }
        if (solids) {
          grid_step_row<true>(in, out, slab, tx, ty, tz, keep, g, s, j, k);
        } else {
          grid_step_row<false>(in, out, slab, tx, ty, tz, keep, g, s, j, k);
        }
      }
    }
  }
}

int native_thread_count() { return omp_get_max_threads(); }

}  // namespace boreas::bench
