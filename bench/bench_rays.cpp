// boreas benchmarks: BM_Rays, rays per second into a windy forest INCLUDING the ray
// structure's update after each step (issue 37, "Reference and speed"): each iteration
// steps the world (not timed), then casts (timed: boreas_world_cast_rays, whose first cast
// after a step updates the structure). Embree 3 on the same triangles in the same run is
// the anchor: its rows time the scene's update (rtcUpdateGeometryBuffer + rtcCommitScene,
// refitting or rebuilding: both are measured) and the cast; reading the triangles back
// through boreas's getters is reported apart (export_ms), as it is boreas's cost, not
// Embree's. The native rows run the kernel's own traversal (cl/shared/ray_cast.h) as C++
// (native_rays.h) on the library's structure: update_ms is the library's update
// (World::update_rays), export_ms the structure's read-back, cast_ms the twin's cast;
// before timing, its hits are checked against the kernel's in the same state (counters
// differ_bits, differ, differ_m; the row fails past kTwinMaxDiffer).
// Iterations are timed by hand (update + cast), so "Time" is that, per step.
//
// Rows: BM_Rays/<scene>/<size>/<boreas|native|embree_refit|embree_rebuild>:
//   trees/<n>        stands of 1 .. 1,000 trees of three species with 1,000 underbrush
//                    components a tree (1 M at 1,000), kRaysPerStep rays of the test's mix
//                    (ray_forest.h) per step;
//   lidar<c>/<n>     a spinning LiDAR of c channels (vertical angles spread over
//                    -22.5 .. +22.5 deg), 2048 columns a turn at 10 Hz, 1.8 m up on a
//                    vehicle driving through the n-tree stand at 5 m/s: each 60 Hz step
//                    casts the slice of the sweep that falls in it. Counter realtime: the
//                    unit's points per second over the rays per second cast.
//   resident/<n>/<step|cast>  what a GPU simulator pays: kResidentRays rays in a device
//                    buffer cast by boreas_world_enqueue_cast_rays into one (no transfer
//                    through the host), timed to the queue's end; `step` after each step
//                    (the update included), `cast` with no step between (the structure
//                    current: the traversal's own throughput).
// Rows whose stand would not fit Embree's memory budget (BOREAS_BENCH_EMBREE_GIB, default a
// quarter of the machine's memory) skip, saying so. Every row casts one untimed step first:
// boreas builds its structure and PoCL compiles the kernels at the first cast, Embree
// builds its first hierarchy (reported as build_s and embree_MiB, not as rays/s).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "api/c_api_guard.h"
#include "bench_harness.h"
#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "embree_world.h"
#include "native_rays.h"
#include "ray_forest.h"
#include "rays/ray_checks.h"

