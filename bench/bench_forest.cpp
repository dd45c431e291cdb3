// boreas benchmarks: forests through the public C API, as an engine builds and steps them —
// BM_ForestBuild (adding 100 .. 10,000 trees, one call each or one batch call, from 20
// templates or all distinct) and BM_ForestStep (a step of forests of 100 .. 10,000 trees,
// and of 1,000 trees over a million underbrush components and 10,000 over ten million,
// levels of detail on and off), and BM_ForestSplit (10,000 .. 40,000 aspens, a forest that
// may pass one allocation: its memory per entry and its step over chunks).
// Times are wall clock of the library's calls; the step rows add the device's stage
// times from boreas_world_get_step_stats, and the process's CPU time a step (every thread
// of it: the device's workers on PoCL), which other processes on a shared machine inflate
// far less than the wall clock; the build rows, the resident memory and device bytes a
// build adds.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_forest.h"
#include "bench_harness.h"
#include "boreas/boreas.h"

namespace boreas::bench {

void check(boreas_status status) {
  if (status != BOREAS_OK) throw std::runtime_error(boreas_last_error());
}

boreas_world make_forest_world(float extent) {
  boreas_world_def def = boreas_default_world_def();
  def.grid.cell_size = 4.0f;
  const int cells = std::max(4, std::min(64, int(std::ceil(extent / def.grid.cell_size))));
  def.grid.resolution[0] = def.grid.resolution[2] = cells;
  def.grid.resolution[1] = 8;
  def.grid.origin[0] = def.grid.origin[2] = -0.5f * float(cells) * def.grid.cell_size;
  def.grid.origin[1] = 0.0f;
  if (bench_wind_interpolated()) def.grid.wind_sampling = BOREAS_WIND_SAMPLING_INTERPOLATED;
  std::vector<boreas_wave> waves(2, boreas_default_wave());
  waves[0].direction[0] = 1.0f;
  waves[0].amplitude = 8.0f;
  waves[0].wavelength = 40.0f;
  waves[0].speed = 6.0f;
  waves[0].sharpness = 2.0f;
  waves[1].direction[0] = 0.3f;
  waves[1].direction[1] = 1.0f;
  waves[1].amplitude = 3.0f;
  waves[1].wavelength = 11.0f;
  waves[1].speed = 4.0f;
  waves[1].sharpness = 1.0f;
  def.waves = waves.data();
  def.wave_count = int(waves.size());
  boreas_world world = nullptr;
  check(boreas_world_create(&def, &world));
  return world;
}

std::vector<boreas_tree_def> forest_defs(int count, int templates,
                                         const std::vector<const char*>& species) {
  std::vector<boreas_tree_def> defs;
  const int side = int(std::ceil(std::sqrt(double(count))));
  const float half = 0.5f * float(side - 1) * kTreeSpacing;
  for (int i = 0; i < count; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    d.species = species[size_t(i) % species.size()];
    d.seed = templates > 0 ? uint64_t(1 + (i / int(species.size())) % templates) : uint64_t(1 + i);
    d.position[0] = float(i % side) * kTreeSpacing - half;
    d.position[2] = float(i / side) * kTreeSpacing - half;
    d.rotation =
        std::fmod(2.39996f * float(i), 6.2831853f);  // the golden angle: no two neighbours alike
    d.scale = 0.85f + 0.3f * float((i * 7919) % 101) / 100.0f;
    defs.push_back(d);
  }
  return defs;
}

namespace {

// User and system time of every thread of this process so far, s.
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---- BM_ForestBuild ---------------------------------------------------------------------

// The process's resident memory, bytes (/proc/self/statm).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE));
}

void forest_build(benchmark::State& state, int count, int templates, bool batch) {
  const std::vector<boreas_tree_def> defs = forest_defs(count, templates, {"quaking_aspen"});
  double total = 0.0, resident = 0.0, device = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    WorldHandle w{make_forest_world(std::sqrt(float(count)) * kTreeSpacing)};
    const double empty = resident_bytes();
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    if (batch) {
      check(boreas_world_add_trees(w.world, defs.data(), count, nullptr));
    } else {
      for (const boreas_tree_def& d : defs) check(boreas_world_add_tree(w.world, &d, nullptr));
    }
    total += seconds_since(start);
    // What the trees hold: the resident memory they added, and the world's device buffers.
    state.PauseTiming();
    boreas_memory_info memory{};
    check(boreas_world_get_memory(w.world, &memory));
    resident = std::max(resident, resident_bytes() - empty);
    device = std::max(device, double(memory.device_bytes));
    state.ResumeTiming();
  }
  const double per_build = total / double(state.iterations());
  state.counters["resident_mb"] = resident / 1e6;
  state.counters["device_mb"] = device / 1e6;
  state.counters["trees"] = count;
  state.counters["seconds"] = per_build;
  state.counters["us_per_tree"] = 1e6 * per_build / double(count);
  state.counters["templates"] = templates > 0 ? templates : count;
}

