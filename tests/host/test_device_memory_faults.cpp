// Library tests: a world that asks for more device memory than it may hold. The device's
// budget is cut to what the world holds now plus a little (Runtime::set_memory_limit, the
// same check BOREAS_DEVICE_MEMORY sets from outside), then every call that allocates is
// pushed past it. Each must fail with BOREAS_ERROR_OUT_OF_MEMORY naming what it tried to
// allocate, leave the world's state hash and device memory as they were, and the world must
// step on to the same states as a twin that was never refused; with the budget back, the
// same call succeeds.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "host/mesh_trees/tube_trees.h"
#include "support/test_support.h"

namespace boreas::test {
namespace {

constexpr float kDt = 1.0f / 30.0f;

class DeviceMemoryFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    boreas_wave wave = steady_wave(1.0f, 0.3f, 6.0f);
    world_ = make_world_with_wave(wave);
    twin_ = make_world_with_wave(wave);
    for (impl::World* w : {world_.get(), twin_.get()}) {
      const boreas_tree_id tree = w->add_tree(boreas_default_tree_def());
      if (w == world_.get()) tree_ = tree;
      boreas_meadow_def meadow = boreas_default_meadow_def();
      meadow.size[0] = meadow.size[1] = 2.0f;
      meadow.density = 100.0f;
      (void)w->add_meadow(meadow);
      w->step(kDt);
    }
    impl::Runtime& rt = world_->runtime();
    full_limit_ = rt.memory_limit();
    rt.set_memory_limit(rt.memory_in_use() + 4096);
  }

  // f must be refused for want of memory, naming `what`, and change nothing.
  void expect_refused_whole(const std::function<void()>& f, const std::string& what) {
    impl::Runtime& rt = world_->runtime();
    const uint64_t hash = world_->state_hash();
    const uint64_t held = rt.memory_in_use();
    expect_error(f, BOREAS_ERROR_OUT_OF_MEMORY, {what});
    EXPECT_EQ(world_->state_hash(), hash) << what << ": the refused call changed the world";
    EXPECT_EQ(rt.memory_in_use(), held) << what << ": device memory leaked by the refused call";
    for (int s = 0; s < 3; ++s) {
      world_->step(kDt);
      twin_->step(kDt);
      ASSERT_EQ(world_->state_hash(), twin_->state_hash()) << what << ", step " << s;
    }
  }
  // The budget back: the same call goes through.
  void restore_budget() { world_->runtime().set_memory_limit(full_limit_); }

  std::unique_ptr<impl::World> world_, twin_;
  boreas_tree_id tree_ = BOREAS_NULL_ID;  // world_'s tree
  uint64_t full_limit_ = 0;
};

TEST_F(DeviceMemoryFaults, ABatchOfTreesPastTheBudgetAddsNoTree) {
  std::vector<boreas_tree_def> defs(40, boreas_default_tree_def());
  for (size_t i = 0; i < defs.size(); ++i) {
    defs[i].seed = 100 + i;
    defs[i].position[0] = 4.0f * float(i);
  }
  expect_refused_whole([&] { (void)world_->add_trees(defs.data(), int(defs.size())); }, "bytes");
  restore_budget();
  EXPECT_EQ(world_->add_trees(defs.data(), int(defs.size())).size(), defs.size());
}

TEST_F(DeviceMemoryFaults, AMeadowPastTheBudgetIsNotPlanted) {
  boreas_meadow_def big = boreas_default_meadow_def();
  big.size[0] = big.size[1] = 20.0f;
  big.center[0] = 30.0f;
  big.density = 200.0f;
  expect_refused_whole([&] { (void)world_->add_meadow(big); }, "underbrush");
  restore_budget();
  (void)world_->add_meadow(big);
}

TEST_F(DeviceMemoryFaults, AnImportedTreePastTheBudgetIsNotAdded) {
  TempDir dir;
  const std::string model = write_tube_tree_obj(dir.path());
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = model.c_str();
  def.cache = 0;
  expect_refused_whole([&] { (void)world_->add_mesh_tree(def); }, "needs");
  restore_budget();
  (void)world_->add_mesh_tree(def);
}

TEST_F(DeviceMemoryFaults, ABlobTreePastTheBudgetIsNotBuilt) {
  boreas_blobtree_def def = boreas_default_blobtree_def();
  def.resolution = 128;
  expect_refused_whole([&] { (void)world_->add_blobtree(tree_, def, nullptr); }, "blobtree");
  restore_budget();
  (void)world_->add_blobtree(tree_, def, nullptr);
}

TEST_F(DeviceMemoryFaults, SamplingMorePointsThanTheBudgetHoldsIsRefused) {
  std::vector<float> points(3 * 200000, 1.0f), out(points.size());
  // Small samples first, with room, so the world holds its smallest sample buffers.
  restore_budget();
  world_->wind().sample(points.data(), 2, out.data());
  world_->runtime().set_memory_limit(world_->runtime().memory_in_use() + 4096);
  expect_refused_whole([&] { world_->wind().sample(points.data(), 200000, out.data()); }, "needs");
  world_->wind().sample(points.data(), 2, out.data());  // small samples still fit
  restore_budget();
  world_->wind().sample(points.data(), 200000, out.data());
}

TEST_F(DeviceMemoryFaults, AWaveSetPastTheBudgetIsNotTaken) {
  std::vector<boreas_wave> waves(1024, steady_wave(1.0f, 0.0f, 0.5f));
  expect_refused_whole(
      [&] { world_->wind().set_waves(waves.data(), int(waves.size()), 0.0f, world_->time()); },
      "needs");
  restore_budget();
  world_->wind().set_waves(waves.data(), int(waves.size()), 0.0f, world_->time());
}

}  // namespace
}  // namespace boreas::test
