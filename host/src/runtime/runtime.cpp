// boreas: runtime set-up on the chosen device.
#include "runtime/runtime.h"

#include <CL/cl_gl.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "errors.h"
#include "runtime/launch.h"

namespace boreas::impl {

namespace {

// "1613179044 bytes (1.5 GiB)", or MiB below a GiB.
std::string gib(uint64_t bytes) {
  char text[64];
  if (bytes >= (uint64_t(1) << 30))
    std::snprintf(text, sizeof text, "%.3g GiB", double(bytes) / double(uint64_t(1) << 30));
  else
    std::snprintf(text, sizeof text, "%.3g MiB", double(bytes) / double(uint64_t(1) << 20));
  return std::to_string(bytes) + " bytes (" + text + ")";
}

// A byte count from the environment variable `name`: bytes, or a number with K, M or G
// (binary); 0 where unset.
uint64_t bytes_from_env(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return 0;
  char* end = nullptr;
  double value = std::strtod(text, &end);
  double unit = 1.0;
  switch (std::toupper(static_cast<unsigned char>(*end))) {
    case 'K':
      unit = 1024.0;
      ++end;
      break;
    case 'M':
      unit = 1024.0 * 1024.0;
      ++end;
      break;
    case 'G':
      unit = 1024.0 * 1024.0 * 1024.0;
      ++end;
      break;
    default:
      break;
  }
  if (end == text || *end != '\0' || !(value > 0.0))
    fail_argument(std::string(name) +
                  " must be a positive number of bytes, optionally with K, M or G (got '" + text +
                  "')");
  return uint64_t(value * unit);
}

// Hands a buffer's bytes back to the runtime's count when OpenCL frees it.
struct HeldBytes {
  std::shared_ptr<std::atomic<uint64_t>> counter;
  uint64_t bytes;
};

void CL_CALLBACK release_bytes(cl_mem, void* user) {
  auto* held = static_cast<HeldBytes*>(user);
  held->counter->fetch_sub(held->bytes);
  delete held;
}

}  // namespace

Runtime::Runtime(const char* device_request, const char* cache_dir,
                 const intptr_t* context_properties) {
  std::vector<Device> devices = list_devices();
  device_ =
      devices[static_cast<size_t>(choose_device(devices, device_request ? device_request : ""))];
  cl_int err = CL_SUCCESS;
  if (context_properties) {
    // The caller's pairs (a GL context to share with), then the platform.
    std::vector<cl_context_properties> props;
    bool shares_gl = false;
    for (int k = 0; context_properties[k] != 0; k += 2) {
      if (k >= 32)
        fail_argument("cl_context_properties has more than 16 pairs (or misses its closing 0)");
      props.push_back(context_properties[k]);
      props.push_back(context_properties[k + 1]);
      shares_gl = shares_gl || context_properties[k] == CL_GL_CONTEXT_KHR;
    }
    // Some drivers (PoCL) accept the GL properties without the extension, and the GL
    // buffers would then fail later, one by one: refuse here, once, saying why.
    if (shares_gl && device_.extensions.find("cl_khr_gl_sharing") == std::string::npos)
      fail(BOREAS_ERROR_NO_DEVICE,
           "cl_context_properties asks to share with an OpenGL context, but " + device_.name +
               " does not support cl_khr_gl_sharing");
    props.push_back(CL_CONTEXT_PLATFORM);
    props.push_back(reinterpret_cast<cl_context_properties>(device_.platform()));
    props.push_back(0);
    context_ = cl::Context(device_.device, props.data(), nullptr, nullptr, &err);
    if (err != CL_SUCCESS)
      fail(BOREAS_ERROR_OPENCL,
           "the OpenCL context with the given cl_context_properties (an OpenGL context to "
           "share with?) could not be made on " +
               device_.name + ": OpenCL error " + std::to_string(err));
  } else {
    context_ = cl::Context(device_.device, nullptr, nullptr, nullptr, &err);
  }
  BOREAS_CL_CHECK(err);
  // Profiling is on so that benchmarks can read kernel time from events.
  queue_ = cl::CommandQueue(context_, device_.device, CL_QUEUE_PROFILING_ENABLE, &err);
  BOREAS_CL_CHECK(err);
  programs_ = std::make_unique<ProgramCache>(
      context_, device_, cache_dir ? std::string(cache_dir) : default_cache_dir());
  group_size_ = launch_group_size(device_);
  max_allocation_ = device_.device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
  if (uint64_t limit = bytes_from_env("BOREAS_MAX_ALLOCATION"); limit > 0)
    max_allocation_ = max_allocation_ > 0 ? std::min<uint64_t>(max_allocation_, limit) : limit;
  memory_limit_ = device_.global_memory;
  if (uint64_t limit = bytes_from_env("BOREAS_DEVICE_MEMORY"); limit > 0)
    memory_limit_ = std::min<uint64_t>(memory_limit_, limit);
}

cl::Kernel& Runtime::kernel(const std::string& file, const std::string& name,
                            const std::string& defines) {
  auto& variants = kernels_[file + '\n' + name];
  if (auto it = variants.find(defines); it != variants.end()) {
    it->second.last_use = ++kernel_uses_;
    return it->second.kernel;
  }
  // Built before anything is released, so a variant that fails to build leaves the kept
  // ones as they were.
  cl::Program program = programs_->get(file, defines);
  cl_int err = CL_SUCCESS;
  cl::Kernel k(program, name.c_str(), &err);
  BOREAS_CL_CHECK(err);
  if (variants.size() >= size_t(kKernelVariantsKept)) {
    auto oldest = variants.begin();
    for (auto it = variants.begin(); it != variants.end(); ++it)
      if (it->second.last_use < oldest->second.last_use) oldest = it;
    const std::string released = oldest->first;
    variants.erase(oldest);
    // The program goes too unless another kernel of the same file still uses it (a
    // launch in flight keeps its own reference to both).
    bool shared = false;
    const std::string prefix = file + '\n';
    for (const auto& [key, others] : kernels_)
      if (key.compare(0, prefix.size(), prefix) == 0 && others.count(released)) shared = true;
    if (!shared) programs_->release(file, released);
  }
  KernelVariant& v = variants[defines];
  v.kernel = std::move(k);
  v.last_use = ++kernel_uses_;
  return v.kernel;
}

size_t Runtime::kernel_variants() const {
  size_t n = 0;
  for (const auto& [key, variants] : kernels_) n += variants.size();
  return n;
}

size_t Runtime::kernel_variants(const std::string& file, const std::string& name) const {
  auto it = kernels_.find(file + '\n' + name);
  return it == kernels_.end() ? 0 : it->second.size();
}

cl::Buffer Runtime::buffer(cl_mem_flags flags, size_t bytes, const char* what) {
  const uint64_t size = bytes == 0 ? 16 : bytes;
  if (max_allocation_ > 0 && size > max_allocation_)
    fail(BOREAS_ERROR_OUT_OF_MEMORY, std::string(what) + " needs one buffer of " + gib(size) +
                                         "; " + device_.name + " allocates at most " +
                                         gib(max_allocation_) + " at once");
  const uint64_t in_use = memory_->load();
  if (memory_limit_ > 0 && in_use + size > memory_limit_)
    fail(BOREAS_ERROR_OUT_OF_MEMORY, std::string(what) + " needs " + gib(size) + " more on " +
                                         device_.name + ", which holds " + gib(in_use) +
                                         " of its " + gib(memory_limit_) + " already");
  cl_int err = CL_SUCCESS;
  cl::Buffer b(context_, flags, size, nullptr, &err);
  if (err == CL_MEM_OBJECT_ALLOCATION_FAILURE || err == CL_OUT_OF_RESOURCES ||
      err == CL_OUT_OF_HOST_MEMORY)
    fail(BOREAS_ERROR_OUT_OF_MEMORY, std::string(what) + ": " + device_.name +
                                         " could not allocate " + gib(size) + " (" +
                                         cl_error_name(err) + ")");
  BOREAS_CL_CHECK(err);
  auto* held = new HeldBytes{memory_, size};
  memory_->fetch_add(size);
  if (clSetMemObjectDestructorCallback(b(), release_bytes, held) != CL_SUCCESS) {
    memory_->fetch_sub(size);  // not counted, rather than counted forever
    delete held;
  }
  return b;
}

void Runtime::write(const cl::Buffer& buffer, size_t offset, size_t bytes, const void* data,
                    bool blocking) {
  if (bytes == 0) return;
  BOREAS_CL_CHECK(
      queue_.enqueueWriteBuffer(buffer, blocking ? CL_TRUE : CL_FALSE, offset, bytes, data));
  traffic_.uploaded += bytes;
}

void Runtime::read(const cl::Buffer& buffer, size_t offset, size_t bytes, void* out) {
  if (bytes == 0) return;
  BOREAS_CL_CHECK(queue_.enqueueReadBuffer(buffer, CL_TRUE, offset, bytes, out));
  traffic_.read_back += bytes;
}

void Runtime::write_planes(const cl::Buffer& buffer, size_t device_stride, size_t first,
                           const void* host, size_t host_stride, size_t count, size_t planes,
                           size_t elem) {
  if (count == 0 || planes == 0) return;
  const cl::array<size_t, 3> device_origin{first * elem, 0, 0}, host_origin{0, 0, 0},
      region{count * elem, planes, 1};
  BOREAS_CL_CHECK(queue_.enqueueWriteBufferRect(buffer, CL_TRUE, device_origin, host_origin, region,
                                                device_stride * elem, 0, host_stride * elem, 0,
                                                host));
  traffic_.uploaded += count * planes * elem;
}

void Runtime::read_planes(const cl::Buffer& buffer, size_t device_stride, size_t first, void* host,
                          size_t host_stride, size_t count, size_t planes, size_t elem) {
  if (count == 0 || planes == 0) return;
  const cl::array<size_t, 3> device_origin{first * elem, 0, 0}, host_origin{0, 0, 0},
      region{count * elem, planes, 1};
  BOREAS_CL_CHECK(queue_.enqueueReadBufferRect(buffer, CL_TRUE, device_origin, host_origin, region,
                                               device_stride * elem, 0, host_stride * elem, 0,
                                               host));
  traffic_.read_back += count * planes * elem;
}

void Runtime::copy_planes(const cl::Buffer& from, size_t from_stride, size_t from_first,
                          const cl::Buffer& to, size_t to_stride, size_t to_first, size_t count,
                          size_t planes, size_t elem) {
  if (count == 0 || planes == 0) return;
  const cl::array<size_t, 3> from_origin{from_first * elem, 0, 0}, to_origin{to_first * elem, 0, 0},
      region{count * elem, planes, 1};
  BOREAS_CL_CHECK(queue_.enqueueCopyBufferRect(from, to, from_origin, to_origin, region,
                                               from_stride * elem, 0, to_stride * elem, 0));
  traffic_.copied_on_device += count * planes * elem;
}

}  // namespace boreas::impl
