/* boreas: the steady forcing field: per grid cell, the summed velocity of the flow
 * primitives that do not change from step to step, and the largest of their coverages
 * (4 planes: x, y, z, coverage). Built only when a primitive is added, removed or expires,
 * so the grid step reads 4 numbers per cell instead of evaluating every primitive. */
#include "shared/flow_primitives.h"

#ifndef BOREAS_FORCING_SLOTS
#define BOREAS_FORCING_SLOTS -1
#endif

__kernel void boreas_wind_forcing_field(__global float* field,
                                        __global const BoreasGpuForcing* forcing, int count,
                                        BoreasGpuGrid g) {
  int i = get_global_id(0); /* the global size is exactly (nx, ny, nz) */
  int j = get_global_id(1);
  int k = get_global_id(2);
  int c = boreas_grid_index(g, i, j, k);
  int n = boreas_grid_cells(g);
  float px = g.origin_x + ((float)i + 0.5f) * g.cell_size;
  float py = g.origin_y + ((float)j + 0.5f) * g.cell_size;
  float pz = g.origin_z + ((float)k + 0.5f) * g.cell_size;
  float tx = 0.0f, ty = 0.0f, tz = 0.0f;
  float coverage_max = 0.0f;
#if BOREAS_FORCING_SLOTS >= 0
#pragma unroll
  for (int m = 0; m < BOREAS_FORCING_SLOTS; ++m) {
#else
  for (int m = 0; m < count; ++m) {
#endif
    __global const BoreasGpuForcing* f = forcing + m;
    float cov = boreas_flow_add(f, px - f->pos_x, py - f->pos_y, pz - f->pos_z, &tx, &ty, &tz);
    coverage_max = max(coverage_max, cov);
  }
  field[c] = tx;
  field[n + c] = ty;
  field[2 * n + c] = tz;
  field[3 * n + c] = coverage_max;
}
