// boreas tests: the one launch path (runtime/launch.h) — ranges rounded and grouped as the
// table says, the event handed back, failures that name the kernel and the argument, and
// 2-D and 3-D launches that cover their range.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "reference/probe_kernels.h"
#include "runtime/launch.h"
#include "support/expect_error.h"

namespace boreas::test {
namespace {

using impl::Items;
using impl::LaunchShape;
using impl::LaunchSizes;

impl::Device device_of_type(cl_device_type type) {
  impl::Device d;
  d.type = type;
  return d;
}

std::vector<size_t> sizes_of(const cl::NDRange& r) {
  return std::vector<size_t>(static_cast<const size_t*>(r),
                             static_cast<const size_t*>(r) + r.dimensions());
}

LaunchShape shape(const LaunchSizes& sizes, const Items& items, size_t limit = 1024) {
  return impl::launch_shape(sizes, items, limit, "boreas_test_kernel");
}

// The default: groups of work-items along x, the range rounded up to whole groups after
// the lanes divided it.
TEST(Launch, WorkItemGroupsRoundTheRangeUpToWholeGroups) {
  const LaunchSizes s = LaunchSizes::work_item_groups({64, 1, 1});
  LaunchShape a = shape(s, Items(1000));
  EXPECT_EQ(sizes_of(a.global), (std::vector<size_t>{1024}));
  EXPECT_EQ(sizes_of(a.group), (std::vector<size_t>{64}));
  LaunchShape b = shape(s, Items(1000).per_work_item(8));  // 125 work-items
  EXPECT_EQ(sizes_of(b.global), (std::vector<size_t>{128}));
  EXPECT_EQ(sizes_of(b.group), (std::vector<size_t>{64}));
  EXPECT_EQ(sizes_of(shape(s, Items(64)).global), (std::vector<size_t>{64}));
  LaunchShape c = shape(LaunchSizes::work_item_groups({8, 4, 2}), Items(9, 5, 3));
  EXPECT_EQ(sizes_of(c.global), (std::vector<size_t>{16, 8, 4}));
  EXPECT_EQ(sizes_of(c.group), (std::vector<size_t>{8, 4, 2}));
}

// Tile kernels: a group is `group` items, so a wider kernel runs fewer work-items per group;
// lanes that do not divide the group are refused, naming the kernel.
TEST(Launch, ItemGroupsDivideByTheLanes) {
  const LaunchSizes s = LaunchSizes::item_groups({64, 1, 1});
  LaunchShape a = shape(s, Items(3 * 64).per_work_item(8));
  EXPECT_EQ(sizes_of(a.global), (std::vector<size_t>{24}));
  EXPECT_EQ(sizes_of(a.group), (std::vector<size_t>{8}));
  LaunchShape b = shape(s, Items(3 * 64));
  EXPECT_EQ(sizes_of(b.global), (std::vector<size_t>{192}));
  EXPECT_EQ(sizes_of(b.group), (std::vector<size_t>{64}));
  expect_error([&] { shape(s, Items(64).per_work_item(3)); }, BOREAS_ERROR_INTERNAL,
               {"boreas_test_kernel", "3 items per work-item", "groups of 64 items"});
}

// Bin kernels: a bin of 8^3 points per group, lanes along x and y, halved along z and then
// y until the kernel can run the group.
TEST(Launch, ItemGroupsShrinkAlongZThenYToFitTheKernel) {
  const LaunchSizes s = LaunchSizes::item_groups({8, 8, 8}, true);
  const Items items = Items(64, 32, 16).per_work_item(8, 2);
  LaunchShape whole = shape(s, items, 4096);
  EXPECT_EQ(sizes_of(whole.global), (std::vector<size_t>{8, 16, 16}));
  EXPECT_EQ(sizes_of(whole.group), (std::vector<size_t>{1, 4, 8}));
  EXPECT_EQ(sizes_of(shape(s, items, 16).group), (std::vector<size_t>{1, 4, 4}));
  EXPECT_EQ(sizes_of(shape(s, items, 2).group), (std::vector<size_t>{1, 2, 1}));
  EXPECT_EQ(sizes_of(shape(s, Items(64, 32, 16), 256).group), (std::vector<size_t>{8, 8, 4}));
}

// The driver's groups: no group range, x rounded up to the row's multiple (its wide one
// where a work-item takes several items), y and z exactly.
TEST(Launch, DriverGroupsRoundOnlyToTheRowsMultiple) {
  const LaunchSizes s = LaunchSizes::driver_groups(256, 16);
  LaunchShape scalar = shape(s, Items(1000));
  EXPECT_EQ(sizes_of(scalar.global), (std::vector<size_t>{1024}));
  EXPECT_EQ(scalar.group.dimensions(), 0u);
  EXPECT_EQ(sizes_of(shape(s, Items(1000).per_work_item(8)).global), (std::vector<size_t>{128}));
  LaunchShape slab = shape(LaunchSizes::driver_groups(), Items(65, 7).per_work_item(8));
  EXPECT_EQ(sizes_of(slab.global), (std::vector<size_t>{9, 7}));
  EXPECT_EQ(slab.group.dimensions(), 0u);
}

// The point sampling's launch (wind/sample_points.cpp) sized itself with simd_global_size: enough
// work-items for the items, rounded up to 256 for the scalar build and 16 for wide ones.
// The table's row gives the same size on every kind of device, so its move to launch()
// changes nothing that runs.
TEST(Launch, SamplePointsRowReproducesSimdGlobalSize) {
  auto simd_global_size = [](size_t n, size_t w) {
    const size_t multiple = w > 1 ? 16 : 256;
    return ((n + w - 1) / w + multiple - 1) / multiple * multiple;
  };
  for (cl_device_type type :
       {cl_device_type(CL_DEVICE_TYPE_CPU), cl_device_type(CL_DEVICE_TYPE_GPU)}) {
    const LaunchSizes s = impl::launch_sizes(device_of_type(type), "boreas_wind_sample_points");
    for (size_t n : {1, 15, 16, 255, 256, 257, 1000, 4097})
      for (size_t w : {1, 2, 4, 8, 16})
        EXPECT_EQ(sizes_of(shape(s, Items(n).per_work_item(w)).global)[0], simd_global_size(n, w))
            << "n " << n << ", width " << w;
  }
}

// Kernels without a row get groups of group_size() work-items; the tile kernels' groups are
// the tiles the batches cut to group_size() items.
TEST(Launch, DefaultAndTileRowsFollowTheDevicesGroupSize) {
  for (cl_device_type type :
       {cl_device_type(CL_DEVICE_TYPE_CPU), cl_device_type(CL_DEVICE_TYPE_GPU)}) {
    const impl::Device d = device_of_type(type);
    const size_t g = impl::launch_group_size(d);
    EXPECT_EQ(g, type == CL_DEVICE_TYPE_GPU ? 128u : 64u);
    const LaunchSizes other = impl::launch_sizes(d, "boreas_no_such_kernel");
    EXPECT_EQ(other.by, LaunchSizes::Group::kWorkItems);
    EXPECT_EQ(other.group, (std::array<size_t, 3>{g, 1, 1}));
    for (const char* tile : {"boreas_tree_step", "boreas_tile_copy", "boreas_underbrush_step"}) {
      const LaunchSizes s = impl::launch_sizes(d, tile);
      EXPECT_EQ(s.by, LaunchSizes::Group::kItems) << tile;
      EXPECT_EQ(s.group, (std::array<size_t, 3>{g, 1, 1})) << tile;
    }
  }
}

class LaunchOnDevice : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    impl::use_probe_kernels();  // bandwidth_copy.cl is not part of the library
    runtime_ = new impl::Runtime(nullptr, "");
  }
  static void TearDownTestSuite() {
    delete runtime_;
    runtime_ = nullptr;
  }
  static impl::Runtime* runtime_;
};
impl::Runtime* LaunchOnDevice::runtime_ = nullptr;

