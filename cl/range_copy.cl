/* boreas: a list of ranges of records copied from one buffer to another in one launch (the
 * vertices of several imported trees into a caller's buffer, boreas_cl.h), instead of a
 * copy command per object; `floats` floats a record (BoreasCopyRange: shared/range_table.h).
 * Ranges are sorted by item_first (the first at 0); a work-item finds its own by bisection
 * (boreas_range_row).
 * Each record's first 3 floats (a position) are moved by the range's offset: an imported
 * tree's vertices from its own coordinates to the caller's (mesh_tree_types.h).
 * Offsets are computed in size_t: a forest's vertices pass 2^31 floats. */
#include "shared/range_table.h"

__kernel void boreas_range_copy(__global const float* src, __global float* dst,
                                __global const BoreasCopyRange* ranges, int range_count, int items,
                                int floats) {
  int item = (int)get_global_id(0);
  if (item >= items) return;
  BoreasCopyRange r = ranges[boreas_range_row((__global const int*)ranges, (int)(sizeof(BoreasCopyRange) / sizeof(int)),
                                                  range_count, item)];
  int k = item - r.item_first;
  size_t from = ((size_t)r.src_first + (size_t)k) * (size_t)floats;
  size_t to = ((size_t)r.dst_first + (size_t)k) * (size_t)floats;
  for (int f = 0; f < floats; ++f) dst[to + f] = src[from + f] + (f < 3 ? r.offset[f] : 0.0f);
}