namespace boreas::bench {

namespace {

using reference::EmbreeOptions;
using reference::EmbreeUpdate;
using reference::EmbreeWorld;
using reference::RayForest;
using reference::RayForestDef;

constexpr float kStepDt = 1.0f / 60.0f;
constexpr int kRaysPerStep = 1 << 18;  // a 512 x 512 depth image a step
constexpr int kComponentsPerTree = 1000;
// The LiDAR: 2048 columns a turn, 10 turns a second, 120 m range, 5 m/s through the stand.
constexpr int kLidarColumns = 2048;
constexpr double kLidarHz = 10.0;
constexpr float kLidarRange = 120.0f;
constexpr float kLidarSpeed = 5.0f;
// Embree's bytes per triangle here, all in, rounded up: on the 10-tree stand (2.7 M
// triangles) Embree held 65 B a triangle after a rebuild and 107 B after a refit build
// (embree_MiB), and EmbreeWorld's copies (positions, indices, parts) about 40 B more.
constexpr double kEmbreeBytesPerTriangle = 160.0;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The process's CPU time (every thread: PoCL's, OpenMP's, Embree's), s: steadier than wall
// time on a shared machine.
double process_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

int64_t embree_budget_bytes() {
  if (const char* gib = std::getenv("BOREAS_BENCH_EMBREE_GIB"))
    return int64_t(std::atof(gib) * double(1ll << 30));
  return int64_t(sysconf(_SC_PHYS_PAGES)) * int64_t(sysconf(_SC_PAGE_SIZE)) / 4;
}

// The triangles Embree will hold for the forest, from the getters' counts alone.
int64_t forest_triangles(const RayForest& f) {
  int64_t triangles = 0;
  for (boreas_tree_id t : f.trees) {
    int vertices = 0, indices = 0, leaves = 0;
    if (boreas_tree_get_mesh(f.world, t, nullptr, 0, &vertices, nullptr, 0, &indices) != BOREAS_OK ||
        boreas_tree_get_leaves(f.world, t, nullptr, 0, &leaves) != BOREAS_OK)
      throw std::runtime_error(boreas_last_error());
    triangles += indices / 3 + 2 * int64_t(leaves);
  }
  // A blade's strip: at most BOREAS_MEADOW_VERTEX_STRIDE - 2 triangles.
  return triangles + int64_t(f.trees.size()) * kComponentsPerTree * (BOREAS_MEADOW_VERTEX_STRIDE - 2);
}

struct RaysFixture : Fixture {
  RayForestDef def;
  std::unique_ptr<RayForest> forest;
  std::vector<boreas_ray> rays;  // the trees rows' (the LiDAR makes its own each step)
  int64_t triangles = 0;
  double build_seconds = 0.0;
  // One Embree scene at a time (two would double the memory), made for the row that runs.
  std::unique_ptr<EmbreeWorld> embree;
  EmbreeUpdate embree_mode = EmbreeUpdate::kRebuild;
};

RaysFixture& rays_fixture(int trees) {
  return fixture<RaysFixture>("rays/" + std::to_string(trees), [&] {
    auto f = std::make_unique<RaysFixture>();
    f->def.trees = trees;
    f->def.templates = 7;  // 21 grown models over the three species
    f->def.scale = 1.0f;
    f->def.components = int64_t(trees) * kComponentsPerTree;
    const auto start = Clock::now();
    f->forest = reference::make_ray_forest(f->def);
    f->build_seconds = seconds(start, Clock::now());
    // Warm up: kernels built, the wind under way.
    for (int s = 0; s < 30; ++s)
      if (boreas_world_step(f->forest->world, kStepDt) != BOREAS_OK)
        throw std::runtime_error(boreas_last_error());
    f->rays = reference::forest_rays(*f->forest, kRaysPerStep, 37);
    f->triangles = forest_triangles(*f->forest);
    return f;
  });
}

// The LiDAR's rays of the step that ends at time t: the columns its head sweeps over in
// that step, every channel of each, from where the vehicle is at t.
void lidar_rays(const RayForest& forest, int channels, double t, std::vector<boreas_ray>* out) {
  const double columns_per_second = kLidarColumns * kLidarHz;
  const int64_t first = int64_t(std::floor((t - kStepDt) * columns_per_second));
  const int64_t last = int64_t(std::floor(t * columns_per_second));
  // Back and forth along x across the stand (over its ground), between two rows of trees.
  const float span = 2.0f * forest.half_extent;
  const float along = std::fmod(float(t) * kLidarSpeed, 2.0f * span);
  const float origin[3] = {-0.5f * span + (along < span ? along : 2.0f * span - along), 1.8f,
                           forest.half_extent > 3.0f ? 3.0f : 0.5f * forest.half_extent};
  out->clear();
  for (int64_t c = first; c < last; ++c) {
    const double azimuth = 2.0 * M_PI * double(c % kLidarColumns) / kLidarColumns;
    for (int ch = 0; ch < channels; ++ch) {
      const double elevation =
          (-22.5 + 45.0 * double(ch) / double(channels > 1 ? channels - 1 : 1)) * M_PI / 180.0;
      boreas_ray r{};
      for (int k = 0; k < 3; ++k) r.origin[k] = origin[k];
      r.direction[0] = float(std::cos(elevation) * std::cos(azimuth));
      r.direction[1] = float(std::sin(elevation));
      r.direction[2] = float(std::cos(elevation) * std::sin(azimuth));
      r.max_distance = kLidarRange;
      out->push_back(r);
    }
  }
}

enum class Caster { kBoreas, kNative, kEmbreeRefit, kEmbreeRebuild };

// Why Embree cannot take this stand here ("" when it can).
std::string embree_misfit(const RaysFixture& f) {
  const double need = double(f.triangles) * kEmbreeBytesPerTriangle;
  const int64_t budget = embree_budget_bytes();
  if (need <= double(budget)) return "";
  return std::to_string(f.triangles / 1000000) + " M triangles need about " +
         std::to_string(int(need / double(1 << 30))) + " GiB in Embree, past its budget of " +
         std::to_string(int(double(budget) / double(1 << 30))) +
         " GiB here (BOREAS_BENCH_EMBREE_GIB)";
}

EmbreeWorld& embree_for(RaysFixture& f, EmbreeUpdate mode) {
  if (!f.embree || f.embree_mode != mode) {
    f.embree.reset();
    EmbreeOptions options;
    options.update = mode;
    options.robust = false;  // Embree at its fastest: the anchor
    options.memory_limit = embree_budget_bytes();
    f.embree = std::make_unique<EmbreeWorld>(options);
    f.embree_mode = mode;
    reference::add_to_embree(*f.forest, f.embree.get());
    f.embree->commit();
  }
  return *f.embree;
}

// What one step's update and cast cost (s), and what it cast.
struct StepCost {
  double update = 0.0, cast = 0.0, exported = 0.0;
  double cpu = 0.0;  // the process's CPU time in update and cast (export left out)
  int64_t rays = 0, hits = 0;
};

// One step of a row: the world steps and the LiDAR (channels > 0) turns, untimed; then the
// structure's update and the cast. Embree's update is its commit after boreas's triangles
// are read into it (the read is export, boreas's cost); boreas's is inside its cast. The
// native twin's update is the library's (World::update_rays), timed apart; reading the
// structure back for it is export.
StepCost cast_step(RaysFixture& f, int channels, bool native, EmbreeWorld* embree,
                   double* lidar_clock, std::vector<boreas_ray>& rays,
                   std::vector<boreas_hit>& hits) {
  StepCost c;
  if (boreas_world_step(f.forest->world, kStepDt) != BOREAS_OK)
    throw std::runtime_error(boreas_last_error());
  *lidar_clock += kStepDt;
  if (channels > 0) lidar_rays(*f.forest, channels, *lidar_clock, &rays);
  hits.resize(rays.size());
  if (native) {
    // The library's update, then the structure read back (export) and the twin's cast.
    impl::World& world = api::world_of(f.forest->world);
    const auto t0 = Clock::now();
    double cpu0 = process_seconds();
    impl::RayScene& scene =
        world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), hits.data()));
    c.update = seconds(t0, Clock::now());
    c.cpu = process_seconds() - cpu0;
    const auto t1 = Clock::now();
    const impl::RayScene::HostCopy copy = scene.host_copy();
    c.exported = seconds(t1, Clock::now());
    const auto t2 = Clock::now();
    cpu0 = process_seconds();
    native_ray_cast(copy, rays.data(), int(rays.size()), hits.data());
    c.cast = seconds(t2, Clock::now());
    c.cpu += process_seconds() - cpu0;
  } else if (embree) {
    const auto t0 = Clock::now();
    embree->read(f.forest->world);
    c.exported = seconds(t0, Clock::now());
    const auto t1 = Clock::now();
    const double cpu0 = process_seconds();
    embree->commit();
    const auto t2 = Clock::now();
    embree->cast(rays.data(), int(rays.size()), hits.data());
    c.update = seconds(t1, t2);
    c.cast = seconds(t2, Clock::now());
    c.cpu = process_seconds() - cpu0;
  } else {
    const auto t0 = Clock::now();
    const double cpu0 = process_seconds();
    if (boreas_world_cast_rays(f.forest->world, rays.data(), int(rays.size()), hits.data()) !=
        BOREAS_OK)
      throw std::runtime_error(boreas_last_error());
    c.cast = seconds(t0, Clock::now());
    c.cpu = process_seconds() - cpu0;
  }
  c.rays = int64_t(rays.size());
  for (const boreas_hit& h : hits) c.hits += h.kind != BOREAS_HIT_NONE;
  return c;
}

