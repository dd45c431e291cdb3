// boreas: runtime set-up on the chosen device.
#include "runtime/runtime.h"

#include "errors.h"

#include <CL/cl_gl.h>

namespace boreas::impl {

Runtime::Runtime(const char* device_request, const char* cache_dir, const intptr_t* context_properties) {
  std::vector<Device> devices = list_devices();
  device_ = devices[static_cast<size_t>(choose_device(devices, device_request ? device_request : ""))];
  cl_int err = CL_SUCCESS;
  if (context_properties) {
    // The caller's pairs (a GL context to share with), then the platform.
    std::vector<cl_context_properties> props;
    bool shares_gl = false;
    for (int k = 0; context_properties[k] != 0; k += 2) {
      if (k >= 32) fail_argument("cl_context_properties has more than 16 pairs (or misses its closing 0)");
      props.push_back(context_properties[k]);
      props.push_back(context_properties[k + 1]);
      shares_gl = shares_gl || context_properties[k] == CL_GL_CONTEXT_KHR;
    }
    // Some drivers (PoCL) accept the GL properties without the extension, and the GL
    // buffers would then fail later, one by one: refuse here, once, saying why.
    if (shares_gl && device_.extensions.find("cl_khr_gl_sharing") == std::string::npos)
      fail(BOREAS_ERROR_NO_DEVICE, "cl_context_properties asks to share with an OpenGL context, but " + device_.name +
                                       " does not support cl_khr_gl_sharing");
    props.push_back(CL_CONTEXT_PLATFORM);
    props.push_back(reinterpret_cast<cl_context_properties>(device_.platform()));
    props.push_back(0);
    context_ = cl::Context(device_.device, props.data(), nullptr, nullptr, &err);
    if (err != CL_SUCCESS)
      fail(BOREAS_ERROR_OPENCL, "the OpenCL context with the given cl_context_properties (an OpenGL context to "
                                "share with?) could not be made on " + device_.name + ": OpenCL error " +
                                std::to_string(err));
  } else {
    context_ = cl::Context(device_.device, nullptr, nullptr, nullptr, &err);
  }
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

void Runtime::launch(cl::Kernel& kernel, size_t items, cl::Event* event) {
  size_t global = (items + kLocalGroup - 1) / kLocalGroup * kLocalGroup;
  BOREAS_CL_CHECK(queue_.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NDRange(kLocalGroup),
                                              nullptr, event));
}

}  // namespace boreas::impl
