/* boreas: the sine sum at the center of every grid column, once per step. The sine sum
 * depends on x and z only, so the grid update reads it from this nx * nz slab instead of
 * evaluating it ny times per column. */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sine_slab(__global float2* slab, __global const BoreasGpuWave* waves,
                                    int wave_count, BoreasGpuGrid g) {
  int i = get_global_id(0);
  int k = get_global_id(1);
  if (i >= g.nx || k >= g.nz) return;
  float x = g.origin_x + ((float)i + 0.5f) * g.cell_size;
  float z = g.origin_z + ((float)k + 0.5f) * g.cell_size;
  slab[k * g.nx + i] = boreas_wind_sine_sum(x, z, waves, wave_count);
}
