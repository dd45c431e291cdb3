// boreas: planes mapped for writing in place (mapped_planes.h).
#include "runtime/mapped_planes.h"

namespace boreas::impl {

MappedPlanes::MappedPlanes(Runtime& runtime, const cl::Buffer& buffer, size_t stride, size_t first,
                           size_t count, size_t planes, size_t elem)
    : runtime_(runtime), buffer_(buffer), bytes_(count * elem) {
  if (count == 0) return;
  pointers_.reserve(planes);
  for (size_t k = 0; k < planes; ++k) {
    cl_int code = CL_SUCCESS;
    void* p = runtime_.queue().enqueueMapBuffer(buffer_, CL_TRUE, CL_MAP_WRITE_INVALIDATE_REGION,
                                                (k * stride + first) * elem, bytes_, nullptr,
                                                nullptr, &code);
    if (code != CL_SUCCESS) {
      release();  // the planes mapped so far
      BOREAS_CL_CHECK(code);
    }
    pointers_.push_back(p);
  }
}

MappedPlanes::~MappedPlanes() { release(); }

void MappedPlanes::release() {
  // After a failure: the planes handed back without checking (nothing could report it).
  for (void* p : pointers_) runtime_.queue().enqueueUnmapMemObject(buffer_, p);
  if (!pointers_.empty()) runtime_.queue().finish();
  pointers_.clear();
}

void MappedPlanes::unmap() {
  std::vector<void*> mapped;
  mapped.swap(pointers_);
  cl_int first_error = CL_SUCCESS;
  for (void* p : mapped) {
    const cl_int code = runtime_.queue().enqueueUnmapMemObject(buffer_, p);
    if (first_error == CL_SUCCESS) first_error = code;
  }
  runtime_.count_upload(uint64_t(mapped.size()) * bytes_);
  BOREAS_CL_CHECK(first_error);
}

}  // namespace boreas::impl
