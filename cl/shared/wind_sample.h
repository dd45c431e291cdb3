/* boreas: the wind at a point, for any kernel (trees and underbrush call this).
 * wind(p, t) = sine_sum(p.x, p.z, t) + trilinear(grid, p), and zero inside solid cells.
 * OpenCL C only; the double-precision host twin is host/src/reference/wind_reference.cpp. */
#ifndef BOREAS_CL_SHARED_WIND_SAMPLE_H
#define BOREAS_CL_SHARED_WIND_SAMPLE_H

#include "shared/fast_math.h"
#include "shared/wind_types.h"

/* Sine sum (Skjermo eq. 14 in the GPU Gems form, seeds README):
 * F = sum_i D_i A_i ((sin(dot(D_i, (x, z)) w_i + phase_i) + 1) / 2)^k_i, horizontal. */
inline float2 boreas_wind_sine_sum(float x, float z, __global const BoreasGpuWave* waves,
                                   int wave_count) {
  float fx = 0.0f;
  float fz = 0.0f;
  for (int i = 0; i < wave_count; ++i) {
    const BoreasGpuWave w = waves[i];
    float theta = fma(fma(w.dir_x, x, w.dir_z * z), w.wavenumber, w.phase);
    float base = fma(boreas_sin(theta), 0.5f, 0.5f);
    float s = w.amplitude * boreas_pow(base, w.sharpness);
    fx = fma(w.dir_x, s, fx);
    fz = fma(w.dir_z, s, fz);
  }
  return (float2)(fx, fz);
}

inline int boreas_grid_index(const BoreasGpuGrid g, int i, int j, int k) {
  return (k * g.ny + j) * g.nx + i;
}

/* Trilinear interpolation of the grid's xyz between cell centers, at a position given in
 * cell units (cell (i,j,k)'s center is at i, j, k). Clamped to the outermost centers, so
 * the field continues flat beyond the grid's extent. */
inline float3 boreas_grid_trilinear(__global const float4* grid, const BoreasGpuGrid g,
                                    float3 c) {
  float3 hi = (float3)((float)(g.nx - 1), (float)(g.ny - 1), (float)(g.nz - 1));
  c = clamp(c, (float3)(0.0f), hi);
  float3 c0 = floor(c);
  float3 f = c - c0;
  int i0 = (int)c0.x;
  int j0 = (int)c0.y;
  int k0 = (int)c0.z;
  int i1 = min(i0 + 1, g.nx - 1);
  int j1 = min(j0 + 1, g.ny - 1);
  int k1 = min(k0 + 1, g.nz - 1);
  float3 v000 = grid[boreas_grid_index(g, i0, j0, k0)].xyz;
  float3 v100 = grid[boreas_grid_index(g, i1, j0, k0)].xyz;
  float3 v010 = grid[boreas_grid_index(g, i0, j1, k0)].xyz;
  float3 v110 = grid[boreas_grid_index(g, i1, j1, k0)].xyz;
  float3 v001 = grid[boreas_grid_index(g, i0, j0, k1)].xyz;
  float3 v101 = grid[boreas_grid_index(g, i1, j0, k1)].xyz;
  float3 v011 = grid[boreas_grid_index(g, i0, j1, k1)].xyz;
  float3 v111 = grid[boreas_grid_index(g, i1, j1, k1)].xyz;
  float3 x00 = mix(v000, v100, f.x);
  float3 x10 = mix(v010, v110, f.x);
  float3 x01 = mix(v001, v101, f.x);
  float3 x11 = mix(v011, v111, f.x);
  return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}

/* The wind at world position p (m), in m/s. */
inline float3 boreas_wind_sample(float3 p, __global const BoreasGpuWave* waves, int wave_count,
                                 __global const float4* grid, const BoreasGpuGrid g) {
  float2 sine = boreas_wind_sine_sum(p.x, p.z, waves, wave_count);
  float inv_h = 1.0f / g.cell_size;
  float3 cell = (p - (float3)(g.origin_x, g.origin_y, g.origin_z)) * inv_h;
  float3 wind = (float3)(sine.x, 0.0f, sine.y) + boreas_grid_trilinear(grid, g, cell - 0.5f);
  /* Inside a solid cell the wind is zero; the solid test applies within the extent only. */
  int3 ci = convert_int3_rtn(cell);
  int inside = ci.x >= 0 && ci.y >= 0 && ci.z >= 0 && ci.x < g.nx && ci.y < g.ny && ci.z < g.nz;
  int solid = inside && g.solid_count > 0 &&
              grid[boreas_grid_index(g, clamp(ci.x, 0, g.nx - 1), clamp(ci.y, 0, g.ny - 1),
                                     clamp(ci.z, 0, g.nz - 1))].w != 0.0f;
  return solid ? (float3)(0.0f) : wind;
}

#endif
