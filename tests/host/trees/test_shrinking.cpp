// boreas tests: a world's buffers follow its population down as well as up
// (runtime/block_space.h) — the trees' planes packed and halved once the live trees fill
// less than a quarter of them, the device memory the runtime counts falling by exactly
// those planes, no resizing back and forth at the edge, and trees and meadows stepping to
// the same bits whether or not their batch shrank under them.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "boreas/boreas.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "trees/tree_batch.h"
#include "world.h"

namespace boreas {
namespace {

using test::bytes_of;
using test::tree_bytes;
using test::make_world_with_wave;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;
// Device bytes per entry of a quasi-static tree's own planes: state and motion (its bend
// and broken flag: no dF/dt), both ping-pong halves.
constexpr uint64_t kEntryBytes =
    2 * (BOREAS_TREE_STATE_PLANES + BOREAS_TREE_MOTION_STILL_PLANES) * sizeof(float);

boreas_tree_def aspen(int index, uint64_t seed) {
  boreas_tree_def def = boreas_default_tree_def();
  def.seed = seed;
  def.position[0] = float(index % 8) * 6.0f;
  def.position[2] = float(index / 8) * 6.0f;
  def.rotation = 0.37f * float(index);
  return def;
}

// The runtime counts a buffer's bytes until the device frees it, which PoCL may do on a
// thread of its own once the commands that used it are done: the count once it reaches
// `expected`, or after a second.
uint64_t settled_memory(impl::World& world, uint64_t expected) {
  world.runtime().queue().finish();
  for (int k = 0; k < 100 && world.runtime().memory_in_use() != expected; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return world.runtime().memory_in_use();
}

// Entries the batch's live trees take, the sink counted.
int64_t used_entries(const impl::TreeBatch& batch) {
  return 1 + int64_t(batch.tree_count()) + batch.branch_count();
}

TEST(Shrinking, TreePlanesFollowTheLiveTreesDownAndTheCountedMemoryWithThem) {
  auto world = make_world_with_wave(windy_wave());
  impl::TreeBatch& batch = world->tree_batch(BOREAS_TREE_LAGGED);
  // 64 trees of 4 templates, removed from the last: the templates stay, so only the
  // trees' own planes may change size.
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 64; ++i) defs.push_back(aspen(i, uint64_t(1 + i % 4)));
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
  world->step(kDt);
  uint64_t memory = settled_memory(*world, 0);
  int shrinks = 0;
  for (int i = 63; i >= 1; --i) {
    const int64_t before = batch.stride();
    world->remove_tree(ids[size_t(i)]);
    const int64_t after = batch.stride(), used = used_entries(batch);
    if (after != before) {
      ++shrinks;
      // Shrunk because the live trees fell below a quarter, into at most twice them.
      EXPECT_LT(4 * used, before) << "tree " << i;
      EXPECT_LE(2 * used, after) << "tree " << i;
    }
    // The counted device memory falls by the trees' planes shrunk, and by nothing else.
    memory -= kEntryBytes * uint64_t(before - after);
    EXPECT_EQ(settled_memory(*world, memory), memory) << "tree " << i;
    // Never left below a quarter full (the batch's smallest capacity aside).
    EXPECT_TRUE(4 * used >= after || after == impl::TreeBatch::kMinEntries) << "tree " << i;
  }
  EXPECT_GE(shrinks, 4) << "64 trees down to 1 halve the planes at least four times";
}

TEST(Shrinking, AddingAndRemovingATreeAtTheEdgeResizesNothingTwice) {
  auto world = make_world_with_wave(windy_wave());
  impl::TreeBatch& batch = world->tree_batch(BOREAS_TREE_LAGGED);
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 16; ++i) defs.push_back(aspen(i, 1));
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
  // Down to just above a quarter of the capacity: the next removal shrinks.
  const int64_t per_tree = (used_entries(batch) - 1) / int64_t(ids.size());
  size_t live = ids.size();
  while (4 * (used_entries(batch) - per_tree) >= batch.stride()) world->remove_tree(ids[--live]);
  const int64_t edge = batch.stride();
  const uint64_t copied = world->runtime().traffic().copied_on_device;
  int resizes = 0;
  int64_t stride = edge;
  for (int k = 0; k < 10; ++k) {
    world->remove_tree(ids[live - 1]);
    ids[live - 1] = world->add_tree(aspen(int(live - 1), 1));
    resizes += batch.stride() != stride;
    stride = batch.stride();
  }
  EXPECT_EQ(resizes, 1) << "one shrink at the first removal, then nothing";
  EXPECT_LT(stride, edge);
  // After the shrink, removing and adding the last tree moves no block on the device: the
  // only copy is the new tree's rest state into the other half of the ping-pong.
  const uint64_t after_shrink = world->runtime().traffic().copied_on_device;
  world->remove_tree(ids[live - 1]);
  ids[live - 1] = world->add_tree(aspen(int(live - 1), 1));
  EXPECT_GT(after_shrink, copied);
  EXPECT_EQ(world->runtime().traffic().copied_on_device - after_shrink,
            uint64_t(per_tree) * BOREAS_TREE_STATE_PLANES * sizeof(float));
}

TEST(Shrinking, TreesStepToTheSameBitsWhetherOrNotTheirBatchShrank) {
  // A world of one tree, and one where it stands among 39 others that go, shrinking the
  // batch (and moving the tree) while it sways.
  auto plain = make_world_with_wave(windy_wave());
  auto busy = make_world_with_wave(windy_wave());
  const boreas_tree_def a_def = aspen(20, 3);
  const boreas_tree_id a0 = plain->add_tree(a_def);
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 40; ++i) defs.push_back(i == 20 ? a_def : aspen(i, uint64_t(1 + i % 5)));
  std::vector<boreas_tree_id> ids = busy->add_trees(defs.data(), int(defs.size()));
  const boreas_tree_id a1 = ids[20];
  const int64_t full = busy->tree_batch(BOREAS_TREE_LAGGED).stride();
  for (int s = 0; s < 30; ++s) {
    plain->step(kDt);
    busy->step(kDt);
    if (s == 10) {
      const std::vector<unsigned char> before = tree_bytes(*busy, a1);
      for (int i = 0; i < 40; ++i)
        if (i != 20) busy->remove_tree(ids[size_t(i)]);
      ASSERT_LT(busy->tree_batch(BOREAS_TREE_LAGGED).stride(), full) << "the batch shrank";
      ASSERT_EQ(tree_bytes(*busy, a1), before) << "the shrink moved the tree, bits and all";
    }
    ASSERT_EQ(tree_bytes(*plain, a0), tree_bytes(*busy, a1)) << "step " << s;
  }
  // The whole simulated state too: the same tree, wind and time.
  EXPECT_EQ(plain->state_hash(), busy->state_hash());
}