// How the twin's hits of one step compare with the kernel's in the same state.
struct TwinCheck {
  int64_t not_identical = 0;  // rays whose hit records differ in any bit
  int64_t differ = 0;         // rays that hit another object or part, or > kTwinDistance apart
  double distance = 0.0;      // m: the largest distance between hits on the same part
  std::string error;          // why the row is skipped ("" when the twin agrees)
};

// The twin may differ from the kernel by float contraction only (PoCL and GCC contract
// a * b + c into fma at different places): the same part of the same object at nearly the
// same distance (a leaf's plane goes through its attachment frame's normalizations: its
// hits were measured up to 5e-6 of the distance apart), except for the rare ray that grazes
// an edge or a leaf's outline, which one rounding puts on one side and the other on the
// other.
constexpr float kTwinDistance = 2e-5f;    // relative to the distance (at least 1 m)
constexpr double kTwinMaxDiffer = 1e-4;  // of the rays

TwinCheck compare_with_cl(RaysFixture& f, const std::vector<boreas_ray>& rays,
                          const std::vector<boreas_hit>& native) {
  std::vector<boreas_hit> cl(rays.size());
  if (boreas_world_cast_rays(f.forest->world, rays.data(), int(rays.size()), cl.data()) !=
      BOREAS_OK)
    throw std::runtime_error(boreas_last_error());
  TwinCheck c;
  for (size_t i = 0; i < rays.size(); ++i) {
    const boreas_hit &a = native[i], &b = cl[i];
    if (std::memcmp(&a, &b, sizeof a) == 0) continue;
    ++c.not_identical;
    const bool same_part =
        a.kind == b.kind && a.part == b.part && a.object.index == b.object.index;
    if (same_part && a.kind != BOREAS_HIT_NONE)
      c.distance = std::max(c.distance, double(std::fabs(a.distance - b.distance)));
    const bool same =
        same_part &&
        std::fabs(a.distance - b.distance) <= kTwinDistance * std::fmax(1.0f, b.distance);
    c.differ += !same;
  }
  if (double(c.differ) > kTwinMaxDiffer * double(rays.size()))
    c.error = "the native twin's hits differ from the kernel's on " + std::to_string(c.differ) +
              " of " + std::to_string(rays.size()) + " rays";
  return c;
}