// ---- BM_ForestSplit ---------------------------------------------------------------------

// A forest past one allocation (world_chunks.cpp): `count` aspens from 20 templates in
// one batch add, then stepped at full detail (every branch). Its counters: the device bytes
// and resident memory the trees hold, the entries (roots and branches) and the device bytes
// per entry, and the process's CPU time a step. Run with BOREAS_MAX_ALLOCATION to force
// more chunks (the same forest, split: an A/B of the chunks' cost).
void forest_split(benchmark::State& state, int count) {
  const std::vector<boreas_tree_def> defs = forest_defs(count, 20, {"quaking_aspen"});
  WorldHandle w{make_forest_world(std::sqrt(float(count)) * kTreeSpacing)};
  const double empty = resident_bytes();
  const auto start = std::chrono::steady_clock::now();
  check(boreas_world_add_trees(w.world, defs.data(), count, nullptr));
  const double build = seconds_since(start);
  for (int s = 0; s < 2; ++s) check(boreas_world_step(w.world, kForestDt));  // kernels built
  boreas_step_stats last{};
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) check(boreas_world_step(w.world, kForestDt));
  const double n = double(state.iterations());
  state.counters["process_cpu_ms"] = 1e3 * (process_cpu_seconds() - cpu_start) / n;
  check(boreas_world_get_step_stats(w.world, &last));
  boreas_memory_info memory{};
  check(boreas_world_get_memory(w.world, &memory));
  const double entries = double(last.branches_stepped + last.branches_carried) + double(count);
  state.counters["trees"] = count;
  state.counters["build_s"] = build;
  state.counters["entries"] = entries;
  state.counters["device_mb"] = double(memory.device_bytes) / 1e6;
  state.counters["device_bytes_per_entry"] = double(memory.device_bytes) / entries;
  state.counters["resident_mb"] = (resident_bytes() - empty) / 1e6;
}

}  // namespace

// ---- BM_ForestStep ----------------------------------------------------------------------

ForestFixture& forest_fixture(int trees, int64_t components,
                              const std::vector<const char*>& species,
                              boreas_tree_response response) {
  const std::string key = "forest/" + std::to_string(trees) + "/" + std::to_string(components) +
                          "/" + std::to_string(species.size()) + "/" +
                          std::to_string(int(response));
  return fixture<ForestFixture>(key, [&] {
    auto f = std::make_unique<ForestFixture>();
    const float extent = std::sqrt(float(trees)) * kTreeSpacing;
    f->world.world = make_forest_world(extent);
    f->trees = trees;
    check(boreas_world_set_focus(f->world.world, kForestFocus, 1));  // before the add
    const auto start = std::chrono::steady_clock::now();
    std::vector<boreas_tree_def> defs = forest_defs(trees, 20, species);
    for (boreas_tree_def& d : defs) d.response = response;
    check(boreas_world_add_trees(f->world.world, defs.data(), trees, nullptr));
    if (components > 0) {
      // One meadow under the whole forest, at the density that makes `components`.
      boreas_meadow_def m = boreas_default_meadow_def();
      m.size[0] = m.size[1] = std::max(extent, 10.0f);
      m.density = float(double(components) / (double(m.size[0]) * double(m.size[1])));
      m.terrain_relief = 0.0f;
      check(boreas_world_add_meadow(f->world.world, &m, nullptr));
      f->components = components;
    }
    f->build_seconds = seconds_since(start);
    return f;
  });
}

