// boreas: the benchmark pairs, each OpenCL kernel beside its native twin at the same size
// and in the same run: BM_<Name>/native/<items> first, then BM_<Name>/cl/<items>.
//
// Every row reports, from wall time (real time; one launch + clFinish per iteration for CL):
//   items_per_second, bytes_per_second  compulsory traffic per item, see kBytesPer*;
// and, as plain counters:
//   kernel_items/s, kernel_bytes/s      CL: from the kernel's profiling event (START..END),
//                                       so launch and finish overhead are left out; native:
//                                       the same as the wall-time figures;
//   vs_native                           this row's items/s over the native row's (0 when the
//                                       native row did not run, e.g. filtered out);
//   vs_copy                             bytes/s over the copy kernel's of the same kind at
//                                       its largest size (0 when that did not run);
//   items                               items per iteration (the size in the name, except for
//                                       rows named by their batch's branch count: BM_Deform
//                                       counts vertices, BM_TreeLeaves leaves; and
//                                       BM_UnderbrushVertices, named by its meadow's
//                                       component count, counts vertices; BM_MeshWind and
//                                       BM_MeshWindPreprocess, named by their tree's trunk
//                                       triangle count, count trunk + leaf vertices).
// BM_BlobTreePolygonize times the whole of polygonize_blobtree, which keeps no events: it
// has no kernel_items/s or kernel_bytes/s (no kernel time) and no bytes.
#include "benchmarks.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_fixture.h"
#include "blobtree/blobtree_bins.h"
#include "blobtree/blobtree_instance.h"
#include "blobtree/polygonizer.h"
#include "mesh_wind/mesh_tree_batch.h"
#include "mesh_wind/noise_texture.h"
#include "mesh_wind/tree_model.h"
#include "mesh_wind/wind_weights.h"
#include "native_blobtree.h"
#include "native_mesh_wind.h"
#include "native_trees.h"
#include "native_underbrush.h"
#include "native_wind.h"
#include "runtime/runtime.h"
#include "scene.h"
#include "shared/blobtree_types.h"
#include "shared/mesh_wind_types.h"
#include "shared/tree_types.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "underbrush/meadow.h"
#include "underbrush/underbrush_batch.h"
#include "wind/wind_grid.h"
#include "wind/wind_params.h"

namespace boreas::bench {

namespace {

using Clock = std::chrono::steady_clock;

// Compulsory memory traffic per item, bytes read + written. Reads that hit the cache
// (waves, the grid under the points, a cell's neighbours and its backtrace) are left out,
// so bytes/s is a lower bound to compare with the copy kernel's.
constexpr double kBytesPerCopyItem = 32.0;   // float4 in + float4 out
constexpr double kBytesPerSample = 24.0;     // xyz in + force out
constexpr double kBytesPerSlabColumn = 8.0;  // x and z out
constexpr double kBytesPerGridCell = 32.0;   // x, y, z, solid in and out (4 planes)

// float4 elements; the largest first, since it is the yardstick of the vs_copy counter.
constexpr int kCopySizes[] = {1 << 22, 1 << 20};
constexpr int kSampleSizes[] = {1 << 16, 1 << 20, 1 << 22};
constexpr int kSlabSides[][2] = {{256, 256}, {1024, 1024}, {2048, 2048}};
constexpr int kGridSizes[][3] = {{32, 16, 32}, {64, 32, 64}, {128, 32, 128}};

// Grid steps run before timing, so that the grid holds a developed field.
constexpr int kWarmSteps = 20;

// ---- shared state ----

// One OpenCL runtime for the whole run, so that programs are built once.
struct ClState {
  std::unique_ptr<impl::Runtime> runtime;
  std::string error;  // why there is no runtime
};

ClState& cl_state() {
  static ClState state = [] {
    ClState s;
    try {
      s.runtime = std::make_unique<impl::Runtime>(nullptr, nullptr);
    } catch (const std::exception& e) {
      s.error = e.what();
    }
    return s;
  }();
  return state;
}

// Figures the later rows compare with: native items/s per "family/size", copy bytes/s per
// kind at the largest copy size.
std::map<std::string, double>& native_items_per_second() {
  static std::map<std::string, double> m;
  return m;
}
std::map<std::string, double>& copy_bytes_per_second() {
  static std::map<std::string, double> m;
  return m;
}

using bench_support::fixture;
using bench_support::Fixture;

double event_seconds(const cl::Event& e) {
  cl_ulong start = 0, end = 0;
  BOREAS_CL_CHECK(e.getProfilingInfo(CL_PROFILING_COMMAND_START, &start));
  BOREAS_CL_CHECK(e.getProfilingInfo(CL_PROFILING_COMMAND_END, &end));
  return double(end - start) * 1e-9;
}

// Sets the counters of one row (see the top of this file).
void report(benchmark::State& state, const std::string& family, const std::string& kind,
            int64_t items, double bytes_per_item, double wall_seconds, double kernel_seconds,
            const std::string& size_key = "") {
  const double iterations = double(state.iterations());
  const double total_items = iterations * double(items);
  state.SetItemsProcessed(static_cast<int64_t>(total_items));
  state.SetBytesProcessed(static_cast<int64_t>(total_items * bytes_per_item));
  const double items_per_second = wall_seconds > 0 ? total_items / wall_seconds : 0.0;
  const double bytes_per_second = items_per_second * bytes_per_item;
  const double kernel_items = kernel_seconds > 0 ? total_items / kernel_seconds : 0.0;
  state.counters["kernel_items/s"] = kernel_items;
  state.counters["items"] = double(items);  // per iteration (vertices, leaves: not the name's size)
  state.counters["kernel_bytes/s"] = kernel_items * bytes_per_item;

  // The native row a CL row compares with: same family and size (the size in the row's
  // name, which is the item count unless the caller names another).
  const std::string key = family + "/" + (size_key.empty() ? std::to_string(items) : size_key);
  if (kind == "native") native_items_per_second()[key] = items_per_second;
  auto native = native_items_per_second().find(key);
  state.counters["vs_native"] = native != native_items_per_second().end() && native->second > 0
                                    ? items_per_second / native->second
                                    : 0.0;

  if (family == "BM_CopyBandwidth" && items == kCopySizes[0])
    copy_bytes_per_second()[kind] = bytes_per_second;
  auto copy = copy_bytes_per_second().find(kind);
  state.counters["vs_copy"] = copy != copy_bytes_per_second().end() && copy->second > 0
                                  ? bytes_per_second / copy->second
                                  : 0.0;
}

// Times the CL launches of one benchmark: launch() enqueues one iteration and returns the
// event of the kernel whose time is reported; each iteration ends in clFinish.
void time_cl(benchmark::State& state, impl::Runtime& rt, const std::string& family, int64_t items,
             double bytes_per_item, const std::function<cl::Event()>& launch) {
  double kernel = 0.0;
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    cl::Event e = launch();
    BOREAS_CL_CHECK(rt.queue().finish());
    kernel += event_seconds(e);
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, family, "cl", items, bytes_per_item, wall, kernel);
}

void time_native(benchmark::State& state, const std::string& family, int64_t items,
                 double bytes_per_item, const std::function<void()>& run,
                 const std::string& size_key = "") {
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    run();
    benchmark::ClobberMemory();
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, family, "native", items, bytes_per_item, wall, wall, size_key);
}

// The device time of work that is more than one kernel launch: from `first` to `last`.
// Kernel events span first START .. last END; markers (`markers` true) span first END ..
// last START, the markers enqueued around the launches (see tree_step_cl).
struct ClSpan {
  cl::Event first, last;
  bool markers = false;
};

double span_seconds(const ClSpan& s) {
  cl_ulong from = 0, to = 0;
  BOREAS_CL_CHECK(s.first.getProfilingInfo(
      s.markers ? CL_PROFILING_COMMAND_END : CL_PROFILING_COMMAND_START, &from));
  BOREAS_CL_CHECK(s.last.getProfilingInfo(
      s.markers ? CL_PROFILING_COMMAND_START : CL_PROFILING_COMMAND_END, &to));
  return to > from ? double(to - from) * 1e-9 : 0.0;
}

// time_cl for launches that return a span; size_key as in report().
void time_cl_span(benchmark::State& state, impl::Runtime& rt, const std::string& family,
                  int64_t items, double bytes_per_item, const std::string& size_key,
                  const std::function<ClSpan()>& launch) {
  double kernel = 0.0;
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    ClSpan span = launch();
    BOREAS_CL_CHECK(rt.queue().finish());
    kernel += span_seconds(span);
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, family, "cl", items, bytes_per_item, wall, kernel, size_key);
}

// The largest difference between two float arrays.
double max_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    worst = std::max(worst, double(std::fabs(a[i] - b[i])));
  return worst;
}

// How far the CL and native results may be apart, m/s: both are float, with the same
// polynomials; they differ only by rounding order (fma contraction in the CL compiler).
constexpr double kAgreement = 1e-3;

impl::Runtime* runtime_or_skip(benchmark::State& state) {
  ClState& cl = cl_state();
  if (!cl.runtime) state.SkipWithError(("no OpenCL device: " + cl.error).c_str());
  return cl.runtime.get();
}

void warm_up(impl::Runtime& rt, const std::function<cl::Event()>& launch) {
  // PoCL compiles the work-group function at the first launch of each local size.
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(rt.queue().finish());
}

// The waves as World uploads them: padded with silent waves up to the slot count the
// kernels unroll over, and the #define that builds the kernels for that count.
struct DeviceWaves {
  std::vector<BoreasGpuWave> padded;
  int slots = 0;
  std::string define;
};

DeviceWaves device_waves(const std::vector<BoreasGpuWave>& waves) {
  DeviceWaves d;
  d.padded = waves;
  d.slots = impl::pad_to_slots(d.padded, BoreasGpuWave{});
  d.define = impl::slot_define("BOREAS_WAVE_SLOTS", d.slots);
  return d;
}

cl::Buffer upload(impl::Runtime& rt, cl_mem_flags flags, const void* data, size_t bytes) {
  cl::Buffer b = rt.buffer(flags, bytes);
  BOREAS_CL_CHECK(rt.queue().enqueueWriteBuffer(b, CL_TRUE, 0, bytes, data));
  return b;
}

// BOREAS_BENCH_NO_CHECK=1 skips the check, to time kernel variants under
// BOREAS_KERNEL_DIR that compute something else on purpose.
std::string disagreement(const char* what, double diff, const char* unit = "m/s",
                         double tolerance = kAgreement) {
  if (diff <= tolerance) return "";
  if (const char* skip = std::getenv("BOREAS_BENCH_NO_CHECK"); skip && std::string(skip) == "1")
    return "";
  char text[160];
  std::snprintf(text, sizeof text, "CL and native %s differ by up to %g %s", what, diff, unit);
  return text;
}

// ---- copy ----

void copy_cl(benchmark::State& state, int n) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Copy : Fixture {
    cl::Kernel kernel;
    cl::Buffer in, out;
  };
  Copy& f = fixture<Copy>("copy/cl/" + std::to_string(n), [&] {
    auto c = std::make_unique<Copy>();
    size_t bytes = size_t(n) * 16;
    c->in = rt->buffer(CL_MEM_READ_ONLY, bytes);
    c->out = rt->buffer(CL_MEM_WRITE_ONLY, bytes);
    BOREAS_CL_CHECK(rt->queue().enqueueFillBuffer(c->in, 1.0f, 0, bytes));
    c->kernel = rt->kernel("bandwidth_copy.cl", "boreas_bandwidth_copy");
    BOREAS_CL_CHECK(c->kernel.setArg(0, c->in));
    BOREAS_CL_CHECK(c->kernel.setArg(1, c->out));
    return c;
  });
  auto launch = [&] {
    cl::Event e;
    BOREAS_CL_CHECK(rt->queue().enqueueNDRangeKernel(f.kernel, cl::NullRange, cl::NDRange(n),
                                                     cl::NullRange, nullptr, &e));
    return e;
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_CopyBandwidth", n, kBytesPerCopyItem, launch);
}

void copy_native(benchmark::State& state, int n) {
  struct Copy : Fixture {
    std::vector<float> in, out;
  };
  Copy& f = fixture<Copy>("copy/native/" + std::to_string(n), [&] {
    auto c = std::make_unique<Copy>();
    c->in.assign(size_t(n) * 4, 1.0f);
    c->out.assign(size_t(n) * 4, 0.0f);
    return c;
  });
  native_copy(f.in.data(), f.out.data(), f.in.size());
  time_native(state, "BM_CopyBandwidth", n, kBytesPerCopyItem,
              [&] { native_copy(f.in.data(), f.out.data(), f.in.size()); });
}

// ---- sine sum at points (boreas_wind_sample_points) ----

// The grid under the points: the default world's 64 x 16 x 64 cells with a solid box.
struct SampleScene {
  boreas_grid_def def = scene_grid_def(64, 16, 64);
  std::vector<uint8_t> solids = scene_solids(def);
  std::vector<float> cells = scene_grid_cells(def, solids);
  std::vector<BoreasGpuWave> waves = scene_waves();
  BoreasGpuGrid g = [this] {
    BoreasGpuGrid r = scene_gpu_grid(def);
    for (uint8_t s : solids) r.solid_count += s ? 1 : 0;
    return r;
  }();
};

