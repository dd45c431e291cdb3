/* boreas: the wind at a batch of points (boreas_wind_sample). xyz and force are packed
 * float triples; the global size may be rounded up past count. */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sample_points(__global const float* xyz, __global float* force,
                                        int count, __global const BoreasGpuWave* waves,
                                        int wave_count, __global const float4* grid,
                                        BoreasGpuGrid g) {
  int id = get_global_id(0);
  if (id >= count) return;
  float3 p = vload3(id, xyz);
  vstore3(boreas_wind_sample(p, waves, wave_count, grid, g), id, force);
}
