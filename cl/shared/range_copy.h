/* boreas: one range of a ranged copy (cl/range_copy.cl): records [src_first, src_first +
 * count) of the source to [dst_first, ...) of the destination, taken by the launch's
 * work-items [item_first, item_first + count). Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_RANGE_COPY_H
#define BOREAS_CL_SHARED_RANGE_COPY_H

#ifndef __OPENCL_C_VERSION__
#include <stdint.h>
typedef struct BoreasCopyRange {
  int32_t item_first, src_first, dst_first, count;
} BoreasCopyRange;
#else
typedef struct BoreasCopyRange {
  int item_first, src_first, dst_first, count;
} BoreasCopyRange;
#endif

#endif
