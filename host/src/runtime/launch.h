// boreas: the one way to launch a kernel — every argument bound in one call, the global
// and group sizes from one table per device keyed by kernel name, the launch's event
// handed back.
//
// A launch says what it covers and what it passes, never how it is grouped. The wind at
// the caller's points (wind/sample_points.cpp), n points, simd_width() per work-item:
//
//   cl::Kernel& k = runtime.kernel("wind_sample_points.cl", "boreas_wind_sample_points",
//                                  wind.defines());
//   launch(runtime, k, Items(n).per_work_item(runtime.simd_width()), points, results, count,
//          *wind.waves, wind.wave_count, *wind.grid, wind.grid_layout);
//
// - Items(x), Items(x, y), Items(x, y, z): a 1-, 2- or 3-D range of the caller's items
//   (points, cells, leaves, rows). per_work_item(w) where one work-item takes w of them
//   along x (kernels written for a SIMD width, cl/shared/simd_width.h; the extra lanes of
//   the last work-item redo the last item); per_work_item(wx, wy) where it takes a block.
// - The arguments: all of the kernel's, in order (a kernel keeps its arguments between
//   launches, so binding fewer would launch with stale ones: refused). A failure names the
//   kernel and the argument.
// - The result: the launch's cl::Event, for callers that profile (the queue has profiling
//   on) or wait; others drop it. An empty range enqueues nothing and returns an empty
//   event (event() == nullptr).
// - The sizes: the kernel's row of the table in launch.cpp, in the column of the device's
//   kind (CPU or GPU); kernels without a row get the default, groups of
//   Runtime::group_size() work-items along x (LaunchSizes). A kernel whose sizes matter
//   (a tile or bin kernel that finds its work by group, or one whose speed or results
//   depend on the group PoCL vectorizes over) gets a row there, never a size at its call.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "runtime/runtime.h"

namespace boreas::impl {

// A launch's range: items along up to 3 axes, `lanes` of them per work-item along each.
struct Items {
  explicit Items(size_t x) : dims(1), count{x, 1, 1} {}
  Items(size_t x, size_t y) : dims(2), count{x, y, 1} {}
  Items(size_t x, size_t y, size_t z) : dims(3), count{x, y, z} {}
  // One work-item takes x_lanes items along x by y_lanes along y.
  Items per_work_item(size_t x_lanes, size_t y_lanes = 1) const {
    Items r = *this;
    r.lanes = {x_lanes, y_lanes, 1};
    return r;
  }
  bool empty() const { return count[0] == 0 || count[1] == 0 || count[2] == 0; }

  int dims;
  std::array<size_t, 3> count;
  std::array<size_t, 3> lanes{1, 1, 1};
};

// How one kernel's launches are sized on one kind of device: a cell of the table. The
// work-items along an axis are its items divided by its lanes, rounded up, then rounded up
// to whole groups (or to `multiple` where the driver chooses the group).
struct LaunchSizes {
  enum class Group {
    kWorkItems,  // `group` work-items per group along each axis
    kItems,      // `group` items per group along each axis: group / lanes work-items (kernels
                 // that find their work by group: tiles, bins); the lanes must divide it
    kDriver,     // the driver chooses (cl::NullRange)
  };
  Group by = Group::kWorkItems;
  std::array<size_t, 3> group{64, 1, 1};
  // kDriver: the work-items along x rounded up to a multiple of this (of wide_multiple
  // where a work-item takes several items along x), so that the driver finds a useful
  // group: boreas_wind_sample_points takes 256 scalar, whose work-item loop PoCL
  // vectorizes, and 16 wide.
  size_t multiple = 1;
  size_t wide_multiple = 1;
  // kItems: a group the kernel cannot run (CL_KERNEL_WORK_GROUP_SIZE) is halved along z,
  // then y, until it can. Otherwise such a launch fails as OpenCL says.
  bool fit_kernel = false;

  // The cells a table is written with.
  static constexpr LaunchSizes work_item_groups(std::array<size_t, 3> group) {
    LaunchSizes s;
    s.group = group;
    return s;
  }
  static constexpr LaunchSizes item_groups(std::array<size_t, 3> group, bool fit_kernel = false) {
    LaunchSizes s;
    s.by = Group::kItems;
    s.group = group;
    s.fit_kernel = fit_kernel;
    return s;
  }
  static constexpr LaunchSizes driver_groups(size_t multiple = 1, size_t wide_multiple = 1) {
    LaunchSizes s;
    s.by = Group::kDriver;
    s.multiple = multiple;
    s.wide_multiple = wide_multiple;
    return s;
  }
};

// One row of the table: a kernel (by its function name) and its sizes per kind of device.
struct LaunchRow {
  const char* kernel;
  LaunchSizes cpu;
  LaunchSizes gpu;
};

// Work-items per group of the default sizes, and items per tile of the tile kernels
// (runtime/launch_tiles.h): 64 on CPUs, 128 on GPUs (Runtime::group_size()).
size_t launch_group_size(const Device& device);

// The sizes of a kernel's launches on a device: its row's, or the default.
LaunchSizes launch_sizes(const Device& device, const std::string& kernel);

// Rows for kernels the library does not carry (the probe kernels of tests and benchmarks,
// reference/probe_kernels.cpp). A kernel keeps the first row given for it, and the
// library's own rows are never replaced. Thread-safe.
void add_launch_rows(const std::vector<LaunchRow>& rows);

// The global and group ranges of a launch (group cl::NullRange where the driver
// chooses); kernel_group_limit is the kernel's CL_KERNEL_WORK_GROUP_SIZE (read only
// where sizes.fit_kernel). Throws BOREAS_ERROR_INTERNAL, naming the kernel, for lanes
// that do not divide an item group.
struct LaunchShape {
  cl::NDRange global;
  cl::NDRange group;
};
LaunchShape launch_shape(const LaunchSizes& sizes, const Items& items, size_t kernel_group_limit,
                         const std::string& kernel);

// The failure paths of launch(), out of line: an argument OpenCL refused (by its position:
// drivers name arguments only for programs built with -cl-kernel-arg-info), and a launch
// that binds another number of arguments than the kernel takes.
[[noreturn]] void kernel_arg_failed(const cl::Kernel& kernel, cl_uint index, cl_int code);
void check_arg_count(const cl::Kernel& kernel, size_t bound);
// Enqueues a kernel whose arguments are bound, sized by its row of the table.
cl::Event enqueue_launch(Runtime& runtime, cl::Kernel& kernel, const Items& items);

template <typename... Args>
cl::Event launch(Runtime& runtime, cl::Kernel& kernel, const Items& items, const Args&... args) {
  check_arg_count(kernel, sizeof...(Args));
  cl_uint index = 0;
  auto bind = [&](const auto& value) {
    const cl_int code = kernel.setArg(index, value);
    if (code != CL_SUCCESS) kernel_arg_failed(kernel, index, code);
    ++index;
  };
  (bind(args), ...);
  return enqueue_launch(runtime, kernel, items);
}

}  // namespace boreas::impl
