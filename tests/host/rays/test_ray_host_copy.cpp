// boreas tests: the ray structure read back (RayScene::host_copy) and the cast's traversal
// (cl/shared/ray_cast.h) run on it as C++, against boreas_world_cast_rays in the same
// state: what the native twin of BM_Rays (bench/native_rays.cpp) stands on. The copy must
// hold every buffer the kernel reads, as of the last update, for the C++ cast to find the
// kernel's hits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "api/c_api_guard.h"
#include "ray_forest.h"
#include "rays/ray_checks.h"

#include "rays/host_scene.h"

namespace boreas::reference {
namespace {

std::vector<boreas_hit> cast_on_host(const impl::RayScene::HostCopy& c,
                                     const std::vector<boreas_ray>& rays) {
  const BoreasRayScene s = impl::host_scene(c);
  std::vector<boreas_hit> hits(rays.size());
  for (size_t i = 0; i < rays.size(); ++i)
    boreas_ray_cast_record(&s, reinterpret_cast<const float*>(&rays[i]),
                           reinterpret_cast<float*>(&hits[i]), reinterpret_cast<int*>(&hits[i]));
  return hits;
}

// Two rays that reach everything within 600 m of the origin: a diagonal across that cube
// and one back from its far corner, their origins so far apart that neither the cones nor
// the map of directions leave anything out (ray_reach.h): every branch of every tree is
// boxed. (One ray across the stand reaches every tree, but only the branches it passes.)
std::vector<boreas_ray> everywhere() {
  return {{{-600.0f, -600.0f, -600.0f}, {1.0f, 1.0f, 1.0f}, 2100.0f},
          {{600.0f, 600.0f, 600.0f}, {-1.0f, -1.0f, -1.0f}, 2100.0f}};
}

TEST(RayHostCopy, TheTraversalOnItFindsTheKernelsHits) {
  RayForestDef def;
  def.trees = 3;  // one of each species
  def.components = 3000;
  auto forest = make_ray_forest(def);
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  const std::vector<boreas_ray> rays = forest_rays(*forest, 20000, 11);
  std::vector<boreas_hit> cl(rays.size());
  ASSERT_EQ(boreas_world_cast_rays(forest->world, rays.data(), int(rays.size()), cl.data()),
            BOREAS_OK)
      << boreas_last_error();
  impl::World& world = api::world_of(forest->world);
  const impl::RayScene::HostCopy copy =
      world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), cl.data())).host_copy();
  ASSERT_GE(copy.top_root, 0);
  const std::vector<boreas_hit> host = cast_on_host(copy, rays);
  // The same part at nearly the same distance: the C++ build fuses a * b + c elsewhere than
  // PoCL does (here without FMA at all), and a leaf's plane goes through its frame's
  // normalizations, so most distances agree to 2e-5 of themselves; a ray that grazes a
  // branch's band moves by millimetres for a rounding of its vertices, and one at an edge
  // or a leaf's border may fall on the other side. Measured: 11 of 20,000 rays past 2e-5,
  // 3 past the Embree agreement's 1 mm (one of them another part).
  int hits = 0, close = 0, within_mm = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const boreas_hit &a = host[i], &b = cl[i];
    hits += b.kind != BOREAS_HIT_NONE;
    const bool same_part = a.kind == b.kind && a.part == b.part &&
                           a.object.index == b.object.index && a.object.tag == b.object.tag;
    const float apart = b.kind == BOREAS_HIT_NONE ? 0.0f : std::fabs(a.distance - b.distance);
    close += same_part && apart <= 2e-5f * std::fmax(1.0f, b.distance);
    within_mm += same_part && apart <= 1e-3f;
  }
  const int n = int(rays.size());
  EXPECT_GT(hits, n / 2);  // the rays meet the forest: the comparison means something
  EXPECT_GE(close, n - n / 200) << "of " << n << " rays";
  EXPECT_GE(within_mm, n - n / 1000) << "of " << n << " rays";
}