void sine_sum_cl(benchmark::State& state, int n) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Sample : Fixture {
    SampleScene scene;
    cl::Kernel kernel;
    cl::Buffer points, force, waves, grid;
    std::string error;
  };
  Sample& f = fixture<Sample>("sine/cl/" + std::to_string(n), [&] {
    auto s = std::make_unique<Sample>();
    const SampleScene& sc = s->scene;
    std::vector<float> points = scene_points(n, sc.def);
    DeviceWaves dw = device_waves(sc.waves);
    s->points = upload(*rt, CL_MEM_READ_ONLY, points.data(), points.size() * sizeof(float));
    s->force = rt->buffer(CL_MEM_WRITE_ONLY, points.size() * sizeof(float));
    s->waves =
        upload(*rt, CL_MEM_READ_ONLY, dw.padded.data(), dw.padded.size() * sizeof(BoreasGpuWave));
    s->grid = upload(*rt, CL_MEM_READ_ONLY, sc.cells.data(), sc.cells.size() * sizeof(float));
    // As World::sample sets it up (points and forces as planes).
    s->kernel = rt->kernel("wind_sample_points.cl", "boreas_wind_sample_points", dw.define);
    BOREAS_CL_CHECK(s->kernel.setArg(0, s->points));
    BOREAS_CL_CHECK(s->kernel.setArg(1, s->force));
    BOREAS_CL_CHECK(s->kernel.setArg(2, n));
    BOREAS_CL_CHECK(s->kernel.setArg(3, s->waves));
    BOREAS_CL_CHECK(s->kernel.setArg(4, int(dw.padded.size())));
    BOREAS_CL_CHECK(s->kernel.setArg(5, s->grid));
    BOREAS_CL_CHECK(s->kernel.setArg(6, sc.g));
    // Once: the kernel's result against the native twin's on the same points.
    cl::CommandQueue& q = rt->queue();
    BOREAS_CL_CHECK(q.enqueueNDRangeKernel(s->kernel, cl::NullRange,
                                           cl::NDRange((size_t(n) + 255) / 256 * 256)));
    std::vector<float> got(points.size()), want(points.size());
    BOREAS_CL_CHECK(
        q.enqueueReadBuffer(s->force, CL_TRUE, 0, got.size() * sizeof(float), got.data()));
    native_sample_points(points.data(), want.data(), n, sc.waves.data(), int(sc.waves.size()),
                         sc.cells.data(), sc.g);
    s->error = disagreement("sine sums", max_difference(got, want));
    return s;
  });
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  // As World::sample launches it: the global size rounded up to 256.
  const size_t global = (size_t(n) + 255) / 256 * 256;
  auto launch = [&] {
    cl::Event e;
    BOREAS_CL_CHECK(rt->queue().enqueueNDRangeKernel(f.kernel, cl::NullRange, cl::NDRange(global),
                                                     cl::NullRange, nullptr, &e));
    return e;
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindSineSum", n, kBytesPerSample, launch);
}

void sine_sum_native(benchmark::State& state, int n) {
  struct Sample : Fixture {
    SampleScene scene;
    std::vector<float> points, force;
  };
  Sample& f = fixture<Sample>("sine/native/" + std::to_string(n), [&] {
    auto s = std::make_unique<Sample>();
    s->points = scene_points(n, s->scene.def);
    s->force.assign(s->points.size(), 0.0f);
    return s;
  });
  const SampleScene& sc = f.scene;
  auto run = [&] {
    native_sample_points(f.points.data(), f.force.data(), n, sc.waves.data(), int(sc.waves.size()),
                         sc.cells.data(), sc.g);
  };
  run();
  time_native(state, "BM_WindSineSum", n, kBytesPerSample, run);
}

// ---- sine sum per grid column (boreas_wind_sine_slab): the bare sine sum ----

void sine_slab_cl(benchmark::State& state, int nx, int nz) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Slab : Fixture {
    cl::Kernel kernel;
    cl::Buffer slab, waves;
    std::string error;
  };
  const int64_t columns = int64_t(nx) * nz;
  Slab& f = fixture<Slab>("slab/cl/" + std::to_string(columns), [&] {
    auto s = std::make_unique<Slab>();
    std::vector<BoreasGpuWave> waves = scene_waves();
    DeviceWaves dw = device_waves(waves);
    BoreasGpuGrid g = scene_gpu_grid(scene_grid_def(nx, 1, nz));
    s->slab = rt->buffer(CL_MEM_WRITE_ONLY, size_t(columns) * 2 * sizeof(float));
    s->waves =
        upload(*rt, CL_MEM_READ_ONLY, dw.padded.data(), dw.padded.size() * sizeof(BoreasGpuWave));
    // As WindGrid::step sets it up.
    s->kernel = rt->kernel("wind_sine_slab.cl", "boreas_wind_sine_slab", dw.define);
    BOREAS_CL_CHECK(s->kernel.setArg(0, s->slab));
    BOREAS_CL_CHECK(s->kernel.setArg(1, s->waves));
    BOREAS_CL_CHECK(s->kernel.setArg(2, int(dw.padded.size())));
    BOREAS_CL_CHECK(s->kernel.setArg(3, g));
    cl::CommandQueue& q = rt->queue();
    BOREAS_CL_CHECK(q.enqueueNDRangeKernel(s->kernel, cl::NullRange, cl::NDRange(nx, nz)));
    std::vector<float> got(size_t(columns) * 2), want(got.size());
    BOREAS_CL_CHECK(
        q.enqueueReadBuffer(s->slab, CL_TRUE, 0, got.size() * sizeof(float), got.data()));
    native_sine_slab(want.data(), waves.data(), int(waves.size()), g);
    s->error = disagreement("sine slabs", max_difference(got, want));
    return s;
  });
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  auto launch = [&] {
    cl::Event e;
    BOREAS_CL_CHECK(rt->queue().enqueueNDRangeKernel(f.kernel, cl::NullRange, cl::NDRange(nx, nz),
                                                     cl::NullRange, nullptr, &e));
    return e;
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindSineSlab", columns, kBytesPerSlabColumn, launch);
}

void sine_slab_native(benchmark::State& state, int nx, int nz) {
  struct Slab : Fixture {
    std::vector<BoreasGpuWave> waves = scene_waves();
    std::vector<float> slab;
  };
  const int64_t columns = int64_t(nx) * nz;
  Slab& f = fixture<Slab>("slab/native/" + std::to_string(columns), [&] {
    auto s = std::make_unique<Slab>();
    s->slab.assign(size_t(columns) * 2, 0.0f);
    return s;
  });
  const BoreasGpuGrid g = scene_gpu_grid(scene_grid_def(nx, 1, nz));
  auto run = [&] { native_sine_slab(f.slab.data(), f.waves.data(), int(f.waves.size()), g); };
  run();
  time_native(state, "BM_WindSineSlab", columns, kBytesPerSlabColumn, run);
}

// ---- grid step (boreas_wind_grid_step, launched by WindGrid::step with its slab) ----

struct GridScene {
  boreas_grid_def def;
  std::vector<uint8_t> solids;
  impl::WindGrid::Forcing drive;
  std::vector<BoreasGpuWave> waves = scene_waves();
  explicit GridScene(const int size[3])
      : def(scene_grid_def(size[0], size[1], size[2])),
        solids(scene_solids(def)),
        drive(scene_forcing(def)) {}
  int varying_count() const { return int(drive.varying.size()); }
  // The steady field as the native twin builds it (once, like the device's).
  std::vector<float> native_steady_field(const BoreasGpuGrid& g) const {
    std::vector<float> field(size_t(g.nx) * g.ny * g.nz * 4);
    native_forcing_field(field.data(), drive.steady.data(), int(drive.steady.size()), g);
    return field;
  }
};

void grid_step_cl(benchmark::State& state, const int size[3]) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Grid : Fixture {
    GridScene scene;
    DeviceWaves waves;
    std::unique_ptr<impl::WindGrid> grid;
    cl::Buffer wave_buffer;
    std::string error;
    explicit Grid(const int size[3]) : scene(size), waves(device_waves(scene.waves)) {}
    void step() {
      grid->step(kStepSeconds, wave_buffer, int(waves.padded.size()), waves.slots, scene.drive);
    }
  };
  const int64_t cells = int64_t(size[0]) * size[1] * size[2];
  Grid& f = fixture<Grid>("grid/cl/" + std::to_string(cells), [&] {
    auto s = std::make_unique<Grid>(size);
    const GridScene& sc = s->scene;
    s->grid = std::make_unique<impl::WindGrid>(*rt, sc.def);
    s->grid->set_always_run(true);
    s->grid->set_solids(sc.solids);
    s->wave_buffer = upload(*rt, CL_MEM_READ_ONLY, s->waves.padded.data(),
                            s->waves.padded.size() * sizeof(BoreasGpuWave));
    for (int i = 0; i < kWarmSteps; ++i) s->step();
    // Once: one step of the kernel against the native twin from the same grid.
    std::vector<float> before = s->grid->read_planes();
    s->step();
    std::vector<float> got = s->grid->read_planes();
    BoreasGpuGrid g = s->grid->gpu();
    std::vector<float> slab(size_t(g.nx) * g.nz * 2), want(before.size());
    native_sine_slab(slab.data(), sc.waves.data(), int(sc.waves.size()), g);
    std::vector<float> steady = sc.native_steady_field(g);
    native_grid_step(before.data(), want.data(), slab.data(), steady.data(),
                     sc.drive.varying.data(), sc.varying_count(), g,
                     impl::grid_step_constants(sc.def, kStepSeconds, sc.varying_count()));
    s->error = disagreement("grid steps", max_difference(got, want));
    return s;
  });
  if (!f.error.empty()) {
    state.SkipWithError(f.error.c_str());
    return;
  }
  auto launch = [&] {
    f.step();
    return f.grid->last_step_event();
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindGridStep", cells, kBytesPerGridCell, launch);
}

void grid_step_native(benchmark::State& state, const int size[3]) {
  struct Grid : Fixture {
    GridScene scene;
    BoreasGpuGrid g{};
    BoreasGpuGridStep constants{};
    std::vector<float> cells[2];
    std::vector<float> slab;
    std::vector<float> steady;
    int current = 0;
    explicit Grid(const int size[3]) : scene(size) {}
    void step() {
      native_sine_slab(slab.data(), scene.waves.data(), int(scene.waves.size()), g);
      native_grid_step(cells[current].data(), cells[1 - current].data(), slab.data(),
                       steady.data(), scene.drive.varying.data(), scene.varying_count(), g,
                       constants);
      current = 1 - current;
    }
  };
  const int64_t cells = int64_t(size[0]) * size[1] * size[2];
  Grid& f = fixture<Grid>("grid/native/" + std::to_string(cells), [&] {
    auto s = std::make_unique<Grid>(size);
    s->g = scene_gpu_grid(s->scene.def);
    const size_t n = size_t(cells);
    s->cells[0].assign(4 * n, 0.0f);
    for (size_t c = 0; c < n; ++c) {
      s->cells[0][3 * n + c] = s->scene.solids[c] ? 1.0f : 0.0f;
      s->g.solid_count += s->scene.solids[c] ? 1 : 0;
    }
    s->cells[1] = s->cells[0];
    s->slab.assign(size_t(s->g.nx) * s->g.nz * 2, 0.0f);
    s->constants =
        impl::grid_step_constants(s->scene.def, kStepSeconds, s->scene.varying_count());
    s->steady = s->scene.native_steady_field(s->g);
    for (int i = 0; i < kWarmSteps; ++i) s->step();
    return s;
  });
  time_native(state, "BM_WindGridStep", cells, kBytesPerGridCell, [&] { f.step(); });
}

// ---- trees (boreas_tree_step, boreas_tree_deform, boreas_tree_leaves) ----

// Compulsory traffic per item; the gathers of the parent's state (15 floats, shared by
// siblings, so mostly cached) are left out.
constexpr double kBytesPerBranchStep = 192.0;  // in: parent index 4, shape 64, response 16,
                                               // motion 24; out: state 60, motion 24
constexpr double kBytesPerVertex = 32.0;       // out: position, normal, uv
constexpr double kBytesPerLeaf = 64.0;         // in: parent 4, placement 24; out: 36

// Branches per batch (both stepping modes, and the deformer over the same batch).
constexpr int kTreeBranchCounts[] = {1 << 16, 1 << 18};
// The leaves row runs on this batch only (its ~1.2 M leaves; the larger one has ~4.8 M).
constexpr int kTreeLeafBatch = 1 << 16;
// Distinct generated trees, replicated across the grid.
constexpr int kTreeModels = 8;
// Work-group size of TreeBatch's launches (tree_batch.cpp), used for the deformer and
// leaf launches made here.
constexpr size_t kTreeLocalGroup = 64;

size_t tree_global_size(size_t work) {
  return (work + kTreeLocalGroup - 1) / kTreeLocalGroup * kTreeLocalGroup;
}

// The trees of every tree row: quaking aspen (the library's default tree, 3 levels,
// ~1224 branches and ~22300 leaves each) grown from seeds 1..kTreeModels at scale 1.
// The one place to change for other species or for hand-built models.
const std::vector<impl::TreeModel>& bench_tree_models() {
  static const std::vector<impl::TreeModel> models = [] {
    const impl::Species species = impl::load_species("quaking_aspen");
    std::vector<impl::TreeModel> m;
    for (int seed = 1; seed <= kTreeModels; ++seed)
      m.push_back(impl::grow_tree(species, uint64_t(seed), 1.0));
    return m;
  }();
  return models;
}

