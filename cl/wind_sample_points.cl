/* boreas: the wind at a batch of points (boreas_wind_sample). Points and forces are
 * planes of count floats (x, then y, then z): packed triples would invite LLVM's SLP
 * vectorizer to pack them, which stops PoCL from vectorizing across work-items; the host
 * transposes. The global size is rounded up past count; the extra work-items redo the
 * last point and write the same value there, which keeps the kernel free of branches. */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sample_points(__global const float* points, __global float* force,
                                        int count, __global const BoreasGpuWave* waves,
                                        int wave_count, __global const float* grid,
                                        BoreasGpuGrid g) {
  int id = min((int)get_global_id(0), count - 1);
  float fx, fy, fz;
  boreas_wind_sample(points[id], points[count + id], points[2 * count + id], waves, wave_count,
                     grid, g, &fx, &fy, &fz);
  force[id] = fx;
  force[count + id] = fy;
  force[2 * count + id] = fz;
}
