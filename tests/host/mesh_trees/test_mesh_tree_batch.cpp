// boreas tests: imported trees come and go without touching each other — every tree of a
// batch evolves bit for bit as it would alone, whatever was added or removed beside it (and
// after the batch packs its holes), and adding or removing one moves only its own bytes.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <vector>

#include "host/mesh_trees/tube_trees.h"
#include "shared/mesh_tree_types.h"
#include "support/test_support.h"

namespace boreas {
namespace {

// Tube tree number n: its own key, place, turn, size and noise seed.
std::shared_ptr<impl::MeshTreeInstance> tube_tree(int n) {
  static const test::TubeTree tubes = test::make_tube_tree();
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = "tube tree";
  def.position[0] = 4.0f * float(n % 5);
  def.position[2] = -3.0f * float(n / 5);
  def.yaw = 0.3f * float(n);
  def.scale = 1.0f + 0.1f * float(n % 3);
  def.leaf_flutter = 0.02f;
  auto tree = std::make_shared<impl::MeshTreeInstance>();
  tree->params = impl::checked_mesh_tree_def(def);
  tree->model = tubes.model;
  tree->data = impl::compute_mesh_tree(tree->model, uint64_t(11 + n));
  tree->drag = impl::mesh_tree_drag(tree->model);
  tree->noise = impl::make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, 2.0, uint64_t(11 + n));
  tree->key = uint64_t(1000 + n);
  return tree;
}

// The wind of every world here (test::make_world_with_wave).
boreas_wave windy_wave() {
  boreas_wave wave = boreas_default_wave();
  wave.amplitude = 9.0f;
  wave.wavelength = 17.0f;
  wave.speed = 5.0f;
  wave.sharpness = 2.0f;
  return wave;
}

// Everything a tree shows: trunk and leaf vertices, its branches' wind, its noise roll.
std::vector<unsigned char> tree_bytes(impl::MeshTreeBatch& batch, uint64_t key) {
  std::vector<unsigned char> out;
  auto append = [&](const void* p, size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(p);
    out.insert(out.end(), c, c + bytes);
  };
  const auto trunk = batch.trunk_vertices(key), leaves = batch.leaf_vertices(key);
  const auto wind = batch.branch_wind(key), roll = batch.noise_roll(key);
  append(trunk.data(), trunk.size() * sizeof(boreas_vertex));
  append(leaves.data(), leaves.size() * sizeof(boreas_vertex));
  append(wind.data(), wind.size() * sizeof(float));
  append(roll.data(), roll.size() * sizeof(float));
  return out;
}

// Adds and removes trees in a busy order, with the same steps, beside a world that holds
// only the trees that stay: each of those is the same, bit for bit, in both.
TEST(MeshTreeBatch, TreesThatStayEvolveBitForBitAsTheyWouldAlone) {
  auto busy = test::make_world_with_wave(windy_wave());
  auto alone = test::make_world_with_wave(windy_wave());
  impl::MeshTreeBatch& b = busy->mesh_tree_batch();
  impl::MeshTreeBatch& a = alone->mesh_tree_batch();
  // Trees 0..11 come into the busy world; trees 2, 7 and 11 stay to the end.
  const std::vector<int> stay = {2, 7, 11};
  auto step_both = [&](int steps) {
    for (int s = 0; s < steps; ++s) {
      busy->step(1.0f / 60.0f);
      alone->step(1.0f / 60.0f);
    }
  };
  for (int n = 0; n < 8; ++n) b.add(tube_tree(n), busy->time());
  a.add(tube_tree(2), alone->time());
  a.add(tube_tree(7), alone->time());
  step_both(12);
  // Removals in the middle and at the end; then more trees, then enough removals that
  // the holes pass half and the batch packs.
  b.remove(1000 + 3, busy->time());
  b.remove(1000 + 0, busy->time());
  step_both(7);
  for (int n = 8; n < 12; ++n) b.add(tube_tree(n), busy->time());
  a.add(tube_tree(11), alone->time());
  step_both(9);
  for (int n : {1, 4, 5, 6, 8, 9, 10}) b.remove(uint64_t(1000 + n), busy->time());
  step_both(11);
  b.add(tube_tree(12), busy->time());  // into the packed batch
  step_both(3);
  for (int n : stay)
    EXPECT_EQ(tree_bytes(b, uint64_t(1000 + n)), tree_bytes(a, uint64_t(1000 + n))) << "tree " << n;
  // And the newest tree is one freshly placed: at rest until it steps.
  auto fresh = test::make_world_with_wave(windy_wave());
  for (int s = 0; s < 12 + 7 + 9 + 11; ++s) fresh->step(1.0f / 60.0f);
  fresh->mesh_tree_batch().add(tube_tree(12), fresh->time());
  for (int s = 0; s < 3; ++s) fresh->step(1.0f / 60.0f);
  EXPECT_EQ(tree_bytes(b, 1012), tree_bytes(fresh->mesh_tree_batch(), 1012));
}

TEST(MeshTreeBatch, AddingOrRemovingATreeMovesOnlyItsOwnBytes) {
  auto world = test::make_world_with_wave(windy_wave());
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  auto moved = [&] {
    const impl::Runtime::Traffic& t = world->runtime().traffic();
    return std::pair<uint64_t, uint64_t>(t.uploaded, t.read_back);
  };
  // The bytes of adding tree 0 to an empty batch (allocation included).
  auto before = moved();
  batch.add(tube_tree(0), world->time());
  const uint64_t first_add = moved().first - before.first;
  EXPECT_EQ(moved().second, before.second) << "adding reads nothing back";
  // 40 trees in, stepped; the 41st fits the doubled spaces (64 slots).
  for (int n = 1; n < 40; ++n) batch.add(tube_tree(n), world->time());
  for (int s = 0; s < 3; ++s) world->step(1.0f / 60.0f);
  const std::vector<unsigned char> kept = tree_bytes(batch, 1000 + 17);
  before = moved();
  batch.add(tube_tree(40), world->time());
  const auto after_add = moved();
  EXPECT_LE(after_add.first - before.first, 2 * first_add);
  EXPECT_EQ(after_add.second, before.second);
  // Removing one in the middle moves nothing at all.
  before = moved();
  batch.remove(1000 + 21, world->time());
  EXPECT_EQ(moved(), before);
  // The others were not touched.
  EXPECT_EQ(tree_bytes(batch, 1000 + 17), kept);
  // A tree's readbacks read that tree: its wind is 3 floats a branch.
  before = moved();
  batch.branch_wind(1000 + 17);
  EXPECT_EQ(moved().second - before.second,
            uint64_t(3 * sizeof(float) * tube_tree(17)->data.branches.size()));
}

TEST(MeshTreeBatch, RemovingEveryTreeAndAddingAgainWorks) {
  auto world = test::make_world_with_wave(windy_wave());
  impl::MeshTreeBatch& batch = world->mesh_tree_batch();
  for (int n = 0; n < 3; ++n) batch.add(tube_tree(n), world->time());
  world->step(1.0f / 60.0f);
  for (int n = 0; n < 3; ++n) batch.remove(uint64_t(1000 + n), world->time());
  EXPECT_TRUE(batch.empty());
  world->step(1.0f / 60.0f);
  batch.add(tube_tree(5), world->time());
  for (int s = 0; s < 4; ++s) world->step(1.0f / 60.0f);
  auto alone = test::make_world_with_wave(windy_wave());
  for (int s = 0; s < 2; ++s) alone->step(1.0f / 60.0f);
  alone->mesh_tree_batch().add(tube_tree(5), alone->time());
  for (int s = 0; s < 4; ++s) alone->step(1.0f / 60.0f);
  EXPECT_EQ(tree_bytes(batch, 1005), tree_bytes(alone->mesh_tree_batch(), 1005));
}

}  // namespace
}  // namespace boreas