// The wind the trees stand in: the scene's four waves, steady (the same device copy every
// step), over the sample benchmark's 64 x 16 x 64 grid of 2 m cells, calm (all zero, no
// solids: what a world without flow primitives holds). The trees still pay for the grid
// sample's gathers.
struct TreeWindScene {
  boreas_grid_def def = scene_grid_def(64, 16, 64);
  BoreasGpuGrid g = scene_gpu_grid(def);
  std::vector<float> cells =
      std::vector<float>(size_t(4) * def.resolution[0] * def.resolution[1] * def.resolution[2]);
  std::vector<BoreasGpuWave> waves = scene_waves();
  DeviceWaves device = device_waves(waves);
  // The kernels' view of this wind, once its waves and grid are on the device.
  impl::TreeWindInput cl(const cl::Buffer& wave_buffer, const cl::Buffer& grid_buffer) const {
    impl::TreeWindInput in;
    in.waves = &wave_buffer;
    in.wave_count = int(device.padded.size());
    in.wave_slots = device.slots;
    in.grid = &grid_buffer;
    in.grid_layout = g;
    return in;
  }
  NativeTreeWind native() const {
    NativeTreeWind w;
    w.waves = waves.data();
    w.wave_count = int(waves.size());
    w.grid = cells.data();
    w.g = g;
    return w;
  }
};

// A model cut to its first `branches` branches (fewer than it has, more than its levels
// before the last): the cut falls on the last level, whose branches have no children;
// leaves on removed branches go too.
impl::TreeModel cut_tree(const impl::TreeModel& m, int branches) {
  impl::TreeModel t = m;
  t.branches.resize(size_t(branches));
  for (auto& begin : t.level_begin) begin = std::min(begin, int32_t(branches));
  t.levels = 0;
  for (int l = 0; l < impl::kMaxTreeLevels; ++l)
    if (t.level_begin[l + 1] > t.level_begin[l]) t.levels = l + 1;
  t.leaves.erase(
      std::remove_if(t.leaves.begin(), t.leaves.end(),
                     [&](const impl::LeafModel& leaf) { return leaf.parent >= branches; }),
      t.leaves.end());
  return t;
}

// Trees with `branches` branches in all (0: one of each model), cycling through
// bench_tree_models() on a square lattice over the grid's ground; the last tree is cut so
// the count is exact. Parameters are boreas_default_tree_def()'s (quasi-static response
// unless given, rings and sides 12x12, 6x8, 4x5, 3x4 per level).
std::vector<std::shared_ptr<impl::TreeInstance>> bench_trees(
    int branches, const boreas_grid_def& def,
    boreas_tree_response response = BOREAS_TREE_QUASI_STATIC) {
  const std::vector<impl::TreeModel>& models = bench_tree_models();
  std::vector<impl::TreeModel> chosen;
  int total = 0;
  for (size_t k = 0; branches > 0 ? total < branches : k < models.size(); ++k) {
    const impl::TreeModel& m = models[k % models.size()];
    const int size = int(m.branches.size());
    if (branches > 0 && total + size > branches) {
      chosen.push_back(cut_tree(m, branches - total));
      total = branches;
    } else {
      chosen.push_back(m);
      total += size;
    }
  }
  const int side = int(std::ceil(std::sqrt(double(chosen.size()))));
  const float spacing_x = def.resolution[0] * def.cell_size / float(side);
  const float spacing_z = def.resolution[2] * def.cell_size / float(side);
  boreas_tree_def tree_def = boreas_default_tree_def();
  tree_def.response = response;
  std::vector<std::shared_ptr<impl::TreeInstance>> trees;
  for (size_t k = 0; k < chosen.size(); ++k) {
    auto tree = std::make_shared<impl::TreeInstance>();
    tree->key = uint64_t(k) + 1;
    tree->params = impl::checked_tree_def(tree_def);
    tree->params.position = {def.origin[0] + (float(k % side) + 0.5f) * spacing_x, 0.0,
                             def.origin[2] + (float(k / side) + 0.5f) * spacing_z};
    tree->model = std::move(chosen[k]);
    trees.push_back(std::move(tree));
  }
  return trees;
}

std::vector<NativeTreeSource> native_sources(
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  std::vector<NativeTreeSource> sources;
  for (const auto& t : trees) sources.push_back({&t->params, &t->model});
  return sources;
}

// A TreeBatch of these trees without their leaves (the step rows time branches only;
// TreeBatch would otherwise run the leaf kernel after every step).
std::unique_ptr<impl::TreeBatch> leafless_batch(
    impl::Runtime& rt, boreas_tree_mode mode,
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  auto batch = std::make_unique<impl::TreeBatch>(rt, mode);
  for (const auto& t : trees) {
    auto copy = std::make_shared<impl::TreeInstance>(*t);
    copy->model.leaves.clear();
    batch->add(std::move(copy));
  }
  return batch;
}

// The mesh of a batch as the deformer rows make it: each level of every tree at the
// level's rings x sides, one plane block of `vertices` vertices.
struct DeformLayout {
  std::array<int, impl::kMaxTreeLevels> rings{}, sides{}, vertex_first{};
  int vertices = 0;
};

DeformLayout deform_layout(const NativeTrees& t, const impl::TreeParams& params) {
  DeformLayout d;
  for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
    d.rings[l] = params.levels[l].rings;
    d.sides[l] = params.levels[l].sides;
    d.vertex_first[l] = d.vertices;
    d.vertices += t.level_count[l] * (d.rings[l] + 1) * (d.sides[l] + 1);
  }
  return d;
}

// Everything the tree rows of one batch size share; made by the first of them, kept for
// the others (the fixture slot holds it under one name). The CL side is made by the
// first CL row.
struct TreeFixture : Fixture {
  TreeWindScene wind;
  std::vector<std::shared_ptr<impl::TreeInstance>> trees;  // with their leaves
  NativeTrees native;                                      // what the native rows step
  DeformLayout mesh;
  std::vector<float> native_vertices, native_leaves;
  // CL
  cl::Buffer waves, grid;
  std::unique_ptr<impl::TreeBatch> batch[2];  // lagged, exact
  std::string step_error[2];
  cl::Buffer vertices, leaf_parents, leaf_shape, leaf_out;
  bool deform_checked = false, leaves_checked = false;
  std::string deform_error, leaves_error;

  impl::TreeWindInput cl_wind() const { return wind.cl(waves, grid); }
};

TreeFixture& tree_fixture(int branches) {
  return fixture<TreeFixture>("trees/" + std::to_string(branches), [&] {
    auto f = std::make_unique<TreeFixture>();
    f->trees = bench_trees(branches, f->wind.def);
    f->native = native_tree_layout(native_sources(f->trees));
    f->mesh = deform_layout(f->native, f->trees.front()->params);
    f->native_vertices.assign(size_t(BOREAS_TREE_VERTEX_PLANES) * f->mesh.vertices, 0.0f);
    f->native_leaves.assign(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * f->native.leaf_n, 0.0f);
    return f;
  });
}

// The CL batch of a mode, checked once against the native twin: the layout (the batch's
// rest state against native_tree_layout's) and one step from rest.
void make_tree_batch(impl::Runtime& rt, TreeFixture& f, bool exact) {
  const int m = exact ? 1 : 0;
  if (f.batch[m]) return;
  if (!f.waves()) {
    f.waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                     f.wind.device.padded.size() * sizeof(BoreasGpuWave));
    f.grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  }
  auto batch = leafless_batch(rt, exact ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED, f.trees);
  NativeTrees twin = native_tree_layout(native_sources(f.trees));
  if (batch->stride() != twin.n) {
    f.step_error[m] = "the batch's layout differs from the native twin's";
  } else {
    std::string layout =
        disagreement("rest states", max_difference(batch->read_state(), twin.state[0]), "m");
    batch->enqueue_step(kStepSeconds, f.cl_wind());
    BOREAS_CL_CHECK(rt.queue().finish());
    batch->commit();
    native_trees_step(twin, exact, kStepSeconds, f.wind.native());
    std::string step = disagreement(
        "tree steps", max_difference(batch->read_state(), twin.state[twin.current]), "m");
    f.step_error[m] = !layout.empty() ? layout : step;
  }
  f.batch[m] = std::move(batch);
}

std::string tree_step_key(int branches, bool exact) {
  return std::to_string(branches) + (exact ? "/exact" : "/lagged");
}

void tree_step_cl(benchmark::State& state, int branches, bool exact) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, exact);
  const int m = exact ? 1 : 0;
  if (!f.step_error[m].empty()) {
    state.SkipWithError(f.step_error[m].c_str());
    return;
  }
  impl::TreeBatch& batch = *f.batch[m];
  const impl::TreeWindInput wind = f.cl_wind();
  cl::CommandQueue& q = rt->queue();
  // As World::step runs it (enqueue_step, finish, commit). The kernels' device time is
  // taken between two markers: TreeBatch launches without events, and the first marker
  // waits on a user event set only after the launches are enqueued, so the span is the
  // device's alone (the launches, back to back), not the host's enqueueing.
  auto launch = [&] {
    cl::UserEvent gate(rt->context());
    const std::vector<cl::Event> wait{gate};
    ClSpan span;
    span.markers = true;
    BOREAS_CL_CHECK(q.enqueueMarkerWithWaitList(&wait, &span.first));
    batch.enqueue_step(kStepSeconds, wind);
    BOREAS_CL_CHECK(q.enqueueMarkerWithWaitList(nullptr, &span.last));
    BOREAS_CL_CHECK(gate.setStatus(CL_COMPLETE));
    batch.commit();
    return span;
  };
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(q.finish());
  time_cl_span(state, *rt, "BM_TreeStep", branches, kBytesPerBranchStep,
               tree_step_key(branches, exact), launch);
}

void tree_step_native(benchmark::State& state, int branches, bool exact) {
  TreeFixture& f = tree_fixture(branches);
  const NativeTreeWind wind = f.wind.native();
  auto run = [&] { native_trees_step(f.native, exact, kStepSeconds, wind); };
  run();
  time_native(state, "BM_TreeStep", branches, kBytesPerBranchStep, run,
              tree_step_key(branches, exact));
}

// The deformer over a batch's state (the lagged batch's, as stepped by its rows), one
// launch per level as TreeBatch::mesh makes them, for every tree at once.
void deform_native_all(TreeFixture& f, const float* state, float* out) {
  const NativeTrees& t = f.native;
  for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
    if (t.level_count[l] <= 0) continue;
    native_tree_deform(state, t.n, t.radius.data(), t.level_first[l], t.level_count[l],
                       f.mesh.rings[l], f.mesh.sides[l], out, f.mesh.vertices,
                       f.mesh.vertex_first[l]);
  }
}

void deform_cl(benchmark::State& state, int branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, false);
  if (!f.step_error[0].empty()) {
    state.SkipWithError(f.step_error[0].c_str());
    return;
  }
  impl::TreeBatch& batch = *f.batch[0];
  const NativeTrees& t = f.native;
  cl::Kernel& kernel = rt->kernel("tree_deform.cl", "boreas_tree_deform");
  auto launch = [&] {
    ClSpan span;
    bool first = true;
    for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
      if (t.level_count[l] <= 0) continue;
      BOREAS_CL_CHECK(kernel.setArg(0, batch.state_buffer()));
      BOREAS_CL_CHECK(kernel.setArg(1, batch.stride()));
      BOREAS_CL_CHECK(kernel.setArg(2, batch.radius_buffer()));
      BOREAS_CL_CHECK(kernel.setArg(3, t.level_first[l]));
      BOREAS_CL_CHECK(kernel.setArg(4, t.level_count[l]));
      BOREAS_CL_CHECK(kernel.setArg(5, f.mesh.rings[l]));
      BOREAS_CL_CHECK(kernel.setArg(6, f.mesh.sides[l]));
      BOREAS_CL_CHECK(kernel.setArg(7, f.vertices));
      BOREAS_CL_CHECK(kernel.setArg(8, f.mesh.vertices));
      BOREAS_CL_CHECK(kernel.setArg(9, f.mesh.vertex_first[l]));
      const size_t work = size_t(t.level_count[l]) * (f.mesh.rings[l] + 1) * (f.mesh.sides[l] + 1);
      cl::Event e;
      BOREAS_CL_CHECK(rt->queue().enqueueNDRangeKernel(kernel, cl::NullRange,
                                                       cl::NDRange(tree_global_size(work)),
                                                       cl::NDRange(kTreeLocalGroup), nullptr, &e));
      if (first) span.first = e;
      span.last = e;
      first = false;
    }
    return span;
  };
  if (!f.deform_checked) {
    f.vertices = rt->buffer(CL_MEM_READ_WRITE,
                            size_t(BOREAS_TREE_VERTEX_PLANES) * f.mesh.vertices * sizeof(float));
    launch();
    std::vector<float> got(size_t(BOREAS_TREE_VERTEX_PLANES) * f.mesh.vertices);
    BOREAS_CL_CHECK(rt->queue().enqueueReadBuffer(f.vertices, CL_TRUE, 0,
                                                  got.size() * sizeof(float), got.data()));
    std::vector<float> want(got.size());
    std::vector<float> state_planes = batch.read_state();
    deform_native_all(f, state_planes.data(), want.data());
    f.deform_error = disagreement("deformed vertices", max_difference(got, want), "(m or unit)");
    f.deform_checked = true;
  }
  if (!f.deform_error.empty()) {
    state.SkipWithError(f.deform_error.c_str());
    return;
  }
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(rt->queue().finish());
  time_cl_span(state, *rt, "BM_Deform", f.mesh.vertices, kBytesPerVertex, std::to_string(branches),
               launch);
}