// One row: `channels` 0 casts the fixture's rays, else the LiDAR's slice of each step.
void rays_row(benchmark::State& state, int trees, int channels, Caster caster) {
  RaysFixture& f = rays_fixture(trees);
  const bool boreas = caster == Caster::kBoreas || caster == Caster::kNative;
  const bool native = caster == Caster::kNative;
  if (!boreas && skipped_for(state, embree_misfit(f))) return;
  EmbreeWorld* embree =
      boreas ? nullptr
             : &embree_for(f, caster == Caster::kEmbreeRefit ? EmbreeUpdate::kRefit
                                                             : EmbreeUpdate::kRebuild);
  std::vector<boreas_ray> rays = f.rays;
  std::vector<boreas_hit> hits;
  // The LiDAR's clock starts with the row: every caster's row drives the same path from the
  // same place (the wind's state goes on from the rows before).
  double lidar_clock = 0.0;
  // The warm-up (see the top of this file).
  cast_step(f, channels, native, embree, &lidar_clock, rays, hits);
  if (native) {
    const TwinCheck check = compare_with_cl(f, rays, hits);
    state.counters["differ_bits"] = double(check.not_identical);
    state.counters["differ"] = double(check.differ);
    state.counters["differ_m"] = check.distance;
    if (skipped_for(state, check.error)) return;
  }
  StepCost sum;
  for (auto _ : state) {
    const StepCost c = cast_step(f, channels, native, embree, &lidar_clock, rays, hits);
    state.SetIterationTime(c.update + c.cast);
    sum.update += c.update;
    sum.cast += c.cast;
    sum.exported += c.exported;
    sum.cpu += c.cpu;
    sum.rays += c.rays;
    sum.hits += c.hits;
  }
  const double n = double(std::max<int64_t>(1, state.iterations()));
  state.SetItemsProcessed(sum.rays);
  state.counters["trees"] = trees;
  state.counters["components"] = double(f.def.components);
  state.counters["triangles"] = double(f.triangles);
  state.counters["rays_per_step"] = double(sum.rays) / n;
  state.counters["hit_fraction"] = sum.rays > 0 ? double(sum.hits) / double(sum.rays) : 0.0;
  state.counters["update_ms"] = 1e3 * sum.update / n;  // Embree: commit (boreas: inside cast_ms)
  state.counters["cast_ms"] = 1e3 * sum.cast / n;
  state.counters["export_ms"] = 1e3 * sum.exported / n;
  // Rays per second of the process's CPU time (2 cores: at most twice the rays/s, when
  // the row had both to itself).
  state.counters["cpu_ms"] = 1e3 * sum.cpu / n;
  state.counters["rays_per_cpu_s"] = sum.cpu > 0.0 ? double(sum.rays) / sum.cpu : 0.0;
  state.counters["build_s"] = f.build_seconds;
  if (embree) state.counters["embree_MiB"] = double(embree->embree_bytes()) / double(1 << 20);
  if (channels > 0 && sum.update + sum.cast > 0.0) {
    const double points_per_second = double(channels) * kLidarColumns * kLidarHz;
    state.counters["realtime"] = (double(sum.rays) / (sum.update + sum.cast)) / points_per_second;
  }
}

