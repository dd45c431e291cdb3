// boreas benchmarks: the shared harness of boreas_bench (bench_harness.h), and the public
// entry points of benchmarks.h but print_tree_lag_error (tree_lag_error.cpp).
#include "bench_harness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <stdexcept>

#include "benchmarks.h"
#include "native_wind.h"
#include "runtime/kernel_defines.h"
#include "trees/species.h"
#include "trees/tree_params.h"

namespace boreas::bench {

namespace {

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

// Distinct generated trees, replicated across the grid.
constexpr int kTreeModels = 8;

// A model cut to its first `branches` branches (fewer than it has, more than its levels
// before the last): the cut falls on the last level, whose branches have no children;
// leaves on removed branches go too.
impl::TreeModel cut_tree(const impl::TreeModel& m, int branches) {
  impl::TreeModel t = m;
  t.branches.resize(size_t(branches));
  for (auto& begin : t.level_begin) begin = std::min(begin, int32_t(branches));
  while (!t.tier_level.empty() && t.tier_begin[t.tier_level.size() - 1] >= branches) {
    t.tier_level.pop_back();
    t.tier_begin.pop_back();
  }
  if (!t.tier_begin.empty()) t.tier_begin.back() = int32_t(branches);
  t.levels = 0;
  for (int l = 0; l < impl::kMaxTreeLevels; ++l)
    if (t.level_begin[l + 1] > t.level_begin[l]) t.levels = l + 1;
  t.leaves.erase(
      std::remove_if(t.leaves.begin(), t.leaves.end(),
                     [&](const impl::LeafModel& leaf) { return leaf.parent >= branches; }),
      t.leaves.end());
  return t;
}

}  // namespace

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

impl::Runtime* width_one_runtime_or_skip(benchmark::State& state) {
  static ClState width_one = [] {
    ClState s;
    // The runtime reads BOREAS_SIMD_WIDTH once, when it builds its prelude.
    const char* old = std::getenv("BOREAS_SIMD_WIDTH");
    const std::string saved = old ? old : "";
    setenv("BOREAS_SIMD_WIDTH", "1", 1);
    try {
      s.runtime = std::make_unique<impl::Runtime>(nullptr, nullptr);
    } catch (const std::exception& e) {
      s.error = e.what();
    }
    if (old) {
      setenv("BOREAS_SIMD_WIDTH", saved.c_str(), 1);
    } else {
      unsetenv("BOREAS_SIMD_WIDTH");
    }
    return s;
  }();
  if (!width_one.runtime) state.SkipWithError(("no OpenCL device: " + width_one.error).c_str());
  return width_one.runtime.get();
}

double event_seconds(const cl::Event& e) {
  cl_ulong start = 0, end = 0;
  BOREAS_CL_CHECK(e.getProfilingInfo(CL_PROFILING_COMMAND_START, &start));
  BOREAS_CL_CHECK(e.getProfilingInfo(CL_PROFILING_COMMAND_END, &end));
  return double(end - start) * 1e-9;
}

void report(benchmark::State& state, const std::string& family, const std::string& kind,
            int64_t items, double bytes_per_item, double wall_seconds, double kernel_seconds,
            const std::string& size_key) {
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
                 const std::string& size_key) {
  Clock::time_point start = Clock::now();
  for (auto _ : state) {
    run();
    benchmark::ClobberMemory();
  }
  double wall = std::chrono::duration<double>(Clock::now() - start).count();
  report(state, family, "native", items, bytes_per_item, wall, wall, size_key);
}

double span_seconds(const ClSpan& s) {
  cl_ulong from = 0, to = 0;
  BOREAS_CL_CHECK(s.first.getProfilingInfo(
      s.markers ? CL_PROFILING_COMMAND_END : CL_PROFILING_COMMAND_START, &from));
  BOREAS_CL_CHECK(s.last.getProfilingInfo(
      s.markers ? CL_PROFILING_COMMAND_START : CL_PROFILING_COMMAND_END, &to));
  return to > from ? double(to - from) * 1e-9 : 0.0;
}

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

double max_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    worst = std::max(worst, double(std::fabs(a[i] - b[i])));
  return worst;
}

impl::Runtime* runtime_or_skip(benchmark::State& state) {
  ClState& cl = cl_state();
  if (!cl.runtime) state.SkipWithError(("no OpenCL device: " + cl.error).c_str());
  return cl.runtime.get();
}

bool skipped_for(benchmark::State& state, const std::string& error) {
  if (error.empty()) return false;
  state.SkipWithError(error.c_str());
  return true;
}