void deform_native(benchmark::State& state, int branches) {
  TreeFixture& f = tree_fixture(branches);
  const float* planes = f.native.state[f.native.current].data();
  auto run = [&] { deform_native_all(f, planes, f.native_vertices.data()); };
  run();
  time_native(state, "BM_Deform", f.mesh.vertices, kBytesPerVertex, run, std::to_string(branches));
}

void leaves_cl(benchmark::State& state, int branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, false);
  if (!f.step_error[0].empty()) {
    state.SkipWithError(f.step_error[0].c_str());
    return;
  }
  impl::TreeBatch& batch = *f.batch[0];
  const NativeTrees& t = f.native;
  cl::Kernel& kernel = rt->kernel("tree_leaves.cl", "boreas_tree_leaves");
  if (!f.leaves_checked) {
    // The leaf planes as TreeBatch lays them out (its own are private): native_tree_layout's.
    f.leaf_parents = upload(*rt, CL_MEM_READ_ONLY, t.leaf_parents.data(),
                            t.leaf_parents.size() * sizeof(int32_t));
    f.leaf_shape =
        upload(*rt, CL_MEM_READ_ONLY, t.leaf_shape.data(), t.leaf_shape.size() * sizeof(float));
    f.leaf_out = rt->buffer(CL_MEM_READ_WRITE,
                            size_t(BOREAS_TREE_LEAF_OUT_PLANES) * t.leaf_n * sizeof(float));
  }
  auto launch = [&] {
    // As TreeBatch::enqueue_leaves.
    BOREAS_CL_CHECK(kernel.setArg(0, batch.state_buffer()));
    BOREAS_CL_CHECK(kernel.setArg(1, batch.stride()));
    BOREAS_CL_CHECK(kernel.setArg(2, f.leaf_parents));
    BOREAS_CL_CHECK(kernel.setArg(3, f.leaf_shape));
    BOREAS_CL_CHECK(kernel.setArg(4, f.leaf_out));
    BOREAS_CL_CHECK(kernel.setArg(5, t.leaf_count));
    BOREAS_CL_CHECK(kernel.setArg(6, t.leaf_n));
    cl::Event e;
    BOREAS_CL_CHECK(rt->queue().enqueueNDRangeKernel(kernel, cl::NullRange,
                                                     cl::NDRange(tree_global_size(t.leaf_count)),
                                                     cl::NDRange(kTreeLocalGroup), nullptr, &e));
    return e;
  };
  if (!f.leaves_checked) {
    launch();
    std::vector<float> got(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * t.leaf_n);
    BOREAS_CL_CHECK(rt->queue().enqueueReadBuffer(f.leaf_out, CL_TRUE, 0,
                                                  got.size() * sizeof(float), got.data()));
    std::vector<float> want(got.size());
    std::vector<float> state_planes = batch.read_state();
    native_tree_leaves(state_planes.data(), t.n, t.leaf_parents.data(), t.leaf_shape.data(),
                       want.data(), t.leaf_count, t.leaf_n);
    f.leaves_error = disagreement("leaves", max_difference(got, want), "(m or unit)");
    f.leaves_checked = true;
  }
  if (!f.leaves_error.empty()) {
    state.SkipWithError(f.leaves_error.c_str());
    return;
  }
  warm_up(*rt, launch);
  time_cl_span(state, *rt, "BM_TreeLeaves", t.leaf_count, kBytesPerLeaf, std::to_string(branches),
               [&] {
                 ClSpan span;
                 span.first = span.last = launch();
                 return span;
               });
}

void leaves_native(benchmark::State& state, int branches) {
  TreeFixture& f = tree_fixture(branches);
  const NativeTrees& t = f.native;
  const float* planes = t.state[t.current].data();
  auto run = [&] {
    native_tree_leaves(planes, t.n, t.leaf_parents.data(), t.leaf_shape.data(),
                       f.native_leaves.data(), t.leaf_count, t.leaf_n);
  };
  run();
  time_native(state, "BM_TreeLeaves", t.leaf_count, kBytesPerLeaf, run, std::to_string(branches));
}

// ---- underbrush (boreas_underbrush_step, boreas_underbrush_vertices) ----

// Compulsory traffic per item; the part records and table cells (a few KiB that every
// component shares) and the wind's grid gathers are left out.
// Step: in, state 40 (X, V, broken, base), frame 44 and the parent's rest X 12, index 8;
// out, state 40.
constexpr double kBytesPerComponentStep = 144.0;
constexpr int kUnderbrushStrip = 2 * BOREAS_UB_JOINTS;  // vertices per component
// out: position, normal, uv; plus the component's share of what its strip reads (X 12,
// broken 4, base 12, frame axis, side and scale 28, part index 4) and writes (its count,
// 4) over its 18 vertices.
constexpr double kBytesPerUnderbrushVertex = 32.0 + 64.0 / kUnderbrushStrip;

// Components per meadow: every size for the step, the smallest and largest for the strips.
constexpr int kUnderbrushSizes[] = {1 << 16, 1 << 18, 1 << 20};
constexpr int kUnderbrushVertexSizes[] = {1 << 16, 1 << 20};
// Work-group size of UnderbrushBatch's launches (underbrush_batch.cpp).
constexpr size_t kUnderbrushLocalGroup = 64;
// CL steps from rest before the twin check, so that it sees bent, moving blades.
constexpr int kUnderbrushCheckSteps = 30;
// Where the strips are seen from: 1.7 m above the meadow's middle (default LOD distances).
constexpr float kUnderbrushCamera[3] = {0.0f, 1.7f, 0.0f};

size_t underbrush_global_size(int n) {
  return (size_t(n) + kUnderbrushLocalGroup - 1) / kUnderbrushLocalGroup * kUnderbrushLocalGroup;
}

// Everything the underbrush rows of one meadow size share; made by the first of them, kept
// for the others. The CL side is made by the first CL row: the planes of a batch holding
// this one meadow (UnderbrushBatch lays out a lone meadow as the meadow's own planes), the
// kernels launched as UnderbrushBatch launches them, but each launch alone, so that its
// event times the kernel. (UnderbrushBatch::enqueue_step returns no event, and it writes
// the collider and impulse buffers with blocking writes, so markers around it would time
// the host too.) One step through a real UnderbrushBatch checks the set-up.
struct UnderbrushFixture : Fixture {
  TreeWindScene wind;  // the trees' wind: the scene's four waves over a calm grid
  std::vector<BoreasGpuCollider> colliders = scene_colliders();
  std::shared_ptr<impl::MeadowInstance> meadow;
  std::vector<BoreasGpuPart> parts;  // decay written for kStepSeconds
  std::array<float, 3> lod{};
  // native
  std::vector<float> native_state[2];
  int native_current = 0;
  std::vector<float> native_vertices;
  std::vector<int32_t> native_counts;
  // CL
  bool cl_made = false, vertices_checked = false;
  std::string step_defines, step_error, vertices_error;
  cl::Buffer waves, grid, state[2], frame, index, part_buffer, tables, collider_buffer,
      impulse_buffer, vertices, counts;
  int cl_current = 0;

  int n() const { return meadow->meadow.count; }
  NativeMeadowPlanes planes() const {
    const impl::Meadow& m = meadow->meadow;
    NativeMeadowPlanes p;
    p.frame = m.frame.data();
    p.index = m.index.data();
    p.parts = parts.data();
    p.tables = m.tables.data();
    p.n = m.count;
    return p;
  }
  impl::TreeWindInput cl_wind() const { return wind.cl(waves, grid); }
};

UnderbrushFixture& underbrush_fixture(int components) {
  return fixture<UnderbrushFixture>("underbrush/" + std::to_string(components), [&] {
    auto f = std::make_unique<UnderbrushFixture>();
    f->meadow = std::make_shared<impl::MeadowInstance>();
    f->meadow->key = 1;
    f->meadow->meadow = scene_meadow(components);
    const impl::Meadow& m = f->meadow->meadow;
    // As UnderbrushBatch::upload_parts writes them for a step of kStepSeconds.
    for (const impl::MeadowPart& part : m.parts) {
      BoreasGpuPart g = part.gpu;
      g.decay = float(std::exp(-kStepSeconds / double(g.tau)));
      f->parts.push_back(g);
    }
    f->lod = m.params.lod;
    f->native_state[0] = f->native_state[1] = m.rest_state;
    f->native_vertices.assign(size_t(m.count) * kUnderbrushStrip * 8, 0.0f);
    f->native_counts.assign(size_t(m.count), 0);
    return f;
  });
}

// One native step of the whole meadow from the current state.
void underbrush_step_native_once(UnderbrushFixture& f) {
  const int next = 1 - f.native_current;
  native_underbrush_step(f.planes(), f.native_state[f.native_current].data(),
                         f.native_state[next].data(), float(kStepSeconds), float(impl::kGravity),
                         f.wind.native(), f.colliders.data(), int(f.colliders.size()), nullptr, 0);
  f.native_current = next;
}

// Enqueues one CL step from state[cl_current], as UnderbrushBatch::enqueue_step sets it up
// (no impulses), and returns the kernel's event; the caller flips cl_current.
cl::Event underbrush_step_launch(impl::Runtime& rt, UnderbrushFixture& f) {
  cl::Kernel& k = rt.kernel("underbrush_step.cl", "boreas_underbrush_step", f.step_defines);
  int arg = 0;
  BOREAS_CL_CHECK(k.setArg(arg++, f.state[f.cl_current]));
  BOREAS_CL_CHECK(k.setArg(arg++, f.state[1 - f.cl_current]));
  BOREAS_CL_CHECK(k.setArg(arg++, f.frame));
  BOREAS_CL_CHECK(k.setArg(arg++, f.index));
  BOREAS_CL_CHECK(k.setArg(arg++, f.part_buffer));
  BOREAS_CL_CHECK(k.setArg(arg++, f.tables));
  BOREAS_CL_CHECK(k.setArg(arg++, f.n()));
  BOREAS_CL_CHECK(k.setArg(arg++, float(kStepSeconds)));
  BOREAS_CL_CHECK(k.setArg(arg++, float(impl::kGravity)));
  BOREAS_CL_CHECK(k.setArg(arg++, f.waves));
  BOREAS_CL_CHECK(k.setArg(arg++, int(f.wind.device.padded.size())));
  BOREAS_CL_CHECK(k.setArg(arg++, f.grid));
  BOREAS_CL_CHECK(k.setArg(arg++, f.wind.g));
  BOREAS_CL_CHECK(k.setArg(arg++, f.collider_buffer));
  BOREAS_CL_CHECK(k.setArg(arg++, int(f.colliders.size())));
  BOREAS_CL_CHECK(k.setArg(arg++, f.impulse_buffer));
  BOREAS_CL_CHECK(k.setArg(arg++, 0));
  cl::Event e;
  BOREAS_CL_CHECK(rt.queue().enqueueNDRangeKernel(k, cl::NullRange,
                                                  cl::NDRange(underbrush_global_size(f.n())),
                                                  cl::NDRange(kUnderbrushLocalGroup), nullptr, &e));
  return e;
}

std::vector<float> read_floats(impl::Runtime& rt, const cl::Buffer& b, size_t count) {
  std::vector<float> out(count);
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, count * sizeof(float), out.data()));
  return out;
}

