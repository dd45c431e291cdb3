// boreas: builds each kernel program once per context, and keeps built binaries on disk
// keyed by source, device, driver and options, so later runs skip the compiler.
#pragma once

#include <map>
#include <string>

#include "runtime/cl_check.h"
#include "runtime/device.h"

namespace boreas::impl {

class ProgramCache {
 public:
  // cache_dir: folder for binaries; "" keeps them in memory only.
  ProgramCache(cl::Context context, const Device& device, std::string cache_dir);

  // The built program of a kernel file, with the device prelude (BOREAS_FAST_MATH, ...)
  // and extra_defines prepended. Throws BOREAS_ERROR_KERNEL_BUILD with the compiler's
  // log when the source does not build.
  cl::Program get(const std::string& file, const std::string& extra_defines = "");

  // Forgets the program get(file, extra_defines) returned, so its memory goes once no
  // kernel holds it (Runtime releases kernel variants it no longer keeps).
  void release(const std::string& file, const std::string& extra_defines);
  size_t programs_held() const { return programs_.size(); }

  // The same for a source text given directly (tests and diagnostics).
  cl::Program build_source(const std::string& label, const std::string& source);

  const std::string& cache_dir() const { return cache_dir_; }
  const std::string& prelude() const { return prelude_; }
  // The prelude's BOREAS_DEVICE_W (Device::simd_width when the cache was made): what
  // kernels build at unless their defines set BOREAS_W, and what their launches divide by.
  int simd_width() const { return simd_width_; }
  int disk_hits() const { return disk_hits_; }
  int compiles() const { return compiles_; }

 private:
  cl::Program build(const std::string& label, const std::string& source);
  cl::Program load_binary(const std::string& path, unsigned long long key);
  void store_binary(const std::string& path, unsigned long long key, const cl::Program& program);

  cl::Context context_;
  Device device_;
  std::string cache_dir_;
  std::string prelude_;
  std::string options_;
  int simd_width_ = 1;
  std::map<std::string, cl::Program> programs_;
  int disk_hits_ = 0;
  int compiles_ = 0;
};

// Default folder for the on-disk cache: BOREAS_CACHE_DIR, else $XDG_CACHE_HOME/boreas,
// else $HOME/.cache/boreas, else "" (no disk cache).
std::string default_cache_dir();

}  // namespace boreas::impl
