/* boreas: the wind at a batch of points (boreas_wind_sample). Points and forces are
 * planes of count floats (x, then y, then z): packed triples would invite LLVM's SLP
 * vectorizer to pack them, which stops PoCL from vectorizing across work-items; the host
 * transposes. Each work-item samples BOREAS_W consecutive points (simd_width.h): the
 * global size is ceil(count / BOREAS_W) rounded up; work-items past the end redo the last
 * point (boreas_load_w) and write nothing new, which keeps the kernel free of branches.
 * Points are relative to the grid's corner (the host subtracts it in double) and the
 * waves' phases are those there (phases: one per wave), so points near a grid far from 0
 * keep their phases (README "Far from the origin"). */
#include "shared/wind_sample.h"

__kernel void boreas_wind_sample_points(__global const float* points, __global float* force,
                                        int count, __global const BoreasGpuWave* waves,
                                        int wave_count, __global const float* phases,
                                        __global const float* grid, BoreasGpuGrid g) {
  int first = (int)get_global_id(0) * BOREAS_W;
  BOREAS_F fx, fy, fz;
  boreas_wind_sample_local(g.origin_x, g.origin_y, g.origin_z, boreas_load_w(points, first, count),
                           boreas_load_w(points + count, first, count),
                           boreas_load_w(points + 2 * count, first, count), waves, wave_count,
                           phases, grid, g, &fx, &fy, &fz);
  boreas_store_w(fx, force, first, count);
  boreas_store_w(fy, force + count, first, count);
  boreas_store_w(fz, force + 2 * count, first, count);
}