// The CL side, checked: one step against a real UnderbrushBatch's from rest, then, after
// kUnderbrushCheckSteps more, one step against the native twin's from the same state.
void make_underbrush_cl(impl::Runtime& rt, UnderbrushFixture& f) {
  if (f.cl_made) return;
  f.cl_made = true;
  const impl::Meadow& m = f.meadow->meadow;
  const size_t state_floats = size_t(BOREAS_UB_STATE_PLANES) * m.count;
  f.waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                   f.wind.device.padded.size() * sizeof(BoreasGpuWave));
  f.grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  for (cl::Buffer& s : f.state)
    s = upload(rt, CL_MEM_READ_WRITE, m.rest_state.data(), state_floats * sizeof(float));
  f.frame = upload(rt, CL_MEM_READ_ONLY, m.frame.data(), m.frame.size() * sizeof(float));
  f.index = upload(rt, CL_MEM_READ_ONLY, m.index.data(), m.index.size() * sizeof(int32_t));
  f.part_buffer =
      upload(rt, CL_MEM_READ_ONLY, f.parts.data(), f.parts.size() * sizeof(BoreasGpuPart));
  f.tables = upload(rt, CL_MEM_READ_ONLY, m.tables.data(), m.tables.size() * sizeof(float));
  // Colliders padded to their slots and one silent impulse, as UnderbrushBatch uploads them.
  std::vector<BoreasGpuCollider> padded = f.colliders;
  const int collider_slots =
      impl::pad_to_slots(padded, BoreasGpuCollider{1e18f, 1e18f, 1e18f, 0.0f});
  const BoreasGpuImpulse silent{1e18f, 1e18f, 1e18f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  f.collider_buffer =
      upload(rt, CL_MEM_READ_ONLY, padded.data(), padded.size() * sizeof(BoreasGpuCollider));
  f.impulse_buffer = upload(rt, CL_MEM_READ_ONLY, &silent, sizeof silent);
  f.step_defines = impl::slot_define("BOREAS_WAVE_SLOTS", f.wind.device.slots) +
                   impl::slot_define("BOREAS_COLLIDER_SLOTS", collider_slots) +
                   impl::slot_define("BOREAS_IMPULSE_SLOTS", 0);

  std::string layout;
  {
    impl::UnderbrushBatch batch(rt);
    batch.add(f.meadow);
    batch.enqueue_step(kStepSeconds, f.cl_wind(), f.colliders, {});
    BOREAS_CL_CHECK(rt.queue().finish());
    batch.commit();
    const std::vector<float> want = batch.read_state();
    underbrush_step_launch(rt, f);
    f.cl_current = 1 - f.cl_current;
    const std::vector<float> got = read_floats(rt, f.state[f.cl_current], state_floats);
    layout = disagreement("steps (bench set-up vs UnderbrushBatch)", max_difference(got, want),
                          "m or m/s");
  }
  for (int s = 0; s < kUnderbrushCheckSteps; ++s) {
    underbrush_step_launch(rt, f);
    f.cl_current = 1 - f.cl_current;
  }
  const std::vector<float> before = read_floats(rt, f.state[f.cl_current], state_floats);
  underbrush_step_launch(rt, f);
  f.cl_current = 1 - f.cl_current;
  const std::vector<float> got = read_floats(rt, f.state[f.cl_current], state_floats);
  std::vector<float> want(state_floats);
  native_underbrush_step(f.planes(), before.data(), want.data(), float(kStepSeconds),
                         float(impl::kGravity), f.wind.native(), f.colliders.data(),
                         int(f.colliders.size()), nullptr, 0);
  const double diff = max_difference(got, want);
  std::printf("underbrush %d: CL step vs native twin, max |difference| %.3g (m, m/s)\n", f.n(),
              diff);
  f.step_error = !layout.empty() ? layout : disagreement("underbrush steps", diff, "m or m/s");
}

void underbrush_step_cl(benchmark::State& state, int components) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  UnderbrushFixture& f = underbrush_fixture(components);
  make_underbrush_cl(*rt, f);
  if (!f.step_error.empty()) {
    state.SkipWithError(f.step_error.c_str());
    return;
  }
  auto launch = [&] {
    cl::Event e = underbrush_step_launch(*rt, f);
    f.cl_current = 1 - f.cl_current;
    return e;
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_UnderbrushStep", components, kBytesPerComponentStep, launch);
}

void underbrush_step_native(benchmark::State& state, int components) {
  UnderbrushFixture& f = underbrush_fixture(components);
  auto run = [&] { underbrush_step_native_once(f); };
  run();
  time_native(state, "BM_UnderbrushStep", components, kBytesPerComponentStep, run);
}

// Enqueues the strips of the current CL state, as UnderbrushBatch::enqueue_vertices.
cl::Event underbrush_vertices_launch(impl::Runtime& rt, UnderbrushFixture& f) {
  cl::Kernel& k = rt.kernel("underbrush_vertices.cl", "boreas_underbrush_vertices");
  int arg = 0;
  BOREAS_CL_CHECK(k.setArg(arg++, f.state[f.cl_current]));
  BOREAS_CL_CHECK(k.setArg(arg++, f.frame));
  BOREAS_CL_CHECK(k.setArg(arg++, f.index));
  BOREAS_CL_CHECK(k.setArg(arg++, f.part_buffer));
  BOREAS_CL_CHECK(k.setArg(arg++, f.tables));
  BOREAS_CL_CHECK(k.setArg(arg++, f.n()));
  for (float c : kUnderbrushCamera) BOREAS_CL_CHECK(k.setArg(arg++, c));
  for (float d : f.lod) BOREAS_CL_CHECK(k.setArg(arg++, d));
  BOREAS_CL_CHECK(k.setArg(arg++, f.vertices));
  BOREAS_CL_CHECK(k.setArg(arg++, f.counts));
  BOREAS_CL_CHECK(k.setArg(arg++, 0));      // first
  BOREAS_CL_CHECK(k.setArg(arg++, f.n()));  // count
  BOREAS_CL_CHECK(k.setArg(arg++, 0));      // out_first
  cl::Event e;
  BOREAS_CL_CHECK(rt.queue().enqueueNDRangeKernel(k, cl::NullRange,
                                                  cl::NDRange(underbrush_global_size(f.n())),
                                                  cl::NDRange(kUnderbrushLocalGroup), nullptr, &e));
  return e;
}

void underbrush_vertices_cl(benchmark::State& state, int components) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  UnderbrushFixture& f = underbrush_fixture(components);
  make_underbrush_cl(*rt, f);
  if (!f.step_error.empty()) {
    state.SkipWithError(f.step_error.c_str());
    return;
  }
  const int64_t vertices = int64_t(f.n()) * kUnderbrushStrip;
  if (!f.vertices_checked) {
    // Against the native twin on the same (CL) state; the native row's buffers hold the
    // twin's result, overwritten by its next run.
    f.vertices_checked = true;
    f.vertices = rt->buffer(CL_MEM_READ_WRITE, size_t(vertices) * 8 * sizeof(float));
    f.counts = rt->buffer(CL_MEM_READ_WRITE, size_t(f.n()) * sizeof(int32_t));
    underbrush_vertices_launch(*rt, f);
    std::vector<int32_t> got_counts(size_t(f.n()));
    BOREAS_CL_CHECK(rt->queue().enqueueReadBuffer(
        f.counts, CL_TRUE, 0, got_counts.size() * sizeof(int32_t), got_counts.data()));
    const std::vector<float> got = read_floats(*rt, f.vertices, size_t(vertices) * 8);
    const std::vector<float> planes =
        read_floats(*rt, f.state[f.cl_current], size_t(BOREAS_UB_STATE_PLANES) * f.n());
    native_underbrush_vertices(f.planes(), planes.data(), kUnderbrushCamera, f.lod.data(),
                               f.native_vertices.data(), f.native_counts.data());
    const double diff = max_difference(got, f.native_vertices);
    std::printf("underbrush %d: CL strips vs native twin, max |difference| %.3g (m or unit)\n",
                f.n(), diff);
    f.vertices_error = got_counts != f.native_counts
                           ? std::string("CL and native strip vertex counts differ")
                           : disagreement("strips", diff, "(m or unit)");
  }
  if (!f.vertices_error.empty()) {
    state.SkipWithError(f.vertices_error.c_str());
    return;
  }
  auto launch = [&] { return underbrush_vertices_launch(*rt, f); };
  warm_up(*rt, launch);
  time_cl_span(state, *rt, "BM_UnderbrushVertices", vertices, kBytesPerUnderbrushVertex,
               std::to_string(components), [&] {
                 ClSpan span;
                 span.first = span.last = launch();
                 return span;
               });
}

void underbrush_vertices_native(benchmark::State& state, int components) {
  UnderbrushFixture& f = underbrush_fixture(components);
  const float* planes = f.native_state[f.native_current].data();
  auto run = [&] {
    native_underbrush_vertices(f.planes(), planes, kUnderbrushCamera, f.lod.data(),
                               f.native_vertices.data(), f.native_counts.data());
  };
  run();
  time_native(state, "BM_UnderbrushVertices", int64_t(f.n()) * kUnderbrushStrip,
              kBytesPerUnderbrushVertex, run, std::to_string(components));
}

// ---- imported trees (boreas_mesh_wind_branches, boreas_mesh_wind_trunk and _leaves) ----

// A tree of tapered tubes as an exporter writes one (one connected run of triangles per
// branch, starting inside its parent, seam vertices duplicated), the idea of
// tests/host/mesh_wind/tube_trees.h scaled up: a stem, limbs on it, twigs on each limb,
// shoots on each twig, and quad leaves (4 vertices, 2 triangles) along every shoot.
struct MeshTreeShape {
  int limbs, twigs, shoots, leaves;  // limbs on the stem, twigs per limb, shoots per twig,
                                     // leaves per shoot
  int sides[4], rings[4];            // per level: stem, limb, twig, shoot
};

// A small game tree (~4.6 k trunk triangles, 480 leaves), and the seed's tree: 70,272
// trunk triangles (~70 k) and 12,000 leaves.
constexpr MeshTreeShape kMeshTreeShapes[] = {
    {4, 4, 3, 10, {16, 8, 6, 5}, {16, 8, 6, 5}},
    {12, 10, 4, 25, {32, 12, 8, 6}, {48, 20, 8, 8}},
};

// Steps both sides take from rest before the second twin check (the first is the first
// step, where every branch starts at the wind).
constexpr int kMeshCheckSteps = 30;
constexpr uint64_t kMeshTreeSeed = 1;

int mesh_tree_triangles(const MeshTreeShape& s) {
  const int tubes[4] = {1, s.limbs, s.limbs * s.twigs, s.limbs * s.twigs * s.shoots};
  int triangles = 0;
  for (int l = 0; l < 4; ++l) triangles += tubes[l] * 2 * s.sides[l] * s.rings[l];
  return triangles;
}

struct Vec3d {
  double x = 0.0, y = 0.0, z = 0.0;
};
Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d operator*(double s, Vec3d a) { return {s * a.x, s * a.y, s * a.z}; }
Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3d normalized(Vec3d a) { return (1.0 / std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z)) * a; }

// A unit direction from azimuth (about +Y, from +X towards +Z) and elevation, radians.
Vec3d mesh_direction(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
          std::cos(elevation) * std::sin(azimuth)};
}

struct BenchTube {
  Vec3d base, dir{0.0, 1.0, 0.0}, a, b;  // dir unit; a, b: unit, normal to dir and each other
  double length = 1.0, r_base = 0.1, r_tip = 0.05;
  double azimuth = 0.0;
  Vec3d point(double u) const { return base + (u * length) * dir; }
  double radius(double u) const { return r_base + u * (r_tip - r_base); }
};

void push3(std::vector<float>& v, Vec3d p) {
  v.push_back(float(p.x));
  v.push_back(float(p.y));
  v.push_back(float(p.z));
}