namespace {

void forest_step(benchmark::State& state, int trees, int64_t components, bool lod,
                 const std::vector<const char*>& species,
                 boreas_tree_response response = BOREAS_TREE_QUASI_STATIC) {
  ForestFixture& f = forest_fixture(trees, components, species, response);
  // The focus (kForestFocus): the levels of detail follow from the trees' distances;
  // without focus every tree is stepped at full detail.
  check(boreas_world_set_focus(f.world.world, lod ? kForestFocus : nullptr, lod ? 1 : 0));
  // The first steps build the kernels and settle the levels of detail (a frozen tree
  // settles for 3 s before it stops costing): warm up past that.
  for (int s = 0; s < 200; ++s) check(boreas_world_step(f.world.world, kForestDt));
  double wind = 0.0, tree = 0.0, underbrush = 0.0;
  boreas_step_stats last{};
  const double cpu_start = process_cpu_seconds();
  for (auto _ : state) {
    check(boreas_world_step(f.world.world, kForestDt));
    check(boreas_world_get_step_stats(f.world.world, &last));
    wind += last.wind;
    tree += last.trees;
    underbrush += last.underbrush;
  }
  const double n = double(state.iterations());
  state.counters["process_cpu_ms"] = 1e3 * (process_cpu_seconds() - cpu_start) / n;
  state.counters["trees"] = trees;
  state.counters["components"] = double(f.components);
  state.counters["build_s"] = f.build_seconds;
  state.counters["wind_ms"] = 1e3 * wind / n;
  state.counters["trees_ms"] = 1e3 * tree / n;
  state.counters["underbrush_ms"] = 1e3 * underbrush / n;
  state.counters["full"] = double(last.trees_by_lod[0]);
  state.counters["reduced"] = double(last.trees_by_lod[1]);
  state.counters["far"] = double(last.trees_by_lod[2]);
  state.counters["frozen"] = double(last.trees_by_lod[3]);
  state.counters["stepped"] = double(last.branches_stepped);
  state.counters["carried"] = double(last.branches_carried);
  check(boreas_world_set_focus(f.world.world, nullptr, 0));
}

}  // namespace

void register_forest_benchmarks() {
  // In milliseconds: builds and steps of forests take that long.
  constexpr benchmark::TimeUnit kMs = benchmark::kMillisecond;
  // Build: one call per tree and one batch call, from 20 templates and all distinct seeds.
  // 10,000 distinct aspens would grow for ~25 s and hold ~18 GiB (their template blocks:
  // 1.4 MiB each): past this 24 GiB machine with the rest of a run, so they stop at 1,000.
  for (int n : {100, 1000, 3000, 10000}) {
    add(
        "BM_ForestBuild/batch/templates/" + std::to_string(n),
        [=](auto& s) { forest_build(s, n, 20, true); }, kMs);
    add(
        "BM_ForestBuild/single/templates/" + std::to_string(n),
        [=](auto& s) { forest_build(s, n, 20, false); }, kMs);
    if (n <= 1000) {
      add(
          "BM_ForestBuild/batch/distinct/" + std::to_string(n),
          [=](auto& s) { forest_build(s, n, 0, true); }, kMs);
      add(
          "BM_ForestBuild/single/distinct/" + std::to_string(n),
          [=](auto& s) { forest_build(s, n, 0, false); }, kMs);
    }
  }
  // A forest past one allocation: 20,000 aspens hold ~4.0 GB (~153 B a device entry in a
  // still batch, ~163 B resident on PoCL), 30,000 ~6.0 GB, 40,000 ~8.0 GB: run them alone on
  // the 24 GB machine.
  for (int n : {10000, 20000, 30000, 40000})
    add(
        "BM_ForestSplit/" + std::to_string(n), [=](auto& s) { forest_split(s, n); }, kMs);
  // Step: a curve over the tree count (aspens from 20 templates, levels of detail on).
  const std::vector<const char*> aspens{"quaking_aspen"};
  for (int n : {100, 300, 1000, 3000, 10000})
    add(
        "BM_ForestStep/trees/" + std::to_string(n) + "/lod",
        [=](auto& s) { forest_step(s, n, 0, true, aspens); }, kMs);
  // The forest of the issue: 1,000 trees of three species and a million components.
  const std::vector<const char*> mixed{"quaking_aspen", "black_tupelo", "ca_black_oak"};
  for (bool lod : {true, false})
    add(
        std::string("BM_ForestStep/mixed/1000/1M/") + (lod ? "lod" : "full"),
        [=](auto& s) { forest_step(s, 1000, 1 << 20, lod, mixed); }, kMs);
  // The same with every tree damped (the exact air damping of the damped step).
  add(
      "BM_ForestStep/mixed/1000/1M/lod/damped",
      [=](auto& s) { forest_step(s, 1000, 1 << 20, true, mixed, BOREAS_TREE_DAMPED); }, kMs);
  // The GPU target of the forest issue: 10,000 trees over 10 M components in 2 ms a step.
  // Sized for a GPU: run it by name there.
  for (bool lod : {true, false})
    add(
        std::string("BM_ForestStep/mixed/10000/10M/") + (lod ? "lod" : "full"),
        [=](auto& s) { forest_step(s, 10000, 10 << 20, lod, mixed); }, kMs);
}

}  // namespace boreas::bench
