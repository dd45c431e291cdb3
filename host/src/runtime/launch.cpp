// boreas: the launch table (every kernel whose sizes are not the default, per kind of
// device), the rule that turns a row and a range into global and group sizes, and the
// enqueue every launch ends in.
#include "runtime/launch.h"

#include <algorithm>
#include <cstring>
#include <mutex>

#include "errors.h"
#include "shared/blobtree_types.h"
#include "shared/tree_records.h"

namespace boreas::impl {

namespace {

// Work-items per group by default, items per tile: on CPUs 64, which PoCL's work-item
// loops vectorize 8 or 16 wide; on GPUs 128, four warps or two wavefronts.
constexpr size_t kCpuGroup = 64;
constexpr size_t kGpuGroup = 128;

constexpr LaunchSizes tiles(size_t items) { return LaunchSizes::item_groups({items, 1, 1}); }

constexpr LaunchSizes kBinGroups =
    LaunchSizes::item_groups({BOREAS_BT_BIN, BOREAS_BT_BIN, BOREAS_BT_BIN}, true);
constexpr LaunchSizes kDriverGroups = LaunchSizes::driver_groups();

// Every size here is the one the kernel ran at before the table, kept because PoCL's
// vectorization, and so the results' last bits, follow the groups: a change to a row is
// a change of results (the state-hash and width tests say which), and of speed (measure
// it with boreas_bench).
constexpr LaunchRow kLibraryRows[] = {
    // Tile kernels (cl/shared/launch_tiles.h): a group is one tile, cut to
    // Runtime::group_size() items by the batches.
    {"boreas_tree_step", tiles(kCpuGroup), tiles(kGpuGroup)},
    {"boreas_tile_copy", tiles(kCpuGroup), tiles(kGpuGroup)},
    {"boreas_underbrush_step", tiles(kCpuGroup), tiles(kGpuGroup)},
    {"boreas_export_branch_records", tiles(kCpuGroup), tiles(kGpuGroup)},
    {"boreas_tree_leaves", tiles(kCpuGroup), tiles(kGpuGroup)},
    {"boreas_tree_deform", tiles(kCpuGroup), tiles(kGpuGroup)},
    // One group places a whole view's records (prefix sums over its tree slots).
    {"boreas_tree_record_offsets", LaunchSizes::work_item_groups({BOREAS_TREE_OFFSETS_GROUP, 1, 1}),
     LaunchSizes::work_item_groups({BOREAS_TREE_OFFSETS_GROUP, 1, 1})},
    // A group spans one bin of BOREAS_BT_BIN^3 points along x (the kernel takes its bin
    // from the group id) and as much of it along y and z as the kernel can run (GPUs with
    // 256-item groups, or a kernel that needs many registers).
    {"boreas_blobtree_field", kBinGroups, kBinGroups},
    {"boreas_blobtree_field_naive", kBinGroups, kBinGroups},
    // The wind grid's kernels: whole rows of columns or cells; the driver's groups.
    {"boreas_wind_forcing_field", kDriverGroups, kDriverGroups},
    {"boreas_wind_sine_slab", kDriverGroups, kDriverGroups},
    {"boreas_wind_grid_step", kDriverGroups, kDriverGroups},
    // Points: enough work-items that the driver finds a useful group, 256 for the scalar
    // build (whose work-item loop PoCL vectorizes), 16 for wide ones.
    {"boreas_wind_sample_points", LaunchSizes::driver_groups(256, 16),
     LaunchSizes::driver_groups(256, 16)},
};

struct ExtraRows {
  std::mutex mutex;
  std::vector<LaunchRow> rows;
};

ExtraRows& extra_rows() {
  static ExtraRows extra;
  return extra;
}

size_t round_up(size_t n, size_t multiple) { return (n + multiple - 1) / multiple * multiple; }

cl::NDRange ndrange(int dims, const std::array<size_t, 3>& n) {
  if (dims == 1) return cl::NDRange(n[0]);
  if (dims == 2) return cl::NDRange(n[0], n[1]);
  return cl::NDRange(n[0], n[1], n[2]);
}

std::string kernel_name(const cl::Kernel& kernel) {
  std::string name = "?";
  kernel.getInfo(CL_KERNEL_FUNCTION_NAME, &name);
  while (!name.empty() && name.back() == '\0') name.pop_back();
  return name;
}

}  // namespace

size_t launch_group_size(const Device& device) { return device.is_gpu() ? kGpuGroup : kCpuGroup; }

LaunchSizes launch_sizes(const Device& device, const std::string& kernel) {
  for (const LaunchRow& r : kLibraryRows)
    if (kernel == r.kernel) return device.is_gpu() ? r.gpu : r.cpu;
  ExtraRows& extra = extra_rows();
  std::lock_guard<std::mutex> lock(extra.mutex);
  for (const LaunchRow& r : extra.rows)
    if (kernel == r.kernel) return device.is_gpu() ? r.gpu : r.cpu;
  return LaunchSizes::work_item_groups({launch_group_size(device), 1, 1});
}

void add_launch_rows(const std::vector<LaunchRow>& rows) {
  ExtraRows& extra = extra_rows();
  std::lock_guard<std::mutex> lock(extra.mutex);
  for (const LaunchRow& r : rows) {
    bool known = false;
    for (const LaunchRow& e : extra.rows) known = known || std::strcmp(e.kernel, r.kernel) == 0;
    if (!known) extra.rows.push_back(r);
  }
}

LaunchShape launch_shape(const LaunchSizes& sizes, const Items& items, size_t kernel_group_limit,
                         const std::string& kernel) {
  using Group = LaunchSizes::Group;
  std::array<size_t, 3> work{}, group{1, 1, 1};
  for (size_t a = 0; a < 3; ++a) {
    const size_t lanes = std::max<size_t>(items.lanes[a], 1);
    work[a] = (items.count[a] + lanes - 1) / lanes;
    if (sizes.by == Group::kWorkItems) group[a] = sizes.group[a];
    if (sizes.by != Group::kItems) continue;
    if (sizes.group[a] % lanes != 0)
      fail(BOREAS_ERROR_INTERNAL, "kernel " + kernel + ": " + std::to_string(lanes) +
                                      " items per work-item along axis " + std::to_string(a) +
                                      " do not divide its groups of " +
                                      std::to_string(sizes.group[a]) + " items");
    group[a] = sizes.group[a] / lanes;
  }
  if (sizes.fit_kernel) {
    auto too_big = [&] { return group[0] * group[1] * group[2] > kernel_group_limit; };
    while (too_big() && group[2] > 1) group[2] /= 2;
    while (too_big() && group[1] > 1) group[1] /= 2;
  }
  if (sizes.by == Group::kDriver) {
    const size_t multiple = items.lanes[0] > 1 ? sizes.wide_multiple : sizes.multiple;
    work[0] = round_up(work[0], multiple > 0 ? multiple : 1);
    return {ndrange(items.dims, work), cl::NullRange};
  }
  for (size_t a = 0; a < 3; ++a) work[a] = round_up(work[a], group[a]);
  return {ndrange(items.dims, work), ndrange(items.dims, group)};
}

void kernel_arg_failed(const cl::Kernel& kernel, cl_uint index, cl_int code) {
  fail(BOREAS_ERROR_OPENCL, "argument " + std::to_string(index) + " of kernel " +
                                kernel_name(kernel) + " could not be set: " + cl_error_name(code));
}

void check_arg_count(const cl::Kernel& kernel, size_t bound) {
  cl_uint takes = 0;
  BOREAS_CL_CHECK(kernel.getInfo(CL_KERNEL_NUM_ARGS, &takes));
  if (size_t(takes) != bound)
    fail(BOREAS_ERROR_INTERNAL, "kernel " + kernel_name(kernel) + " takes " +
                                    std::to_string(takes) + " arguments; the launch binds " +
                                    std::to_string(bound));
}

cl::Event enqueue_launch(Runtime& runtime, cl::Kernel& kernel, const Items& items) {
  cl::Event event;
  if (items.empty()) return event;
  const std::string name = kernel_name(kernel);
  const LaunchSizes sizes = launch_sizes(runtime.device(), name);
  size_t limit = 0;
  if (sizes.fit_kernel)
    limit = kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(runtime.device().device);
  const LaunchShape shape = launch_shape(sizes, items, limit, name);
  BOREAS_CL_CHECK(runtime.queue().enqueueNDRangeKernel(kernel, cl::NullRange, shape.global,
                                                       shape.group, nullptr, &event));
  runtime.count_launch();
  return event;
}

}  // namespace boreas::impl
