// boreas tests: the drag load on generated trees (trees/wind_load.h). The beam against the
// cantilever's closed forms (a uniform load, a point load, a child's whole load handed to
// its parent, the pipe model's radius, the crown's sheltering), the beam ratios between
// branches (radius, modulus, stiffness), and the kernels: a doubled steady wind quadruples
// every branch's bend under drag and doubles it under the paper's linear load, and a tree
// twice as large bends twice as far.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "boreas/boreas.h"
#include "host/trees/hand_built_trees.h"
#include "host/trees/tree_bends.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_layout.h"
#include "trees/leaf_area.h"
#include "trees/wind_load.h"
#include "world.h"

namespace boreas {
namespace {

using glm::dvec3;
using impl::BranchModel;
using impl::LeafModel;
using impl::TreeModel;

constexpr double kPi = 3.14159265358979323846;

// A straight, untapered branch of length L and radius r along +x.
BranchModel rod(int level, int parent, double length, double radius, double v = 0.0) {
  return test::hand_branch(level, parent, length, radius, 0.0, 0.0, v, 0.0, 0.5, 0.0);
}

// A leaf of blade area `area` (the broadleaf outline of one_branch's species "rod").
LeafModel leaf_at(int parent, double v, double area) {
  LeafModel l;
  l.parent = parent;
  l.v = v;
  l.length = std::sqrt(area / impl::leaf_fill(BOREAS_LEAF_OUTLINE_BROADLEAF));  // length = width
  l.width = l.length;
  return l;
}

TreeModel one_branch(double length, double radius, std::vector<LeafModel> leaves = {}) {
  TreeModel m;
  m.species = "rod";
  m.branches.push_back(rod(0, -1, length, radius));
  m.leaves = std::move(leaves);
  m.levels = 1;
  m.level_begin = {0, 1, 1, 1, 1};
  return m;
}

double stiffness_ei(const TreeModel& m, double radius) {
  return m.wood_modulus * kPi * std::pow(radius, 4) / 4.0;
}

double deflection(const TreeModel& m, int branch = 0) {
  return impl::deflection_per_pressure(m, impl::TreeParams{})[size_t(branch)];
}

// ---- The beam ------------------------------------------------------------------------------

// A rod under its own drag, w = C_d 2r per unit pressure and length: w L^4 / (8 E I). The
// midpoint rule on 16 slices with the load lumped at the midpoints is within 1 %.
TEST(WindLoad, UniformLoadDeflectsAsTheClosedForm) {
  const double length = 3.0, radius = 0.02;
  const TreeModel m = one_branch(length, radius);
  const double w = impl::kWoodDragCoefficient * 2.0 * radius;
  const double want = w * std::pow(length, 4) / (8.0 * stiffness_ei(m, radius));
  EXPECT_NEAR(deflection(m), want, 0.01 * want);
}

// A leaf's drag as a point force P at a: P a^2 (3L - a) / (6 E I), on top of the rod's own.
TEST(WindLoad, PointLoadDeflectsAsTheClosedForm) {
  const double length = 2.0, radius = 0.015, area = 0.01;
  const double bare = deflection(one_branch(length, radius));
  for (double v : {1.0, 0.5, 0.25}) {
    const TreeModel m = one_branch(length, radius, {leaf_at(0, v, area)});
    ASSERT_EQ(impl::leaf_shelter(m), 1.0) << "no crown known: no sheltering";
    const double p = impl::kLeafDragCoefficient * area, a = v * length;
    const double want = p * a * a * (3.0 * length - a) / (6.0 * stiffness_ei(m, radius));
    // The load sits in the slice it falls in: its arm is exact beyond that slice, and the
    // slice itself is 1/16 of the beam.
    EXPECT_NEAR(deflection(m) - bare, want, 0.02 * want) << "leaf at v = " << v;
  }
}

// A child hands its whole drag (its wood and its leaves) to its parent where it attaches.
TEST(WindLoad, ParentCarriesItsChildsWholeLoad) {
  const double length = 4.0, radius = 0.05, v = 0.5;
  TreeModel alone = one_branch(length, radius);
  TreeModel m = alone;
  m.branches.push_back(rod(1, 0, 1.0, 0.01, v));
  m.leaves = {leaf_at(1, 1.0, 0.02), leaf_at(1, 0.6, 0.02)};
  m.levels = 2;
  m.level_begin = {0, 1, 2, 2, 2};
  TreeModel child_only;
  child_only.branches = {m.branches[1]};
  child_only.branches[0].parent = -1;
  child_only.branches[0].level = 0;
  child_only.leaves = m.leaves;
  for (LeafModel& l : child_only.leaves) l.parent = 0;
  // The child's drag area: its wood (16 slices of its untapered rod) and two leaves.
  const double child_drag =
      impl::kWoodDragCoefficient * 2.0 * 0.01 * 1.0 + 2.0 * impl::kLeafDragCoefficient * 0.02;
  const double a = v * length;
  const double want = child_drag * a * a * (3.0 * length - a) / (6.0 * stiffness_ei(m, radius));
  EXPECT_NEAR(deflection(m, 0) - deflection(alone, 0), want, 0.02 * want);
  // The child itself bends as it would alone: what its parent does is not its load.
  EXPECT_NEAR(deflection(m, 1), deflection(child_only, 0), 1e-12 * deflection(m, 1));
}

// Two branches of one length: the deflections stand in the ratio of E r^4 for the same
// load, and of E r^3 under their own drag (area r, I r^4).
TEST(WindLoad, StifferBranchBendsLessByTheBeamRatio) {
  const double length = 1.5, area = 0.004;
  const double thin = 0.01, thick = 0.02;
  const double own_ratio =
      deflection(one_branch(length, thin)) / deflection(one_branch(length, thick));
  EXPECT_NEAR(own_ratio, 8.0, 1e-9 * 8.0);
  const double leaf_thin = deflection(one_branch(length, thin, {leaf_at(0, 1.0, area)})) -
                           deflection(one_branch(length, thin));
  const double leaf_thick = deflection(one_branch(length, thick, {leaf_at(0, 1.0, area)})) -
                            deflection(one_branch(length, thick));
  EXPECT_NEAR(leaf_thin / leaf_thick, 16.0, 1e-9 * 16.0);
  // Twice the modulus, half the bend; the level's stiffness multiplies the modulus.
  TreeModel soft = one_branch(length, thin, {leaf_at(0, 0.7, area)});
  TreeModel hard = soft;
  hard.wood_modulus = 2.0 * soft.wood_modulus;
  EXPECT_NEAR(deflection(soft) / deflection(hard), 2.0, 1e-12);
  impl::TreeParams stiff;
  stiff.levels[0].stiffness = 4.0;
  EXPECT_NEAR(deflection(soft) / impl::deflection_per_pressure(soft, stiff)[0], 4.0, 1e-12);
}

// A twig drawn thinner than the leaves it holds could be (the pipe model: 1e-4 m^2 of wood
// per m^2 of leaves beyond a point) bends as a beam of the pipe model's radius.
TEST(WindLoad, ThinTwigsAreAsThickAsThePipeModelAsks) {
  const double length = 0.4, area = 0.002;
  std::vector<LeafModel> leaves(10, leaf_at(0, 1.0, area));
  const TreeModel m = one_branch(length, 1e-6, leaves);
  const double pipe = std::sqrt(impl::kHuberValue * 10.0 * area / kPi);
  const double p = 10.0 * impl::kLeafDragCoefficient * area;
  const double want = p * std::pow(length, 3) / (3.0 * stiffness_ei(m, pipe));
  EXPECT_NEAR(deflection(m), want, 0.01 * want);
  EXPECT_LT(want / length, 1.0) << "a finite bend: 10 leaves of 20 cm^2 at 1 Pa";
  // Its natural frequency is the pipe-model beam's too.
  EXPECT_NEAR(impl::beam_base_radius(m)[0], pipe, 1e-12);
}

// The leaves of a crown drag together as its silhouette does (C_d 0.4), never more than
// alone; a Weber-Penn crown holds far more leaf area than its silhouette.
TEST(WindLoad, LeavesOfACrownDragAsItsSilhouette) {
  const TreeModel aspen = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  ASSERT_GT(aspen.crown_area, 10.0);
  const double shelter = impl::leaf_shelter(aspen);
  EXPECT_GT(shelter, 0.0);
  EXPECT_LT(shelter, 0.5);
  double leaves = 0.0;
  for (const LeafModel& l : aspen.leaves)
    leaves += impl::leaf_area(l.length, l.width, BOREAS_LEAF_OUTLINE_ASPEN);
  EXPECT_NEAR(shelter * impl::kLeafDragCoefficient * leaves,
              impl::kCrownDragCoefficient * aspen.crown_area, 1e-9 * leaves);
  TreeModel sparse = one_branch(1.0, 0.01, {leaf_at(0, 1.0, 0.001)});
  sparse.crown_area = 1.0;
  EXPECT_EQ(impl::leaf_shelter(sparse), 1.0);
}

// ---- The kernels -------------------------------------------------------------------------------

// A world whose wind is `speed` m/s along (1, 0, 0.4) everywhere, for ever.
std::unique_ptr<impl::World> uniform_wind_world(float speed) {
  boreas_wave w = test::steady_wave(1.0f, 0.4f, speed);
  return test::make_world_with_wave(w);
}

// Every branch's bend factor F after `steps` steps of dt.
std::vector<dvec3> settled_bends(float speed, boreas_tree_def def, int steps = 8,
                                 float dt = 1.0f / 60.0f) {
  auto world = uniform_wind_world(speed);
  boreas_tree_id id = world->add_tree(def);
  for (int s = 0; s < steps; ++s) world->step(dt);
  return test::tree_bends(*world, id);
}

boreas_tree_def aspen_def() {
  boreas_tree_def def = boreas_default_tree_def();
  def.species = "quaking_aspen";
  def.mode = BOREAS_TREE_EXACT;  // every level settles in the first step
  return def;
}

// Doubling a steady wind: F* = K |u| u quadruples, F* = C u doubles, for every branch.
// Quasi-static, exact mode, a uniform wind: F is its target, in float.
TEST(WindLoad, DoublingTheWindQuadruplesTheDragBend) {
  for (boreas_tree_load load : {BOREAS_TREE_LOAD_DRAG, BOREAS_TREE_LOAD_LINEAR}) {
    boreas_tree_def def = aspen_def();
    def.load = load;
    const std::vector<dvec3> slow = settled_bends(2.0f, def), fast = settled_bends(4.0f, def);
    ASSERT_EQ(slow.size(), fast.size());
    const double want = load == BOREAS_TREE_LOAD_DRAG ? 4.0 : 2.0;
    for (size_t b = 0; b < slow.size(); ++b) {
      ASSERT_GT(glm::length(slow[b]), 0.0) << "branch " << b;
      EXPECT_NEAR(glm::length(fast[b]) / glm::length(slow[b]), want, 1e-5 * want) << "branch " << b;
      EXPECT_GT(glm::dot(fast[b], slow[b]), 0.0) << "downwind both times";
    }
  }
}

// Stiffer wood on one level: that level bends less by exactly the ratio, the others not
// at all differently (their loads are the same drag).
TEST(WindLoad, StifferLevelBendsLessByTheRatio) {
  boreas_tree_def def = aspen_def();
  const std::vector<dvec3> plain = settled_bends(6.0f, def);
  def.levels[1].stiffness = 2.5f;
  const std::vector<dvec3> stiff = settled_bends(6.0f, def);
  const TreeModel m = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  int level_one = 0;
  for (size_t b = 0; b < plain.size(); ++b) {
    // Level 1 bends less; the trunk's bend is the same; level 2 sits where its stiffer
    // parent put it, so its wind and bend are its own again (uniform wind).
    const double want = m.branches[b].level == 1 ? 1.0 / 2.5 : 1.0;
    level_one += m.branches[b].level == 1;
    EXPECT_NEAR(glm::length(stiff[b]) / glm::length(plain[b]), want, 1e-5) << "branch " << b;
  }
  EXPECT_GT(level_one, 10);
}

// A tree of scale s is the template with every length s times: its drag bends are s times
// the template's (area s^2, moment arm s^3, I s^4); the linear load's sqrt(s).
TEST(WindLoad, ScaledTreeBendsInProportion) {
  for (boreas_tree_load load : {BOREAS_TREE_LOAD_DRAG, BOREAS_TREE_LOAD_LINEAR}) {
    boreas_tree_def def = aspen_def();
    def.load = load;
    const std::vector<dvec3> small = settled_bends(5.0f, def);
    def.scale = 2.0f;
    const std::vector<dvec3> large = settled_bends(5.0f, def);
    const double want = load == BOREAS_TREE_LOAD_DRAG ? 2.0 : std::sqrt(2.0);
    for (size_t b = 0; b < small.size(); ++b)
      EXPECT_NEAR(glm::length(large[b]) / glm::length(small[b]), want, 1e-5 * want)
          << "branch " << b;
  }
}

// A template block holds the load in one signed plane (cl/shared/tree_types.h,
// BOREAS_TREE_SHAPE_LOAD): the drag negated, or the linear compliance. What the step reads
// back through boreas_tree_drag and boreas_tree_compliance must be, bit for bit, the two
// planes it replaced (the float of the model's drag and compliance, and +0 for the other),
// so that nothing the step computes changes. A sign mixed up, a half not read back, or a
// -0 where +0 was would show here.
TEST(WindLoad, OneSignedPlaneHoldsBothLoadsExactly) {
  const TreeModel m = impl::grow_tree(impl::load_species("quaking_aspen"), 3);
  auto bits = [](float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
  };
  for (boreas_tree_load load : {BOREAS_TREE_LOAD_DRAG, BOREAS_TREE_LOAD_LINEAR}) {
    boreas_tree_def def = aspen_def();
    def.load = load;
    const impl::TreeParams params = impl::checked_tree_def(def);
    const impl::TreeTemplateBlock block = impl::tree_template_block(params, m);
    const std::vector<double> drag = impl::drag_compliance(m, params);
    const size_t n = size_t(block.count);
    for (size_t b = 0; b < m.branches.size(); ++b) {
      const float held = block.shape[size_t(BOREAS_TREE_SHAPE_LOAD) * n + size_t(impl::block_index(int32_t(b)))];
      const float want_drag = load == BOREAS_TREE_LOAD_DRAG ? float(drag[b]) : 0.0f;
      const float want_compliance =
          load == BOREAS_TREE_LOAD_LINEAR
              ? float(impl::bend_compliance(m.branches[b], params.levels[size_t(m.branches[b].level)]))
              : 0.0f;
      ASSERT_EQ(bits(boreas_tree_drag(held)), bits(want_drag)) << "branch " << b;
      ASSERT_EQ(bits(boreas_tree_compliance(held)), bits(want_compliance)) << "branch " << b;
    }
  }
}

// The damped response settles on the same bend: the tip's own velocity goes to zero, so
// the relative wind is the wind.
TEST(WindLoad, DampedDragSettlesOnTheQuasiStaticBend) {
  boreas_tree_def def = aspen_def();
  const std::vector<dvec3> quasi = settled_bends(5.0f, def);
  def.response = BOREAS_TREE_DAMPED;
  def.levels[0].damping_ratio = def.levels[1].damping_ratio = def.levels[2].damping_ratio = 1.0f;
  const std::vector<dvec3> damped = settled_bends(5.0f, def, 600, 0.1f);  // a minute
  for (size_t b = 0; b < quasi.size(); ++b)
    EXPECT_NEAR(glm::length(damped[b] - quasi[b]), 0.0, 1e-3 * glm::length(quasi[b]) + 1e-7)
        << "branch " << b;
}

}  // namespace
}  // namespace boreas