// BM_RaysUpdate/<trees|lidar32>/<n>: the update alone (World::update_rays: the structure's refit after a step, for the rays
// of that step), where the rows above time it with the cast: each iteration steps the world
// and the LiDAR (untimed), then times the update. A fixed count of iterations (kUpdateSteps)
// so that every build of the library drives the same path and refits the same trees;
// cpu_ms is the process's CPU time (every PoCL thread), steadier than wall time on a
// shared machine.
constexpr int kUpdateSteps = 12;

void update_row(benchmark::State& state, int trees, int channels) {
  RaysFixture& f = rays_fixture(trees);
  impl::World& world = api::world_of(f.forest->world);
  std::vector<boreas_ray> rays = f.rays;
  std::vector<boreas_hit> hits;
  double lidar_clock = 0.0, cpu = 0.0;
  int64_t refitted = 0;
  auto step = [&] {
    if (boreas_world_step(f.forest->world, kStepDt) != BOREAS_OK)
      throw std::runtime_error(boreas_last_error());
    lidar_clock += kStepDt;
    if (channels > 0) lidar_rays(*f.forest, channels, lidar_clock, &rays);
    hits.resize(rays.size());
  };
  auto update = [&] {
    return world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), hits.data()))
        .refitted_instances();
  };
  step();
  update();  // the warm-up: the structure and the kernels built
  for (auto _ : state) {
    step();
    const auto t0 = Clock::now();
    const double c0 = process_seconds();
    refitted += update();
    cpu += process_seconds() - c0;
    state.SetIterationTime(seconds(t0, Clock::now()));
  }
  const double n = double(std::max<int64_t>(1, state.iterations()));
  state.counters["cpu_ms"] = 1e3 * cpu / n;
  state.counters["refitted"] = double(refitted) / n;
  state.counters["rays_per_step"] = double(rays.size());
}

// Rays for the resident rows: a 2048 x 2048 depth image's worth a cast.
constexpr int kResidentRays = 1 << 22;

