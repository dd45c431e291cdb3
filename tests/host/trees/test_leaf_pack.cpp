// boreas tests: packed leaves (cl/shared/leaf_pack.h) — the codec within its stated
// bounds, and a world's aspen's leaves, made on the device from 8 bytes each, against the
// double placement of the unquantized model on the same branches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "boreas/boreas.hpp"
#include "host/trees/leaf_bound.h"
#include "reference/tree_reference.h"
#include "shared/leaf_pack.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace {

using glm::dvec3;
namespace test = boreas::test;
namespace ref = boreas::impl::reference;

constexpr double kPi = 3.14159265358979323846;

// The angle between two unit 2-vectors, rad.
double turn_error(double c, double s, float dc, float ds) {
  return std::fabs(std::atan2(c * double(ds) - s * double(dc), c * double(dc) + s * double(ds)));
}

TEST(LeafPack, DecodedLeavesAreWithinTheStatedBounds) {
  std::mt19937 rng(39);
  std::uniform_real_distribution<double> unit(0.0, 1.0), angle(-kPi, kPi);
  std::uniform_int_distribution<int> entry(0, (1 << BOREAS_LEAF_ENTRY_BITS) - 1);
  double worst_v = 0.0, worst[3] = {0.0, 0.0, 0.0};
  const int bits[3] = {BOREAS_LEAF_THETA_BITS, BOREAS_LEAF_ALPHA_BITS, BOREAS_LEAF_ROLL_BITS};
  for (int trial = 0; trial < 200000; ++trial) {
    const int e = entry(rng);
    const double v = unit(rng), a[3] = {angle(rng), angle(rng), angle(rng)};
    int words[BOREAS_TREE_LEAF_PLANES];
    boreas_leaf_pack(e, v, std::cos(a[0]), std::sin(a[0]), std::cos(a[1]), std::sin(a[1]),
                     std::cos(a[2]), std::sin(a[2]), words);
    const BoreasLeafPlace l = boreas_leaf_unpack(words[0], words[1]);
    ASSERT_EQ(l.entry, e);
    worst_v = std::max(worst_v, std::fabs(double(l.v) - v));
    const float got[3][2] = {{l.cos_theta, l.sin_theta}, {l.cos_alpha, l.sin_alpha}, {l.cos_roll, l.sin_roll}};
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(std::hypot(double(got[k][0]), double(got[k][1])), 1.0, 1e-6);
      worst[k] = std::max(worst[k], turn_error(std::cos(a[k]), std::sin(a[k]), got[k][0], got[k][1]));
    }
  }
  // Within the bounds (and float's rounding), and the bounds not loose by more than 2x:
  // the quantization is what the header says it is.
  EXPECT_LE(worst_v, test::leaf_v_bound() + 1e-7);
  EXPECT_GT(worst_v, 0.5 * test::leaf_v_bound());
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(worst[k], test::leaf_turn_bound(bits[k]) + 1e-6) << "turn " << k;
    EXPECT_GT(worst[k], 0.5 * test::leaf_turn_bound(bits[k])) << "turn " << k;
  }
  std::printf("    worst: v %.3g (bound %.3g); theta %.3g, alpha %.3g, roll %.3g rad\n", worst_v,
              test::leaf_v_bound(), worst[0], worst[1], worst[2]);
}

TEST(LeafPack, EndsAndAxesAreExact) {
  // v = 0 and 1 (a twig's tip leaves) and the four axis directions come back exactly.
  const double dirs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  for (double v : {0.0, 1.0})
    for (const auto& d : dirs) {
      int words[BOREAS_TREE_LEAF_PLANES];
      boreas_leaf_pack((1 << BOREAS_LEAF_ENTRY_BITS) - 1, v, d[0], d[1], d[0], d[1], d[0], d[1], words);
      const BoreasLeafPlace l = boreas_leaf_unpack(words[0], words[1]);
      EXPECT_EQ(l.entry, (1 << BOREAS_LEAF_ENTRY_BITS) - 1);
      EXPECT_EQ(l.v, float(v));
      for (auto [c, s] : {std::pair{l.cos_theta, l.sin_theta}, std::pair{l.cos_alpha, l.sin_alpha},
                          std::pair{l.cos_roll, l.sin_roll}}) {
        EXPECT_EQ(c, float(d[0]));
        EXPECT_EQ(s, float(d[1]));
      }
    }
}

dvec3 d3(const float* v) { return dvec3(v[0], v[1], v[2]); }

// A distinct aspen of the world (scale 1.3: the petiole comes scaled through the leaf
// tiles), swaying in a storm: every leaf the getter reads (made on the device from its
// packed words) within the bound of the double placement of the unquantized model's leaf
// on the getter's branch.
TEST(LeafPack, WorldLeavesMatchTheDoublePlacementWithinTheBound) {
  boreas::World world;
  boreas_tree_def def = boreas_default_tree_def();
  def.seed = 23;
  def.scale = 1.3f;
  const boreas_tree_id tree = world.add_tree(def);
  boreas_wave w = boreas_default_wave();
  w.amplitude = 9.0f;
  world.wind_set_waves({w});
  const boreas::impl::Species species =
      boreas::impl::parse_species_source(boreas::impl::read_species_source("quaking_aspen"));
  const boreas::impl::TreeModel model = boreas::impl::grow_tree(species, def.seed, 1.0);
  ASSERT_GT(model.leaves.size(), 1000u);
  for (int s = 0; s < 20; ++s) world.step(1.0f / 30.0f);
  std::vector<boreas_branch> branches = world.tree_get_branches(tree);
  std::vector<boreas_leaf> leaves = world.tree_get_leaves(tree);
  ASSERT_EQ(leaves.size(), model.leaves.size());
  double worst[3] = {0.0, 0.0, 0.0}, used[3] = {0.0, 0.0, 0.0};
  for (size_t j = 0; j < leaves.size(); ++j) {
    boreas::impl::LeafModel lm = model.leaves[j];
    lm.stem *= double(def.scale);
    ASSERT_EQ(leaves[j].branch, lm.parent);
    const boreas_branch& b = branches[size_t(lm.parent)];
    ref::Branch parent;
    for (int k = 0; k < 4; ++k) parent.curve.p[k] = d3(b.control_points[k]);
    parent.o = d3(b.orientation);
    const ref::LeafPose want = ref::leaf_pose(parent, lm);
    const test::LeafBound bound = test::leaf_bound(parent, lm.stem);
    const double e[3] = {glm::length(d3(leaves[j].position) - want.position),
                         glm::length(d3(leaves[j].axis) - want.axis),
                         glm::length(d3(leaves[j].normal) - want.normal)};
    // The float placement's own error (1e-5 m and unit, as the kernel tests allow) on top.
    const double limit[3] = {bound.position + 1e-5, bound.axis + 1e-5, bound.normal + 1e-5};
    for (int k = 0; k < 3; ++k) {
      ASSERT_LE(e[k], limit[k]) << "leaf " << j << " quantity " << k;
      worst[k] = std::max(worst[k], e[k]);
      used[k] = std::max(used[k], e[k] / limit[k]);
    }
    EXPECT_FLOAT_EQ(leaves[j].length, float(lm.length * double(def.scale)));
  }
  std::printf("    %zu leaves: position within %.3g m, axis %.3g, normal %.3g (at most %.0f %%, %.0f %%, "
              "%.0f %% of the bound)\n",
              leaves.size(), worst[0], worst[1], worst[2], 100.0 * used[0], 100.0 * used[1],
              100.0 * used[2]);
}

}  // namespace
