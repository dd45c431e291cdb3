/* boreas: the sine sum at the center of every grid column, once per step. The sine sum
 * depends on x and z only, so the grid update reads it from this slab (two planes of
 * nx * nz floats, x then z) instead of evaluating it ny times per column. */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sine_slab(__global float* slab, __global const BoreasGpuWave* waves,
                                    int wave_count, BoreasGpuGrid g) {
  int i = get_global_id(0);  /* the global size is exactly (nx, nz) */
  int k = get_global_id(1);
  float x = g.origin_x + ((float)i + 0.5f) * g.cell_size;
  float z = g.origin_z + ((float)k + 0.5f) * g.cell_size;
  float fx, fz;
  boreas_wind_sine_sum(x, z, waves, wave_count, &fx, &fz);
  slab[k * g.nx + i] = fx;
  slab[g.nx * g.nz + k * g.nx + i] = fz;
}