// The event a launch hands back completes and carries the kernel's profiling times.
TEST_F(LaunchOnDevice, EventCompletesAndCanBeProfiled) {
  impl::Runtime& rt = *runtime_;
  cl::Kernel& k = rt.kernel("bandwidth_copy.cl", "boreas_bandwidth_copy");
  std::vector<float> in(256), out(256, -1.0f);
  for (size_t i = 0; i < in.size(); ++i) in[i] = float(i) + 0.5f;
  cl::Buffer a = rt.buffer(CL_MEM_READ_ONLY, 1024), b = rt.buffer(CL_MEM_WRITE_ONLY, 1024);
  rt.upload(a, in);
  cl::Event e = impl::launch(rt, k, Items(64), a, b);  // a float4 per item
  ASSERT_NE(e(), nullptr);
  e.wait();
  EXPECT_EQ(e.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>(), CL_COMPLETE);
  const cl_ulong start = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
  const cl_ulong end = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
  EXPECT_GT(start, 0u);
  EXPECT_GE(end, start);
  rt.read(b, 0, 1024, out.data());
  EXPECT_EQ(in, out);
  // An empty range enqueues nothing: an empty event, and the output as it was.
  std::vector<float> zeros(256, 0.0f);
  rt.upload(a, zeros);
  EXPECT_EQ(impl::launch(rt, k, Items(0), a, b)(), nullptr);
  rt.read(b, 0, 1024, out.data());
  EXPECT_EQ(in, out);
}

