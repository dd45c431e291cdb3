// boreas tests: BlobTree models — the junction rules of Galbraith et al. sec. 3.1-3.3
// measured on the double reference's surface (the delta_A offset against bulging, PCM's
// bark ridge), bends keeping their ends, trees grown from built-in species and species
// files, and clear refusals of bad options.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "blobtree/blobtree_bins.h"
#include "blobtree/blobtree_model.h"
#include "reference/blobtree_reference.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::test {
namespace {

using glm::dvec3;
using impl::BlobInternode;
using impl::BlobModel;
using impl::BlobTreeOptions;

// Distance from `from` (inside) along `dir` to the surface, by bisection on the reference.
double surface_along(const BlobModel& m, const dvec3& from, const dvec3& dir, double far) {
  double lo = 0.0, hi = far;
  for (int i = 0; i < 100; ++i) {
    double mid = 0.5 * (lo + hi);
    (impl::reference::blob_field(m, from + mid * dir) > 0.5 ? lo : hi) = mid;
  }
  return lo;
}

// Two collinear internodes along +y meeting at (0, 1, 0): radius 0.1 -> 0.08 -> 0.06.
std::vector<BlobInternode> collinear_pair() {
  std::vector<BlobInternode> s(2);
  s[0].top = dvec3(0.0, 1.0, 0.0);
  s[0].r_base = 0.1;
  s[0].r_top = 0.08;
  s[1].base = dvec3(0.0, 1.0, 0.0);
  s[1].top = dvec3(0.0, 2.0, 0.0);
  s[1].r_base = 0.08;
  s[1].r_top = 0.06;
  s[1].parent = 0;
  return s;
}

// The largest excess of the surface's radius over the internodes' own around the joint.
double worst_bulge(const BlobModel& m) {
  double worst = 0.0;
  for (double y = 0.5; y <= 1.5; y += 0.005) {
    double nominal = y < 1.0 ? 0.1 - 0.02 * y : 0.08 - 0.02 * (y - 1.0);
    worst =
        std::max(worst, surface_along(m, dvec3(0.0, y, 0.0), dvec3(1.0, 0.0, 0.0), 1.0) - nominal);
  }
  return worst;
}

TEST(BlobTreeJunctions, DeltaAOffsetReducesTheBulgeOfCollinearCones) {
  BlobTreeOptions with, without;
  without.offsets = false;
  BlobModel a = impl::blob_model_of(collinear_pair(), with);
  BlobModel b = impl::blob_model_of(collinear_pair(), without);
  // eq. 3: A is shortened by 1.75 r_Bt = 0.105 m.
  EXPECT_NEAR(a.primitives[0].length, 1.0 - 1.75 * 0.06, 1e-12);
  EXPECT_NEAR(b.primitives[0].length, 1.0, 1e-12);
  double bulge_with = worst_bulge(a), bulge_without = worst_bulge(b);
  // Measured: 7.7 mm with the offset, 23 mm (29 % of the 8 cm radius) without.
  EXPECT_GT(bulge_without, 0.02);
  EXPECT_LT(bulge_with, 0.01);
  EXPECT_LT(bulge_with, 0.5 * bulge_without);
  // At the joint itself the radius is within 8 % of the internodes' 0.08 m with it.
  EXPECT_NEAR(surface_along(a, dvec3(0.0, 1.0, 0.0), dvec3(1.0, 0.0, 0.0), 1.0), 0.08, 0.08 * 0.08);
}

// A basal internode and two branches leaving its top 8 degrees either side of vertical.
BlobModel crotch(bool pcm) {
  const double angle = 8.0 * 3.14159265358979 / 180.0;
  std::vector<BlobInternode> s(3);
  s[0].base = dvec3(0.0, -0.5, 0.0);
  s[0].r_base = s[0].r_top = 0.12;
  for (int k = 1; k < 3; ++k) {
    double side = k == 1 ? 1.0 : -1.0;
    s[k].top = 2.0 * dvec3(side * std::sin(angle), std::cos(angle), 0.0);
    s[k].r_base = 0.1;
    s[k].r_top = 0.09;
    s[k].parent = 0;
  }
  BlobTreeOptions o;
  o.pcm = pcm;
  return impl::blob_model_of(s, o);
}

TEST(BlobTreeJunctions, PcmRaisesABarkRidgeWhereThePlainBlendLeavesAValley) {
  BlobModel pcm = crotch(true), blend = crotch(false);
  // eq. 6 and 7: the branches move 0.02 m off the branching point, A shortens by
  // 2.75 * 0.1 - 0.12 = 0.155 m; the two branches form one PCM group.
  ASSERT_EQ(pcm.primitives.size(), 3u);
  EXPECT_NEAR(pcm.primitives[0].length, 0.5 - 0.155, 1e-12);
  EXPECT_NEAR(glm::length(pcm.primitives[1].base), 0.02, 1e-12);
  EXPECT_TRUE(pcm.primitives[1].pcm && pcm.primitives[2].pcm);
  EXPECT_EQ(pcm.primitives[1].group, pcm.primitives[2].group);
  EXPECT_FALSE(blend.primitives[1].pcm);
  // Blend (sec. 3.2): the branches stay at P and only A shortens, by eq. 3 for the
  // thicker top radius, 1.75 * 0.09 m.
  EXPECT_NEAR(blend.primitives[0].length, 0.5 - 1.75 * 0.09, 1e-12);
  EXPECT_NEAR(glm::length(blend.primitives[1].base), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(blend.primitives[2].base), 0.0, 1e-12);
  // Across the seam between the branches, 0.7 m up (their axes 0.2 m apart, touching):
  // the profile of the surface's height z over x.
  auto height = [](const BlobModel& m, double x) {
    return surface_along(m, dvec3(x, 0.7, 0.0), dvec3(0.0, 0.0, 1.0), 1.0);
  };
  // PCM: a ridge on the seam, standing above the surface either side (measured 0.0706 m
  // at the seam, 0.0689 m 1.25 cm aside, 0.0654 m 2.5 cm aside).
  for (double aside : {-0.0125, 0.0125}) EXPECT_GT(height(pcm, 0.0), height(pcm, aside) + 0.001);
  for (double aside : {-0.025, 0.025}) EXPECT_GT(height(pcm, 0.0), height(pcm, aside) + 0.004);
  // Blend: a smooth valley there (0.0817 m at the seam, 0.0821 m 1.25 cm aside).
  EXPECT_LT(height(blend, 0.0), height(blend, 0.0125));
  EXPECT_LT(height(blend, 0.0), height(blend, -0.0125));
}

TEST(BlobTreeJunctions, EveryMemberOfABranchingPointIsGroupedAndGroupsAreContiguous) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions o;
  o.min_radius = 0.01;
  BlobModel m = impl::build_blobtree(tree, dvec3(0.0), o);
  ASSERT_GT(m.primitives.size(), 50u);
  EXPECT_GT(m.branches_modeled, 10);
  int previous = -1, pcm_groups = 0;
  for (size_t i = 0; i < m.primitives.size(); ++i) {
    const impl::BlobPrimitive& p = m.primitives[i];
    EXPECT_GE(p.group, previous) << "group ids rise: members are contiguous";
    if (p.group != previous && p.pcm) ++pcm_groups;
    previous = p.group;
    EXPECT_GT(p.length, 0.0);
    EXPECT_GT(p.iso_distance, 0.0);
    EXPECT_GE(p.iso_distance, o.min_radius);
    EXPECT_NEAR(glm::length(p.axis), 1.0, 1e-9);
    size_t size = 0;
    for (const impl::BlobPrimitive& q : m.primitives) size += q.group == p.group ? 1 : 0;
    EXPECT_EQ(p.pcm, size > 1) << "a group of two or more is a PCM group";
  }
  EXPECT_GT(pcm_groups, 5);
  // Every primitive lies inside the model's bounds.
  for (const impl::BlobPrimitive& p : m.primitives)
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(p.base[c], m.bounds_min[c]);
      EXPECT_LT(p.base[c], m.bounds_max[c]);
    }
}

