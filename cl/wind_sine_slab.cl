/* boreas: the sine sum at the center of every grid column, once per step. The sine sum
 * depends on x and z only, so the grid update reads it from this slab (two planes of
 * nx * nz floats, x then z, in the grid buffer's tail: boreas_grid_slab_offset) instead of
 * evaluating it ny times per column; with wind_sampling interpolated the plants read it
 * too. Each work-item computes BOREAS_W neighbouring columns of a row (simd_width.h).
 * The sums are taken relative to the grid's corner, with the waves' phases there from the
 * host in double (phases: one per wave), so a grid far from 0 keeps its phases (README
 * "Far from the origin"). */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sine_slab(__global float* grid, __global const BoreasGpuWave* waves,
                                    int wave_count, __global const float* phases,
                                    BoreasGpuGrid g) {
  __global float* slab = grid + boreas_grid_slab_offset(g);
  int first = (int)get_global_id(0) * BOREAS_W; /* global size (ceil(nx / W), nz) */
  int k = get_global_id(1);
  BOREAS_F x = (BOREAS_TO_FLOAT(first + BOREAS_LANES) + 0.5f) * g.cell_size;
  float z = ((float)k + 0.5f) * g.cell_size;
  BOREAS_F fx, fz;
  boreas_wind_sine_sum_phased(x, (BOREAS_F)(z), waves, wave_count, phases, 1, &fx, &fz);
  boreas_store_w(fx, slab + k * g.nx, first, g.nx);
  boreas_store_w(fz, slab + g.nx * g.nz + k * g.nx, first, g.nx);
}
