// boreas: listing OpenCL devices and choosing the one a world runs on.
#pragma once

#include <string>
#include <vector>

#include "runtime/cl_check.h"

namespace boreas::impl {

struct Device {
  int platform_index = 0;
  int device_index = 0;
  cl::Platform platform;
  cl::Device device;
  std::string platform_name;
  std::string platform_version;
  std::string name;
  std::string version;         // CL_DEVICE_VERSION
  std::string driver_version;  // CL_DRIVER_VERSION
  std::string extensions;
  cl_device_type type = 0;
  int compute_units = 0;
  unsigned long long global_memory = 0;
  bool is_gpu() const { return (type & CL_DEVICE_TYPE_GPU) != 0; }
  bool has_extension(const std::string& name) const;
  // Polynomial math where builtins stop vectorization (CPU devices); builtins on GPUs.
  // BOREAS_FAST_MATH=0 or 1 in the environment overrides, for testing both paths.
  bool uses_fast_math() const;
  // Items a kernel written for it (cl/shared/simd_width.h) processes per work-item: on a
  // CPU the native float vector width (16 with AVX-512, 8 with AVX2), since PoCL compiles
  // OpenCL vectors straight to that width where its own work-item vectorizer stops at 8;
  // 1 on GPUs, and wherever builtins replace the polynomials. BOREAS_SIMD_WIDTH (1, 2, 4,
  // 8 or 16) in the environment overrides, for testing and benchmarking each width.
  int simd_width() const;
  int native_float_width = 1;  // CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT
};

// Every device of every platform. Throws BOREAS_ERROR_NO_DEVICE, naming the packages that
// provide a driver, when there is no OpenCL platform or no device at all.
std::vector<Device> list_devices();

// Index into devices for a request: "" for the best (GPU over CPU, then more compute
// units; BOREAS_DEVICE honoured), "gpu", "cpu", "P:D", or part of a device or platform
// name (case-insensitive). Throws BOREAS_ERROR_NO_DEVICE listing what exists.
int choose_device(const std::vector<Device>& devices, const std::string& request);

}  // namespace boreas::impl
