// boreas: one OpenCL context, queue and program cache on the chosen device.
#pragma once

#include <atomic>
#include <cstdint>
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
  Runtime(const char* device_request, const char* cache_dir,
          const intptr_t* context_properties = nullptr);

  const Device& device() const { return device_; }
  cl::Context& context() { return context_; }
  cl::CommandQueue& queue() { return queue_; }
  ProgramCache& programs() { return *programs_; }

  // A kernel from a file of cl/, built on first use with the given extra #defines
  // (one program per distinct set). The same kernel object is returned for the same
  // arguments while it is kept; callers bind every argument before each launch, because
  // a variant may have been released and rebuilt in between.
  //
  // Variants are kept per (file, kernel): at most kKernelVariantsKept of them, the least
  // recently used released first. The defines are slot counts (waves, colliders, ...)
  // that change with the world, and each held program costs 15-24 MiB of host memory on
  // PoCL (tree_step and underbrush_step, measured 2026-11-29), so keeping every variant
  // ever built grows without a useful bound in a world that lives for hours (the
  // underbrush step alone has hundreds of combinations). A released variant is loaded
  // again from the on-disk cache in tenths of a second on PoCL, which keeps ~50-60 KiB of
  // every load until the context goes (bench/RESULTS.md, "Issue 39, twelfth round:
  // soak"): a world whose wave count keeps changing pays both. The reference
  // stays valid until kKernelVariantsKept other variants of the same kernel are asked for.
  static constexpr int kKernelVariantsKept = 8;
  cl::Kernel& kernel(const std::string& file, const std::string& name,
                     const std::string& defines = "");
  // The items per work-item of kernels written for a SIMD width (cl/shared/simd_width.h)
  // built without a BOREAS_W of their own: the device's (Device::simd_width).
  int simd_width() const { return programs_->simd_width(); }
  // Kernel variants held now (all kernels, or those of one file and kernel name).
  size_t kernel_variants() const;
  size_t kernel_variants(const std::string& file, const std::string& name) const;

  // A device buffer of at least bytes (never zero-sized, which OpenCL refuses). Refused
  // with BOREAS_ERROR_OUT_OF_MEMORY, naming `what` and the sizes, when it would take the
  // buffers alive past the device's memory (or memory_limit()), or one buffer past the
  // device's largest allocation.
  cl::Buffer buffer(cl_mem_flags flags, size_t bytes, const char* what = "buffer");

  // Device memory this runtime may hold in buffers: the device's global memory, or less
  // where BOREAS_DEVICE_MEMORY (bytes, with an optional K/M/G suffix) or set_memory_limit
  // says so. Bytes held now by live buffers made through buffer().
  uint64_t memory_limit() const { return memory_limit_; }
  void set_memory_limit(uint64_t bytes) { memory_limit_ = bytes; }
  uint64_t memory_in_use() const { return memory_->load(); }
  // The largest buffer the device allocates at once (CL_DEVICE_MAX_MEM_ALLOC_SIZE), or less
  // where BOREAS_MAX_ALLOCATION (bytes, with an optional K/M/G suffix) or set_max_allocation
  // says so (tests of worlds split over several buffers). The tree batches keep each of
  // their buffers within it (the world splits its trees into chunks: world_chunks.cpp).
  uint64_t max_allocation() const { return max_allocation_; }
  void set_max_allocation(uint64_t bytes) { max_allocation_ = bytes; }

  // Bytes moved between host and device through the helpers below, since the runtime was
  // made: the yardstick of "an operation costs in proportion to what it changes", which
  // machine noise cannot blur (tests assert it). Device-to-device copies are counted apart.
  struct Traffic {
    uint64_t uploaded = 0;
    uint64_t read_back = 0;
    uint64_t copied_on_device = 0;
    // Kernels enqueued (launch.h's enqueue_launch, the one place that enqueues one): what
    // "a fixed number of launches per call" is checked against.
    uint64_t launches = 0;
    // Tree rows the host walked to build a per-call table anew (the readers' offsets, the
    // posed scratch's tiles: tree_batch_view.cpp): 0 for a call that finds nothing changed.
    uint64_t table_rows_built = 0;
  };
  const Traffic& traffic() const { return traffic_; }
  // Bytes written to the device by other means than the helpers below (mapped planes).
  void count_upload(uint64_t bytes) { traffic_.uploaded += bytes; }
  void count_launch() { ++traffic_.launches; }
  void count_table_rows(uint64_t rows) { traffic_.table_rows_built += rows; }

  // Copies data to the start of buffer, blocking (nothing for an empty vector).
  template <typename T>
  void upload(const cl::Buffer& buffer, const std::vector<T>& data) {
    write(buffer, 0, data.size() * sizeof(T), data.data(), true);
  }

  // The same without waiting for the copy: for the small per-step uploads, which would
  // otherwise each cost a round trip. The caller keeps `data` unchanged and alive until
  // the queue has finished (a staging member, and a finish before it is written again).
  template <typename T>
  void upload_async(const cl::Buffer& buffer, const std::vector<T>& data) {
    write(buffer, 0, data.size() * sizeof(T), data.data(), false);
  }

  // bytes from host data into buffer at offset (nothing for 0 bytes).
  void write(const cl::Buffer& buffer, size_t offset, size_t bytes, const void* data,
             bool blocking = true);
  // bytes of buffer from offset into out, blocking.
  void read(const cl::Buffer& buffer, size_t offset, size_t bytes, void* out);

  // Planar data (cl/shared/*_types.h): `planes` rows of `count` elements of elem bytes.
  // The device rows are `device_stride` elements apart and start at element `first`; the
  // host rows are `host_stride` elements apart. One rectangular transfer each, blocking.
  void write_planes(const cl::Buffer& buffer, size_t device_stride, size_t first, const void* host,
                    size_t host_stride, size_t count, size_t planes, size_t elem = sizeof(float));
  void read_planes(const cl::Buffer& buffer, size_t device_stride, size_t first, void* host,
                   size_t host_stride, size_t count, size_t planes, size_t elem = sizeof(float));
  // The same between two device buffers (which must not be the same buffer), enqueued.
  void copy_planes(const cl::Buffer& from, size_t from_stride, size_t from_first,
                   const cl::Buffer& to, size_t to_stride, size_t to_first, size_t count,
                   size_t planes, size_t elem = sizeof(float));

  // Work-items per group of a launch by default, and items per tile of the tile kernels
  // (launch.h's launch_group_size: 64 on CPUs, 128 on GPUs). Kernels are launched with
  // launch() (runtime/launch.h).
  size_t group_size() const { return group_size_; }

 private:
  Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::unique_ptr<ProgramCache> programs_;
  // Per "file\nname": the kernels by their defines, with the use count they were last
  // asked for at (the eviction order).
  struct KernelVariant {
    cl::Kernel kernel;
    uint64_t last_use = 0;
  };
  std::map<std::string, std::map<std::string, KernelVariant>> kernels_;
  uint64_t kernel_uses_ = 0;
  size_t group_size_ = 64;
  uint64_t memory_limit_ = 0;
  uint64_t max_allocation_ = 0;
  // Shared with the buffers' destructor callbacks, which may outlive a call.
  std::shared_ptr<std::atomic<uint64_t>> memory_ = std::make_shared<std::atomic<uint64_t>>(0);
  Traffic traffic_;
};

}  // namespace boreas::impl
