// boreas: a range of a planar buffer's planes mapped for the host to write in place.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/runtime.h"

namespace boreas::impl {

// Elements [first, first + count) of each of `planes` planes (`stride` elements apart) of
// a device buffer, mapped for writing, one map per plane. Their old contents are not read
// (CL_MAP_WRITE_INVALIDATE_REGION): the host must write every element. On a CPU device
// the pointers are the buffer's own memory, so the host lays data out in place instead of
// staging it and copying it again (a batch of distinct trees is over a gigabyte of
// leaves); on a GPU the driver stages the ranges and uploads them at unmap. Threads may
// write disjoint parts at once.
//
// unmap() hands the planes back and counts them as uploaded; the destructor unmaps what is
// still mapped (after a failure, the ranges then hold whatever was written: callers map
// only ranges nothing reads yet).
class MappedPlanes {
 public:
  MappedPlanes(Runtime& runtime, const cl::Buffer& buffer, size_t stride, size_t first,
               size_t count, size_t planes, size_t elem = sizeof(float));
  ~MappedPlanes();
  MappedPlanes(const MappedPlanes&) = delete;
  MappedPlanes& operator=(const MappedPlanes&) = delete;

  // Plane k's first mapped element.
  template <typename T>
  T* plane(size_t k) const {
    return static_cast<T*>(pointers_[k]);
  }
  void unmap();

 private:
  void release();

  Runtime& runtime_;
  cl::Buffer buffer_;
  size_t bytes_ = 0;  // per plane
  std::vector<void*> pointers_;
};

}  // namespace boreas::impl
