// boreas benchmarks: BM_Colliders — what moving colliders add to a step: 0, 10 and 100
// colliders, a third each cars (4.5 x 1.5 x 1.8 m boxes at 5 m/s), walkers (capsules 1.8 m
// tall at 1.4 m/s) and balls (0.11 m spheres at 3 m/s), spread over the plants and driving
// on in straight lines (wrapped back in at their edge), in
//   forest/1000/1M: the forest of BM_ForestStep (1,000 trees of three species over a
//     million underbrush components, levels of detail on);
//   mesh_trees/100: 100 imported trees (the small game tree of BM_MeshTree at scale 0.25,
//     3.5 m, its limbs from 1 m up: a car brushes the lower ones) 4 m apart.
// Each step also reads every collider's contact, as a simulator would. The 0 row is the
// plants alone, measured the same way, so the rows' difference is the colliders' cost.
// Times are wall clock of the library's calls; the device's stage times come from
// boreas_world_get_step_stats.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench_forest.h"
#include "bench_harness.h"
#include "boreas/boreas.h"
#include "mesh_trees/obj_writer.h"

namespace boreas::bench {

namespace {

constexpr int kForestTrees = 1000;
constexpr int64_t kForestComponents = int64_t(1) << 20;

// Collider i of a run: its kind by i % 3, placed by a low-discrepancy walk over the forest
// (half-width `half` m), heading by the golden angle.
boreas_collider_def collider_def(int i, float half) {
  boreas_collider_def d = boreas_default_collider_def();
  const float u = std::fmod(0.6180340f * float(i + 1), 1.0f);
  const float v = std::fmod(0.7548777f * float(i + 1), 1.0f);
  const float heading = std::fmod(2.39996f * float(i), 6.2831853f);
  float speed = 3.0f;
  d.pose.position[0] = (2.0f * u - 1.0f) * half;
  d.pose.position[2] = (2.0f * v - 1.0f) * half;
  switch (i % 3) {
    case 0:  // a car, its length along its heading
      d.shape = BOREAS_COLLIDER_BOX;
      d.half_extents[0] = 2.25f;
      d.half_extents[1] = 0.75f;
      d.half_extents[2] = 0.9f;
      d.pose.position[1] = 0.75f;
      d.pose.orientation[1] = std::sin(-0.5f * heading);
      d.pose.orientation[3] = std::cos(-0.5f * heading);
      speed = 5.0f;
      break;
    case 1:  // a walker
      d.shape = BOREAS_COLLIDER_CAPSULE;
      d.radius = 0.25f;
      d.half_height = 0.65f;
      d.pose.position[1] = 0.9f;
      speed = 1.4f;
      break;
    default:  // a ball, rolling
      d.pose.position[1] = d.radius;
  }
  d.velocity[0] = speed * std::cos(heading);
  d.velocity[2] = speed * std::sin(heading);
  return d;
}

// A collider that has driven out of the forest comes back in on the opposite side.
void wrap(boreas_world world, boreas_collider_id id, float half) {
  boreas_pose pose{};
  check(boreas_collider_get_pose(world, id, &pose));
  bool moved = false;
  for (int a : {0, 2}) {
    if (std::fabs(pose.position[a]) <= half) continue;
    pose.position[a] -= std::copysign(2.0f * half, pose.position[a]);
    moved = true;
  }
  if (moved) check(boreas_collider_set_pose(world, id, &pose));
}

// Steps `world` with `count` colliders driving over the square of half-width `half` m
// about the origin (removed again at the end), and sets the row's counters.
void drive(benchmark::State& state, boreas_world world, float half, int count) {
  check(boreas_world_set_focus(world, kForestFocus, 1));
  std::vector<boreas_collider_id> ids(static_cast<size_t>(count), boreas_collider_id{});
  for (int i = 0; i < count; ++i) {
    const boreas_collider_def d = collider_def(i, half);
    check(boreas_world_add_collider(world, &d, &ids[size_t(i)]));
  }
  // Kernels for this many colliders, levels of detail settled (a frozen tree settles for
  // 3 s before it stops costing).
  for (int s = 0; s < 200; ++s) check(boreas_world_step(world, kForestDt));
  double wind = 0.0, tree = 0.0, underbrush = 0.0, contact = 0.0;
  int64_t touching = 0;
  boreas_step_stats last{};
  for (auto _ : state) {
    for (const boreas_collider_id& id : ids) wrap(world, id, half);
    check(boreas_world_step(world, kForestDt));
    const auto read = Clock::now();
    for (const boreas_collider_id& id : ids) {
      boreas_collider_contact c{};
      check(boreas_collider_get_contact(world, id, &c));
      touching += c.contacts;
    }
    contact += std::chrono::duration<double>(Clock::now() - read).count();
    check(boreas_world_get_step_stats(world, &last));
    wind += last.wind;
    tree += last.trees;
    underbrush += last.underbrush;
  }
  for (const boreas_collider_id& id : ids) check(boreas_world_remove_collider(world, id));
  check(boreas_world_set_focus(world, nullptr, 0));
  const double n = double(state.iterations());
  state.counters["colliders"] = count;
  state.counters["wind_ms"] = 1e3 * wind / n;
  state.counters["trees_ms"] = 1e3 * tree / n;
  state.counters["underbrush_ms"] = 1e3 * underbrush / n;
  state.counters["contact_ms"] = 1e3 * contact / n;
  state.counters["contacts"] = double(touching) / n;
}

void forest_colliders(benchmark::State& state, int count) {
  const std::vector<const char*> mixed{"quaking_aspen", "black_tupelo", "ca_black_oak"};
  ForestFixture& f = forest_fixture(kForestTrees, kForestComponents, mixed);
  drive(state, f.world.world, 0.5f * std::sqrt(float(kForestTrees)) * kTreeSpacing, count);
  state.counters["trees"] = kForestTrees;
  state.counters["components"] = double(f.components);
}

// ---- imported trees ----

constexpr int kMeshTrees = 100;
constexpr float kMeshTreeSpacing = 4.0f;  // m
constexpr float kMeshTreeScale = 0.25f;

// The model as an OBJ file (objects "trunk" and "leaves"), written once per run.
std::string mesh_tree_obj() {
  static const std::string path = [] {
    const std::string p =
        (std::filesystem::temp_directory_path() / "boreas_bench_colliders_tree.obj").string();
    const impl::MeshModel& m = bench_mesh_model(0);
    std::ofstream out(p);
    impl::write_obj(out, m);
    return p;
  }();
  return path;
}

struct MeshForestFixture : Fixture {
  WorldHandle world;
};

void mesh_tree_colliders(benchmark::State& state, int count) {
  MeshForestFixture& f = fixture<MeshForestFixture>("colliders/mesh_trees", [] {
    auto f = std::make_unique<MeshForestFixture>();
    boreas_world_def def = boreas_default_world_def();
    boreas_wave wave = boreas_default_wave();
    wave.amplitude = 4.0f;
    def.waves = &wave;
    def.wave_count = 1;
    check(boreas_world_create(&def, &f->world.world));
    const std::string model = mesh_tree_obj();
    const int side = int(std::ceil(std::sqrt(double(kMeshTrees))));
    for (int i = 0; i < kMeshTrees; ++i) {
      boreas_mesh_tree_def t = boreas_default_mesh_tree_def();
      t.model = model.c_str();
      t.cache = 0;
      t.scale = kMeshTreeScale;
      t.seed = uint64_t(1 + i);
      t.yaw = std::fmod(2.39996f * float(i), 6.2831853f);
      t.position[0] = (float(i % side) - 0.5f * float(side - 1)) * kMeshTreeSpacing;
      t.position[2] = (float(i / side) - 0.5f * float(side - 1)) * kMeshTreeSpacing;
      check(boreas_world_add_mesh_tree(f->world.world, &t, nullptr));
    }
    return f;
  });
  const int side = int(std::ceil(std::sqrt(double(kMeshTrees))));
  drive(state, f.world.world, 0.5f * float(side) * kMeshTreeSpacing, count);
  state.counters["trees"] = kMeshTrees;
}

}  // namespace

void register_collider_benchmarks() {
  for (int n : {0, 10, 100})
    add(
        "BM_Colliders/forest/1000/1M/" + std::to_string(n),
        [=](auto& s) { forest_colliders(s, n); }, benchmark::kMillisecond);
  for (int n : {0, 10, 100})
    add(
        "BM_Colliders/mesh_trees/100/" + std::to_string(n),
        [=](auto& s) { mesh_tree_colliders(s, n); }, benchmark::kMillisecond);
}

}  // namespace boreas::bench