TEST(BlobTreeJunctions, ThinnerBranchesAreLeftOutWithTheirChildren) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions coarse, fine;
  coarse.min_radius = 0.03;
  fine.min_radius = 0.005;
  BlobModel a = impl::build_blobtree(tree, dvec3(0.0), coarse);
  BlobModel b = impl::build_blobtree(tree, dvec3(0.0), fine);
  EXPECT_LT(a.branches_modeled, b.branches_modeled);
  for (const impl::BlobPrimitive& p : a.primitives) {
    if (p.branch < 0) continue;
    EXPECT_GE(tree.branches[p.branch].radius, coarse.min_radius);
    int parent = tree.branches[p.branch].parent;
    if (parent >= 0) EXPECT_GE(tree.branches[parent].radius, coarse.min_radius);
  }
  BlobTreeOptions trunk_only = fine;
  trunk_only.max_level = 0;
  EXPECT_EQ(impl::build_blobtree(tree, dvec3(0.0), trunk_only).branches_modeled, 1);
}

// An internode offset at both ends (a child at its base, a parent at its top) keeps at
// least half its length: no primitive collapses to a point (a scar's stub used to).
TEST(BlobTreeJunctions, OffsetsAtBothEndsLeaveEveryPrimitiveItsLength) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("black_tupelo"), 1);
  BlobTreeOptions o;
  o.min_radius = 0.003;
  for (int k = 0; k < 6; ++k) o.scars.push_back({tree.level_begin[1] + 3 * k, 0.05, 0.5});
  BlobModel m = impl::build_blobtree(tree, dvec3(0.0), o);
  int scars = 0;
  for (const impl::BlobPrimitive& p : m.primitives) {
    scars += p.weight < 0.0 ? 1 : 0;
    EXPECT_GT(p.length, 0.0);
    EXPECT_GT(p.chord(), 1e-4 * p.iso_distance);
  }
  EXPECT_EQ(scars, 6);
}

