/* boreas: the wind at a point, for any kernel (trees and underbrush call this).
 * wind(p, t) = sine_sum(p.x, p.z, t) + fade(p) trilinear(grid, p), and zero inside solid
 * cells.
 * OpenCL C only; the double-precision host twin is host/src/reference/wind_reference.cpp.
 *
 * Written in scalar floats on purpose: on PoCL (LLVM 15) the loop vectorizer refuses any
 * instruction of vector type (float2/3/4 values, whole-struct copies) inside the
 * work-item loop, and a kernel that is not vectorized runs one lane at a time. */
#ifndef BOREAS_CL_SHARED_WIND_SAMPLE_H
#define BOREAS_CL_SHARED_WIND_SAMPLE_H

#include "shared/fast_math.h"
#include "shared/wind_types.h"

/* Every helper is inlined: PoCL vectorizes across work-items only a loop with no calls. */
#define BOREAS_INLINE inline __attribute__((always_inline))

/* Waves are summed over a compile-time number of slots (the host pads the set with
 * silent waves up to it) so the loop unrolls and the work-item loop around the kernel
 * stays innermost, which LLVM's vectorizer needs. -1 sums wave_count waves in a plain
 * loop (sets beyond the largest slot count). */
#ifndef BOREAS_WAVE_SLOTS
#define BOREAS_WAVE_SLOTS -1
#endif

/* Sine sum (Skjermo eq. 14 in the GPU Gems form, seeds README):
 * F = sum_i D_i A_i ((sin(dot(D_i, (x, z)) w_i + phase_i) + 1) / 2)^k_i, horizontal,
 * with phase_i = t phi_i, phi_i = -speed_i w_i (crests move downwind; see boreas.h). */