// rings + 1 rings of sides + 1 vertices (the seam's first and last coincide), open ends.
BenchTube add_bench_tube(impl::MeshPart& part, Vec3d base, Vec3d dir, double length, double r_base,
                         double r_tip, double azimuth, int sides, int rings) {
  BenchTube t;
  t.base = base;
  t.dir = normalized(dir);
  t.length = length;
  t.r_base = r_base;
  t.r_tip = r_tip;
  t.azimuth = azimuth;
  const Vec3d ref = std::abs(t.dir.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
  t.a = normalized(cross(t.dir, ref));
  t.b = cross(t.dir, t.a);
  const uint32_t first = uint32_t(part.vertex_count());
  for (int i = 0; i <= rings; ++i) {
    const double u = double(i) / rings;
    for (int j = 0; j <= sides; ++j) {
      const double phi = 2.0 * M_PI * (j % sides) / sides;
      const Vec3d n = std::cos(phi) * t.a + std::sin(phi) * t.b;
      push3(part.positions, t.point(u) + t.radius(u) * n);
      push3(part.normals, n);
      part.uvs.push_back(float(j) / float(sides));
      part.uvs.push_back(float(u));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      const uint32_t v00 = first + uint32_t(i * (sides + 1) + j), v01 = v00 + 1;
      const uint32_t v10 = v00 + uint32_t(sides + 1), v11 = v10 + 1;
      part.indices.insert(part.indices.end(), {v00, v10, v11, v00, v11, v01});
    }
  return t;
}

// The bench tree of a shape, model space (m, Y up): a 14 m stem; limbs spread by the
// golden angle between 30 % and 90 % of its height, shorter towards the top; twigs and
// shoots alternating left and right along their parent; leaves 10 cm x 5 cm whose base
// sits on the shoot's surface, turned around it by the golden angle, pointing outwards and
// towards the shoot's tip.
impl::MeshModel bench_mesh_tree(const MeshTreeShape& s) {
  constexpr double kGolden = 2.39996322972865332;
  impl::MeshModel m;
  impl::MeshPart& trunk = m.trunk;
  impl::MeshPart& leaves = m.leaves;
  const BenchTube stem =
      add_bench_tube(trunk, {}, {0, 1, 0}, 14.0, 0.35, 0.1, 0.0, s.sides[0], s.rings[0]);
  for (int i = 0; i < s.limbs; ++i) {
    const double at = 0.3 + 0.6 * (i + 0.5) / s.limbs;
    const double azimuth = i * kGolden;
    const BenchTube limb =
        add_bench_tube(trunk, stem.point(at), mesh_direction(azimuth, 0.6), 5.5 - 4.0 * (at - 0.3),
                       0.12, 0.035, azimuth, s.sides[1], s.rings[1]);
    for (int j = 0; j < s.twigs; ++j) {
      const double side = j % 2 == 0 ? 1.0 : -1.0;
      const double twig_at = 0.2 + 0.75 * (j + 0.5) / s.twigs;
      const double twig_azimuth = limb.azimuth + 0.8 * side;
      const BenchTube twig =
          add_bench_tube(trunk, limb.point(twig_at), mesh_direction(twig_azimuth, 0.45), 1.8, 0.03,
                         0.012, twig_azimuth, s.sides[2], s.rings[2]);
      for (int k = 0; k < s.shoots; ++k) {
        const double shoot_side = k % 2 == 0 ? 1.0 : -1.0;
        const double shoot_at = 0.3 + 0.65 * (k + 0.5) / s.shoots;
        const double shoot_azimuth = twig.azimuth + 0.7 * shoot_side;
        const BenchTube shoot =
            add_bench_tube(trunk, twig.point(shoot_at), mesh_direction(shoot_azimuth, 0.3), 0.7,
                           0.011, 0.004, shoot_azimuth, s.sides[3], s.rings[3]);
        for (int q = 0; q < s.leaves; ++q) {
          const double u = 0.15 + 0.85 * (q + 0.5) / s.leaves;
          const double phi = q * kGolden;
          const Vec3d out = std::cos(phi) * shoot.a + std::sin(phi) * shoot.b;
          const Vec3d p = shoot.point(u) + shoot.radius(u) * out;
          const Vec3d along = normalized(out + 0.6 * shoot.dir);
          const Vec3d width = 0.025 * normalized(cross(along, out));
          const Vec3d normal = normalized(cross(width, along));
          const Vec3d corners[4] = {p - width, p + width, p + width + 0.1 * along,
                                    p - width + 0.1 * along};
          const uint32_t first = uint32_t(leaves.vertex_count());
          for (const Vec3d& c : corners) {
            push3(leaves.positions, c);
            push3(leaves.normals, normal);
            leaves.uvs.insert(leaves.uvs.end(), {0.0f, 0.0f});
          }
          leaves.indices.insert(leaves.indices.end(),
                                {first, first + 1, first + 2, first, first + 2, first + 3});
        }
      }
    }
  }
  return m;
}

// The model of each shape, built once for the whole run.
const impl::MeshModel& bench_mesh_model(int shape) {
  static std::map<int, impl::MeshModel> models;
  auto it = models.find(shape);
  if (it == models.end()) it = models.emplace(shape, bench_mesh_tree(kMeshTreeShapes[shape])).first;
  return it->second;
}

// The tree as a world places it: default parameters (boreas_default_mesh_tree_def), at
// the grid's middle on the ground, preprocessed with compute_mesh_wind and its noise.
std::shared_ptr<impl::MeshTreeInstance> bench_mesh_instance(int shape) {
  auto tree = std::make_shared<impl::MeshTreeInstance>();
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = "bench tube tree";
  def.seed = kMeshTreeSeed;
  tree->params = impl::checked_mesh_tree_def(def);
  tree->model = bench_mesh_model(shape);
  tree->data = impl::compute_mesh_wind(tree->model, kMeshTreeSeed);
  tree->noise =
      impl::make_noise_texture(BOREAS_MW_NOISE_SIZE, double(def.noise_beta), kMeshTreeSeed);
  tree->key = 1;
  return tree;
}

// Compulsory traffic per vertex, bytes read + written: a trunk vertex reads its rest
// position and 4 weights (28) and its branch (4) and writes its position (12); a leaf
// vertex reads its rest position, normal and tip distance (28) and its leaf (4), writes
// position and normal (24), and shares its leaf's row (10 floats: petiole, axis and
// weights; and its branch: 44 B) with the leaf's other 3 vertices. Branch rows, tree rows
// and the noise textures (512 KiB per tree) are left out, as cached.
constexpr double kBytesPerTrunkVertex = 44.0;
constexpr double kBytesPerLeafVertex = 56.0 + 44.0 / 4.0;

// Everything the mesh-wind rows of one shape share: made by the first of them. The CL
// side is a MeshTreeBatch holding the tree, stepped with each kernel's event kept; it is
// checked once against the native twin.
struct MeshWindFixture : Fixture {
  TreeWindScene wind;  // the trees' wind: the scene's four waves over a calm grid
  std::shared_ptr<impl::MeshTreeInstance> tree;
  NativeMeshTrees native;
  double native_time = 0.0;
  int64_t vertices = 0;  // trunk + leaf vertices
  double bytes_per_vertex = 0.0;
  // CL
  bool cl_made = false;
  std::string cl_error;
  double twin_difference = 0.0;
  std::unique_ptr<impl::MeshTreeBatch> batch;
  cl::Buffer waves, grid;
  double cl_time = 0.0;
};

MeshWindFixture& mesh_wind_fixture(int shape) {
  return fixture<MeshWindFixture>("meshwind/" + std::to_string(shape), [&] {
    auto f = std::make_unique<MeshWindFixture>();
    f->tree = bench_mesh_instance(shape);
    f->native = native_mesh_layout({f->tree.get()});
    const double nv = f->native.nv, nlv = f->native.nlv;
    f->vertices = int64_t(f->native.nv) + f->native.nlv;
    f->bytes_per_vertex = (kBytesPerTrunkVertex * nv + kBytesPerLeafVertex * nlv) / (nv + nlv);
    return f;
  });
}

// One CL step of kStepSeconds from the current state, committed at once (commit only
// moves the batch's host-side index); the caller finishes the queue before the next step,
// as the batch's per-step upload requires.
impl::MeshWindStepEvents mesh_wind_launch(MeshWindFixture& f) {
  f.cl_time += kStepSeconds;
  impl::MeshWindStepEvents e;
  f.batch->enqueue_step(kStepSeconds, f.cl_time, f.wind.cl(f.waves, f.grid), &e);
  f.batch->commit();
  return e;
}

// The CL result of the last step as the native twin holds it: trunk positions, then leaf
// positions and normals, then the branches' wind (planar) and the tree's roll.
std::vector<float> mesh_wind_cl_result(MeshWindFixture& f) {
  impl::MeshTreeBatch& batch = *f.batch;
  const uint64_t key = f.tree->key;
  std::vector<float> r;
  for (const boreas_vertex& v : batch.trunk_vertices(key)) r.insert(r.end(), v.position, v.position + 3);
  for (const boreas_vertex& v : batch.leaf_vertices(key)) {
    r.insert(r.end(), v.position, v.position + 3);
    r.insert(r.end(), v.normal, v.normal + 3);
  }
  const std::vector<float> wind = batch.branch_wind(key);
  const size_t nb = wind.size() / 3;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = 0; b < nb; ++b) r.push_back(wind[3 * b + a]);
  const std::vector<float> roll = batch.noise_roll(key);
  r.insert(r.end(), roll.begin(), roll.end());
  return r;
}

std::vector<float> mesh_wind_native_result(const NativeMeshTrees& t) {
  std::vector<float> r = t.trunk_out;
  r.insert(r.end(), t.leaf_out.begin(), t.leaf_out.end());
  r.insert(r.end(), t.state[t.current].begin(), t.state[t.current].end());
  r.insert(r.end(), t.roll[t.current].begin(), t.roll[t.current].end());
  return r;
}

// The CL side, checked against the native twin's after the first step (every branch
// starts at the wind) and after kMeshCheckSteps more (low-passed wind, rolled noise). The
// largest difference is kept for the row's counter.
void make_mesh_wind_cl(impl::Runtime& rt, MeshWindFixture& f) {
  if (f.cl_made) return;
  f.cl_made = true;
  f.waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                   f.wind.device.padded.size() * sizeof(BoreasGpuWave));
  f.grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  f.batch = std::make_unique<impl::MeshTreeBatch>(rt);
  f.batch->add(f.tree, 0.0);
  f.cl_time = 0.0;

  NativeMeshTrees twin = native_mesh_layout({f.tree.get()});
  double time = 0.0;
  for (int s = 0; s <= kMeshCheckSteps; ++s) {
    time += kStepSeconds;
    native_mesh_step(twin, kStepSeconds, time, f.wind.native());
    mesh_wind_launch(f);
    BOREAS_CL_CHECK(rt.queue().finish());
    if (s == 0 || s == kMeshCheckSteps)
      f.twin_difference =
          std::max(f.twin_difference, max_difference(mesh_wind_cl_result(f), mesh_wind_native_result(twin)));
  }
  // How far the twin's vertices moved from rest, so that the differences above can be
  // read against it (a check of vertices that hardly move would prove little).
  double moved = 0.0;
  for (int i = 0; i < twin.nv; ++i)
    for (int a = 0; a < 3; ++a)
      moved = std::max(
          moved, double(std::fabs(twin.trunk_out[size_t(3 * i + a)] -
                                  twin.trunk[size_t(BOREAS_MW_TRUNK_REST + a) * twin.nv + i])));
  for (int i = 0; i < twin.nlv; ++i)
    for (int a = 0; a < 3; ++a)
      moved = std::max(
          moved, double(std::fabs(
                     twin.leaf_out[size_t(6 * i + a)] -
                     twin.leaf_vertices[size_t(BOREAS_MW_LEAF_VERTEX_REST + a) * twin.nlv + i])));
  std::printf(
      "mesh wind %d+%d vertices: CL (MeshTreeBatch) vs native twin (steps 1 and %d), max "
      "|difference| %.3g (m, unit or m/s); vertices moved up to %.3g m per axis\n",
      twin.nv, twin.nlv, kMeshCheckSteps + 1, f.twin_difference, moved);
  f.cl_error = disagreement("mesh-wind steps", f.twin_difference, "(m, unit or m/s)");
}

void mesh_wind_cl(benchmark::State& state, int shape) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  MeshWindFixture& f = mesh_wind_fixture(shape);
  make_mesh_wind_cl(*rt, f);
  if (!f.cl_error.empty()) {
    state.SkipWithError(f.cl_error.c_str());
    return;
  }
  // Warm-up: PoCL compiles each work-group function at its first launch. Finished after
  // each step, as the tree planes' staging must outlive their upload.
  for (int i = 0; i < 3; ++i) {
    mesh_wind_launch(f);
    BOREAS_CL_CHECK(rt->queue().finish());
  }
  // Device time per kernel, summed over the timed iterations: each iteration's events are
  // read at the start of the next (time_cl_span has finished the queue by then).
  double branches = 0.0, trunk = 0.0, leaves = 0.0;
  impl::MeshWindStepEvents last;
  bool pending = false;
  auto take = [&] {
    if (!pending) return;
    branches += event_seconds(last.branches);
    trunk += event_seconds(last.trunk);
    leaves += event_seconds(last.leaves);
    pending = false;
  };
  time_cl_span(state, *rt, "BM_MeshWind", f.vertices, f.bytes_per_vertex,
               std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])), [&] {
                 take();
                 last = mesh_wind_launch(f);
                 pending = true;
                 ClSpan span;
                 span.first = last.branches;
                 span.last = last.leaves;
                 return span;
               });
  take();
  const double steps = double(std::max<int64_t>(state.iterations(), 1));
  state.counters["branches_us"] = 1e6 * branches / steps;
  state.counters["trunk_us"] = 1e6 * trunk / steps;
  state.counters["leaves_us"] = 1e6 * leaves / steps;
  state.counters["vs_native_max_diff"] = f.twin_difference;
}

void mesh_wind_native(benchmark::State& state, int shape) {
  MeshWindFixture& f = mesh_wind_fixture(shape);
  const NativeTreeWind wind = f.wind.native();
  double passes[3] = {0.0, 0.0, 0.0};  // wall time per pass, as the CL row's per kernel
  auto run = [&] {
    f.native_time += kStepSeconds;
    native_mesh_step(f.native, kStepSeconds, f.native_time, wind, passes);
  };
  run();
  passes[0] = passes[1] = passes[2] = 0.0;
  time_native(state, "BM_MeshWind", f.vertices, f.bytes_per_vertex, run,
              std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])));
  const double steps = double(std::max<int64_t>(state.iterations(), 1));
  state.counters["branches_us"] = 1e6 * passes[0] / steps;
  state.counters["trunk_us"] = 1e6 * passes[1] / steps;
  state.counters["leaves_us"] = 1e6 * passes[2] / steps;
}

// The one-time preprocessing of an imported tree (compute_mesh_wind: hierarchy, weights,
// phases, motion vectors, leaf assignment), one thread, on the already built mesh; the
// noise texture (make_noise_texture, the other per-tree cost) as a counter.
void mesh_wind_preprocess(benchmark::State& state, int shape) {
  const impl::MeshModel& model = bench_mesh_model(shape);
  const int64_t vertices = int64_t(model.trunk.vertex_count() + model.leaves.vertex_count());
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    impl::MeshWindData data = impl::compute_mesh_wind(model, kMeshTreeSeed);
    benchmark::DoNotOptimize(data.branches.data());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, "BM_MeshWindPreprocess", "native", vertices, 0.0, wall, wall,
         std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape])));
  Clock::time_point noise_start = Clock::now();
  impl::NoiseTexture noise = impl::make_noise_texture(BOREAS_MW_NOISE_SIZE, 2.0, kMeshTreeSeed);
  benchmark::DoNotOptimize(noise.texels.data());
  state.counters["noise_ms"] =
      1e3 * std::chrono::duration<double>(Clock::now() - noise_start).count();
  const impl::MeshWindData data = impl::compute_mesh_wind(model, kMeshTreeSeed);
  state.counters["branches"] = double(data.branches.size());
  state.counters["leaves"] = double(data.leaf_length.size());
  state.counters["levels"] = double(data.levels);
  state.counters["orphans"] = double(data.orphans);
}

// ---- BlobTree trees (boreas_blobtree_field; polygonize_blobtree: field, count, emit,
// attributes) ----