// A scar hollows the bark around its stub, not the wood: even at full depth, for a lost
// branch half as thick as the trunk, the trunk's axis there stays inside.
TEST(BlobTreeScars, AScarHollowsTheBarkButNeverSeversItsParent) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  const int lost = tree.level_begin[1] + 14;
  BlobTreeOptions plain, scarred;
  plain.min_radius = scarred.min_radius = 0.02;
  scarred.scars.push_back({lost, 0.08, 1.0});
  BlobModel a = impl::build_blobtree(tree, dvec3(0.0), plain);
  BlobModel b = impl::build_blobtree(tree, dvec3(0.0), scarred);
  const impl::BlobPrimitive* scar = nullptr;
  for (const impl::BlobPrimitive& p : b.primitives)
    if (p.weight < 0.0) scar = &p;
  ASSERT_NE(scar, nullptr);
  // Back along the stub's axis into the trunk: the deepest wood (the unscarred field's
  // largest value) stays inside with the scar.
  dvec3 deepest = scar->base;
  for (double d = 0.0; d <= 0.3; d += 0.002) {
    dvec3 p = scar->base - d * scar->axis;
    if (impl::reference::blob_field(a, p) > impl::reference::blob_field(a, deepest)) deepest = p;
  }
  double lowest = impl::reference::blob_field(b, deepest);
  EXPECT_GT(lowest, 0.5) << "the trunk's wood at the scar";
  // Beside the stub, in the bark, the field is lower than without the scar: a hollow.
  dvec3 side = glm::normalize(glm::cross(scar->axis, dvec3(0.0, 1.0, 0.0)));
  dvec3 bark = scar->base + scar->length * scar->axis + 1.2 * scar->iso_distance * side;
  EXPECT_LT(impl::reference::blob_field(b, bark), impl::reference::blob_field(a, bark) - 0.05);
}