// The refit after a swaying step (cl/ray_refit.cl, its runs: refit_runs.h) makes each inner
// node after its children: every instance's inner node holds exactly the union of its
// children's boxes (min and max round nothing), and the roots move with the wind.
TEST(RayRefit, EveryInnerNodeIsTheUnionOfItsChildrenAfterASwayingStep) {
  RayForestDef def;
  def.trees = 3;
  def.components = 3000;
  auto forest = make_ray_forest(def);
  const std::vector<boreas_ray> rays = forest_rays(*forest, 2000, 5);
  std::vector<boreas_hit> hits(rays.size());
  impl::World& world = api::world_of(forest->world);
  std::vector<float> first_roots;
  for (int cast = 0; cast < 2; ++cast) {
    for (int s = 0; s < 20; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
    const impl::RayScene::HostCopy c =
        world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), hits.data())).host_copy();
    std::vector<float> roots;
    int inner = 0;
    for (size_t i = 0; i * BOREAS_RAY_INST_WORDS < c.instances.size(); ++i) {
      std::vector<int> stack = {c.instances[i * BOREAS_RAY_INST_WORDS + BOREAS_RAY_INST_ROOT]};
      if (size_t(stack[0] + 1) * BOREAS_RAY_NODE_WORDS > c.nodes.size()) continue;  // no nodes
      const float* root = &c.nodes[size_t(stack[0]) * BOREAS_RAY_NODE_WORDS];
      roots.insert(roots.end(), {root[0], root[1], root[2], root[4], root[5], root[6]});
      while (!stack.empty()) {
        const float* w = &c.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
        stack.pop_back();
        if (boreas_as_int(w[7]) > 0) continue;
        const int a = boreas_as_int(w[3]);
        const float* l = &c.nodes[size_t(a) * BOREAS_RAY_NODE_WORDS];
        const float* r = l + BOREAS_RAY_NODE_WORDS;
        // A child with nothing below it stands nowhere and is left out of the union.
        if (l[0] == BOREAS_RAY_NOWHERE) l = r;
        if (r[0] == BOREAS_RAY_NOWHERE) r = l;
        for (int k : {0, 1, 2}) {
          ASSERT_EQ(w[k], std::fmin(l[k], r[k])) << "instance " << i << ", children " << a;
          ASSERT_EQ(w[k + 4], std::fmax(l[k + 4], r[k + 4])) << "instance " << i;
        }
        ++inner;
        stack.insert(stack.end(), {a, a + 1});
      }
    }
    EXPECT_GT(inner, 1000);
    if (cast == 0) first_roots = roots;
    else EXPECT_NE(roots, first_roots);  // the wind moved the plants between the casts
  }
}

// The cast walks wide nodes (host/src/rays/bvh_wide.h) whose boxes cl/ray_wide.cl gathers
// from the binary nodes after each refit: after swaying steps every leaf slot holds exactly
// the refitted binary leaf's box for its items, every inner slot the union of the slots
// below it, and every item of an instance lies in one leaf slot.
TEST(RayWide, EverySlotHoldsTheRefittedBoxAfterASwayingStep) {
  RayForestDef def;
  def.trees = 3;
  def.components = 3000;
  auto forest = make_ray_forest(def);
  const std::vector<boreas_ray> rays = forest_rays(*forest, 2000, 5);
  std::vector<boreas_hit> hits(rays.size());
  impl::World& world = api::world_of(forest->world);
  for (int cast = 0; cast < 2; ++cast) {
    for (int s = 0; s < 20; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
    const impl::RayScene::HostCopy c =
        world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), hits.data())).host_copy();
    int leaves = 0;
    for (size_t i = 0; i * BOREAS_RAY_INST_WORDS < c.instances.size(); ++i) {
      const int32_t* inst = &c.instances[i * BOREAS_RAY_INST_WORDS];
      const int root = inst[BOREAS_RAY_INST_ROOT];
      if (size_t(root + 1) * BOREAS_RAY_NODE_WORDS > c.nodes.size()) continue;  // no nodes
      // The binary leaves' boxes by their first item (one leaf each).
      std::map<int, const float*> binary;
      std::vector<int> stack = {root};
      while (!stack.empty()) {
        const float* w = &c.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
        stack.pop_back();
        if (boreas_as_int(w[7]) > 0) binary[boreas_as_int(w[3])] = w;
        else stack.insert(stack.end(), {boreas_as_int(w[3]), boreas_as_int(w[3]) + 1});
      }
      std::map<int, int> seen;
      // Each wide node with the slot box that named it (the root: none).
      std::vector<std::pair<int, std::array<float, 6>>> wide = {{inst[BOREAS_RAY_INST_WIDE_ROOT], {}}};
      bool root_node = true;
      while (!wide.empty()) {
        const auto [n, parent] = wide.back();
        wide.pop_back();
        const float* node = &c.wide[size_t(n) * BOREAS_RAY_WIDE_WORDS];
        std::array<float, 6> u = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
        for (int k = 0; k < 4; ++k) {
          const int a = boreas_as_int(node[BOREAS_RAY_WIDE_A + k]);
          const int count = boreas_as_int(node[BOREAS_RAY_WIDE_COUNT + k]);
          if (count < 0) continue;
          std::array<float, 6> box;
          for (int axis = 0; axis < 3; ++axis) {
            box[size_t(axis)] = node[BOREAS_RAY_WIDE_LO + 4 * axis + k];
            box[size_t(axis) + 3] = node[BOREAS_RAY_WIDE_HI + 4 * axis + k];
            u[size_t(axis)] = std::fmin(u[size_t(axis)], box[size_t(axis)]);
            u[size_t(axis) + 3] = std::fmax(u[size_t(axis) + 3], box[size_t(axis) + 3]);
          }
          if (count == 0) {
            wide.push_back({a, box});
            continue;
          }
          ++leaves;
          ASSERT_EQ(binary.count(a), 1u) << "instance " << i << ", wide node " << n << " slot " << k;
          const float* b = binary[a];
          EXPECT_EQ(boreas_as_int(b[7]), count);
          for (int axis = 0; axis < 3; ++axis) {
            ASSERT_EQ(box[size_t(axis)], b[axis]) << "instance " << i << ", items from " << a;
            ASSERT_EQ(box[size_t(axis) + 3], b[4 + axis]) << "instance " << i << ", items from " << a;
          }
          for (int k2 = a; k2 < a + count; ++k2) ++seen[k2];
        }
        if (!root_node) ASSERT_EQ(u, parent) << "instance " << i << ", wide node " << n;
        root_node = false;
      }
      ASSERT_EQ(seen.size(), [&] {
        size_t items = 0;
        for (const auto& [a, b] : binary) items += size_t(boreas_as_int(b[7]));
        return items;
      }());
      for (const auto& [item, times] : seen) ASSERT_EQ(times, 1) << "instance " << i << ", item " << item;
    }
    EXPECT_GT(leaves, 1000);
  }
}