// Cubic grids (blob_grid(model, resolution, cubic)): 128^3 and 256^3 points.
constexpr int kBlobResolutions[] = {128, 256};
// Compulsory traffic per grid point of the field stage: the point's F written. The
// primitives and bin lists (a few hundred KiB) stay in cache.
constexpr double kBytesPerFieldPoint = 4.0;
// How far the native twin may be from the device's field, field units (F is 0 .. ~1):
// both are float with the same polynomials and differ only by rounding order (fma
// contraction in the CL compiler).
constexpr double kBlobAgreement = 1e-5;
// The grid the naive rows warm PoCL up on (it compiles each kernel at its first launch):
// the smallest blob_grid takes, so that the warm-up costs no full naive pass.
constexpr int kBlobWarmUpResolution = 16;

// The tree of the BlobTree rows: quaking aspen seed 1 (bench_tree_models()[0]: 3 levels,
// ~1224 branches), at the origin.
const impl::TreeModel& blob_bench_tree() { return bench_tree_models()[0]; }

// Which branches a row's model has: those make_blobtree keeps (min_radius automatic, half
// a grid cell: the product's case, but on this tree that leaves the trunk alone at 128^3
// and the trunk with its ~10 thickest limbs at 256^3), or every branch (the whole tree's
// ~5900 primitives, the thinnest thickened to 0.9 cells as the product does; the load of
// a tree polygonized whole).
enum class BlobBranches { kAutomatic, kEvery };

// Everything the BlobTree rows of one resolution and model share, made by the first of
// them: the model and grid of blobtree_setup (what make_blobtree polygonizes) from
// boreas_default_blobtree_def() with this resolution, cubic, min_radius automatic (half a
// grid cell) or below every branch; the planes and bins the kernels read; the native twin's field,
// checked once against boreas_bt_field per point and against the device's field; on the
// device, the binned mesh and the buffers of the field kernel's timed launch.
struct BlobTreeFixture : Fixture {
  impl::BlobModel model;
  impl::BlobGrid grid;
  double min_radius = 0.0;  // m
  impl::BlobPlanes planes;
  impl::BlobBins bins;
  double bins_seconds = 0.0;  // blob_planes + blob_bins, best of 3 (host; polygonize_blobtree
                              // runs both)
  std::vector<float> native_field;
  std::string native_error;         // the SIMD twin is not boreas_bt_field
  double per_point_difference = 0;  // SIMD twin vs boreas_bt_field per point
  // CL
  bool cl_made = false;
  std::string cl_error;
  double twin_difference = 0.0;  // native twin vs sample_blobtree_field
  impl::BlobMesh mesh;           // polygonize_blobtree, binned
  impl::BlobScratch scratch;     // the field grid kept between calls, as a world keeps it
  cl::Buffer prims, ints, cuts, bin_first, bin_items, field;
  double binned_seconds = 0.0;  // per polygonize_blobtree in the binned row (0: not run)
};

BlobTreeFixture& blobtree_fixture(int resolution, BlobBranches branches) {
  const std::string key = "blobtree/" + std::to_string(resolution) +
                          (branches == BlobBranches::kEvery ? "/every" : "/automatic");
  return fixture<BlobTreeFixture>(key, [&] {
    auto f = std::make_unique<BlobTreeFixture>();
    boreas_blobtree_def def = boreas_default_blobtree_def();
    def.resolution = resolution;
    def.cubic = 1;
    impl::BlobTreeParams params = impl::checked_blobtree_def(def);
    // Every branch: a radius below any branch's (0 would mean the automatic half cell).
    if (branches == BlobBranches::kEvery) params.options.min_radius = 1e-6;
    impl::BlobSetup setup = impl::blobtree_setup(blob_bench_tree(), glm::dvec3(0.0), params);
    f->model = std::move(setup.model);
    f->grid = setup.grid;
    f->min_radius = setup.min_radius;
    f->bins_seconds = 1e30;
    for (int i = 0; i < 3; ++i) {
      Clock::time_point start = Clock::now();
      f->planes = impl::blob_planes(f->model, f->grid.origin);
      f->bins = impl::blob_bins(f->model, f->grid);
      f->bins_seconds =
          std::min(f->bins_seconds, std::chrono::duration<double>(Clock::now() - start).count());
    }

    f->native_field.assign(size_t(f->grid.points()), 0.0f);
    native_blobtree_field(f->planes, f->bins, f->grid, f->native_field.data());
    std::vector<float> per_point(f->native_field.size());
    native_blobtree_field_per_point(f->planes, f->bins, f->grid, per_point.data());
    f->per_point_difference = max_difference(f->native_field, per_point);
    if (f->per_point_difference > kBlobAgreement) {
      f->native_error =
          "the native twin (bench/native_blobtree.cpp) differs from "
          "boreas_bt_field by up to " +
          std::to_string(f->per_point_difference) +
          ": follow cl/shared/blobtree_field.h's walk there";
    }
    return f;
  });
}

// The counters every BlobTree row reports (triangles and vertices once the device made
// the mesh).
void blob_counters(benchmark::State& state, const BlobTreeFixture& f) {
  state.counters["points"] = double(f.grid.points());
  state.counters["primitives"] = double(f.model.primitives.size());
  state.counters["bin_items"] = double(f.bins.items.size());
  state.counters["min_radius_mm"] = 1e3 * f.min_radius;
  if (f.cl_made) {
    state.counters["triangles"] = double(f.mesh.triangle_count());
    state.counters["vertices"] = double(f.mesh.vertex_count());
  }
}

// The field kernel's launch as polygonize_blobtree's stage 1 makes it (its arguments, one
// work-group per bin, or a half or quarter of one where the kernel allows fewer than 512
// work-items), in one launch over the whole grid instead of slabs. make_blobtree_cl checks
// that it computes what sample_blobtree_field does.
cl::Event blobtree_field_launch(impl::Runtime& rt, BlobTreeFixture& f) {
  cl::Kernel& k = rt.kernel("blobtree_field.cl", "boreas_blobtree_field");
  int a = 0;
  BOREAS_CL_CHECK(k.setArg(a++, f.prims));
  BOREAS_CL_CHECK(k.setArg(a++, f.ints));
  BOREAS_CL_CHECK(k.setArg(a++, f.planes.n));
  BOREAS_CL_CHECK(k.setArg(a++, f.bin_first));
  BOREAS_CL_CHECK(k.setArg(a++, f.bin_items));
  BOREAS_CL_CHECK(k.setArg(a++, f.bins.bx));
  BOREAS_CL_CHECK(k.setArg(a++, f.bins.by));
  BOREAS_CL_CHECK(k.setArg(a++, f.cuts));
  BOREAS_CL_CHECK(k.setArg(a++, f.planes.cut_count));
  BOREAS_CL_CHECK(k.setArg(a++, float(f.grid.cell)));
  BOREAS_CL_CHECK(k.setArg(a++, f.grid.nx));
  BOREAS_CL_CHECK(k.setArg(a++, f.grid.ny));
  BOREAS_CL_CHECK(k.setArg(a++, 0));  // z0: the whole grid
  BOREAS_CL_CHECK(k.setArg(a++, f.field));
  const size_t allowed = k.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(rt.device().device);
  const size_t local_z = allowed >= 512 ? 8 : (allowed >= 256 ? 4 : (allowed >= 128 ? 2 : 1));
  const size_t local_y = allowed >= 64 ? 8 : 4;
  cl::Event e;
  BOREAS_CL_CHECK(rt.queue().enqueueNDRangeKernel(
      k, cl::NullRange, cl::NDRange(f.grid.nx, f.grid.ny, f.grid.nz),
      cl::NDRange(BOREAS_BT_BIN, local_y, local_z), nullptr, &e));
  return e;
}

// The device side, once: the binned mesh (which also has PoCL compile the binned path's
// kernels), the product's field (sample_blobtree_field) compared with the native twin's,
// and the timed launch's buffers, its result checked identical to the product's.
void make_blobtree_cl(impl::Runtime& rt, BlobTreeFixture& f) {
  if (f.cl_made) return;
  impl::PolygonizeOptions first;
  first.scratch = &f.scratch;
  f.mesh = impl::polygonize_blobtree(rt, f.model, f.grid, first);
  const std::vector<float> device = impl::sample_blobtree_field(rt, f.model, f.grid);
  f.twin_difference = max_difference(f.native_field, device);
  f.prims =
      upload(rt, CL_MEM_READ_ONLY, f.planes.prims.data(), f.planes.prims.size() * sizeof(float));
  f.ints =
      upload(rt, CL_MEM_READ_ONLY, f.planes.ints.data(), f.planes.ints.size() * sizeof(int32_t));
  f.cuts = upload(rt, CL_MEM_READ_ONLY, f.planes.cuts.data(), f.planes.cuts.size() * sizeof(float));
  f.bin_first =
      upload(rt, CL_MEM_READ_ONLY, f.bins.first.data(), f.bins.first.size() * sizeof(int32_t));
  f.bin_items = rt.buffer(CL_MEM_READ_ONLY, f.bins.items.size() * sizeof(int32_t));
  rt.upload(f.bin_items, f.bins.items);
  f.field = rt.buffer(CL_MEM_READ_WRITE, size_t(f.grid.points()) * sizeof(float));
  blobtree_field_launch(rt, f);
  std::vector<float> launched(device.size());
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(f.field, CL_TRUE, 0, launched.size() * sizeof(float),
                                               launched.data()));
  f.cl_made = true;
  std::printf(
      "blobtree %dx%dx%d: %zu primitives (min_radius %.3g m), %zu bin items, %zu triangles; "
      "native twin vs device field max |difference| %.3g, vs boreas_bt_field per point %.3g\n",
      f.grid.nx, f.grid.ny, f.grid.nz, f.model.primitives.size(), f.min_radius, f.bins.items.size(),
      f.mesh.triangle_count(), f.twin_difference, f.per_point_difference);
  if (const double d = max_difference(launched, device); d != 0.0) {
    f.cl_error = "the bench's field launch differs from sample_blobtree_field by up to " +
                 std::to_string(d) + ": follow polygonizer.cpp's run_field";
  } else {
    f.cl_error = disagreement("fields", f.twin_difference, "(field units)", kBlobAgreement);
  }
}

void blobtree_field_native(benchmark::State& state, int resolution, BlobBranches branches) {
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  if (!f.native_error.empty()) {
    state.SkipWithError(f.native_error.c_str());
    return;
  }
  time_native(state, "BM_BlobTreeField", f.grid.points(), kBytesPerFieldPoint,
              [&] { native_blobtree_field(f.planes, f.bins, f.grid, f.native_field.data()); });
  blob_counters(state, f);
}

void blobtree_field_cl(benchmark::State& state, int resolution, BlobBranches branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  make_blobtree_cl(*rt, f);
  if (!f.cl_error.empty()) {
    state.SkipWithError(f.cl_error.c_str());
    return;
  }
  auto launch = [&] { return blobtree_field_launch(*rt, f); };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_BlobTreeField", f.grid.points(), kBytesPerFieldPoint, launch);
  blob_counters(state, f);
  state.counters["vs_native_max_diff"] = f.twin_difference;
}

// Where polygonize_blobtree's time goes, ms, best of 3 untimed calls with a progress
// callback: the polygonizer finishes the queue before each report (every field slab, the
// counts, the triangles, the end), so the stages' wall times can be told apart: field
// (with the upload, blob_bins and the field buffer), count (with the counts read back and
// scanned), emit, attributes (with the mesh read back).
void blobtree_stage_counters(benchmark::State& state, impl::Runtime& rt, BlobTreeFixture& f) {
  const char* const stages[] = {"field", "count", "triangles", "done"};
  const char* const counters[] = {"field_ms", "count_ms", "emit_ms", "attributes_ms"};
  double best[4] = {1e30, 1e30, 1e30, 1e30};
  for (int call = 0; call < 3; ++call) {
    double at[4] = {0.0, 0.0, 0.0, 0.0};  // when each stage's last report came, s
    Clock::time_point start = Clock::now();
    impl::PolygonizeOptions options;
    options.scratch = &f.scratch;
    options.progress = [&](double, const char* stage) {
      for (int i = 0; i < 4; ++i)
        if (std::string(stage) == stages[i])
          at[i] = std::chrono::duration<double>(Clock::now() - start).count();
    };
    impl::polygonize_blobtree(rt, f.model, f.grid, options);
    for (int i = 0; i < 4; ++i) best[i] = std::min(best[i], at[i] - (i > 0 ? at[i - 1] : 0.0));
  }
  for (int i = 0; i < 4; ++i) state.counters[counters[i]] = 1e3 * best[i];
}

