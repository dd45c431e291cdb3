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
                                    __global const BoreasGpuForcing* forcing,
                                    __global const float* steady,
                                    BoreasGpuGrid g, BoreasGpuGridStep s) {
  /* BOREAS_W neighbouring cells of a row per work-item (simd_width.h): the global size is
   * (ceil(nx / W), ny, nz); lanes past the row's end redo its last cell and store nothing. */
  int first = (int)get_global_id(0) * BOREAS_W;
  int j = get_global_id(1);
  int k = get_global_id(2);
  BOREAS_I i = min(first + BOREAS_LANES, g.nx - 1);
  int row = (k * g.ny + j) * g.nx; /* the row's first cell */
  BOREAS_I c = row + i;
  int n = boreas_grid_cells(g);
  __global const float* in_x = in;
  __global const float* in_y = in + n;
  __global const float* in_z = in + 2 * n;
  __global const float* in_solid = in + 3 * n;
  /* The step's sine sums, written into this step's output buffer (wind_sine_slab.cl), past
   * the planes written here. */
  __global const float* slab = out + boreas_grid_slab_offset(g);
  BOREAS_F sine_x = boreas_load_w(slab + k * g.nx, first, g.nx);
  BOREAS_F sine_z = boreas_load_w(slab + g.nx * g.nz + k * g.nx, first, g.nx);
  BOREAS_F cell_x = boreas_load_w(in_x + row, first, g.nx);
  BOREAS_F cell_y = boreas_load_w(in_y + row, first, g.nx);
  BOREAS_F cell_z = boreas_load_w(in_z + row, first, g.nx);
  BOREAS_F solid = boreas_load_w(in_solid + row, first, g.nx);

  /* 1. transport */
  BOREAS_F bx = BOREAS_TO_FLOAT(i) - (sine_x + cell_x) * s.dt_over_cell;
  BOREAS_F by = (float)j - cell_y * s.dt_over_cell;
  BOREAS_F bz = (float)k - (sine_z + cell_z) * s.dt_over_cell;
  BOREAS_F vx, vy, vz;
  boreas_grid_trilinear(in, g, bx, by, bz, &vx, &vy, &vz);

  /* 2. diffusion: neighbours clamped at the grid's edge (zero-gradient boundary). Along
   * x per lane; the rows above, below, in front and behind are whole rows. */
  BOREAS_I xm = c - ((i > 0) & 1);
  BOREAS_I xp = c + ((i < g.nx - 1) & 1);
  int ym = row - g.nx * (j > 0);
  int yp = row + g.nx * (j < g.ny - 1);
  int zm = row - g.nx * g.ny * (k > 0);
  int zp = row + g.nx * g.ny * (k < g.nz - 1);
  BOREAS_F mx = (BOREAS_GATHER(in_x, xm) + BOREAS_GATHER(in_x, xp) +
                 boreas_load_w(in_x + ym, first, g.nx) + boreas_load_w(in_x + yp, first, g.nx) +
                 boreas_load_w(in_x + zm, first, g.nx) + boreas_load_w(in_x + zp, first, g.nx)) *
                (1.0f / 6.0f);
  BOREAS_F my = (BOREAS_GATHER(in_y, xm) + BOREAS_GATHER(in_y, xp) +
                 boreas_load_w(in_y + ym, first, g.nx) + boreas_load_w(in_y + yp, first, g.nx) +
                 boreas_load_w(in_y + zm, first, g.nx) + boreas_load_w(in_y + zp, first, g.nx)) *
                (1.0f / 6.0f);
  BOREAS_F mz = (BOREAS_GATHER(in_z, xm) + BOREAS_GATHER(in_z, xp) +
                 boreas_load_w(in_z + ym, first, g.nx) + boreas_load_w(in_z + yp, first, g.nx) +
                 boreas_load_w(in_z + zm, first, g.nx) + boreas_load_w(in_z + zp, first, g.nx)) *
                (1.0f / 6.0f);
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
    BOREAS_F tx = (BOREAS_F)(0.0f), ty = (BOREAS_F)(0.0f), tz = (BOREAS_F)(0.0f);
    BOREAS_F coverage_max = (BOREAS_F)(0.0f);
#if BOREAS_STEADY_FORCING
    tx = boreas_load_w(steady + row, first, g.nx);
    ty = boreas_load_w(steady + n + row, first, g.nx);
    tz = boreas_load_w(steady + 2 * n + row, first, g.nx);
    coverage_max = boreas_load_w(steady + 3 * n + row, first, g.nx);
#endif
#if BOREAS_FORCING_SLOTS != 0
    BOREAS_F px = g.origin_x + (BOREAS_TO_FLOAT(i) + 0.5f) * g.cell_size;
    float py = g.origin_y + ((float)j + 0.5f) * g.cell_size;
    float pz = g.origin_z + ((float)k + 0.5f) * g.cell_size;
#if BOREAS_FORCING_SLOTS > 0
#pragma unroll
    for (int m = 0; m < BOREAS_FORCING_SLOTS; ++m) {
#else
    for (int m = 0; m < s.forcing_count; ++m) {
#endif
      __global const BoreasGpuForcing* f = forcing + m;
      BOREAS_F cov = boreas_flow_add(f, px - f->pos_x, (BOREAS_F)(py - f->pos_y),
                                     (BOREAS_F)(pz - f->pos_z), &tx, &ty, &tz);
      coverage_max = max(coverage_max, cov);
    }
#endif
    /* Select, not arithmetic, where nothing covers the cell: 0 * a huge exponent is no
     * number to trust. */
    BOREAS_F keep = select((BOREAS_F)(1.0f), boreas_exp2(-coverage_max * s.drive_exponent),
                           coverage_max > 0.0f);
    vx = mix(tx, vx, keep);
    vy = mix(ty, vy, keep);
    vz = mix(tz, vz, keep);
  }
#endif

  /* 5. obstacles */
#if BOREAS_GRID_SOLIDS
  {
    BOREAS_F wx =
        select(sine_x + vx, (BOREAS_F)(0.0f),
               (BOREAS_GATHER(in_solid, xp) != 0.0f) | (BOREAS_GATHER(in_solid, xm) != 0.0f));
    BOREAS_F wy = select(vy, (BOREAS_F)(0.0f),
                         (boreas_load_w(in_solid + yp, first, g.nx) != 0.0f) |
                             (boreas_load_w(in_solid + ym, first, g.nx) != 0.0f));
    BOREAS_F wz = select(sine_z + vz, (BOREAS_F)(0.0f),
                         (boreas_load_w(in_solid + zp, first, g.nx) != 0.0f) |
                             (boreas_load_w(in_solid + zm, first, g.nx) != 0.0f));
    BOREAS_I is_solid = solid != 0.0f;
    vx = select(wx - sine_x, -sine_x, is_solid);
    vy = select(wy, (BOREAS_F)(0.0f), is_solid);
    vz = select(wz - sine_z, -sine_z, is_solid);
  }
#endif
  boreas_store_w(vx, out + row, first, g.nx);
  boreas_store_w(vy, out + n + row, first, g.nx);
  boreas_store_w(vz, out + 2 * n + row, first, g.nx);
  boreas_store_w(solid, out + 3 * n + row, first, g.nx);
}
