// boreas benchmarks: the harness every suite of boreas_bench shares (bench_*.cpp, one per
// feature): the OpenCL runtime, the timing loops and counters of a row, the CL-versus-native
// checks, uploads, registration, and the trees and wind that several suites stand in.
//
// The benchmark pairs, each OpenCL kernel beside its native twin at the same size
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
//                                       component count, counts vertices; BM_MeshTree and
//                                       BM_MeshTreePreprocess, named by their tree's trunk
//                                       triangle count, count trunk + leaf vertices).
// BM_BlobTreePolygonize times the whole of polygonize_blobtree, which keeps no events: it
// has no kernel_items/s or kernel_bytes/s (no kernel time) and no bytes.
#pragma once

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench_fixture.h"
#include "boreas/boreas.h"
#include "mesh_trees/tree_model.h"
#include "native_trees.h"
#include "runtime/runtime.h"
#include "scene.h"
#include "shared/wind_types.h"
#include "trees/tree_batch.h"
#include "trees/tree_model.h"

// What more than one suite uses, in boreas::bench rather than an anonymous namespace so
// that each suite's file (and tree_lag_error.cpp) can reach it; helpers of one suite stay
// in that suite's file.
namespace boreas::bench {

using Clock = std::chrono::steady_clock;

using bench_support::fixture;
using bench_support::Fixture;

// float4 elements; the largest first, since it is the yardstick of the vs_copy counter.
constexpr int kCopySizes[] = {1 << 22, 1 << 20};

// ---- shared state ----

// One OpenCL runtime for the whole run, so that programs are built once.
struct ClState {
  std::unique_ptr<impl::Runtime> runtime;
  std::string error;  // why there is no runtime
};

ClState& cl_state();

// The device time of one kernel's event (START .. END), s.
double event_seconds(const cl::Event& e);

// Sets the counters of one row (see the top of this file).
void report(benchmark::State& state, const std::string& family, const std::string& kind,
            int64_t items, double bytes_per_item, double wall_seconds, double kernel_seconds,
            const std::string& size_key = "");

// Times the CL launches of one benchmark: launch() enqueues one iteration and returns the
// event of the kernel whose time is reported; each iteration ends in clFinish.
void time_cl(benchmark::State& state, impl::Runtime& rt, const std::string& family, int64_t items,
             double bytes_per_item, const std::function<cl::Event()>& launch);

// Times run() on the host (a native row); size_key as in report().
void time_native(benchmark::State& state, const std::string& family, int64_t items,
                 double bytes_per_item, const std::function<void()>& run,
                 const std::string& size_key = "");

// The device time of work that is more than one kernel launch: from `first` to `last`.
// Kernel events span first START .. last END; markers (`markers` true) span first END ..
// last START, the markers enqueued around the launches (see tree_step_cl, bench_trees.cpp).
struct ClSpan {
  cl::Event first, last;
  bool markers = false;
};

double span_seconds(const ClSpan& s);

// time_cl for launches that return a span; size_key as in report().
void time_cl_span(benchmark::State& state, impl::Runtime& rt, const std::string& family,
                  int64_t items, double bytes_per_item, const std::string& size_key,
                  const std::function<ClSpan()>& launch);

// The largest difference between two float arrays.
double max_difference(const std::vector<float>& a, const std::vector<float>& b);

// How far the CL and native results may be apart, m/s: both are float, with the same
// polynomials; they differ only by rounding order (fma contraction in the CL compiler).
constexpr double kAgreement = 1e-3;

// The runtime, or nullptr once the row is skipped with why there is no OpenCL device.
impl::Runtime* runtime_or_skip(benchmark::State& state);
// The same device with every kernel built at SIMD width 1 (BOREAS_SIMD_WIDTH=1): the form
// the kernels had before issue 22, for "before" rows of kernels the library launches
// itself (the grid step), measured beside the device's width in the same run.
impl::Runtime* width_one_runtime_or_skip(benchmark::State& state);
// Skips the row with `error` when there is one (a fixture that failed to build or whose
// results disagree with its twin's); whether it did.
bool skipped_for(benchmark::State& state, const std::string& error);

// A few launches, finished, before timing (PoCL compiles at the first launch).
void warm_up(impl::Runtime& rt, const std::function<cl::Event()>& launch);

// The waves as World uploads them: padded with silent waves up to the slot count the
// kernels unroll over, and the #define that builds the kernels for that count.
struct DeviceWaves {
  std::vector<BoreasGpuWave> padded;
  int slots = 0;
  std::string define;
};

DeviceWaves device_waves(const std::vector<BoreasGpuWave>& waves);

// A buffer of `bytes` holding `data` (a blocking write).
cl::Buffer upload(impl::Runtime& rt, cl_mem_flags flags, const void* data, size_t bytes);

// Why a row is skipped: "" while the CL and native results agree within `tolerance` (what
// and unit name them in the message).
// BOREAS_BENCH_NO_CHECK=1 skips the check, to time kernel variants under
// BOREAS_KERNEL_DIR that compute something else on purpose.
std::string disagreement(const char* what, double diff, const char* unit = "m/s",
                         double tolerance = kAgreement);

// Registers one row under `name`, reported in real time in `unit`, with a thrown error as
// the row's. manual_time: the body times each iteration itself (State::SetIterationTime),
// for rows whose iterations hold untimed work (BM_Rays: the world's step).
void add(const std::string& name, std::function<void(benchmark::State&)> body,
         benchmark::TimeUnit unit = benchmark::kMicrosecond, bool manual_time = false);

// ---- the trees and their wind (the tree, underbrush, mesh-tree and BlobTree suites and
// print_tree_lag_error) ----

// The trees of every tree row: quaking aspen (the library's default tree, 3 levels,
// ~1224 branches and ~22300 leaves each) grown from seeds 1..kTreeModels at scale 1.
// The one place to change for other species or for hand-built models.
const std::vector<impl::TreeModel>& bench_tree_models();

// Whether BOREAS_BENCH_WIND_SAMPLING asks for interpolated sampling ("exact", the default,
// or "interpolated"; anything else throws).
bool bench_wind_interpolated();

// A calm grid's device buffer (boreas_grid_buffer_floats): zero planes, then the slab of
// these waves' sums at the column centers (native_sine_slab).
std::vector<float> calm_grid_buffer(const BoreasGpuGrid& g,
                                    const std::vector<BoreasGpuWave>& waves);

// The wind the trees stand in: the scene's four waves, steady (the same device copy every
// step), over the sample benchmark's 64 x 16 x 64 grid of 2 m cells, calm (all zero, no
// solids: what a world without flow primitives holds). The trees still pay for the grid
// sample's gathers.
// BOREAS_BENCH_WIND_SAMPLING=interpolated: the plants read the sine sums from the grid's
// slab (wind_sampling interpolated), the CL kernels and the native twins alike.
struct TreeWindScene {
  boreas_grid_def def = scene_grid_def(64, 16, 64);
  BoreasGpuGrid g = scene_gpu_grid(def);
  std::vector<BoreasGpuWave> waves = scene_waves();
  DeviceWaves device = device_waves(waves);
  bool interpolated = bench_wind_interpolated();
  // The grid's buffer: its planes zero, its slab the waves' sums (the same every step).
  std::vector<float> cells = calm_grid_buffer(g, waves);
  // The kernels' view of this wind, once its waves and grid are on the device.
  impl::PlantWind cl(const cl::Buffer& wave_buffer, const cl::Buffer& grid_buffer) const {
    impl::PlantWind in;
    in.waves = &wave_buffer;
    in.wave_count = int(device.padded.size());
    in.wave_slots = device.slots;
    in.grid = &grid_buffer;
    in.grid_layout = g;
    in.interpolated = interpolated;
    in.host_waves = &device.padded;
    return in;
  }
  NativeTreeWind native() const {
    NativeTreeWind w;
    w.waves = waves.data();
    w.wave_count = int(waves.size());
    w.grid = cells.data();
    w.g = g;
    w.interpolated = interpolated;
    return w;
  }
};

// Trees with `branches` branches in all (0: one of each model), cycling through
// bench_tree_models() on a square lattice over the grid's ground; the last tree is cut so
// the count is exact. Parameters are boreas_default_tree_def()'s (quasi-static response
// unless given, rings and sides 12x12, 6x8, 4x5, 3x4 per level).
std::vector<std::shared_ptr<impl::TreeInstance>> bench_trees(
    int branches, const boreas_grid_def& def,
    boreas_tree_response response = BOREAS_TREE_QUASI_STATIC);

// Copies of these trees whose models have no leaves (one copy per model). Under the drag
// load a branch's leaves load it, so a leafless tree bends otherwise than its full one:
// compare a leafless batch with a twin of leafless trees.
std::vector<std::shared_ptr<impl::TreeInstance>> leafless_trees(
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees);

// A TreeBatch of these trees without their leaves (the step rows time branches only;
// TreeBatch would otherwise run the leaf kernel after every step).
std::unique_ptr<impl::TreeBatch> leafless_batch(
    impl::Runtime& rt, boreas_tree_mode mode,
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees);

// ---- the suites ----

// Each registers its rows (bench_<feature>.cpp); register_benchmarks calls them in this
// order, which is the order the rows run in.
void register_wind_benchmarks();        // copy bandwidth, sine sum, sine slab, grid step
void register_trees_benchmarks();       // tree step, deform, leaves
void register_underbrush_benchmarks();  // underbrush step and strips
void register_mesh_tree_benchmarks();   // imported trees: step and preprocessing
void register_blobtree_benchmarks();    // BlobTree field and polygonizer
// The imported-tree rows' tube tree (bench_mesh_tree.cpp), built once for the whole run:
// shape 0 a small game tree (~4.6 k trunk triangles, 480 leaves), 1 a big one (~70 k).
const impl::MeshModel& bench_mesh_model(int shape);

void register_forest_benchmarks();      // forests: build and step through the C API
void register_collider_benchmarks();    // moving colliders in the forest of BM_ForestStep
void register_tree_records_benchmarks();  // a forest's records in one call, over its size
// Rays into a windy forest against Embree (bench_rays.cpp; built where Embree is,
// BOREAS_BENCH_RAYS).
void register_rays_benchmarks();

}  // namespace boreas::bench
