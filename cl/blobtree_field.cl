/* boreas: the BlobTree's field on the polygonizer's grid (Galbraith et al. 2004; the field
 * is defined in shared/blobtree_field.h). One work-group per bin of 8^3 points: its points
 * evaluate only the bin's primitives, the same list for the whole group. The naive twin
 * evaluates every primitive at every point (the benchmark's baseline; the same values,
 * bit for bit). Work-groups are a bin, or a half or quarter of one where the device or the
 * compiled kernel allows fewer than 512 work-items. The launch covers bins z in [z0, z0 + global size / 8), so the host can
 * report progress between slabs. */
#include "shared/blobtree_field.h"

__kernel void boreas_blobtree_field(__global const float* prims, __global const int* ints, int n,
                                    __global const int* bin_first, __global const int* bin_items,
                                    int bins_x, int bins_y, __global const float* cuts, int nc,
                                    float cell, int nx, int ny, int z0,
                                    __global float* field) {
  int x = get_global_id(0);
  int y = get_global_id(1);
  int z = get_global_id(2) + z0;
  /* Work-groups never straddle bins (the host picks local sizes dividing 8, and 8 along
   * x), so the bin, and with it the loop over its primitives, is the same for the whole
   * group; along x it comes from the group id, which PoCL's vectorizer knows is uniform. */
  int bin = ((z / BOREAS_BT_BIN) * bins_y + y / BOREAS_BT_BIN) * bins_x + (int)get_group_id(0);
  BoreasV3 p = boreas_v3(cell * (float)x, cell * (float)y, cell * (float)z);
  field[((size_t)z * ny + y) * nx + x] =
      boreas_bt_field(p, prims, ints, n, bin_items, bin_first[bin], bin_first[bin + 1], cuts, nc);
}

/* items: 0 .. n-1. */
__kernel void boreas_blobtree_field_naive(__global const float* prims, __global const int* ints, int n,
                                          __global const int* items, __global const float* cuts, int nc,
                                          float cell, int nx, int ny, int z0,
                                          __global float* field) {
  int x = get_global_id(0);
  int y = get_global_id(1);
  int z = get_global_id(2) + z0;
  BoreasV3 p = boreas_v3(cell * (float)x, cell * (float)y, cell * (float)z);
  field[((size_t)z * ny + y) * nx + x] = boreas_bt_field(p, prims, ints, n, items, 0, n, cuts, nc);
}
