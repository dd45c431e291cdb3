// boreas: the caller's OpenCL buffers that the enqueue calls of boreas_cl.h write into,
// checked before anything is enqueued.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/cl_check.h"

namespace boreas::impl {

// Refuses a caller's buffer that cannot hold `records` records of `record_bytes` from
// record `first` on, naming what it was for (`what`) and both sizes.
void check_buffer_holds(const cl::Buffer& buffer, size_t first, size_t records, size_t record_bytes,
                        const char* what);

// The records one object of a list writes into a caller's buffer.
struct CallerRange {
  size_t first, count;
};
// Refuses a list whose objects' ranges overlap (their writes would race), naming both
// entries of the list `what` (ranges[k] belongs to what[k]).
void check_disjoint(const std::vector<CallerRange>& ranges, const char* what);

}  // namespace boreas::impl
