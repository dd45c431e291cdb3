// boreas tests: a capsule placed into a generated tree's fork (cl/tree_step.cl's contact
// variant). It stands 0.2 m beside an aspen's trunk at 4.5 .. 7.5 m, where seven limbs
// leave it: their bases are inside and no bend takes them out, so they hold loads of tens
// of kN against it, and their trunk takes those loads. The trunk bends, but its break is
// the wind's (decided on the bend the plain launch made, which counts it): before, those
// loads broke the trunk on the second step in contact and it hung from its base, upside
// down (P3 at y -11 m), in a fresh world and in one that had stepped before the tree came,
// depending only on whether the collider happened to catch the falling trunk.
#include <gtest/gtest.h>

#include <vector>

#include "boreas/boreas.h"
#include "support/test_support.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

class ColliderInAFork : public ::testing::TestWithParam<int> {};

// A windy world (test::windy_wave: 9 m/s), `steps_before` steps, then the aspen and the capsule;
// its trunk over ten steps after.
TEST_P(ColliderInAFork, TrunkNeverBreaksNorHangs) {
  boreas_wave w = boreas::test::windy_wave();
  boreas_world_def def = boreas_default_world_def();
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -20, g.origin[1] = 0, g.origin[2] = -20;
  g.cell_size = 10;
  g.resolution[0] = 4, g.resolution[1] = 2, g.resolution[2] = 4;
  def.grid = g;
  def.waves = &w;
  def.wave_count = 1;
  boreas_world world = nullptr;
  ASSERT_EQ(boreas_world_create(&def, &world), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < GetParam(); ++s) ASSERT_EQ(boreas_world_step(world, kDt), BOREAS_OK);

  boreas_tree_def d = boreas_default_tree_def();
  d.species = "quaking_aspen";
  d.seed = 4;
  d.position[0] = 30.0f;
  d.position[2] = 9.0f;
  d.rotation = 0.37f * 4;
  boreas_tree_id id;
  ASSERT_EQ(boreas_world_add_tree(world, &d, &id), BOREAS_OK) << boreas_last_error();
  boreas_collider_def c = boreas_default_collider_def();
  c.shape = BOREAS_COLLIDER_CAPSULE;
  c.pose.position[0] = 30.2f;
  c.pose.position[1] = 6.0f;
  c.pose.position[2] = 9.06f;
  c.radius = 0.15f;
  c.half_height = 1.5f;
  boreas_collider_id cid;
  ASSERT_EQ(boreas_world_add_collider(world, &c, &cid), BOREAS_OK) << boreas_last_error();

  int count = 0;
  ASSERT_EQ(boreas_tree_get_branches(world, id, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_branch> b(static_cast<size_t>(count));
  ASSERT_EQ(boreas_tree_get_branches(world, id, b.data(), count, &count), BOREAS_OK);
  ASSERT_EQ(b[0].level, 0);
  const float rest_tip = b[0].control_points[3][1];
  ASSERT_GT(rest_tip, 10.0f);
  for (int s = 0; s < 10; ++s) {
    ASSERT_EQ(boreas_world_step(world, kDt), BOREAS_OK) << boreas_last_error();
    ASSERT_EQ(boreas_tree_get_branches(world, id, b.data(), count, &count), BOREAS_OK);
    EXPECT_EQ(b[0].broken, 0) << "step " << s;
    // Bent by its limbs' loads, but standing: its tip above the ground (hanging, 11 m below).
    EXPECT_GT(b[0].control_points[3][1], 0.0f) << "step " << s;
  }
  boreas_world_destroy(world);
}

INSTANTIATE_TEST_SUITE_P(StepsBefore, ColliderInAFork, ::testing::Values(0, 1, 30));

}  // namespace