// A refused argument names the kernel and the argument; so does a launch that binds fewer
// or more arguments than the kernel takes (fewer would launch with stale ones).
TEST_F(LaunchOnDevice, FailuresNameTheKernelAndTheArgument) {
  impl::Runtime& rt = *runtime_;
  cl::Kernel& k = rt.kernel("bandwidth_copy.cl", "boreas_bandwidth_copy");
  cl::Buffer a = rt.buffer(CL_MEM_READ_WRITE, 1024);
  expect_error([&] { impl::launch(rt, k, Items(64), a, 7); }, BOREAS_ERROR_OPENCL,
               {"argument 1", "of kernel boreas_bandwidth_copy"});
  expect_error([&] { impl::launch(rt, k, Items(64), a); }, BOREAS_ERROR_INTERNAL,
               {"kernel boreas_bandwidth_copy takes 2 arguments; the launch binds 1"});
  expect_error([&] { impl::launch(rt, k, Items(64), a, a, a); }, BOREAS_ERROR_INTERNAL,
               {"kernel boreas_bandwidth_copy takes 2 arguments; the launch binds 3"});
}

// A kernel that counts the items each work-item covers (lanes along x) and records the
// ranges it ran with; one copy sized by groups of work-items, one by the driver.
const char* const kCoverSource = R"CL(
#define BOREAS_COVER_BODY                                                              \
  int x0 = (int)get_global_id(0) * lanes, y = (int)get_global_id(1),                   \
      z = (int)get_global_id(2);                                                       \
  for (int l = 0; l < lanes; ++l) {                                                    \
    int x = x0 + l;                                                                    \
    if (x < nx && y < ny && z < nz) atomic_inc(&hits[(z * ny + y) * nx + x]);           \
  }                                                                                    \
  if (get_global_id(0) == 0 && get_global_id(1) == 0 && get_global_id(2) == 0) {       \
    for (int d = 0; d < 3; ++d) {                                                      \
      shape[d] = (int)get_global_size(d);                                              \
      shape[3 + d] = (int)get_local_size(d);                                           \
    }                                                                                  \
    shape[6] = (int)get_work_dim();                                                    \
  }
__kernel void boreas_test_cover_groups(__global int* hits, int nx, int ny, int nz, int lanes,
                                       __global int* shape) { BOREAS_COVER_BODY }
__kernel void boreas_test_cover_driver(__global int* hits, int nx, int ny, int nz, int lanes,
                                       __global int* shape) { BOREAS_COVER_BODY }
)CL";

TEST_F(LaunchOnDevice, TwoAndThreeDimensionalLaunchesCoverTheirRange) {
  impl::Runtime& rt = *runtime_;
  const LaunchSizes groups = LaunchSizes::work_item_groups({8, 4, 2});
  const LaunchSizes driver = LaunchSizes::driver_groups();
  impl::add_launch_rows(
      {{"boreas_test_cover_groups", groups, groups}, {"boreas_test_cover_driver", driver, driver}});
  cl::Program program = rt.programs().build_source("launch_cover_test.cl", kCoverSource);
  struct Case {
    Items items;
    int lanes;
  };
  const Case cases[] = {{Items(37, 5), 1},
                        {Items(37, 5).per_work_item(4), 4},
                        {Items(19, 6, 3), 1},
                        {Items(19, 6, 3).per_work_item(8), 8}};
  for (const char* name : {"boreas_test_cover_groups", "boreas_test_cover_driver"}) {
    cl::Kernel k(program, name);
    for (const Case& c : cases) {
      const int nx = int(c.items.count[0]), ny = int(c.items.count[1]), nz = int(c.items.count[2]);
      const size_t n = size_t(nx) * ny * nz;
      cl::Buffer hits = rt.buffer(CL_MEM_READ_WRITE, n * sizeof(int));
      cl::Buffer ran = rt.buffer(CL_MEM_READ_WRITE, 7 * sizeof(int));
      rt.upload(hits, std::vector<int>(n, 0));
      impl::launch(rt, k, c.items, hits, nx, ny, nz, c.lanes, ran).wait();
      std::vector<int> counted(n), shape_ran(7);
      rt.read(hits, 0, n * sizeof(int), counted.data());
      rt.read(ran, 0, 7 * sizeof(int), shape_ran.data());
      const std::string what = std::string(name) + ", " + std::to_string(c.items.dims) +
                               "-D, lanes " + std::to_string(c.lanes);
      EXPECT_EQ(counted, std::vector<int>(n, 1)) << what;
      const LaunchShape want =
          shape(std::string(name).find("groups") != std::string::npos ? groups : driver, c.items);
      EXPECT_EQ(shape_ran[6], c.items.dims) << what;
      for (int d = 0; d < c.items.dims; ++d) {
        EXPECT_EQ(size_t(shape_ran[size_t(d)]), sizes_of(want.global)[size_t(d)]) << what;
        if (want.group.dimensions() > 0)
          EXPECT_EQ(size_t(shape_ran[3 + size_t(d)]), sizes_of(want.group)[size_t(d)]) << what;
      }
    }
  }
}

}  // namespace
}  // namespace boreas::test
