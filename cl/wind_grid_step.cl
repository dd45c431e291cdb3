/* boreas: one step of the force-field grid (Endo et al. sec. 4.1: the force propagates to
 * adjacent cells each step and is changed by the objects in the field).
 *
 * Per cell, reading only the previous grid (ping-pong), in this order:
 *  1. transport: semi-Lagrangian backtrace along the total flow (sine sum + grid) over dt,
 *     trilinear sample of the previous grid there (Stam, "Stable Fluids");
 *  2. diffusion: mixed with the mean of the 6 neighbours by 1 - exp(-6 nu dt / h^2), the
 *     exact relaxation of the discrete Laplacian toward that mean;
 *  3. decay: times exp(-lambda dt);
 *  4. forcing: flow primitives and gusts drive the cell toward the sum of their velocity
 *     fields T with rate coverage / response_time, integrated exactly: T + (v - T) e^(-K dt);
 *  5. obstacles: a solid cell holds minus the sine sum, so the total wind there is zero;
 *     a fluid cell next to a solid face loses the total wind's component normal to that
 *     face, into or out of it (a free-slip wall: no flux through the face, the tangential
 *     flow goes on along it, so the wind is deflected around the obstacle, not stopped).
 * Why this scheme: each of 1-4 is a convex combination of previous values and targets
 * (or a scaling by a factor <= 1), and 5 only removes components, so no value can grow
 * beyond the largest input for any dt: unconditionally stable, no CFL limit. The price
 * is first-order accuracy in time and some numerical diffusion from the interpolation.
 * With nothing to force and no solids, a zero grid stays exactly zero. */
#include "shared/flow_primitives.h"
#include "shared/wind_sample.h"

/* Compile-time shape of the step (the host builds one program per combination in use):
 * BOREAS_STEADY_FORCING reads the summed target and coverage of the primitives that do
 * not change from step to step (4 planes, built by wind_forcing_field.cl when they
 * change); BOREAS_FORCING_SLOTS varying ones (gusts) are summed in an unrolled loop (the
 * host pads with primitives of zero coverage; -1 loops over forcing_count); and
 * BOREAS_GRID_SOLIDS compiles the obstacle stage in or out. No branches are left in the
 * work-item loop. */
#ifndef BOREAS_STEADY_FORCING
#define BOREAS_STEADY_FORCING 0
#endif
#ifndef BOREAS_FORCING_SLOTS
#define BOREAS_FORCING_SLOTS -1
#endif
#ifndef BOREAS_GRID_SOLIDS
#define BOREAS_GRID_SOLIDS 1
#endif

__kernel void boreas_wind_grid_step(__global const float* in, __global float* out,
                                    __global const float* slab,
                                    __global const BoreasGpuForcing* forcing,
                                    __global const float* steady,
                                    BoreasGpuGrid g, BoreasGpuGridStep s) {
  int i = get_global_id(0); /* the global size is exactly (nx, ny, nz) */
  int j = get_global_id(1);
  int k = get_global_id(2);
  int c = boreas_grid_index(g, i, j, k);
  int n = boreas_grid_cells(g);
  __global const float* in_x = in;
  __global const float* in_y = in + n;
  __global const float* in_z = in + 2 * n;
  __global const float* in_solid = in + 3 * n;
  float sine_x = slab[k * g.nx + i];
  float sine_z = slab[g.nx * g.nz + k * g.nx + i];
  float solid = in_solid[c];

  /* 1. transport */
  float bx = (float)i - (sine_x + in_x[c]) * s.dt_over_cell;
  float by = (float)j - in_y[c] * s.dt_over_cell;
  float bz = (float)k - (sine_z + in_z[c]) * s.dt_over_cell;
  float vx, vy, vz;
  boreas_grid_trilinear(in, g, bx, by, bz, &vx, &vy, &vz);

  /* 2. diffusion: neighbours clamped at the grid's edge (zero-gradient boundary) */
  int xm = c - (i > 0);
  int xp = c + (i < g.nx - 1);
  int ym = c - g.nx * (j > 0);
  int yp = c + g.nx * (j < g.ny - 1);
  int zm = c - g.nx * g.ny * (k > 0);
  int zp = c + g.nx * g.ny * (k < g.nz - 1);
  float mx = (in_x[xm] + in_x[xp] + in_x[ym] + in_x[yp] + in_x[zm] + in_x[zp]) * (1.0f / 6.0f);
  float my = (in_y[xm] + in_y[xp] + in_y[ym] + in_y[yp] + in_y[zm] + in_y[zp]) * (1.0f / 6.0f);
  float mz = (in_z[xm] + in_z[xp] + in_z[ym] + in_z[yp] + in_z[zm] + in_z[zp]) * (1.0f / 6.0f);
  vx = mix(vx, mx, s.diffusion_mix);
  vy = mix(vy, my, s.diffusion_mix);
  vz = mix(vz, mz, s.diffusion_mix);

  /* 3. decay */
  vx *= s.decay_factor;
  vy *= s.decay_factor;
  vz *= s.decay_factor;

  /* 4. forcing */
#if BOREAS_STEADY_FORCING || BOREAS_FORCING_SLOTS != 0
  {
    float tx = 0.0f, ty = 0.0f, tz = 0.0f;
    float coverage_max = 0.0f;
#if BOREAS_STEADY_FORCING
    tx = steady[c];
    ty = steady[n + c];
    tz = steady[2 * n + c];
    coverage_max = steady[3 * n + c];
#endif
#if BOREAS_FORCING_SLOTS != 0
    float px = g.origin_x + ((float)i + 0.5f) * g.cell_size;
    float py = g.origin_y + ((float)j + 0.5f) * g.cell_size;
    float pz = g.origin_z + ((float)k + 0.5f) * g.cell_size;
#if BOREAS_FORCING_SLOTS > 0
#pragma unroll
    for (int m = 0; m < BOREAS_FORCING_SLOTS; ++m) {
#else
    for (int m = 0; m < s.forcing_count; ++m) {
#endif
      __global const BoreasGpuForcing* f = forcing + m;
      float cov = boreas_flow_add(f, px - f->pos_x, py - f->pos_y, pz - f->pos_z, &tx, &ty, &tz);
      coverage_max = max(coverage_max, cov);
    }
#endif
    /* Select, not arithmetic, where nothing covers the cell: 0 * a huge exponent is no
     * number to trust. */
    float keep = coverage_max > 0.0f ? boreas_exp2(-coverage_max * s.drive_exponent) : 1.0f;
    vx = mix(tx, vx, keep);
    vy = mix(ty, vy, keep);
    vz = mix(tz, vz, keep);
  }
#endif

  /* 5. obstacles */
#if BOREAS_GRID_SOLIDS
  {
    float wx = ((in_solid[xp] != 0.0f) | (in_solid[xm] != 0.0f)) ? 0.0f : sine_x + vx;
    float wy = ((in_solid[yp] != 0.0f) | (in_solid[ym] != 0.0f)) ? 0.0f : vy;
    float wz = ((in_solid[zp] != 0.0f) | (in_solid[zm] != 0.0f)) ? 0.0f : sine_z + vz;
    int is_solid = solid != 0.0f;
    vx = is_solid ? -sine_x : wx - sine_x;
    vy = is_solid ? 0.0f : wy;
    vz = is_solid ? -sine_z : wz - sine_z;
  }
#endif
  out[c] = vx;
  out[n + c] = vy;
  out[2 * n + c] = vz;
  out[3 * n + c] = solid;
}
