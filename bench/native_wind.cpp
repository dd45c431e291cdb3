// boreas: the native twins of the hot kernels, built with -O3 -march=native -fopenmp (see
// bench/CMakeLists.txt). The per-point math is the kernels' own (the C++ builds of
// cl/shared/wind_sample.h and flow_primitives.h, polynomials on); the loops around it are
// shaped so that GCC vectorizes every inner one (checked with -fopt-info-vec-missed: what
// stops it is noted where the code looks unusual).
#include "native_wind.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#define BOREAS_FAST_MATH 1
#include "shared/flow_primitives.h"

namespace boreas::bench {

namespace {

// Every function whose SIMD loop calls the header's is [[gnu::flatten]]: the header
// declares them plain static inline, GCC leaves boreas_grid_trilinear a call ("call is
// cold"), and a call stops the loop's vectorization.

// Points per block of the sine-sum loops. The loop over waves runs outside the SIMD loop
// over a block (GCC does not vectorize a loop with a loop inside), and a block's partial
// sums stay in L1.
constexpr int kBlock = kNativeWindBlock;

// boreas_wind_sine_sum (cl/shared/wind_sample.h) for n <= kBlock points, summed over the
// waves in the same order.
[[gnu::flatten]] void sine_sum_block(const float* x, const float* z, int n,
                                     const BoreasGpuWave* waves, int wave_count, float* fx,
                                     float* fz) {
#pragma omp simd
  for (int i = 0; i < n; ++i) fx[i] = fz[i] = 0.0f;
  for (int w = 0; w < wave_count; ++w) {
    const BoreasGpuWave wave = waves[w];
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      const float s = boreas_wind_wave(&wave, wave.phase_cycles, wave.dir_x, wave.dir_z, x[i], z[i]);
      fx[i] = BOREAS_FMA(wave.dir_x, s, fx[i]);
      fz[i] = BOREAS_FMA(wave.dir_z, s, fz[i]);
    }
  }
}

// Steps 1-5 of wind_grid_step.cl for the cells of row (j, k), given the forcing's target
// and keep factor per cell. Obstacles are a template parameter because a uniform bool
// inside the SIMD loop stops GCC vectorizing it.
template <bool kSolids>
[[gnu::flatten]] void grid_step_row(const float* in, float* out, const float* slab, const float* tx,
                                    const float* ty, const float* tz, const float* keep,
                                    const BoreasGpuGrid& g, const BoreasGpuGridStep& s, int j,
                                    int k) {
  const int nx = g.nx, ny = g.ny, nz = g.nz, n = boreas_grid_cells(g);
  const float* in_x = in;
  const float* in_y = in + n;
  const float* in_z = in + 2 * n;
  const float* in_solid = in + 3 * n;
  const float* sine_x = slab + size_t(k) * nx;
  const float* sine_z = slab + size_t(nx) * nz + size_t(k) * nx;
  const int row = boreas_grid_index(g, 0, j, k);
  // Neighbour rows, clamped at the grid's edge (zero-gradient boundary).
  const int dym = j > 0 ? nx : 0, dyp = j < ny - 1 ? nx : 0;
  const int dzm = k > 0 ? nx * ny : 0, dzp = k < nz - 1 ? nx * ny : 0;
#pragma omp simd
  for (int i = 0; i < nx; ++i) {
    const int c = row + i;
    const int xm = c - (i > 0 ? 1 : 0), xp = c + (i < nx - 1 ? 1 : 0);
    const int ym = c - dym, yp = c + dyp, zm = c - dzm, zp = c + dzp;
    const float sx = sine_x[i], sz = sine_z[i];
    // 1. transport: the wind where the backtrace lands
    float bx, by, bz;
    boreas_grid_trilinear(in, g, float(i) - (sx + in_x[c]) * s.dt_over_cell,
                          float(j) - in_y[c] * s.dt_over_cell,
                          float(k) - (sz + in_z[c]) * s.dt_over_cell, &bx, &by, &bz);
    // 2. diffusion
    const float mx =
        (in_x[xm] + in_x[xp] + in_x[ym] + in_x[yp] + in_x[zm] + in_x[zp]) * (1.0f / 6.0f);
    const float my =
        (in_y[xm] + in_y[xp] + in_y[ym] + in_y[yp] + in_y[zm] + in_y[zp]) * (1.0f / 6.0f);
    const float mz =
        (in_z[xm] + in_z[xp] + in_z[ym] + in_z[yp] + in_z[zm] + in_z[zp]) * (1.0f / 6.0f);
    // 3. decay, 4. forcing
    float vx = BOREAS_MIX(tx[i], BOREAS_MIX(bx, mx, s.diffusion_mix) * s.decay_factor, keep[i]);
    float vy = BOREAS_MIX(ty[i], BOREAS_MIX(by, my, s.diffusion_mix) * s.decay_factor, keep[i]);
    float vz = BOREAS_MIX(tz[i], BOREAS_MIX(bz, mz, s.diffusion_mix) * s.decay_factor, keep[i]);
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

namespace {

// As boreas_wind_sine_interpolated (cl/shared/wind_sample_width.inc): bilinear in the slab
// within the rectangle of the column centers, handing over to the exact sum in its
// outermost cell; the block's exact sums only where a point lies near the edge or beyond.
[[gnu::flatten]] void sine_interpolated_block(const float* px, const float* pz, int n,
                                              const BoreasGpuWave* waves, int wave_count,
                                              const float* grid, const BoreasGpuGrid& g, float* fx,
                                              float* fz) {
  const float inv_h = 1.0f / g.cell_size;
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
    boreas_slab_bilinear(grid, g, ux[i], uz[i], &fx[i], &fz[i]);
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

[[gnu::flatten]] void native_wind_block(const float* px, const float* py, const float* pz, int n,
                                        const BoreasGpuWave* waves, int wave_count,
                                        const float* grid, const BoreasGpuGrid& g, float* fx,
                                        float* fy, float* fz, bool interpolated) {
  const float inv_h = 1.0f / g.cell_size;
  if (interpolated)
    sine_interpolated_block(px, pz, n, waves, wave_count, grid, g, fx, fz);
  else
    sine_sum_block(px, pz, n, waves, wave_count, fx, fz);
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const float cx = (px[i] - g.origin_x) * inv_h;
    const float cy = (py[i] - g.origin_y) * inv_h;
    const float cz = (pz[i] - g.origin_z) * inv_h;
    boreas_wind_with_grid(grid, g, cx, cy, cz, fx[i], fz[i], &fx[i], &fy[i], &fz[i]);
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
[[gnu::flatten]] void add_flow_row(const BoreasGpuForcing* forcing, int count, float ox, float h,
                                   float py, float pz, int nx, float* tx, float* ty, float* tz,
                                   float* cov) {
  for (int m = 0; m < count; ++m) {
    const BoreasGpuForcing* f = forcing + m;
    const float ry = py - f->pos_y, rz = pz - f->pos_z;
#pragma omp simd
    for (int i = 0; i < nx; ++i) {
      const float rx = ox + (float(i) + 0.5f) * h - f->pos_x;
      const float c = boreas_flow_add(f, rx, ry, rz, &tx[i], &ty[i], &tz[i]);
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
