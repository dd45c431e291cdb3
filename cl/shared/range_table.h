/* boreas: launches over a list of ranges (one launch for many objects): a table of rows, each
 * starting with the first work-item of its range (sorted, the first at 0); and one range of
 * a ranged copy (cl/range_copy.cl): records [src_first, src_first + count) of the source to
 * [dst_first, ...) of the destination, taken by the launch's work-items [item_first,
 * item_first + count). Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_RANGE_TABLE_H
#define BOREAS_CL_SHARED_RANGE_TABLE_H

#ifndef __OPENCL_C_VERSION__
#include <stdint.h>
typedef struct BoreasCopyRange {
  int32_t item_first, src_first, dst_first, count;
  float offset[3]; /* added to each record's first 3 floats (a position), m */
  int32_t pad;
} BoreasCopyRange;
#else
#include "shared/simd_width.h"

typedef struct BoreasCopyRange {
  int item_first, src_first, dst_first, count;
  float offset[3];
  int pad;
} BoreasCopyRange;

/* The row of a table of `rows` rows of `row_ints` ints, each beginning with its first
 * work-item, that holds work-item `item`: the last whose first is at most item, found by
 * bisection (a step per doubling of the list). */
BOREAS_FN int boreas_range_row(__global const int* table, int row_ints, int rows, int item) {
  int lo = 0, hi = rows - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (table[mid * row_ints] <= item)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}
#endif

#endif
