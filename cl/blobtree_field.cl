/* boreas: the BlobTree's field on the polygonizer's grid (Galbraith et al. 2004; the field
 * is defined in shared/blobtree_field.h). One work-group per bin of 8^3 points: its points
 * evaluate only the bin's primitives, the same list for the whole group. The naive twin
 * evaluates every primitive at every point (the benchmark's baseline; the same values,
 * bit for bit). Work-groups are a bin, or a part of one (halved along z, then y) where the
 * device or the compiled kernel allows fewer work-items. The launch covers bins z in
 * [z0, z0 + global size / 8), so the host can report progress between slabs.
 *
 * A work-item evaluates BOREAS_W points (simd_width.h: 1 on GPUs, the vector width on
 * CPUs), BOREAS_BT_LX along x by BOREAS_BT_LY along y, all in one bin: every lane walks
 * the same list, so the walk's branches are the work-item's and the arithmetic is the
 * lanes'. PoCL does not vectorize the walk across work-items (a loop of data-dependent
 * length), so the lanes are what makes it wide. */
#include "shared/blobtree_field.h"

#define BOREAS_BT_LX (BOREAS_W < BOREAS_BT_BIN ? BOREAS_W : BOREAS_BT_BIN)
#define BOREAS_BT_LY (BOREAS_W / BOREAS_BT_LX)

/* A work-item's points: lane l at grid point (x0 + l % LX, y0 + l / LX, z). */
BOREAS_FN BOREAS_V3 boreas_bt_points(float cell, int x0, int y0, int z) {
  BOREAS_I x = x0 + BOREAS_LANES % BOREAS_BT_LX;
  BOREAS_I y = y0 + BOREAS_LANES / BOREAS_BT_LX;
  return boreas_v3(cell * BOREAS_TO_FLOAT(x), cell * BOREAS_TO_FLOAT(y),
                   (BOREAS_F)(cell * (float)z));
}

/* Stores a work-item's values at point (x0, y0, z), index `at`: LY rows of LX floats. */
BOREAS_FN void boreas_bt_store_points(BOREAS_F v, __global float* field, size_t at, int nx) {
#if BOREAS_W == 1
  field[at] = v;
#elif BOREAS_W <= BOREAS_BT_BIN
  BOREAS_CAT(vstore, BOREAS_W)(v, 0, field + at);
#else
  vstore8(v.lo, 0, field + at);
  vstore8(v.hi, 0, field + at + nx);
#endif
}

__kernel void boreas_blobtree_field(__global const float* prims, __global const int* ints, int n,
                                    __global const int* bin_first, __global const int* bin_items,
                                    int bins_x, int bins_y, __global const float* cuts, int nc,
                                    float cell, int nx, int ny, int z0,
                                    __global float* field) {
  int x0 = get_global_id(0) * BOREAS_BT_LX;
  int y0 = get_global_id(1) * BOREAS_BT_LY;
  int z = get_global_id(2) + z0;
  /* Work-groups never straddle bins (the host picks local sizes dividing a bin, and a
   * whole bin along x), so the bin, and with it the walk over its primitives, is the same
   * for the whole group; along x it is the group id. */
  int bin = ((z / BOREAS_BT_BIN) * bins_y + y0 / BOREAS_BT_BIN) * bins_x + (int)get_group_id(0);
  BOREAS_F f = boreas_bt_field(boreas_bt_points(cell, x0, y0, z), prims, ints, n, bin_items,
                               bin_first[bin], bin_first[bin + 1], cuts, nc);
  boreas_bt_store_points(f, field, ((size_t)z * ny + y0) * nx + x0, nx);
}

/* items: 0 .. n-1. */
__kernel void boreas_blobtree_field_naive(__global const float* prims, __global const int* ints, int n,
                                          __global const int* items, __global const float* cuts, int nc,
                                          float cell, int nx, int ny, int z0,
                                          __global float* field) {
  int x0 = get_global_id(0) * BOREAS_BT_LX;
  int y0 = get_global_id(1) * BOREAS_BT_LY;
  int z = get_global_id(2) + z0;
  BOREAS_F f =
      boreas_bt_field(boreas_bt_points(cell, x0, y0, z), prims, ints, n, items, 0, n, cuts, nc);
  boreas_bt_store_points(f, field, ((size_t)z * ny + y0) * nx + x0, nx);
}