boreas_meadow_def meadow(int index) {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.center[0] = float(index) * 3.0f;
  d.size[0] = d.size[1] = 2.5f;
  d.density = 400.0f;
  d.seed = uint64_t(1 + index);
  return d;
}

TEST(Shrinking, AMeadowStepsToTheSameBitsWhetherOrNotItsBatchShrank) {
  // Meadows keep their components in a block space too: eight planted, seven removed.
  auto plain = make_world_with_wave(windy_wave());
  auto busy = make_world_with_wave(windy_wave());
  const boreas_meadow_id m0 = plain->add_meadow(meadow(3));
  std::vector<boreas_meadow_def> defs;
  for (int i = 0; i < 8; ++i) defs.push_back(meadow(i));
  std::vector<boreas_meadow_id> ids = busy->add_meadows(defs.data(), int(defs.size()));
  const int64_t full = busy->underbrush().stride();
  for (int s = 0; s < 20; ++s) {
    plain->step(kDt);
    busy->step(kDt);
    if (s == 5) {
      const std::vector<unsigned char> before = bytes_of(busy->meadow_components(ids[3]));
      for (int i = 0; i < 8; ++i)
        if (i != 3) busy->remove_meadow(ids[size_t(i)]);
      ASSERT_LT(busy->underbrush().stride(), full) << "the batch shrank";
      ASSERT_EQ(bytes_of(busy->meadow_components(ids[3])), before) << "the shrink moved it whole";
    }
    ASSERT_EQ(bytes_of(plain->meadow_components(m0)), bytes_of(busy->meadow_components(ids[3])))
        << "step " << s;
  }
}

}  // namespace
}  // namespace boreas
