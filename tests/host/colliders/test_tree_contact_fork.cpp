// boreas tests: a capsule placed into a generated tree's fork (cl/tree_step.cl's contact
// variant). It stands 0.2 m beside an aspen's trunk at 4.5 .. 7.5 m, where a score of limbs
// leave it: their bases are inside and no bend takes them out. Held off by their own
// elastic loads, they took tens of kN and swung the trunk 5 to 9 m; a branch's base is now
// its parent's contact (tree_contact.h, BOREAS_CONTACT_SHARE_MIN), and the load a branch
// holds a collider off with is bounded by its wood's strength (boreas_contact_bearable).
// The trunk's break is the wind's (decided on the bend the plain launch made, which counts
// it): before, those loads broke the trunk on the second step in contact and it hung from
// its base, upside down (P3 at y -11 m), in a fresh world and in one that had stepped
// before the tree came, depending only on whether the collider happened to catch it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "boreas/boreas.h"
#include "support/test_support.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

class ColliderInAFork : public ::testing::TestWithParam<int> {};

// What ten steps of the aspen in the fork did, beside the same aspen in the same wind
// with no collider.
struct ForkRun {
  bool ok = false;
  float rest_tip_y = 0.0f;
  std::vector<boreas_branch> trunk;  // the trunk per step
  std::vector<float> force;          // |force| on the capsule per step, N
};

// A windy world (test::windy_wave: 9 m/s), `steps_before` steps, then the aspen (and the
// capsule, with `capsule`); ten steps after.
ForkRun run_fork(int steps_before, bool capsule) {
  ForkRun r;
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
  EXPECT_EQ(boreas_world_create(&def, &world), BOREAS_OK) << boreas_last_error();
  if (!world) return r;
  bool ok = true;
  for (int s = 0; s < steps_before; ++s) ok &= boreas_world_step(world, kDt) == BOREAS_OK;

  boreas_tree_def d = boreas_default_tree_def();
  d.species = "quaking_aspen";
  d.seed = 4;
  d.position[0] = 30.0f;
  d.position[2] = 9.0f;
  d.rotation = 0.37f * 4;
  boreas_tree_id id;
  ok &= boreas_world_add_tree(world, &d, &id) == BOREAS_OK;
  boreas_collider_id cid{};
  if (capsule) {
    boreas_collider_def c = boreas_default_collider_def();
    c.shape = BOREAS_COLLIDER_CAPSULE;
    c.pose.position[0] = 30.2f;
    c.pose.position[1] = 6.0f;
    c.pose.position[2] = 9.06f;
    c.radius = 0.15f;
    c.half_height = 1.5f;
    ok &= boreas_world_add_collider(world, &c, &cid) == BOREAS_OK;
  }
  int count = 0;
  ok &= boreas_tree_get_branches(world, id, nullptr, 0, &count) == BOREAS_OK;
  std::vector<boreas_branch> b(static_cast<size_t>(count));
  ok &= boreas_tree_get_branches(world, id, b.data(), count, &count) == BOREAS_OK;
  r.rest_tip_y = b.empty() ? 0.0f : b[0].control_points[3][1];
  for (int s = 0; ok && s < 10; ++s) {
    ok &= boreas_world_step(world, kDt) == BOREAS_OK;
    ok &= boreas_tree_get_branches(world, id, b.data(), count, &count) == BOREAS_OK;
    r.trunk.push_back(b[0]);
    boreas_collider_contact contact{};
    if (capsule) ok &= boreas_collider_get_contact(world, cid, &contact) == BOREAS_OK;
    r.force.push_back(std::hypot(contact.force[0], contact.force[1], contact.force[2]));
  }
  EXPECT_TRUE(ok) << boreas_last_error();
  r.ok = ok && !b.empty() && b[0].level == 0;
  boreas_world_destroy(world);
  return r;
}

TEST_P(ColliderInAFork, TrunkNeverBreaksNorHangs) {
  const ForkRun r = run_fork(GetParam(), true);
  ASSERT_TRUE(r.ok);
  ASSERT_GT(r.rest_tip_y, 10.0f);
  for (size_t s = 0; s < r.trunk.size(); ++s) {
    EXPECT_EQ(r.trunk[s].broken, 0) << "step " << s;
    // Bent by its limbs' loads, but standing: its tip above the ground (hanging, 11 m below).
    EXPECT_GT(r.trunk[s].control_points[3][1], 0.0f) << "step " << s;
  }
}

// The capsule resting in the fork overlaps the trunk itself (its axis 0.2 m from the
// trunk's, radii 0.15 m and up to 0.17 m). What holds it off is the trunk's elastic load,
// pushed out of it, within the wood's strength: less than the load that, at the capsule's
// top (7.5 m up), would put the aspen's modulus of rupture (WoodRupture 35 MPa,
// host/species/quaking_aspen.json) into the trunk's base, sigma pi r^3 / 4 / h. The trunk's
// axis is out of the capsule, and its tip stays within 0.6 m of the same trunk's in the
// same wind with no collider (its push: the overlap, about 0.1 m at 6 m, over the share of
// the tip's move that height makes, 0.48 m; before, limbs whose bases lie in the capsule
// held it off with tens of kN and swung the trunk 5 to 9 m).
TEST_P(ColliderInAFork, LoadsStayWithinTheWoodsStrengthAndTheTrunkSwaysLittle) {
  const ForkRun with = run_fork(GetParam(), true);
  const ForkRun without = run_fork(GetParam(), false);
  ASSERT_TRUE(with.ok && without.ok);
  ASSERT_EQ(with.trunk.size(), without.trunk.size());
  constexpr double kPi = 3.14159265358979;
  const double r = with.trunk[0].radius;
  const double breaking = 35e6 * kPi * r * r * r / 4.0 / 7.5;  // N
  for (size_t s = 0; s < with.trunk.size(); ++s) {
    const boreas_branch& t = with.trunk[s];
    const float* a = t.control_points[3];
    const float* b = without.trunk[s].control_points[3];
    const float apart = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    std::printf(
        "step %zu: %.0f N on the capsule (the trunk breaks at %.0f N), trunk tip %.3f m "
        "from the wind-only one\n",
        s, double(with.force[s]), breaking, double(apart));
    EXPECT_GT(with.force[s], 0.0f) << "step " << s;  // it is held off
    EXPECT_LT(with.force[s], breaking) << "step " << s;
    EXPECT_LT(apart, 0.6f) << "step " << s;
    // The trunk's axis, where it passes the capsule, is out of it.
    for (int i = 0; i <= 64; ++i) {
      const double u = i / 64.0, v = 1.0 - u;
      const double w[4] = {v * v * v, 3 * v * v * u, 3 * v * u * u, u * u * u};
      double p[3] = {0, 0, 0};
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) p[c] += w[k] * t.control_points[k][c];
      if (p[1] < 4.5 || p[1] > 7.5) continue;
      EXPECT_GE(std::hypot(p[0] - 30.2, p[2] - 9.06), 0.15) << "step " << s << " at " << u;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(StepsBefore, ColliderInAFork, ::testing::Values(0, 1, 30));

}  // namespace
