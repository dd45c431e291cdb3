// boreas: one OpenCL context, queue and program cache on the chosen device.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "runtime/cl_check.h"
#include "runtime/device.h"
#include "runtime/program_cache.h"

namespace boreas::impl {

class Runtime {
 public:
  // device_request and cache_dir as in boreas_world_def (nullptr for the defaults).
  Runtime(const char* device_request, const char* cache_dir);

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

 private:
  Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::unique_ptr<ProgramCache> programs_;
  std::map<std::string, cl::Kernel> kernels_;
};

}  // namespace boreas::impl
