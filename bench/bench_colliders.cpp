// boreas benchmarks: BM_Colliders — what moving colliders add to a step of the forest of
// BM_ForestStep (1,000 trees of three species over a million underbrush components, levels
// of detail on): 0, 10 and 100 colliders, a third each cars (4.5 x 1.5 x 1.8 m boxes at
// 5 m/s), walkers (capsules 1.8 m tall at 1.4 m/s) and balls (0.11 m spheres at 3 m/s),
// spread over the forest and driving on in straight lines (wrapped back in at its edge).
// Each step also reads every collider's contact, as a simulator would. The 0 row is the
// forest alone, measured the same way, so the rows' difference is the colliders' cost.
// Times are wall clock of the library's calls; the device's stage times come from
// boreas_world_get_step_stats.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_forest.h"
#include "bench_harness.h"
#include "boreas/boreas.h"

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

void colliders_step(benchmark::State& state, int count) {
  const std::vector<const char*> mixed{"quaking_aspen", "black_tupelo", "ca_black_oak"};
  ForestFixture& f = forest_fixture(kForestTrees, kForestComponents, mixed);
  boreas_world world = f.world.world;
  const float half = 0.5f * std::sqrt(float(kForestTrees)) * kTreeSpacing;
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  check(boreas_world_set_focus(world, focus, 1));
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
  state.counters["trees"] = kForestTrees;
  state.counters["components"] = double(f.components);
  state.counters["wind_ms"] = 1e3 * wind / n;
  state.counters["trees_ms"] = 1e3 * tree / n;
  state.counters["underbrush_ms"] = 1e3 * underbrush / n;
  state.counters["contact_ms"] = 1e3 * contact / n;
  state.counters["contacts"] = double(touching) / n;
}

}  // namespace

void register_collider_benchmarks() {
  for (int n : {0, 10, 100})
    add(
        "BM_Colliders/forest/1000/1M/" + std::to_string(n),
        [=](auto& s) { colliders_step(s, n); }, benchmark::kMillisecond);
}

}  // namespace boreas::bench