// The whole of polygonize_blobtree, as make_blobtree calls it in a world (upload, bins,
// the five stages, the mesh read back; the field grid's buffer kept from the previous
// call), wall time: it keeps no events, so there is no kernel time.
void blobtree_polygonize_cl(benchmark::State& state, int resolution, BlobBranches branches,
                            bool naive) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  BlobTreeFixture& f = blobtree_fixture(resolution, branches);
  make_blobtree_cl(*rt, f);
  if (!f.cl_error.empty()) {
    state.SkipWithError(f.cl_error.c_str());
    return;
  }
  impl::PolygonizeOptions options;
  options.naive = naive;
  options.scratch = &f.scratch;
  if (naive) {
    // The binned path is warm (make_blobtree_cl); the naive field kernel is not.
    impl::polygonize_blobtree(*rt, f.model, impl::blob_grid(f.model, kBlobWarmUpResolution, true),
                              options);
  }
  impl::BlobMesh mesh;
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    mesh = impl::polygonize_blobtree(*rt, f.model, f.grid, options);
    benchmark::DoNotOptimize(mesh.indices.data());
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, "BM_BlobTreePolygonize", "cl", f.grid.points(), 0.0, wall, 0.0);
  state.counters.erase("kernel_items/s");  // no kernel time: "-" in results-table.py
  state.counters.erase("kernel_bytes/s");
  blob_counters(state, f);
  state.counters["bins_ms"] = 1e3 * f.bins_seconds;
  const double per_call = wall / double(std::max<int64_t>(state.iterations(), 1));
  if (!naive) {
    f.binned_seconds = per_call;
    blobtree_stage_counters(state, *rt, f);
    return;
  }
  // Naive and binned evaluate the same terms in the same order, so the meshes are equal.
  double diff = -1.0;  // -1: the vertex or triangle counts differ
  if (mesh.positions.size() == f.mesh.positions.size() && mesh.indices == f.mesh.indices)
    diff = max_difference(mesh.positions, f.mesh.positions);
  state.counters["vs_binned_max_diff"] = diff;
  state.counters["binned_speedup"] = f.binned_seconds > 0 ? per_call / f.binned_seconds : 0.0;
}

// ---- lagged versus exact (print_tree_lag_error) ----

// The scene's waves at time t, as a world's device copy would hold them: steady (the
// phases of t = 0), or gusty: crests moving downwind at 6 m/s and every amplitude swelling
// and dropping with two incommensurate gust periods (3.1 s and 1.3 s), between 0.2x and
// 1.8x.
std::vector<BoreasGpuWave> lag_error_waves(double t, bool gusty) {
  std::vector<BoreasGpuWave> waves = scene_waves();
  if (!gusty) return waves;
  const double kPi = 3.14159265358979324;
  const double gust =
      1.0 + 0.5 * std::sin(2.0 * kPi * t / 3.1) + 0.3 * std::sin(2.0 * kPi * t / 1.3 + 1.0);
  for (BoreasGpuWave& w : waves) {
    double phase = double(w.phase_cycles) - 6.0 * t * double(w.cycles_per_meter);
    w.phase_cycles = float(phase - std::floor(phase));
    w.amplitude = float(double(w.amplitude) * gust);
  }
  return waves;
}

}  // namespace

int print_tree_lag_error(int steps) {
  ClState& cl = cl_state();
  if (!cl.runtime) {
    std::fprintf(stderr, "no OpenCL device: %s\n", cl.error.c_str());
    return 1;
  }
  impl::Runtime& rt = *cl.runtime;
  const TreeWindScene scene;
  cl::Buffer grid =
      upload(rt, CL_MEM_READ_ONLY, scene.cells.data(), scene.cells.size() * sizeof(float));
  std::printf(
      "| wind | response | steps | max tip error | RMS tip error | max tip error, last second | "
      "RMS tip error, last second | max tip error (m) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  double mean_height = 0.0;
  int branch_total = 0;
  for (boreas_tree_response response : {BOREAS_TREE_QUASI_STATIC, BOREAS_TREE_DAMPED}) {
    for (bool gusty : {false, true}) {
      // One of each bench tree, side by side, in a lagged and an exact batch.
      const auto trees = bench_trees(0, scene.def, response);
      auto lagged = leafless_batch(rt, BOREAS_TREE_LAGGED, trees);
      auto exact = leafless_batch(rt, BOREAS_TREE_EXACT, trees);
      const int n = exact->stride();
      // Each branch's tree, and each tree's height at rest (highest control point above
      // its base).
      std::vector<int> tree_of(size_t(n), -1);
      std::vector<double> height(trees.size(), 0.0);
      const std::vector<float> rest = exact->read_state();
      for (size_t k = 0; k < trees.size(); ++k) {
        const impl::TreeModel& m = trees[k]->model;
        for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
          const int first = exact->level_first(trees[k]->key, l);
          for (int b = 0; b < m.level_begin[l + 1] - m.level_begin[l]; ++b) {
            tree_of[size_t(first + b)] = int(k);
            for (int c = 0; c < 4; ++c)
              height[k] = std::max(height[k], double(rest[size_t(3 * c + 1) * n + first + b]) -
                                                  trees[k]->params.position[1]);
          }
        }
      }
      mean_height = 0.0;
      for (double h : height) mean_height += h / double(height.size());
      branch_total = exact->branch_count();
      DeviceWaves device = device_waves(scene.waves);
      cl::Buffer waves = upload(rt, CL_MEM_READ_WRITE, device.padded.data(),
                                device.padded.size() * sizeof(BoreasGpuWave));
      impl::TreeWindInput in;
      in.waves = &waves;
      in.wave_count = int(device.padded.size());
      in.wave_slots = device.slots;
      in.grid = &grid;
      in.grid_layout = scene.g;
      const int last_second = std::max(steps - int(std::lround(1.0 / kStepSeconds)), 0);
      double max_rel = 0.0, sum_sq = 0.0, max_abs = 0.0, late_max = 0.0, late_sum_sq = 0.0;
      int64_t count = 0, late_count = 0;
      for (int s = 1; s <= steps; ++s) {
        DeviceWaves now = device_waves(lag_error_waves(s * kStepSeconds, gusty));
        BOREAS_CL_CHECK(rt.queue().enqueueWriteBuffer(
            waves, CL_TRUE, 0, now.padded.size() * sizeof(BoreasGpuWave), now.padded.data()));
        lagged->enqueue_step(kStepSeconds, in);
        exact->enqueue_step(kStepSeconds, in);
        BOREAS_CL_CHECK(rt.queue().finish());
        lagged->commit();
        exact->commit();
        const std::vector<float> a = lagged->read_state(), b = exact->read_state();
        for (int i = 0; i < n; ++i) {
          if (tree_of[size_t(i)] < 0) continue;  // a root
          double d2 = 0.0;
          for (int c = 0; c < 3; ++c) {
            const size_t k = size_t(BOREAS_TREE_STATE_P3 + c) * n + i;
            d2 += double(a[k] - b[k]) * double(a[k] - b[k]);
          }
          const double h = height[size_t(tree_of[size_t(i)])];
          const double rel = std::sqrt(d2) / h;
          max_rel = std::max(max_rel, rel);
          max_abs = std::max(max_abs, std::sqrt(d2));
          sum_sq += rel * rel;
          ++count;
          if (s > last_second) {
            late_max = std::max(late_max, rel);
            late_sum_sq += rel * rel;
            ++late_count;
          }
        }
      }
      std::printf(
          "| %s | %s | %d | %.3g %% | %.3g %% | %.3g %% | %.3g %% | %.3g |\n",
          gusty ? "gusty" : "steady", response == BOREAS_TREE_DAMPED ? "damped" : "quasi-static",
          steps, 100.0 * max_rel, 100.0 * std::sqrt(sum_sq / double(std::max<int64_t>(count, 1))),
          100.0 * late_max,
          100.0 * std::sqrt(late_sum_sq / double(std::max<int64_t>(late_count, 1))), max_abs);
      std::fflush(stdout);
    }
  }
  std::printf(
      "\n%d trees (%d branches), mean height %.3g m; errors are |P3 lagged - P3 exact| "
      "over every branch and step, relative to the branch's tree height.\n",
      int(bench_tree_models().size()), branch_total, mean_height);
  return 0;
}

namespace {

void add(const std::string& name, std::function<void(benchmark::State&)> body) {
  // Real time everywhere: CL work runs on PoCL's threads, native work on OpenMP's, so the
  // main thread's CPU time says nothing about either.
  // A failing OpenCL call throws; the row then reports the error instead of ending the run.
  auto guarded = [body = std::move(body)](benchmark::State& state) {
    try {
      body(state);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
    }
  };
  benchmark::RegisterBenchmark(name.c_str(), std::move(guarded))
      ->UseRealTime()
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

void register_benchmarks() {
  for (int n : kCopySizes) {
    add("BM_CopyBandwidth/native/" + std::to_string(n), [n](auto& s) { copy_native(s, n); });
    add("BM_CopyBandwidth/cl/" + std::to_string(n), [n](auto& s) { copy_cl(s, n); });
  }
  for (int n : kSampleSizes) {
    add("BM_WindSineSum/native/" + std::to_string(n), [n](auto& s) { sine_sum_native(s, n); });
    add("BM_WindSineSum/cl/" + std::to_string(n), [n](auto& s) { sine_sum_cl(s, n); });
  }
  for (const auto& side : kSlabSides) {
    const int nx = side[0], nz = side[1];
    const std::string columns = std::to_string(int64_t(nx) * nz);
    add("BM_WindSineSlab/native/" + columns, [=](auto& s) { sine_slab_native(s, nx, nz); });
    add("BM_WindSineSlab/cl/" + columns, [=](auto& s) { sine_slab_cl(s, nx, nz); });
  }
  for (const auto& size : kGridSizes) {
    const std::string cells = std::to_string(int64_t(size[0]) * size[1] * size[2]);
    add("BM_WindGridStep/native/" + cells, [&size](auto& s) { grid_step_native(s, size); });
    add("BM_WindGridStep/cl/" + cells, [&size](auto& s) { grid_step_cl(s, size); });
  }
  for (int n : kTreeBranchCounts) {
    const std::string branches = std::to_string(n);
    for (bool exact : {false, true}) {
      const std::string mode = exact ? "/exact" : "/lagged";
      add("BM_TreeStep/native/" + branches + mode,
          [=](auto& s) { tree_step_native(s, n, exact); });
      add("BM_TreeStep/cl/" + branches + mode, [=](auto& s) { tree_step_cl(s, n, exact); });
    }
    add("BM_Deform/native/" + branches, [=](auto& s) { deform_native(s, n); });
    add("BM_Deform/cl/" + branches, [=](auto& s) { deform_cl(s, n); });
    if (n == kTreeLeafBatch) {
      add("BM_TreeLeaves/native/" + branches, [=](auto& s) { leaves_native(s, n); });
      add("BM_TreeLeaves/cl/" + branches, [=](auto& s) { leaves_cl(s, n); });
    }
  }
  for (int n : kUnderbrushSizes) {
    const std::string components = std::to_string(n);
    add("BM_UnderbrushStep/native/" + components, [=](auto& s) { underbrush_step_native(s, n); });
    add("BM_UnderbrushStep/cl/" + components, [=](auto& s) { underbrush_step_cl(s, n); });
    if (std::find(std::begin(kUnderbrushVertexSizes), std::end(kUnderbrushVertexSizes), n) !=
        std::end(kUnderbrushVertexSizes)) {
      add("BM_UnderbrushVertices/native/" + components,
          [=](auto& s) { underbrush_vertices_native(s, n); });
      add("BM_UnderbrushVertices/cl/" + components, [=](auto& s) { underbrush_vertices_cl(s, n); });
    }
  }
  for (int shape = 0; shape < int(std::size(kMeshTreeShapes)); ++shape) {
    const std::string triangles = std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape]));
    add("BM_MeshWind/native/" + triangles, [=](auto& s) { mesh_wind_native(s, shape); });
    add("BM_MeshWind/cl/" + triangles, [=](auto& s) { mesh_wind_cl(s, shape); });
  }
  for (int shape = 0; shape < int(std::size(kMeshTreeShapes)); ++shape) {
    const std::string triangles = std::to_string(mesh_tree_triangles(kMeshTreeShapes[shape]));
    add("BM_MeshWindPreprocess/native/" + triangles,
        [=](auto& s) { mesh_wind_preprocess(s, shape); });
  }
  // Variants: binned and naive (every primitive at every point) on the model make_blobtree
  // builds; all_branches: binned on every branch (naive there would take minutes). A
  // naive iteration at 256^3 takes 10-20 s, so Google Benchmark runs one (->Iterations()
  // would add "/iterations:1" to the name).
  for (int resolution : kBlobResolutions) {
    const std::string points = std::to_string(int64_t(resolution) * resolution * resolution);
    for (BlobBranches branches : {BlobBranches::kAutomatic, BlobBranches::kEvery}) {
      const std::string variant = branches == BlobBranches::kEvery ? "/all_branches" : "/binned";
      add("BM_BlobTreeField/native/" + points + variant,
          [=](auto& s) { blobtree_field_native(s, resolution, branches); });
      add("BM_BlobTreeField/cl/" + points + variant,
          [=](auto& s) { blobtree_field_cl(s, resolution, branches); });
      add("BM_BlobTreePolygonize/cl/" + points + variant,
          [=](auto& s) { blobtree_polygonize_cl(s, resolution, branches, false); });
      if (branches == BlobBranches::kAutomatic) {
        add("BM_BlobTreePolygonize/cl/" + points + "/naive",
            [=](auto& s) { blobtree_polygonize_cl(s, resolution, branches, true); });
      }
    }
  }
}

std::string cl_device_description() {
  ClState& cl = cl_state();
  if (!cl.runtime) return "none (" + cl.error + ")";
  const impl::Device& d = cl.runtime->device();
  return d.name + " (" + d.platform_version + ", driver " + d.driver_version + ", " +
         std::to_string(d.compute_units) + " compute units, fast math " +
         (d.uses_fast_math() ? "on" : "off") + ")";
}

int native_threads() { return native_thread_count(); }

}  // namespace boreas::bench