BOREAS_INLINE void boreas_wind_sine_sum(float x, float z, __global const BoreasGpuWave* waves,
                                        int wave_count, float* out_x, float* out_z) {
  float fx = 0.0f;
  float fz = 0.0f;
#if BOREAS_WAVE_SLOTS >= 0
#pragma unroll
  for (int i = 0; i < BOREAS_WAVE_SLOTS; ++i) {
#else
  for (int i = 0; i < wave_count; ++i) {
#endif
    float dx = waves[i].dir_x;
    float dz = waves[i].dir_z;
    /* The phase in cycles, reduced to [-1/2, 1/2] before the sine: any point and any
     * wavelength keep the argument within [-pi, pi], where the polynomial holds. */
    float u = fma(fma(dx, x, dz * z), waves[i].cycles_per_meter, waves[i].phase_cycles);
    u -= floor(u + 0.5f);
    float base = fma(boreas_sin_cycle(u), 0.5f, 0.5f);
    float s = waves[i].amplitude * boreas_pow(base, waves[i].sharpness);
    fx = fma(dx, s, fx);
    fz = fma(dz, s, fz);
  }
  *out_x = fx;
  *out_z = fz;
}

BOREAS_INLINE int boreas_grid_index(const BoreasGpuGrid g, int i, int j, int k) {
  return (k * g.ny + j) * g.nx + i;
}

BOREAS_INLINE int boreas_grid_cells(const BoreasGpuGrid g) { return g.nx * g.ny * g.nz; }

/* Trilinear interpolation of the grid's xyz between cell centers, at a position given in
 * cell units (cell (i,j,k)'s center is at i, j, k). Clamped to the outermost centers, so
 * the field continues flat beyond the grid's extent (boreas_wind_sample fades it out
 * beyond the sides). grid holds the 4 planes. */
BOREAS_INLINE void boreas_grid_trilinear(__global const float* grid, const BoreasGpuGrid g,
                                         float cx, float cy, float cz, float* out_x,
                                         float* out_y, float* out_z) {
  cx = clamp(cx, 0.0f, (float)(g.nx - 1));
  cy = clamp(cy, 0.0f, (float)(g.ny - 1));
  cz = clamp(cz, 0.0f, (float)(g.nz - 1));
  float x0 = floor(cx);
  float y0 = floor(cy);
  float z0 = floor(cz);
  float fx = cx - x0;
  float fy = cy - y0;
  float fz = cz - z0;
  int i0 = (int)x0;
  int j0 = (int)y0;
  int k0 = (int)z0;
  int di = min(i0 + 1, g.nx - 1) - i0; /* 0 on the last cell */
  int dj = (min(j0 + 1, g.ny - 1) - j0) * g.nx;
  int dk = (min(k0 + 1, g.nz - 1) - k0) * g.nx * g.ny;
  int c000 = boreas_grid_index(g, i0, j0, k0);
  int c100 = c000 + di;
  int c010 = c000 + dj;
  int c110 = c010 + di;
  int c001 = c000 + dk;
  int c101 = c001 + di;
  int c011 = c001 + dj;
  int c111 = c011 + di;
  float w000 = (1.0f - fx) * (1.0f - fy) * (1.0f - fz);
  float w100 = fx * (1.0f - fy) * (1.0f - fz);
  float w010 = (1.0f - fx) * fy * (1.0f - fz);
  float w110 = fx * fy * (1.0f - fz);
  float w001 = (1.0f - fx) * (1.0f - fy) * fz;
  float w101 = fx * (1.0f - fy) * fz;
  float w011 = (1.0f - fx) * fy * fz;
  float w111 = fx * fy * fz;
  int plane = boreas_grid_cells(g);
  float r[3];
#pragma unroll
  for (int a = 0; a < 3; ++a) {
    __global const float* p = grid + a * plane;
    r[a] = w000 * p[c000] + w100 * p[c100] + w010 * p[c010] + w110 * p[c110] +
           w001 * p[c001] + w101 * p[c101] + w011 * p[c011] + w111 * p[c111];
  }
  *out_x = r[0];
  *out_y = r[1];
  *out_z = r[2];
}

/* How much of the grid's wind reaches a point (cx, cz) in cells from the grid's corner
 * (the grid spans [0, nx) x [0, nz)): 1 within the extent, easing to 0 over
 * 1 / fade_per_cell cells beyond it, by the point's distance outside the extent in the
 * max norm (smoothstep: continuous in value and slope, so nothing marks where the grid
 * ends). The maximum is taken on the floats' bits as ints (a non-negative float orders
 * like its bits, a negative one reads as a negative int, so the result is exact): float
 * compare-and-selects on x and z side by side are what LLVM's SLP vectorizer packs into
 * a vector, and one vector value stops PoCL's work-item vectorizer (see the file's head). */
BOREAS_INLINE float boreas_grid_fade(float cx, float cz, int nx, int nz, float fade_per_cell) {
  float hx = 0.5f * (float)nx;
  float hz = 0.5f * (float)nz;
  float ox = fabs(cx - hx) - hx; /* cells beyond the nearer side along x; < 0 inside */
  float oz = fabs(cz - hz) - hz;
  float outside = as_float(max(max(as_int(ox), as_int(oz)), 0));
  float s = clamp(1.0f - outside * fade_per_cell, 0.0f, 1.0f);
  return s * s * (3.0f - 2.0f * s);
}

/* The wind at world position (px, py, pz) in m, in m/s. */
BOREAS_INLINE void boreas_wind_sample(float px, float py, float pz,
                                      __global const BoreasGpuWave* waves, int wave_count,
                                      __global const float* grid, const BoreasGpuGrid g,
                                      float* out_x, float* out_y, float* out_z) {
  float sx, sz;
  boreas_wind_sine_sum(px, pz, waves, wave_count, &sx, &sz);
  float inv_h = 1.0f / g.cell_size;
  float cx = (px - g.origin_x) * inv_h;
  float cy = (py - g.origin_y) * inv_h;
  float cz = (pz - g.origin_z) * inv_h;
  float gx, gy, gz;
  boreas_grid_trilinear(grid, g, cx - 0.5f, cy - 0.5f, cz - 0.5f, &gx, &gy, &gz);
  /* Beyond the sides the grid's wind fades out (boreas_grid_def.edge_fade); above and
   * below it goes on as in the outermost cells (the clamp above). */
  float fade = boreas_grid_fade(cx, cz, g.nx, g.nz, g.fade_per_cell);
  gx *= fade;
  gy *= fade;
  gz *= fade;
  /* Inside a solid cell the wind is zero; the solid test applies within the extent only.
   * Bitwise & rather than &&: no short-circuit branches in the vectorized loop. */
  float fi = floor(cx);
  float fj = floor(cy);
  float fk = floor(cz);
  int inside = (fi >= 0.0f) & (fj >= 0.0f) & (fk >= 0.0f) & (fi < (float)g.nx) &
               (fj < (float)g.ny) & (fk < (float)g.nz);
  /* Clamped as floats first: a far point's float would not fit an int. */
  int ci = (int)clamp(fi, 0.0f, (float)(g.nx - 1));
  int cj = (int)clamp(fj, 0.0f, (float)(g.ny - 1));
  int ck = (int)clamp(fk, 0.0f, (float)(g.nz - 1));
  float flag = grid[3 * boreas_grid_cells(g) + boreas_grid_index(g, ci, cj, ck)];
  int solid = inside & (g.solid_count > 0) & (flag != 0.0f);
  *out_x = solid ? 0.0f : sx + gx;
  *out_y = solid ? 0.0f : gy;
  *out_z = solid ? 0.0f : sz + gz;
}

#endif
