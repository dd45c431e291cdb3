// boreas: one OpenCL context, queue and program cache on the chosen device.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "runtime/cl_check.h"
#include "runtime/device.h"
#include "runtime/program_cache.h"

namespace boreas::impl {

class Runtime {
 public:
  // device_request, cache_dir and context_properties as in boreas_world_def (nullptr for
  // the defaults).
  Runtime(const char* device_request, const char* cache_dir, const intptr_t* context_properties = nullptr);

  const Device& device() const { return device_; }
  cl::Context& context() { return context_; }
  cl::CommandQueue& queue() { return queue_; }
  ProgramCache& programs() { return *programs_; }

  // A kernel from a file of cl/, built on first use with the given extra #defines
  // (one program per distinct set). The same kernel object is returned for the same
  // arguments, so callers may keep setting its arguments.
  cl::Kernel& kernel(const std::string& file, const std::string& name,
                     const std::string& defines = "");

  // A device buffer of at least bytes (never zero-sized, which OpenCL refuses).
  cl::Buffer buffer(cl_mem_flags flags, size_t bytes);

  // Copies data to the start of buffer, blocking (nothing for an empty vector).
  template <typename T>
  void upload(const cl::Buffer& buffer, const std::vector<T>& data) {
    if (!data.empty())
      BOREAS_CL_CHECK(queue_.enqueueWriteBuffer(buffer, CL_TRUE, 0, data.size() * sizeof(T), data.data()));
  }

  // The same without waiting for the copy: for the small per-step uploads, which would
  // otherwise each cost a round trip. The caller keeps `data` unchanged and alive until
  // the queue has finished (a staging member, and a finish before it is written again).
  template <typename T>
  void upload_async(const cl::Buffer& buffer, const std::vector<T>& data) {
    if (!data.empty())
      BOREAS_CL_CHECK(queue_.enqueueWriteBuffer(buffer, CL_FALSE, 0, data.size() * sizeof(T), data.data()));
  }

  // Enqueues a 1-D kernel over `items` work-items in groups of kLocalGroup; the range is
  // rounded up to whole groups, so the kernels clamp their ids to the last item. With
  // `event`, the launch's event is kept there (for profiling).
  static constexpr size_t kLocalGroup = 64;
  void launch(cl::Kernel& kernel, size_t items, cl::Event* event = nullptr);

 private:
  Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::unique_ptr<ProgramCache> programs_;
  std::map<std::string, cl::Kernel> kernels_;
};

}  // namespace boreas::impl