// An update covers what the rays can reach (ray_scene.h): rays cast near one tree refit that
// tree, and neither a tree nor a meadow far away (a meadow once its first refit has bounded
// it); rays that reach everything refit everything.
TEST(RayReach, AnUpdateRefitsOnlyWhatTheRaysCanReach) {
  boreas_world_def wd = boreas_default_world_def();
  boreas_world w = nullptr;
  ASSERT_EQ(boreas_world_create(&wd, &w), BOREAS_OK);
  boreas_tree_def near_tree = boreas_default_tree_def(), far_tree = near_tree;
  far_tree.position[0] = 500.0f;
  boreas_meadow_def far_meadow = boreas_default_meadow_def();
  far_meadow.center[0] = -500.0f;
  far_meadow.size[0] = far_meadow.size[1] = 1.5f;  // some 900 components: one run (add_meadow)
  ASSERT_EQ(boreas_world_add_tree(w, &near_tree, nullptr), BOREAS_OK);
  ASSERT_EQ(boreas_world_add_tree(w, &far_tree, nullptr), BOREAS_OK);
  ASSERT_EQ(boreas_world_add_meadow(w, &far_meadow, nullptr), BOREAS_OK);
  impl::World& world = api::world_of(w);
  const std::vector<boreas_ray> near = {{{0.0f, 3.0f, -8.0f}, {0.0f, 0.0f, 1.0f}, 16.0f}};
  const std::vector<boreas_ray> all = {{{-600.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1200.0f}};
  std::vector<boreas_hit> hits(1);
  auto refitted = [&](const std::vector<boreas_ray>& rays) {
    EXPECT_EQ(boreas_world_step(w, 1.0f / 60.0f), BOREAS_OK);
    return world.update_rays(impl::checked_rays(rays.data(), 1, hits.data())).refitted_instances();
  };
  // The first update refits the meadow, whose bound is not known before.
  EXPECT_EQ(refitted(near), 2);  // the near tree and the meadow
  EXPECT_EQ(refitted(near), 1);  // the near tree alone
  EXPECT_EQ(refitted(all), 3);   // all three
  boreas_world_destroy(w);
}

// A tree is updated only where the rays reach the box of its bark as it stands, widened by
// how far its leaves reach from their branches (RayScene::reached_trees), not wherever
// they reach the sphere it could sway into (some twice its size): a ray a metre beside
// the tree's box, well inside that sphere, updates nothing; one just inside the box
// updates the tree. And what the box leaves out is what no ray hits: rays cast with trees
// left out find the same bits as when every tree is updated in the same state.
TEST(RayReach, ATreeIsUpdatedOnlyWhereTheRaysReachItsBox) {
  boreas_world_def wd = boreas_default_world_def();
  boreas_world w = nullptr;
  ASSERT_EQ(boreas_world_create(&wd, &w), BOREAS_OK);
  boreas_tree_def tree = boreas_default_tree_def();
  ASSERT_EQ(boreas_world_add_tree(w, &tree, nullptr), BOREAS_OK);
  impl::World& world = api::world_of(w);
  std::vector<boreas_hit> hits(2);
  auto update = [&](const std::vector<boreas_ray>& r) {
    EXPECT_EQ(boreas_world_step(w, 1.0f / 60.0f), BOREAS_OK);
    return &world.update_rays(impl::checked_rays(r.data(), int(r.size()), hits.data()));
  };
  const impl::RayScene::HostCopy c = update(everywhere())->host_copy();
  const float* root = &c.nodes[size_t(c.instances[BOREAS_RAY_INST_ROOT]) * BOREAS_RAY_NODE_WORDS];
  const float height = 0.5f * (root[1] + root[5]);
  const boreas_ray beside = {{root[4] + 1.0f, height, -100.0f}, {0.0f, 0.0f, 1.0f}, 200.0f};
  const boreas_ray inside = {{root[4] - 0.05f, height, -100.0f}, {0.0f, 0.0f, 1.0f}, 200.0f};
  EXPECT_EQ(update({beside})->refitted_instances(), 0);
  EXPECT_EQ(update({inside})->refitted_instances(), 1);
  boreas_world_destroy(w);

  RayForestDef def;
  def.trees = 9;
  def.components = 900;
  auto forest = make_ray_forest(def);
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  // A LiDAR's slice: 20 degrees of azimuth from the stand's middle, 16 channels a column.
  std::vector<boreas_ray> rays;
  for (int col = 0; col < 64; ++col)
    for (int ch = 0; ch < 16; ++ch) {
      const double az = (0.3 + 0.35 * col / 63.0), el = (-20.0 + 40.0 * ch / 15.0) * M_PI / 180.0;
      rays.push_back({{0.5f, 1.8f, 0.5f},
                      {float(std::cos(el) * std::cos(az)), float(std::sin(el)), float(std::cos(el) * std::sin(az))},
                      60.0f});
    }
  impl::World& fw = api::world_of(forest->world);
  std::vector<boreas_hit> first(rays.size()), again(rays.size() + 1);
  const int trees = fw.update_rays(impl::checked_rays(rays.data(), int(rays.size()), first.data()))
                        .refitted_instances();
  ASSERT_EQ(boreas_world_cast_rays(forest->world, rays.data(), int(rays.size()), first.data()), BOREAS_OK);
  EXPECT_GT(trees, 0);
  EXPECT_LT(trees, def.trees);  // some trees left out (the meadow is refitted too)
  // The same rays with two that reach everything: every tree updated in the same state.
  std::vector<boreas_ray> all = rays;
  for (const boreas_ray& r : everywhere()) all.push_back(r);
  again.resize(all.size());
  ASSERT_EQ(boreas_world_cast_rays(forest->world, all.data(), int(all.size()), again.data()), BOREAS_OK);
  EXPECT_EQ(fw.update_rays(impl::checked_rays(all.data(), int(all.size()), again.data())).refitted_instances(), 0)
      << "the cast before updated the rest";
  EXPECT_EQ(std::memcmp(first.data(), again.data(), first.size() * sizeof(boreas_hit)), 0);
}

// A meadow is laid into the structure as runs of its components (ray_scene.cpp,
// add_meadow): a ray aimed at each component's first quad names that component (the runs'
// parts count from the meadow's first), a ray over one patch updates only the runs it can
// reach, and those left out are what no ray hits: the same ray cast with the whole meadow
// updated in the same state finds the same bits.
TEST(RayReach, AMeadowIsUpdatedInRunsWhoseHitsNameTheirComponent) {
  RayForestDef def;
  def.trees = 0;
  def.components = 16000;  // sixteen runs of 1,024 and fewer, each some 3 m across
  auto forest = make_ray_forest(def);
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  int vertex_count = 0;
  ASSERT_EQ(boreas_meadow_get_vertices(forest->world, forest->meadow, nullptr, nullptr, 0,
                                       &vertex_count, nullptr), BOREAS_OK);
  std::vector<boreas_meadow_vertex> v(static_cast<size_t>(vertex_count));
  std::vector<int32_t> counts(size_t(vertex_count / BOREAS_MEADOW_VERTEX_STRIDE));
  ASSERT_EQ(boreas_meadow_get_vertices(forest->world, forest->meadow, nullptr, v.data(), vertex_count,
                                       &vertex_count, counts.data()), BOREAS_OK);
  ASSERT_GT(counts.size(), size_t(15 * 1024));  // about what was asked
  // A ray 0.1 mm off the middle of each component's first quad, along its normal.
  std::vector<boreas_ray> rays;
  for (size_t c = 0; c < counts.size(); ++c) {
    const boreas_meadow_vertex* q = &v[c * BOREAS_MEADOW_VERTEX_STRIDE];
    boreas_ray r{};
    for (int k = 0; k < 3; ++k) {
      const float mid = 0.25f * (q[0].position[k] + q[1].position[k] + q[2].position[k] + q[3].position[k]);
      r.origin[k] = mid + 1e-4f * q[0].normal[k];
      r.direction[k] = -q[0].normal[k];
    }
    r.max_distance = 1e-2f;
    rays.push_back(r);
  }
  std::vector<boreas_hit> hits(rays.size());
  ASSERT_EQ(boreas_world_cast_rays(forest->world, rays.data(), int(rays.size()), hits.data()), BOREAS_OK);
  int named = 0;
  for (size_t c = 0; c < hits.size(); ++c) named += hits[c].kind == BOREAS_HIT_UNDERBRUSH && hits[c].part == int(c);
  EXPECT_GE(named, 0.99 * double(hits.size()));

  // Straight down onto component 0 (a corner of the meadow: its runs are in Z-order) from
  // half a metre above it: the runs near that corner (their sway bounds are some three
  // times their patches) and no others.
  ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  const boreas_meadow_vertex& base = v[0];
  const boreas_ray down = {{base.position[0], base.position[1] + 0.5f, base.position[2]}, {0.0f, -1.0f, 0.0f}, 1.0f};
  impl::World& world = api::world_of(forest->world);
  std::vector<boreas_hit> first(1), again(2);
  const int runs = world.update_rays(impl::checked_rays(&down, 1, first.data())).refitted_instances();
  EXPECT_GE(runs, 1);
  EXPECT_LT(runs, 8);
  ASSERT_EQ(boreas_world_cast_rays(forest->world, &down, 1, first.data()), BOREAS_OK);
  const std::vector<boreas_ray> all = {down, {{-600.0f, 0.1f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1200.0f}};
  ASSERT_EQ(boreas_world_cast_rays(forest->world, all.data(), 2, again.data()), BOREAS_OK);
  EXPECT_EQ(world.update_rays(impl::checked_rays(all.data(), 2, again.data())).refitted_instances(), 0)
      << "the cast before updated the rest";
  EXPECT_EQ(std::memcmp(first.data(), again.data(), sizeof(boreas_hit)), 0);
}

// In a tree the rays reach, only the branches they reach are boxed (ray_scene.cpp,
// select_branches): a fan of level rays through the stand's lower crowns boxes some
// branches and leaves the rest out (the same rays with one more that reaches everything, in
// the same step, box the rest); and what is left out is what no ray hits: the fan's hits
// are the same bits either way. At the next step rays from just above the crowns reach
// branches the fan did not (their boxes were emptied at the last update, or never made),
// and find the same bits as when every branch is boxed in that state.
TEST(RayReach, ATreeIsUpdatedOnlyInTheBranchesTheRaysReach) {
  RayForestDef def;
  def.trees = 3;
  auto forest = make_ray_forest(def);
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  impl::World& world = api::world_of(forest->world);
  const float half = forest->half_extent;
  std::vector<boreas_ray> low, high;
  for (int col = 0; col < 64; ++col)
    for (int ch = 0; ch < 8; ++ch) {
      const double az = 0.6 * (col / 63.0 - 0.5), el = (-4.0 + 8.0 * ch / 7.0) * M_PI / 180.0;
      low.push_back({{-half - 8.0f, 1.5f, 0.0f},
                     {float(std::cos(el) * std::cos(az)), float(std::sin(el)), float(std::cos(el) * std::sin(az))},
                     2.0f * half + 16.0f});
    }
  for (int i = 0; i < 48; ++i)
    for (int k = 0; k < 48; ++k)
      high.push_back({{-half - 2.0f + (2.0f * half + 4.0f) * float(i) / 47.0f, forest->top + 3.0f,
                       -half - 2.0f + (2.0f * half + 4.0f) * float(k) / 47.0f},
                      {0.0f, -1.0f, 0.0f}, 5.0f});
  // Casts `rays`, then them and everywhere() in the same step: the branches each update
  // boxed, and the first cast's hits, which must be the same bits in the second.
  auto cast_both = [&](const std::vector<boreas_ray>& rays, int* boxed, int* rest) {
    std::vector<boreas_hit> first(rays.size()), again(rays.size() + 2);
    EXPECT_EQ(boreas_world_cast_rays(forest->world, rays.data(), int(rays.size()), first.data()), BOREAS_OK);
    *boxed = world.update_rays(impl::checked_rays(rays.data(), int(rays.size()), first.data())).boxed_branches();
    std::vector<boreas_ray> all = rays;
    for (const boreas_ray& r : everywhere()) all.push_back(r);
    const impl::RayScene& scene = world.update_rays(impl::checked_rays(all.data(), int(all.size()), again.data()));
    *rest = scene.boxed_branches();
    EXPECT_EQ(boreas_world_cast_rays(forest->world, all.data(), int(all.size()), again.data()), BOREAS_OK);
    EXPECT_EQ(std::memcmp(first.data(), again.data(), first.size() * sizeof(boreas_hit)), 0);
    int hit = 0;
    for (const boreas_hit& h : first) hit += h.kind != BOREAS_HIT_NONE;
    return hit;
  };
  int boxed = 0, rest = 0;
  ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  EXPECT_GT(cast_both(low, &boxed, &rest), int(low.size()) / 10);
  EXPECT_EQ(boxed, 0) << "the cast before boxed them";
  ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  std::vector<boreas_hit> hits(low.size());
  const impl::RayScene& low_scene = world.update_rays(impl::checked_rays(low.data(), int(low.size()), hits.data()));
  const int low_boxed = low_scene.boxed_branches();
  EXPECT_GT(low_boxed, 0);
  // The branches left out have their boxes emptied, and a node with nothing below it stands
  // nowhere rather than inverted (which the slab test would take for all of space): every
  // node's box is a box or that point.
  const impl::RayScene::HostCopy copy = low_scene.host_copy();
  int nowhere = 0, inverted = 0;
  for (size_t i = 0; i * BOREAS_RAY_INST_WORDS < copy.instances.size(); ++i) {
    if (copy.instances[i * BOREAS_RAY_INST_WORDS + BOREAS_RAY_INST_TYPE] != BOREAS_RAY_TYPE_TREE) continue;
    std::vector<int> stack = {copy.instances[i * BOREAS_RAY_INST_WORDS + BOREAS_RAY_INST_ROOT]};
    while (!stack.empty()) {
      const float* w = &copy.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
      stack.pop_back();
      nowhere += w[0] == BOREAS_RAY_NOWHERE;
      inverted += w[0] != BOREAS_RAY_NOWHERE && (w[0] > w[4] || w[1] > w[5] || w[2] > w[6]);
      if (boreas_as_int(w[7]) == 0) stack.insert(stack.end(), {boreas_as_int(w[3]), boreas_as_int(w[3]) + 1});
    }
  }
  EXPECT_GT(nowhere, 0);
  EXPECT_EQ(inverted, 0);
  std::vector<boreas_ray> all = low;
  for (const boreas_ray& r : everywhere()) all.push_back(r);
  hits.resize(all.size());
  const int left_out =
      world.update_rays(impl::checked_rays(all.data(), int(all.size()), hits.data())).boxed_branches();
  EXPECT_GT(left_out, low_boxed) << "the low fan reaches most of the crowns";
  ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  // The crowns' tops, not reached by the fan at the last update.
  EXPECT_GT(cast_both(high, &boxed, &rest), 24);  // 48 of the 2,304 meet a crown
  EXPECT_EQ(boxed, 0) << "the cast before boxed them";
}

// A tree's leaves placed in runs (TreeBatch::enqueue_leaf_runs, the ray structure's placing
// of its reached branches' leaves) are the whole tree's records, bit for bit, in every run;
// and a leaf more than a tile from every run is left as it was.
TEST(RayReach, LeavesPlacedInRunsAreTheWholeTreesRecords) {
  RayForestDef def;
  def.trees = 1;
  auto forest = make_ray_forest(def);
  for (int s = 0; s < 3; ++s) ASSERT_EQ(boreas_world_step(forest->world, 1.0f / 60.0f), BOREAS_OK);
  impl::World& world = api::world_of(forest->world);
  const impl::TreeInstance& tree = world.tree(forest->trees[0]);
  impl::TreeBatch& batch = world.tree_batch(tree);
  const int32_t n = int32_t(tree.model->leaf_count());
  ASSERT_GT(n, 20000) << "runs far apart need a tree of many tiles";
  constexpr size_t kPlanes = BOREAS_LEAF_RECORD_FLOATS;
  const size_t bytes = size_t(n) * kPlanes * sizeof(float);
  impl::Runtime& rt = world.runtime();
  const std::vector<float> sentinel(size_t(n) * kPlanes, -7.0f);
  cl::Buffer whole = rt.buffer(CL_MEM_READ_WRITE, bytes, "test whole"), runs = rt.buffer(CL_MEM_READ_WRITE, bytes, "test runs");
  rt.write(runs, 0, bytes, sentinel.data());
  batch.enqueue_leaf_records(tree.key, whole, 0);
  // A run at the start, one inside, one crossing where the first's tile would end, the last leaf.
  const std::vector<int32_t> placed = {0, 3, 9000, 17, 9010, 1500, n - 1, 1};
  batch.enqueue_leaf_runs(tree.key, runs, 0, placed);
  std::vector<float> a(size_t(n) * kPlanes), b(a.size());
  rt.read(whole, 0, bytes, a.data());
  rt.read(runs, 0, bytes, b.data());
  for (size_t r = 0; r < placed.size(); r += 2)
    for (int32_t i = placed[r]; i < placed[r] + placed[r + 1]; ++i)
      ASSERT_EQ(std::memcmp(&a[size_t(i) * kPlanes], &b[size_t(i) * kPlanes], kPlanes * sizeof(float)), 0)
          << "leaf " << i;
  // Leaves 4500 and 15000 lie more than a tile (at most 16 lanes of 64 items) from every run.
  for (const int32_t i : {4500, 15000}) EXPECT_EQ(b[size_t(i) * kPlanes], -7.0f) << "leaf " << i;
}

// The primitives of every tree whose hierarchy's leaf box the ray enters within t_max (no
// nearest hit stops the walk): fn(instance, its words, primitive).
template <class Fn>
void for_each_entered_primitive(const impl::RayScene::HostCopy& c, const BoreasRay& r, float t_max,
                                Fn fn) {
  for (size_t i = 0; i * BOREAS_RAY_INST_WORDS < c.instances.size(); ++i) {
    const int32_t* inst = &c.instances[i * BOREAS_RAY_INST_WORDS];
    if (inst[BOREAS_RAY_INST_TYPE] != BOREAS_RAY_TYPE_TREE) continue;
    std::vector<int> stack = {inst[BOREAS_RAY_INST_ROOT]};
    while (!stack.empty()) {
      const float* node = &c.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
      stack.pop_back();
      if (boreas_ray_node_box(&r, node, t_max) < 0.0f) continue;
      const int a = boreas_as_int(node[3]), count = boreas_as_int(node[7]);
      if (count == 0) stack.insert(stack.end(), {a, a + 1});
      for (int k = a; k < a + count; ++k) fn(int(i), inst, c.items[size_t(k)]);
    }
  }
}

struct WindyForestCopy {
  std::unique_ptr<RayForest> forest;
  std::vector<boreas_ray> rays;
  impl::RayScene::HostCopy copy;
};

// Three trees and their meadow after ten windy steps, 4,000 rays of the forest's mix, and
// the structure updated for them, read back.
WindyForestCopy windy_forest_copy() {
  WindyForestCopy w;
  RayForestDef def;
  def.trees = 3;
  def.components = 300;
  w.forest = make_ray_forest(def);
  for (int s = 0; s < 10; ++s) EXPECT_EQ(boreas_world_step(w.forest->world, 1.0f / 60.0f), BOREAS_OK);
  w.rays = forest_rays(*w.forest, 4000, 23);
  std::vector<boreas_hit> hits(w.rays.size());
  impl::World& world = api::world_of(w.forest->world);
  w.copy = world.update_rays(impl::checked_rays(w.rays.data(), int(w.rays.size()), hits.data())).host_copy();
  return w;
}

BoreasRay ray_of(const boreas_ray& in) {
  return boreas_ray_make(boreas_v3(in.origin[0], in.origin[1], in.origin[2]),
                         boreas_v3_normalize(boreas_v3(in.direction[0], in.direction[1], in.direction[2])));
}

// The cast asks boreas_ray_band_near (cl/shared/ray_cast.h) whether a ray can meet a bark
// band before it makes the band's triangles: a band it turns away must be one the ray's
// triangles would not hit, or the hits would change. Every band whose leaf box a ray of the
// forest's mix enters is asked, and its triangles made: none turned away is hit; and the
// test pays (it turns away most of the bands whose boxes let the ray in: a slanted
// branch's box is mostly empty).
TEST(RayBand, ABandTurnedAwayBeforeItsTrianglesHasNoHit) {
  const WindyForestCopy w = windy_forest_copy();
  const impl::RayScene::HostCopy& c = w.copy;
  int64_t asked = 0, turned_away = 0, hit = 0, wrongly = 0;
  for (const boreas_ray& in : w.rays) {
    const BoreasRay r = ray_of(in);
    for_each_entered_primitive(c, r, in.max_distance, [&](int i, const int32_t* inst, int p) {
      if (p >= inst[BOREAS_RAY_INST_BAND_COUNT]) return;  // a leaf
      const float* band = &c.bands[size_t(inst[BOREAS_RAY_INST_BANDS] + p) * BOREAS_RAY_BAND_FLOATS];
      const int b = int(band[BOREAS_RAY_BAND_BRANCH]), ring = int(band[BOREAS_RAY_BAND_RING]);
      const float* rec = &c.branches[size_t(inst[BOREAS_RAY_INST_BRANCHES] + b) * BOREAS_RAY_BRANCH_FLOATS];
      const float* shape = &c.shapes[size_t(inst[BOREAS_RAY_INST_SHAPES] + b) * BOREAS_RAY_SHAPE_FLOATS];
      const BoreasBezier curve = {boreas_ray_load3(rec, 0), boreas_ray_load3(rec, 3),
                                  boreas_ray_load3(rec, 6), boreas_ray_load3(rec, 9)};
      const float scale = boreas_as_float(inst[BOREAS_RAY_INST_SCALE]);
      const int rings = int(shape[BOREAS_RAY_SHAPE_RINGS]);
      const float cap = shape[BOREAS_RAY_SHAPE_TIP_CAP];  // rings round a cap: boreas_ring_v
      const bool near = boreas_ray_band_near(&r, curve, boreas_ring_v(float(ring), rings, cap),
                                             boreas_ring_v(float(ring + 1), rings, cap),
                                             band[BOREAS_RAY_BAND_BOUND] * scale) != 0;
      BoreasRayHit h;
      h.t = in.max_distance;
      h.kind = BOREAS_RAY_HIT_NONE;
      boreas_ray_band(&r, curve, boreas_sloan_frame(curve, boreas_ray_load3(rec, 12)),
                      boreas_ray_shape_radius(shape, scale), ring, rings,
                      int(shape[BOREAS_RAY_SHAPE_SIDES]), i, b, &h);
      ++asked;
      turned_away += !near;
      hit += h.kind != BOREAS_RAY_HIT_NONE;
      wrongly += !near && h.kind != BOREAS_RAY_HIT_NONE;
    });
  }
  EXPECT_GT(hit, 1000) << "the rays meet the bark: the check means something";
  EXPECT_EQ(wrongly, 0) << "bands turned away though the ray hits them, of " << hit << " hit";
  EXPECT_GT(turned_away, asked / 2) << "of " << asked << " bands asked";
  std::printf("bands asked %lld, turned away %lld, hit %lld\n", (long long)asked,
              (long long)turned_away, (long long)hit);
}

// The cast reads a tree's primitives from records in its hierarchy's item order
// (cl/shared/ray_types.h, BOREAS_RAY_PRIM_*) that the update writes beside their boxes: item
// k's record must be primitive items[k] as the structure holds it, a bark band's template
// words or a leaf as placed at this update (its axis and normal made units, its blade at the
// tree's scale), each leaf once.
TEST(RayRecords, EachTreeItemsRecordIsItsPrimitiveAsPlaced) {
  const WindyForestCopy w = windy_forest_copy();
  const impl::RayScene::HostCopy& c = w.copy;
  int trees = 0;
  for (size_t i = 0; i * BOREAS_RAY_INST_WORDS < c.instances.size(); ++i) {
    const int32_t* inst = &c.instances[i * BOREAS_RAY_INST_WORDS];
    if (inst[BOREAS_RAY_INST_TYPE] != BOREAS_RAY_TYPE_TREE) continue;
    ++trees;
    const int bands = inst[BOREAS_RAY_INST_BAND_COUNT];
    const float scale = boreas_as_float(inst[BOREAS_RAY_INST_SCALE]);
    std::vector<int> seen;
    std::vector<int> stack = {inst[BOREAS_RAY_INST_ROOT]};
    while (!stack.empty()) {
      const float* node = &c.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
      stack.pop_back();
      const int a = boreas_as_int(node[3]), count = boreas_as_int(node[7]);
      if (count == 0) stack.insert(stack.end(), {a, a + 1});
      for (int k = a; k < a + count; ++k) {
        const int p = c.items[size_t(k)];
        const float* rec = &c.records[size_t(k + inst[BOREAS_RAY_INST_RECORDS]) * BOREAS_RAY_PRIM_FLOATS];
        const int index = boreas_as_int(rec[BOREAS_RAY_PRIM_INDEX]);
        if (p < bands) {
          ASSERT_EQ(index, -1) << "tree " << i << " item " << k << " (band " << p << ")";
          const float* band = &c.bands[size_t(inst[BOREAS_RAY_INST_BANDS] + p) * BOREAS_RAY_BAND_FLOATS];
          for (int q = 0; q < 3; ++q) EXPECT_EQ(rec[q], band[q]) << "band " << p << " word " << q;
          continue;
        }
        const int l = p - bands;
        ASSERT_EQ(index, l) << "tree " << i << " item " << k;
        seen.push_back(l);
        const float* placed = &c.placed[size_t(inst[BOREAS_RAY_INST_PLACED] + l) * BOREAS_RAY_PLACED_FLOATS];
        const float* blade = &c.leaves[size_t(inst[BOREAS_RAY_INST_LEAVES] + l) * BOREAS_RAY_LEAF_FLOATS];
        const BoreasV3 axis = boreas_v3_normalize(boreas_ray_load3(placed, BOREAS_TREE_LEAF_OUT_AXIS));
        const BoreasV3 normal = boreas_v3_normalize(boreas_ray_load3(placed, BOREAS_TREE_LEAF_OUT_NORMAL));
        const float want[11] = {placed[BOREAS_TREE_LEAF_OUT_POSITION], placed[BOREAS_TREE_LEAF_OUT_POSITION + 1],
                                placed[BOREAS_TREE_LEAF_OUT_POSITION + 2], axis.x, axis.y, axis.z,
                                normal.x, normal.y, normal.z, blade[BOREAS_RAY_LEAF_LENGTH] * scale,
                                blade[BOREAS_RAY_LEAF_WIDTH] * scale};
        // The units as PoCL rounds them: within a few ulps of the C++ build's.
        for (int q = 0; q < 11; ++q)
          EXPECT_NEAR(rec[q], want[q], q >= 3 && q < 9 ? 1e-6f : 0.0f) << "leaf " << l << " word " << q;
      }
    }
    std::sort(seen.begin(), seen.end());
    ASSERT_FALSE(seen.empty());
    for (size_t l = 0; l < seen.size(); ++l) ASSERT_EQ(seen[l], int(l)) << "tree " << i << ": each leaf once";
  }
  EXPECT_EQ(trees, 3);
}

}  // namespace
}  // namespace boreas::reference
