// boreas tests: the imported-tree kernels (cl/mesh_tree_*.cl) against their double
// reference, in calm, in steady wind, and as the wind changes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

#include "host/mesh_trees/tube_trees.h"
#include "mesh_trees/mesh_tree_drag.h"
#include "reference/mesh_tree_reference.h"
#include "shared/mesh_tree_types.h"
#include "support/test_support.h"

namespace boreas {
namespace {

constexpr uint64_t kKey = 1000;  // the batch's handle, apart from the world's own keys

std::shared_ptr<impl::MeshTreeInstance> tube_tree_instance(
    boreas_mesh_tree_def def = boreas_default_mesh_tree_def()) {
  test::TubeTree tubes = test::make_tube_tree();
  auto tree = std::make_shared<impl::MeshTreeInstance>();
  def.model = "tube tree";
  def.position[0] = 3.0f;
  def.position[2] = -2.0f;
  def.yaw = 0.4f;
  def.scale = 1.5f;
  tree->params = impl::checked_mesh_tree_def(def);
  tree->model = tubes.model;
  tree->data = impl::compute_mesh_tree(tree->model, 11);
  tree->drag = impl::mesh_tree_drag(tree->model);
  tree->noise = impl::make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, 2.0, 11);
  tree->key = kKey;
  return tree;
}

std::vector<glm::dvec3> positions(const std::vector<boreas_vertex>& v) {
  std::vector<glm::dvec3> out;
  for (const boreas_vertex& x : v) out.emplace_back(x.position[0], x.position[1], x.position[2]);
  return out;
}

std::vector<glm::dvec3> branch_wind(impl::MeshTreeBatch& batch) {
  std::vector<float> w = batch.branch_wind(kKey);
  std::vector<glm::dvec3> out;
  for (size_t i = 0; i < w.size(); i += 3) out.emplace_back(w[i], w[i + 1], w[i + 2]);
  return out;
}

// A world on the calm grid whose wind is `wave` alone (none: calm), with `tree` added to
// its imported-tree batch.
std::unique_ptr<impl::World> world_with(std::shared_ptr<impl::MeshTreeInstance> tree,
                                        const boreas_wave* wave = nullptr) {
  boreas_grid_def grid = test::calm_grid();
  auto world = test::make_world(&grid);
  if (wave) world->wind().set_waves(wave, 1, 0.0f, world->time());
  world->mesh_tree_batch().add(std::move(tree), world->time());
  return world;
}

TEST(MeshTreeKernels, NoWindNoDisplacement) {
  auto tree = tube_tree_instance();
  auto world = world_with(tree);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  std::vector<boreas_vertex> trunk0 = batch.trunk_vertices(kKey),
                             leaves0 = batch.leaf_vertices(kKey);
  for (int s = 0; s < 5; ++s) world->step(0.05f);
  std::vector<boreas_vertex> trunk = batch.trunk_vertices(kKey), leaves = batch.leaf_vertices(kKey);
  ASSERT_EQ(trunk.size(), tree->model.trunk.vertex_count());
  ASSERT_EQ(leaves.size(), tree->model.leaves.vertex_count());
  EXPECT_EQ(0, std::memcmp(trunk.data(), trunk0.data(), trunk.size() * sizeof(boreas_vertex)));
  EXPECT_EQ(0, std::memcmp(leaves.data(), leaves0.data(), leaves.size() * sizeof(boreas_vertex)));
  // And that rest pose is the model placed: scaled, turned, moved.
  float placed[3];
  impl::place_point(tree->params, &tree->model.trunk.positions[0], placed);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(trunk[0].position[a], placed[a]);
}

TEST(MeshTreeKernels, SteadyWindMatchesDoubleReference) {
  boreas_wave wave = test::steady_wave(0.8f, 0.6f, 12.0f);
  auto tree = tube_tree_instance();
  auto world = world_with(tree, &wave);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const float dt = 0.04f;
  const glm::dvec3 wind(0.8 * 12.0, 0.0, 0.6 * 12.0);
  glm::dvec2 roll(0.0);
  double largest = 0.0;
  for (int s = 1; s <= 30; ++s) {
    world->step(dt);
    // The uniform wind reaches every branch at once (a fresh tree starts at the wind).
    std::vector<glm::dvec3> felt = branch_wind(batch);
    for (const glm::dvec3& w : felt) ASSERT_LT(glm::distance(w, wind), 1e-4);
    roll += glm::dvec2(felt[0].x, felt[0].z) * double(dt) / double(tree->params.flutter_wavelength);
    roll -= glm::floor(roll);
    if (s % 10 != 0) continue;
    reference::MeshTreePose ref = reference::mesh_tree_pose(*tree, felt, roll, world->time());
    std::vector<glm::dvec3> trunk = positions(batch.trunk_vertices(kKey));
    std::vector<boreas_vertex> leaves = batch.leaf_vertices(kKey);
    for (size_t v = 0; v < trunk.size(); ++v) {
      // float32 positions of a tree 12 m across: a few ulp of 10 m plus the noise's
      // float lookup.
      ASSERT_LT(glm::distance(trunk[v], ref.trunk[v]), 2e-5)
          << "trunk vertex " << v << " step " << s;
      float rest[3];
      impl::place_point(tree->params, &tree->model.trunk.positions[3 * v], rest);
      largest = std::max(largest, glm::distance(trunk[v], glm::dvec3(rest[0], rest[1], rest[2])));
    }
    for (size_t v = 0; v < leaves.size(); ++v) {
      glm::dvec3 p(leaves[v].position[0], leaves[v].position[1], leaves[v].position[2]);
      glm::dvec3 n(leaves[v].normal[0], leaves[v].normal[1], leaves[v].normal[2]);
      ASSERT_LT(glm::distance(p, ref.leaves[v]), 2e-5) << "leaf vertex " << v << " step " << s;
      ASSERT_LT(glm::distance(n, ref.leaf_normals[v]), 1e-5) << "leaf vertex " << v;
    }
  }
  // 12 m/s moves the tips by about their bend and sway amplitudes (0.3 m + 0.25 m ...).
  EXPECT_GT(largest, 0.2);
  EXPECT_LT(largest, 2.0);
}

// Branch b's response time to a change of its wind along the wind (s): its level's, plus
// the air's J = (2 + b') bend L(|W|) / |W| (cl/shared/mesh_tree_math.h, boreas_mesh_tree_follow),
// in double; `air` false leaves the air out.
double response_time(const impl::MeshTreeInstance& tree, size_t b, double speed, bool air = true) {
  const impl::MeshTreeBranch& br = tree.data.branches[b];
  const double tau = tree.params.levels[std::min(br.level, 3)].response_time;
  if (!air || br.level > 3) return tau;
  const double bend = tree.params.levels[size_t(br.level)].bend;
  const double above = speed / impl::kMeshTreeVogelSpeed;
  const double r = above > 1.0 ? std::pow(above, tree.drag.vogel_b) : 1.0;
  const double load = tree.drag.load_per_speed2 * speed * speed * r;
  return tau + (2.0 + (above > 1.0 ? tree.drag.vogel_b : 0.0)) * bend * load / speed;
}

// Each level follows a change of wind with its own lag, lengthened by the air: backward
// Euler of (tau + J) dW/dt = wind - W, W_{n+1} = W_n + dt / (tau + J(W_n) + dt) (wind - W_n).
TEST(MeshTreeKernels, LevelsFollowTheWindWithTheirResponseTimes) {
  boreas_wave calm = test::steady_wave(1.0f, 0.0f, 2.0f);
  auto tree = tube_tree_instance();
  auto world = world_with(tree, &calm);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const float dt = 0.05f;
  world->step(dt);
  boreas_wave gust = test::steady_wave(1.0f, 0.0f, 10.0f);
  world->wind().set_waves(&gust, 1, 0.0f, world->time());
  std::vector<double> expected(tree->data.branches.size(), 2.0);
  for (int s = 0; s < 20; ++s) {
    world->step(dt);
    std::vector<glm::dvec3> felt = branch_wind(batch);
    for (size_t b = 0; b < felt.size(); ++b) {
      expected[b] += dt / (response_time(*tree, b, expected[b]) + dt) * (10.0 - expected[b]);
      ASSERT_NEAR(felt[b].x, expected[b], 1e-4) << "branch " << b << " step " << s;
    }
  }
  // The stem lags the twigs.
  std::vector<glm::dvec3> felt = branch_wind(batch);
  EXPECT_LT(felt[0].x, felt.back().x - 1.0);
}

// After a storm, in calm air: each branch's wind (its bend) relaxes as the equation
// (tau + J(W)) dW/dt = -W says, integrated in double by RK4 (small steps, so the backward
// Euler's own error stays under 1 %), and slower than without the air (tau alone), most
// where the branch bends most.
TEST(MeshTreeKernels, CalmAirHoldsBackABranchSpringingBack) {
  const double storm = 30.0;
  boreas_wave gale = test::steady_wave(1.0f, 0.0f, float(storm));
  auto tree = tube_tree_instance();
  auto world = world_with(tree, &gale);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  const float dt = 0.0005f;
  world->step(dt);  // fresh: every branch at the storm's wind
  world->wind().set_waves(nullptr, 0, 0.0f, world->time());
  const size_t nb = tree->data.branches.size();
  std::vector<double> ref(nb, storm), still(nb, storm);
  double worst = 0.0, slowest = 0.0;
  for (int s = 1; s <= 600; ++s) {
    world->step(dt);
    std::vector<glm::dvec3> felt = branch_wind(batch);
    for (size_t b = 0; b < nb; ++b) {
      for (int k = 0; k < 10; ++k) {  // RK4 of W' = -W / T(W) over dt / 10
        const double h = dt / 10.0;
        auto f = [&](double w) { return -w / response_time(*tree, b, std::max(w, 1e-9)); };
        const double k1 = f(ref[b]), k2 = f(ref[b] + h / 2 * k1), k3 = f(ref[b] + h / 2 * k2),
                     k4 = f(ref[b] + h * k3);
        ref[b] += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        still[b] *= std::exp(-h / response_time(*tree, b, storm, false));
      }
      worst = std::max(worst, std::fabs(felt[b].x - ref[b]) / storm);
      EXPECT_GT(felt[b].x, still[b] - 1e-4) << "branch " << b << " step " << s;
      slowest = std::max(slowest, felt[b].x / still[b]);
    }
  }
  std::printf("    after 0.3 s of calm: worst gap to the equation %.2g of the storm's wind; the air "
              "holds a branch's wind up to %.2f times the no-air value\n", worst, slowest);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(slowest, 1.1) << "the air's hold is visible";
}

TEST(MeshTreeKernels, LeavesTurnRigidlyIntoTheWind) {
  boreas_wave wave = test::steady_wave(0.0f, 1.0f, 15.0f);
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  for (boreas_mesh_level_def& l : def.levels) l.bend = l.sway = 0.0f;
  def.leaf_flutter = 0.0f;
  def.leaf_turn = 1.0f;
  auto world = world_with(tube_tree_instance(def), &wave);
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  std::vector<boreas_vertex> rest = batch.leaf_vertices(kKey);
  world->step(0.05f);
  std::vector<boreas_vertex> moved = batch.leaf_vertices(kKey);
  const glm::dvec3 toward(0.0, 0.0, 1.0);
  double downwind = 0.0;
  size_t leaves = moved.size() / 4;
  for (size_t leaf = 0; leaf * 4 < moved.size(); ++leaf) {
    auto at = [&](const std::vector<boreas_vertex>& v, size_t i) {
      return glm::dvec3(v[i].position[0], v[i].position[1], v[i].position[2]);
    };
    // Rigid: every pairwise distance kept.
    for (size_t i = 4 * leaf; i < 4 * leaf + 4; ++i)
      for (size_t j = i + 1; j < 4 * leaf + 4; ++j)
        EXPECT_NEAR(glm::distance(at(moved, i), at(moved, j)),
                    glm::distance(at(rest, i), at(rest, j)), 1e-5);
    // Turned towards the wind: the leaf's centre moved downwind (by how much depends on
    // how far its axis was from the wind to begin with).
    glm::dvec3 c_rest(0.0), c_moved(0.0);
    for (size_t i = 4 * leaf; i < 4 * leaf + 4; ++i)
      c_rest += at(rest, i) / 4.0, c_moved += at(moved, i) / 4.0;
    EXPECT_GT(glm::dot(c_moved - c_rest, toward), 0.0) << "leaf " << leaf;
    downwind += glm::dot(c_moved - c_rest, toward) / double(leaves);
  }
  EXPECT_GT(downwind, 0.01);  // m, leaves 0.13 m long turned about 0.6 of the way
}

TEST(MeshTreeKernels, SameInputsGiveBitIdenticalVertices) {
  std::vector<boreas_vertex> runs[2];
  for (auto& run : runs) {
    boreas_wave wave = test::steady_wave(0.6f, 0.8f, 9.0f);
    wave.sharpness = 2.0f;
    auto world = world_with(tube_tree_instance(), &wave);
    impl::MeshTreeBatch& batch = world->mesh_tree_batch();
    for (int s = 0; s < 8; ++s) world->step(0.03f);
    run = batch.leaf_vertices(kKey);
    std::vector<boreas_vertex> trunk = batch.trunk_vertices(kKey);
    run.insert(run.end(), trunk.begin(), trunk.end());
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_EQ(0, std::memcmp(runs[0].data(), runs[1].data(), runs[0].size() * sizeof(boreas_vertex)));
}

}  // namespace
}  // namespace boreas