TEST(BlobTreeBend, BentPrimitivesKeepTheirEndsAndTurnAwayFromTheParent) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions straight, bent;
  straight.min_radius = bent.min_radius = 0.02;
  straight.offsets = bent.offsets = false;
  bent.bend_angle = 0.6;
  BlobModel a = impl::build_blobtree(tree, dvec3(0.0), straight);
  BlobModel b = impl::build_blobtree(tree, dvec3(0.0), bent);
  ASSERT_EQ(a.primitives.size(), b.primitives.size());
  int bends = 0;
  for (size_t i = 0; i < a.primitives.size(); ++i) {
    const impl::BlobPrimitive& p = a.primitives[i];
    const impl::BlobPrimitive& q = b.primitives[i];
    dvec3 top_a = p.base + p.chord() * p.axis;
    dvec3 top_b = q.base + impl::reference::blob_chord_length(q) * q.axis;
    EXPECT_LT(glm::length(q.base - p.base), 1e-12);
    EXPECT_LT(glm::length(top_b - top_a), 1e-9) << "primitive " << i;
    if (q.bend_angle == 0.0) continue;
    ++bends;
    // The arc is longer than the chord, and the field is 1 on its skeleton at both ends
    // and at its middle, which stands a sagitta aside towards the bend direction.
    EXPECT_GT(q.length, p.length);
    dvec3 middle = impl::reference::blob_skeleton_point(q, 0.5 * q.length);
    double rho = q.length / q.bend_angle;
    double sagitta = rho * (1.0 - std::cos(0.5 * q.bend_angle));
    EXPECT_NEAR(glm::dot(middle - 0.5 * (q.base + top_b), q.bend_direction), sagitta, 1e-9);
    EXPECT_NEAR(impl::reference::blob_primitive_field(q, q.base), 1.0, 1e-9);
    EXPECT_NEAR(impl::reference::blob_primitive_field(q, top_b), 1.0, 1e-9);
    EXPECT_NEAR(impl::reference::blob_primitive_field(q, middle), 1.0, 1e-9);
  }
  EXPECT_GT(bends, 5) << "every lateral branch's first internode bends";
}

TEST(BlobTreeSpecies, AnArbaroSpeciesFileBuildsLikeTheBuiltIn) {
  impl::TreeModel tree =
      impl::grow_tree(impl::load_species(BOREAS_TEST_DATA_DIR "/arbaro/quaking_aspen.xml"), 3);
  BlobTreeOptions o;
  o.min_radius = 0.02;
  BlobModel m = impl::build_blobtree(tree, dvec3(5.0, 0.0, -2.0), o);
  EXPECT_GT(m.branches_modeled, 3);
  // Standing where it was put: the trunk's first internode starts at the position.
  EXPECT_LT(glm::length(m.primitives[0].base - dvec3(5.0, 0.0, -2.0)), 1e-5);
}

void expect_invalid(const impl::TreeModel& tree, const BlobTreeOptions& o,
                    const std::string& piece) {
  try {
    impl::build_blobtree(tree, dvec3(0.0), o);
    ADD_FAILURE() << "accepted options that should name " << piece;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(piece), std::string::npos) << e.what();
  }
}

TEST(BlobTreeErrors, BadOptionsAreRefusedNamingTheField) {
  impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions o;
  o.max_level = 4;
  expect_invalid(tree, o, "max_level");
  o = {};
  o.pcm_peak = std::nan("");
  expect_invalid(tree, o, "pcm_peak");
  o = {};
  o.cuts.push_back({99999, 0.5});
  expect_invalid(tree, o, "cuts[0].branch: 99999 is not a branch");
  o = {};
  o.cuts.push_back({1, 1.5});
  expect_invalid(tree, o, "cuts[0].at");
  o = {};
  o.scars.push_back({0, 0.1, 0.5});
  expect_invalid(tree, o, "scars[0].branch: the trunk cannot be lost");
  o = {};
  o.scars.push_back({3, 0.1, -1.0});
  expect_invalid(tree, o, "scars[0].depth");
  o = {};
  o.bend_angle = 2.0;
  expect_invalid(tree, o, "bend_angle");

  std::vector<BlobInternode> s = collinear_pair();
  s[0].parent = 1;
  EXPECT_THROW(impl::blob_model_of(s, {}), std::invalid_argument);
  s = collinear_pair();
  s[1].r_base = -1.0;
  EXPECT_THROW(impl::blob_model_of(s, {}), std::invalid_argument);
  s = collinear_pair();
  s[1].top = s[1].base;
  EXPECT_THROW(impl::blob_model_of(s, {}), std::invalid_argument);

  BlobModel empty;
  EXPECT_THROW(impl::blob_grid(empty, 128), std::invalid_argument);
  BlobModel m = impl::blob_model_of(collinear_pair(), {});
  EXPECT_THROW(impl::blob_grid(m, 8), std::invalid_argument);
  EXPECT_THROW(impl::blob_grid(m, 4096), std::invalid_argument);
}

}  // namespace
}  // namespace boreas::test