void warm_up(impl::Runtime& rt, const std::function<cl::Event()>& launch) {
  // PoCL compiles the work-group function at the first launch of each local size.
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(rt.queue().finish());
}

bool bench_wind_interpolated() {
  const char* value = std::getenv("BOREAS_BENCH_WIND_SAMPLING");
  if (!value || std::string(value).empty() || std::string(value) == "exact") return false;
  if (std::string(value) == "interpolated") return true;
  throw std::runtime_error("BOREAS_BENCH_WIND_SAMPLING must be exact or interpolated (got \"" +
                           std::string(value) + "\")");
}

std::vector<float> calm_grid_buffer(const BoreasGpuGrid& g,
                                    const std::vector<BoreasGpuWave>& waves) {
  std::vector<float> buffer(size_t(boreas_grid_buffer_floats(g)), 0.0f);
  native_sine_slab(buffer.data() + boreas_grid_slab_offset(g), waves.data(), int(waves.size()), g);
  return buffer;
}

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

std::string disagreement(const char* what, double diff, const char* unit, double tolerance) {
  if (diff <= tolerance) return "";
  if (const char* skip = std::getenv("BOREAS_BENCH_NO_CHECK"); skip && std::string(skip) == "1")
    return "";
  char text[160];
  std::snprintf(text, sizeof text, "CL and native %s differ by up to %g %s", what, diff, unit);
  return text;
}

void add(const std::string& name, std::function<void(benchmark::State&)> body,
         benchmark::TimeUnit unit, bool manual_time) {
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
  benchmark::internal::Benchmark* b = benchmark::RegisterBenchmark(name.c_str(), std::move(guarded));
  (manual_time ? b->UseManualTime() : b->UseRealTime())->Unit(unit);
}

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

std::vector<std::shared_ptr<impl::TreeInstance>> bench_trees(int branches,
                                                             const boreas_grid_def& def,
                                                             boreas_tree_response response) {
  // The models as templates: the trees of one model share it (as a world's trees of one
  // species and seed do), only the last tree, cut to fill the count, has its own.
  static const std::vector<std::shared_ptr<const impl::TreeModel>> shared = [] {
    std::vector<std::shared_ptr<const impl::TreeModel>> out;
    for (const impl::TreeModel& m : bench_tree_models())
      out.push_back(std::make_shared<const impl::TreeModel>(m));
    return out;
  }();
  std::vector<std::shared_ptr<const impl::TreeModel>> chosen;
  int total = 0;
  for (size_t k = 0; branches > 0 ? total < branches : k < shared.size(); ++k) {
    const std::shared_ptr<const impl::TreeModel>& m = shared[k % shared.size()];
    const int size = int(m->branches.size());
    if (branches > 0 && total + size > branches) {
      chosen.push_back(std::make_shared<const impl::TreeModel>(cut_tree(*m, branches - total)));
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
    tree->model = chosen[k];
    trees.push_back(std::move(tree));
  }
  return trees;
}

std::vector<std::shared_ptr<impl::TreeInstance>> leafless_trees(
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  std::vector<std::shared_ptr<impl::TreeInstance>> copies;
  std::map<const impl::TreeModel*, std::shared_ptr<const impl::TreeModel>>
      leafless;  // one per model
  for (const auto& t : trees) {
    auto copy = std::make_shared<impl::TreeInstance>(*t);
    std::shared_ptr<const impl::TreeModel>& model = leafless[t->model.get()];
    if (!model) {
      auto bare = std::make_shared<impl::TreeModel>(*t->model);
      bare->leaves.clear();
      model = std::move(bare);
    }
    copy->model = model;
    copies.push_back(std::move(copy));
  }
  return copies;
}

std::unique_ptr<impl::TreeBatch> leafless_batch(
    impl::Runtime& rt, boreas_tree_mode mode,
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  auto batch = std::make_unique<impl::TreeBatch>(rt, mode);
  const auto bare = leafless_trees(trees);
  batch->add(std::vector<std::shared_ptr<const impl::TreeInstance>>(bare.begin(), bare.end()));
  return batch;  // one call: packed from entry 0, as tree_layout lays them out
}

void register_benchmarks() {
  register_wind_benchmarks();
  register_trees_benchmarks();
  register_underbrush_benchmarks();
  register_mesh_tree_benchmarks();
  register_blobtree_benchmarks();
  register_forest_benchmarks();
  register_collider_benchmarks();
  register_tree_records_benchmarks();
#ifdef BOREAS_BENCH_RAYS
  register_rays_benchmarks();
#endif
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
