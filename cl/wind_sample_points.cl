/* boreas: the wind at a batch of points (boreas_wind_sample). xyz and force are packed
 * float triples. The global size is rounded up past count; the extra work-items redo the
 * last point and write the same value there, which keeps the kernel free of branches. */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sample_points(__global const float* xyz, __global float* force,
                                        int count, __global const BoreasGpuWave* waves,
                                        int wave_count, __global const float* grid,
                                        BoreasGpuGrid g) {
  int id = min((int)get_global_id(0), count - 1);
  float fx, fy, fz;
  boreas_wind_sample(xyz[3 * id], xyz[3 * id + 1], xyz[3 * id + 2], waves, wave_count, grid, g,
                     &fx, &fy, &fz);
  force[3 * id] = fx;
  force[3 * id + 1] = fy;
  force[3 * id + 2] = fz;
}
