// boreas tests: a world keeps its trees' models packed once the device holds their blocks
// (trees/tree_templates.h, TreeModel::Packed) — without their branches and leaves, which
// grow again from species and seed where they are needed. What the getters read, and the
// rest pose adds and heal place, must not change.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <memory>
#include <vector>

#include "boreas/boreas.hpp"
#include "trees/species.h"
#include "trees/tree_layout.h"
#include "trees/tree_model.h"
#include "trees/tree_templates.h"

namespace {

using boreas::impl::TreeModel;

boreas_world_def small_world_def() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = def.grid.origin[2] = -16.0f;
  def.grid.origin[1] = 0.0f;
  def.grid.cell_size = 4.0f;
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 6;
  return def;
}

std::shared_ptr<const boreas::impl::Species> aspen() {
  using namespace boreas::impl;
  return std::make_shared<const Species>(
      parse_species_source(read_species_source("quaking_aspen")));
}

boreas_wave storm() {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[2] = 0.4f;
  w.amplitude = 11.0f;
  w.wavelength = 25.0f;
  w.speed = 7.0f;
  w.sharpness = 2.0f;
  return w;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(PackedModels, PackingDropsBranchesAndLeavesAndGrowingAgainGivesTheSameModel) {
  using namespace boreas::impl;
  const auto species = aspen();
  const auto whole = std::make_shared<const TreeModel>(grow_tree(*species, 7, 1.0));
  ASSERT_FALSE(whole->leaves.empty());
  const auto packed = pack_model(whole, species, 7);
  ASSERT_TRUE(packed->packed);
  EXPECT_TRUE(packed->leaves.empty());
  EXPECT_EQ(packed->leaf_count(), int32_t(whole->leaves.size()));
  EXPECT_EQ(packed->packed->leaf_length, whole->leaves.front().length);
  EXPECT_EQ(packed->packed->leaf_width, whole->leaves.front().width);
  EXPECT_EQ(packed->level_begin, whole->level_begin);
  EXPECT_EQ(packed->tier_begin, whole->tier_begin);

  const auto again = whole_model(packed);
  ASSERT_FALSE(again->packed);
  ASSERT_EQ(again->branches.size(), whole->branches.size());
  for (size_t b = 0; b < whole->branches.size(); ++b) {
    const BranchModel &a = whole->branches[b], &c = again->branches[b];
    ASSERT_EQ(a.local, c.local) << "branch " << b;
    ASSERT_EQ(a.parent, c.parent) << "branch " << b;
    ASSERT_TRUE(a.v == c.v && a.theta == c.theta && a.alpha == c.alpha && a.radius == c.radius &&
                a.length == c.length && a.taper_depth == c.taper_depth)
        << "branch " << b;
  }
  ASSERT_EQ(again->leaves.size(), whole->leaves.size());
  for (size_t j = 0; j < whole->leaves.size(); ++j) {
    const LeafModel &a = whole->leaves[j], &b = again->leaves[j];
    ASSERT_EQ(a.parent, b.parent) << "leaf " << j;
    ASSERT_EQ(std::memcmp(&a.v, &b.v, sizeof(LeafModel) - offsetof(LeafModel, v)), 0)
        << "leaf " << j;
  }
  // A packed model is packed once, and keeps what the branch getter and the adds read.
  EXPECT_EQ(pack_model(packed, species, 7), packed);
  EXPECT_TRUE(packed->branches.empty());
  ASSERT_EQ(packed->branch_count(), int32_t(whole->branches.size()));
  for (size_t b = 0; b < whole->branches.size(); ++b) {
    const BranchModel& w = whole->branches[b];
    const TreeModel::Packed::Branch& p = packed->packed->branches[b];
    ASSERT_EQ(p.parent, w.parent);
    ASSERT_EQ(p.v, float(w.v));
    ASSERT_EQ(p.radius, w.radius);
    ASSERT_EQ(p.length, w.length);
  }
}

// An aspen of seed 11 at scale 1.3, whose model the world keeps packed, and the whole model
// grown again at scale 1: what the getters must agree with.
class PackedGetters : public ::testing::Test {
 protected:
  PackedGetters() : world(small_world_def()) {
    def.seed = 11;
    def.scale = 1.3f;
    id = world.add_tree(def);
  }
  boreas::World world;
  boreas_tree_def def = boreas_default_tree_def();
  boreas_tree_id id{};
  const TreeModel whole = boreas::impl::grow_tree(*aspen(), 11, 1.0);
};

TEST_F(PackedGetters, BranchGetterReadsWhatTheWholeModelSays) {
  using namespace boreas::impl;
  const std::vector<boreas_branch> branches = world.tree_get_branches(id);
  ASSERT_EQ(branches.size(), whole.branches.size());
  for (size_t b = 0; b < branches.size(); ++b) {
    const BranchModel& w = whole.branches[b];
    ASSERT_EQ(branches[b].level, w.level) << "branch " << b;
    ASSERT_EQ(branches[b].parent, w.parent) << "branch " << b;
    ASSERT_EQ(branches[b].parent_v, float(w.v)) << "branch " << b;
    ASSERT_EQ(branches[b].radius, float(w.radius * double(def.scale))) << "branch " << b;
    ASSERT_EQ(branches[b].length, float(w.length * double(def.scale))) << "branch " << b;
  }
}

TEST_F(PackedGetters, LeafGetterReadsWhatTheWholeModelSays) {
  using namespace boreas::impl;
  const std::vector<boreas_leaf> leaves = world.tree_get_leaves(id);
  ASSERT_EQ(leaves.size(), whole.leaves.size());
  for (size_t j = 0; j < leaves.size(); ++j) {
    const LeafModel& l = whole.leaves[j];
    ASSERT_EQ(leaves[j].branch, l.parent) << "leaf " << j;
    ASSERT_EQ(leaves[j].length, float(l.length * double(def.scale))) << "leaf " << j;
    ASSERT_EQ(leaves[j].width, float(l.width * double(def.scale))) << "leaf " << j;
  }
}

TEST(PackedModels, ANewBlockOfAKeptModelStepsAsAFreshOne) {
  // The second tree shares the first's (packed) model but not its physics: its template
  // block is made from the model grown again. It must step to the bits of the same tree
  // added to a world that grew the model for it.
  boreas_tree_def first = boreas_default_tree_def();
  first.seed = 5;
  boreas_tree_def second = first;
  second.position[0] = 6.0f;
  for (boreas_tree_level_def& l : second.levels) l.stiffness *= 1.7f;
  boreas::World kept(small_world_def()), fresh(small_world_def());
  (void)kept.add_tree(first);
  const boreas_tree_id a = kept.add_tree(second);
  const boreas_tree_id b = fresh.add_tree(second);
  for (boreas::World* w : {&kept, &fresh}) {
    w->wind_set_waves({storm()});
    for (int s = 0; s < 20; ++s) w->step(1.0f / 60.0f);
  }
  const std::vector<boreas_branch> ba = kept.tree_get_branches(a), bb = fresh.tree_get_branches(b);
  EXPECT_TRUE(same_bits(ba, bb));
  const std::vector<boreas_leaf> la = kept.tree_get_leaves(a), lb = fresh.tree_get_leaves(b);
  ASSERT_FALSE(la.empty());
  EXPECT_TRUE(same_bits(la, lb));
}

TEST(PackedModels, ATreeOfAKeptTemplateIsPlacedAsAFreshOne) {
  // The second call's tree takes its template's rest pose from the device's copy of the
  // block (the host keeps none): the same bits as the block made for it.
  boreas_tree_def first = boreas_default_tree_def();
  first.seed = 9;
  boreas_tree_def second = first;
  second.position[0] = 7.0f;
  second.rotation = 1.1f;
  second.scale = 1.2f;
  boreas::World kept(small_world_def()), fresh(small_world_def());
  (void)kept.add_tree(first);
  const boreas_tree_id a = kept.add_tree(second);
  const boreas_tree_id b = fresh.add_tree(second);
  EXPECT_TRUE(same_bits(kept.tree_get_branches(a), fresh.tree_get_branches(b)));
  // And heal puts it back there.
  kept.wind_set_waves({storm()});
  for (int s = 0; s < 10; ++s) kept.step(1.0f / 60.0f);
  kept.tree_heal(a);
  EXPECT_TRUE(same_bits(kept.tree_get_branches(a), fresh.tree_get_branches(b)));
}

}  // namespace
