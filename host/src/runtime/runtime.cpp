// boreas: runtime set-up on the chosen device.
#include "runtime/runtime.h"

#include "errors.h"

namespace boreas::impl {

Runtime::Runtime(const char* device_request, const char* cache_dir) {
  std::vector<Device> devices = list_devices();
  device_ = devices[static_cast<size_t>(choose_device(devices, device_request ? device_request : ""))];
  cl_int err = CL_SUCCESS;
  context_ = cl::Context(device_.device, nullptr, nullptr, nullptr, &err);
  BOREAS_CL_CHECK(err);
  // Profiling is on so that benchmarks can read kernel time from events.
  queue_ = cl::CommandQueue(context_, device_.device, CL_QUEUE_PROFILING_ENABLE, &err);
  BOREAS_CL_CHECK(err);
  programs_ = std::make_unique<ProgramCache>(context_, device_,
                                             cache_dir ? std::string(cache_dir) : default_cache_dir());
}

cl::Kernel& Runtime::kernel(const std::string& file, const std::string& name,
                            const std::string& defines) {
  std::string key = file + '\n' + name + '\n' + defines;
  if (auto it = kernels_.find(key); it != kernels_.end()) return it->second;
  cl::Program program = programs_->get(file, defines);
  cl_int err = CL_SUCCESS;
  cl::Kernel k(program, name.c_str(), &err);
  BOREAS_CL_CHECK(err);
  return kernels_.emplace(key, k).first->second;
}

cl::Buffer Runtime::buffer(cl_mem_flags flags, size_t bytes) {
  cl_int err = CL_SUCCESS;
  cl::Buffer b(context_, flags, bytes == 0 ? 16 : bytes, nullptr, &err);
  BOREAS_CL_CHECK(err);
  return b;
}

void Runtime::launch(cl::Kernel& kernel, size_t items) {
  size_t global = (items + kLocalGroup - 1) / kLocalGroup * kLocalGroup;
  BOREAS_CL_CHECK(queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(kLocalGroup)));
}

}  // namespace boreas::impl