// The resident rows: rays and hits in the world's device memory; `step` steps (untimed)
// before each cast, else the world stands still and only the traversal is timed.
void resident_row(benchmark::State& state, int trees, bool step) {
  RaysFixture& f = rays_fixture(trees);
  boreas_cl_objects cl{};
  if (boreas_world_get_cl(f.forest->world, &cl) != BOREAS_OK) throw std::runtime_error(boreas_last_error());
  const std::vector<boreas_ray> rays = reference::forest_rays(*f.forest, kResidentRays, 41);
  cl_int err = CL_SUCCESS;
  cl_mem in = clCreateBuffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             rays.size() * sizeof(boreas_ray), const_cast<boreas_ray*>(rays.data()), &err);
  cl_mem out = clCreateBuffer(cl.context, CL_MEM_WRITE_ONLY, rays.size() * sizeof(boreas_hit), nullptr, &err);
  auto cast = [&] {
    const auto t0 = Clock::now();
    if (boreas_world_enqueue_cast_rays(f.forest->world, in, 0, int(rays.size()), out, 0) != BOREAS_OK)
      throw std::runtime_error(boreas_last_error());
    clFinish(cl.queue);
    return seconds(t0, Clock::now());
  };
  cast();  // the warm-up: the structure and the kernels built
  double sum = 0.0;
  for (auto _ : state) {
    if (step && boreas_world_step(f.forest->world, kStepDt) != BOREAS_OK)
      throw std::runtime_error(boreas_last_error());
    const double t = cast();
    state.SetIterationTime(t);
    sum += t;
  }
  clReleaseMemObject(in);
  clReleaseMemObject(out);
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  state.counters["rays_per_step"] = double(rays.size());
  state.counters["trees"] = trees;
  state.counters["cast_ms"] = 1e3 * sum / double(std::max<int64_t>(1, state.iterations()));
}

const char* caster_name(Caster c) {
  switch (c) {
    case Caster::kBoreas: return "boreas";
    case Caster::kNative: return "native";
    case Caster::kEmbreeRefit: return "embree_refit";
    case Caster::kEmbreeRebuild: return "embree_rebuild";
  }
  return "";
}

}  // namespace

void register_rays_benchmarks() {
  constexpr benchmark::TimeUnit kMs = benchmark::kMillisecond;
  const Caster casters[] = {Caster::kEmbreeRebuild, Caster::kEmbreeRefit, Caster::kNative,
                            Caster::kBoreas};
  // The curve over stand sizes; rows of one size share their world (the fixture slot).
  for (int trees : {1, 10, 100, 1000}) {
    for (Caster c : casters)
      add("BM_Rays/trees/" + std::to_string(trees) + "/" + caster_name(c),
          [=](auto& s) { rays_row(s, trees, 0, c); }, kMs, true);
    // The LiDARs drive through the 100- and 1,000-tree stands.
    if (trees < 100) continue;
    for (int channels : {32, 128})
      for (Caster c : casters)
        add("BM_Rays/lidar" + std::to_string(channels) + "/" + std::to_string(trees) + "/" +
                caster_name(c),
            [=](auto& s) { rays_row(s, trees, channels, c); }, kMs, true);
  }
  for (const auto& [trees, channels] : {std::pair{1, 0}, {10, 0}, {100, 0}, {100, 32}, {1000, 32}})
    benchmark::RegisterBenchmark(
        ("BM_RaysUpdate/" + (channels > 0 ? "lidar" + std::to_string(channels) : std::string("trees")) + "/" +
         std::to_string(trees))
            .c_str(),
        [=](benchmark::State& s) {
          try {
            update_row(s, trees, channels);
          } catch (const std::exception& e) {
            s.SkipWithError(e.what());
          }
        })
        ->Unit(kMs)
        ->UseManualTime()
        ->Iterations(kUpdateSteps);
  for (int trees : {1, 100, 1000})
    for (const bool step : {true, false})
      add("BM_Rays/resident/" + std::to_string(trees) + "/" + (step ? "step" : "cast"),
          [=](auto& s) { resident_row(s, trees, step); }, kMs, true);
}

}  // namespace boreas::bench
