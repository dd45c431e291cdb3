// boreas tests: the tree animation kernels (cl/tree_step.cl, cl/tree_leaves.cl) against
// the double-precision reference (host/src/reference/tree_reference.h), and what the
// animation must do whatever the precision: no wind no motion, segment lengths kept,
// children on their parents, leaves on their branches, the damped overshoot, determinism.
//
// Trees are built by hand here (not grown), so these tests depend on the kernels only.
// They run in a World whose grid has nothing to force it (no primitives, no solids), so
// its grid part of the wind stays exactly zero and the wind is the sine sum alone, which
// reference::sine_sum gives in double at the world's time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <vector>

#define BOREAS_FAST_MATH 1
#include "reference/tree_reference.h"
#include "reference/wind_reference.h"
#include "shared/tree_math.h"
#include "support/test_support.h"
#include "host/trees/hand_built_trees.h"
#include "host/trees/leaf_bound.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_params.h"

namespace boreas::test {
namespace {

namespace ref = impl::reference;
using glm::dvec3;
using impl::BranchModel;
using impl::LeafModel;
using impl::TreeInstance;
using impl::TreeModel;

constexpr double kPi = 3.14159265358979323846;

// ---- Hand-built trees (hand_built_trees.h) ---------------------------------------------

// Trunk (8 m, curved, slightly tilted), three level-1 limbs, four level-2 branches, two
// level-3 twigs, and leaves on the twigs and on one level-2 branch without twigs.
// Its branches are thick and carry six leaves between them: under the drag load its wood
// is as soft as rubber (10 MPa, 700 times softer than green hardwood), so that 8 m/s moves
// its tips well past the tolerances below.
TreeModel hand_tree() {
  TreeModel m;
  m.species = "hand";
  m.wood_modulus = 1e7;
  BranchModel trunk = hand_branch(0, -1, 8.0, 0.3, 0.08, 0.7, 0.0, 0.3, 0.05);
  trunk.flare = 0.5;
  m.branches.push_back(trunk);                                             // 0
  m.branches.push_back(hand_branch(1, 0, 3.0, 0.08, 0.25, 1.1, 0.45, 0.4, 0.9));  // 1
  m.branches.push_back(hand_branch(1, 0, 2.6, 0.07, -0.2, 0.3, 0.62, 2.5, 1.1));  // 2
  m.branches.push_back(hand_branch(1, 0, 2.0, 0.05, 0.3, -0.8, 0.86, 4.4, 0.7));  // 3
  m.branches.push_back(hand_branch(2, 1, 1.2, 0.02, 0.35, 0.5, 0.5, 1.0, 0.8));   // 4
  m.branches.push_back(hand_branch(2, 1, 1.0, 0.02, -0.3, 2.0, 0.8, 3.9, 0.6));   // 5
  m.branches.push_back(hand_branch(2, 2, 1.1, 0.02, 0.2, -1.2, 0.55, 5.5, 1.2));  // 6
  m.branches.push_back(hand_branch(2, 3, 0.9, 0.015, 0.4, 0.9, 0.7, 0.2, 0.9));   // 7
  m.branches.push_back(hand_branch(3, 4, 0.4, 0.006, 0.3, 0.4, 0.6, 2.2, 0.7));   // 8
  m.branches.push_back(hand_branch(3, 6, 0.35, 0.005, -0.4, 1.3, 0.75, 4.0, 1.0)); // 9
  finish_levels(m);
  auto leaf = [](int parent, double v, double theta, double alpha) {
    LeafModel l;
    l.parent = parent;
    l.v = v;
    l.set_theta(theta);
    l.set_alpha(alpha);
    l.length = 0.08;
    l.width = 0.04;
    l.stem = 0.03;
    return l;
  };
  m.leaves = {leaf(5, 0.3, 0.5, 0.6), leaf(5, 0.9, 3.0, 1.0), leaf(8, 0.2, 1.5, 0.8), leaf(8, 1.0, 4.5, 0.4),
              leaf(9, 0.5, 0.1, 1.2), leaf(9, 0.7, 2.8, 0.9)};
  return m;
}

std::shared_ptr<TreeInstance> instance(uint64_t key, TreeModel model, dvec3 position, boreas_tree_mode mode,
                                       boreas_tree_response response) {
  auto t = std::make_shared<TreeInstance>();
  t->key = key;
  t->model = std::make_shared<const TreeModel>(std::move(model));
  t->params.species = t->model->species;
  t->params.position = {position.x, position.y, position.z};
  t->params.mode = mode;
  t->params.response = response;
  t->params.bend_exponent = 1.8;
  return t;
}

// ---- Worlds -------------------------------------------------------------------------------

using test::calm_grid;

std::unique_ptr<impl::World> wave_world(const std::vector<boreas_wave>& waves) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = calm_grid();
  def.waves = waves.empty() ? nullptr : waves.data();
  def.wave_count = static_cast<int>(waves.size());
  return std::make_unique<impl::World>(def);
}

boreas_wave wave(float dx, float dz, float amplitude, float wavelength, float speed, float sharpness) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = dx;
  w.direction[1] = dz;
  w.amplitude = amplitude;
  w.wavelength = wavelength;
  w.speed = speed;
  w.sharpness = sharpness;
  return w;
}

std::vector<boreas_wave> steady_wind(float amplitude) { return {wave(1.0f, 0.5f, amplitude, 20.0f, 0.0f, 0.0f)}; }

// Gusts of several lengths crossing the tree from different directions, peaks sharpened;
// `amplitude` is the strongest wave's.
std::vector<boreas_wave> gusty_wind(float amplitude) {
  return {wave(1.0f, 0.3f, amplitude, 17.0f, 6.0f, 2.0f), wave(0.6f, -1.0f, 0.6f * amplitude, 7.3f, 4.0f, 3.5f),
          wave(-0.4f, 1.0f, 0.4f * amplitude, 3.1f, 9.0f, 1.5f), wave(1.0f, 1.0f, 0.3f * amplitude, 1.7f, 2.5f, 1.0f)};
}

// The world's wind at p at its current time, in double (the grid part is zero).
ref::WindFn reference_wind(const impl::World& world) {
  const double t = world.time();
  const impl::WaveLayers& layers = world.wind().wave_layers();
  return [t, &layers](const dvec3& p) {
    std::array<double, 2> f = ref::sine_sum(layers, p.x, p.z, t);
    return dvec3(f[0], 0.0, f[1]);
  };
}

// ---- Reading the batch ------------------------------------------------------------------

dvec3 d3(const float* v) { return dvec3(v[0], v[1], v[2]); }

ref::Branch as_branch(const boreas_branch& b) {
  ref::Branch r;
  for (int k = 0; k < 4; ++k) r.curve.p[k] = d3(b.control_points[k]);
  r.o = d3(b.orientation);
  return r;
}

std::vector<ref::Branch> as_branches(const std::vector<boreas_branch>& bs) {
  std::vector<ref::Branch> out;
  for (const boreas_branch& b : bs) out.push_back(as_branch(b));
  return out;
}

struct Errors {
  double position = 0.0;  // m, largest over every control point
  double orientation = 0.0;
  double orientation_share = 0.0;  // largest of each branch's error over its tolerance
};

// `orientation_tolerance`: one per branch (orientation_tolerances below); empty: none.
Errors compare(const std::vector<boreas_branch>& kernel, const std::vector<ref::Branch>& reference,
               const std::vector<double>& orientation_tolerance = {}) {
  Errors e;
  EXPECT_EQ(kernel.size(), reference.size());
  for (size_t b = 0; b < std::min(kernel.size(), reference.size()); ++b) {
    for (int k = 0; k < 4; ++k)
      e.position = std::max(e.position, glm::length(d3(kernel[b].control_points[k]) - reference[b].curve.p[k]));
    const double o = glm::length(d3(kernel[b].orientation) - reference[b].o);
    e.orientation = std::max(e.orientation, o);
    if (b < orientation_tolerance.size())
      e.orientation_share = std::max(e.orientation_share, o / orientation_tolerance[b]);
  }
  return e;
}

// The tree's extent: the largest distance of a control point from the trunk's base.
double tree_size(const std::vector<ref::Branch>& branches) {
  double s = 0.0;
  for (const ref::Branch& b : branches)
    for (const dvec3& p : b.curve.p) s = std::max(s, glm::length(p - branches[0].curve.p[0]));
  return s;
}

uint64_t fnv1a(const void* data, size_t bytes, uint64_t h = 1469598103934665603ull) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

// ---- (a) kernels against the double reference ----------------------------------------------

// Tolerance: float32 rounds at 2^-24 ~ 6e-8 relative. A control point is the end of a
// chain of at most four attachments (each a Sloan frame and a placement: ~10 roundings
// with the tree's size as lever arm) and one bend, so one step's error is about
// 100 x 6e-8 ~ 6e-6 of the tree's size. It does not accumulate: every step re-places the
// branches from their static shapes, and the only carried state (the bend factor F) is a
// contracting linear recursion of the wind, whose error (float sine polynomial, the
// sampling point's position error times the wind's gradient) is below 1e-6 relative.
// 1e-4 of the tree's size leaves more than 10x margin.
constexpr double kRelativeTolerance = 1e-4;

// The orientation vectors are unit, but they are not conditioned by the tree's size: each
// branch's frame is rebuilt from its parent's control points, world positions in float32,
// so the directions of the parent's segments (and with them its Sloan frame at v, the
// child's axis and O) carry the rounding of those positions over the segment's length:
// about 2^-24 X / segment, X the largest coordinate. A branch adds that of every
// branch between it and the root, since its O is built on theirs. For segments of
// decimeters and more this is below 1e-5 and 1e-4 absolute holds with 10x margin; but a
// split stem's pieces can be one segment of a short stem (the split tree's level-1 pieces:
// 1.6 cm segments 9.8 m up, four splits deep, ~1e-4). No formula gets under it: the double
// reference with its state rounded to float32 after each branch is as far off (7e-5 on
// the split tree). So each branch's tolerance is 10x that chain's sum where it passes
// 1e-4 (branches with coarse chains keep 1e-4).
std::vector<double> orientation_tolerances(const TreeModel& model, const std::vector<ref::Branch>& rest) {
  double x = 0.0;
  for (const ref::Branch& b : rest)
    for (const dvec3& p : b.curve.p) x = std::max({x, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const double ulp = std::ldexp(x, -24);
  std::vector<double> chain(rest.size(), 0.0), tolerance(rest.size());
  for (size_t b = 0; b < rest.size(); ++b) {
    double shortest = glm::length(rest[b].curve.p[1] - rest[b].curve.p[0]);
    for (int k = 1; k < 3; ++k) shortest = std::min(shortest, glm::length(rest[b].curve.p[k + 1] - rest[b].curve.p[k]));
    const int parent = model.branches[b].parent;
    chain[b] = ulp / shortest + (parent >= 0 ? chain[size_t(parent)] : 0.0);
    tolerance[b] = std::max(kRelativeTolerance, 10.0 * chain[b]);
  }
  return tolerance;
}

void run_against_reference(boreas_tree_mode mode, boreas_tree_response response,
                           const std::vector<boreas_wave>& waves, int steps, float dt,
                           const TreeModel& model = hand_tree(),
                           boreas_tree_load load = BOREAS_TREE_LOAD_DRAG) {
  auto world = wave_world(waves);
  auto tree = instance(7, model, dvec3(3.0, 0.5, -2.0), mode, response);
  tree->params.load = load;
  impl::TreeBatch& batch = world->tree_batch(mode);
  batch.add(tree);
  ref::TreeReference reference(*tree);
  const double size = tree_size(reference.rest());
  ASSERT_GT(size, 8.0);
  const std::vector<double> orientation_tolerance = orientation_tolerances(model, reference.rest());
  Errors worst;
  double moved = 0.0;
  for (int s = 0; s < steps; ++s) {
    world->step(dt);
    reference.step(double(dt), mode, reference_wind(*world));
    std::vector<boreas_branch> kernel = batch.branches(tree->key);
    Errors e = compare(kernel, reference.branches(), orientation_tolerance);
    worst.position = std::max(worst.position, e.position);
    worst.orientation = std::max(worst.orientation, e.orientation);
    worst.orientation_share = std::max(worst.orientation_share, e.orientation_share);
    ASSERT_LT(e.position, kRelativeTolerance * size) << "step " << s;
    ASSERT_LT(e.orientation_share, 1.0) << "step " << s << ", orientation " << e.orientation;
    // Leaves: the kernel's against the reference's on the reference's state, within the
    // tolerance plus the packed leaves' bound (cl/shared/leaf_pack.h).
    std::vector<boreas_leaf> leaves = batch.leaves(tree->key);
    std::vector<ref::LeafPose> ref_leaves = reference.leaves();
    ASSERT_EQ(leaves.size(), ref_leaves.size());
    for (size_t j = 0; j < leaves.size(); ++j) {
      const LeafModel& lm = model.leaves[j];
      const test::LeafBound bound =
          test::leaf_bound(reference.branches()[size_t(lm.parent)], lm.stem * tree->params.scale);
      ASSERT_LT(glm::length(d3(leaves[j].position) - ref_leaves[j].position),
                kRelativeTolerance * size + bound.position);
      ASSERT_LT(glm::length(d3(leaves[j].axis) - ref_leaves[j].axis), kRelativeTolerance + bound.axis);
      ASSERT_LT(glm::length(d3(leaves[j].normal) - ref_leaves[j].normal),
                kRelativeTolerance + bound.normal);
    }
    for (size_t b = 0; b < kernel.size(); ++b)
      moved = std::max(moved, glm::length(reference.branches()[b].curve.p[3] - reference.rest()[b].curve.p[3]));
  }
  // The wind did something worth comparing: tips moved by far more than the tolerance.
  EXPECT_GT(moved, 100.0 * kRelativeTolerance * size);
  std::printf("    [%s %s %s] max position error %.3g m (%.3g of size %.2f m), orientation %.3g (%.2g of its "
              "tolerance, %.3g at most), tips moved %.3g m\n",
              mode == BOREAS_TREE_LAGGED ? "lagged" : "exact",
              response == BOREAS_TREE_DAMPED ? "damped" : "quasi-static",
              load == BOREAS_TREE_LOAD_DRAG ? "drag" : "linear", worst.position, worst.position / size,
              size, worst.orientation, worst.orientation_share,
              *std::max_element(orientation_tolerance.begin(), orientation_tolerance.end()), moved);
}

TEST(TreeKernel, LaggedMatchesReferenceUnderSteadyWind) {
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC, steady_wind(8.0f), 12, 1.0f / 30.0f);
}

TEST(TreeKernel, ExactMatchesReferenceUnderSteadyWind) {
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC, steady_wind(8.0f), 12, 1.0f / 30.0f);
}

// A tree whose stems split: its pieces hang from the tips of the pieces they grow from, in
// the same level. Exact mode steps them tier by tier (TreeModel::tier_begin), so each is
// placed on its parent's new state, as the reference does branch by branch.
TreeModel split_tree() {
  impl::Species s;
  s.name = "split";
  s.levels = 3;
  s.scale = 9.0;
  s.base_size = 0.3;
  s.base_splits = 2;
  s.level[0].curve_res = 5;
  s.level[0].split_angle = 25.0;
  s.level[0].seg_splits = 0.3;
  s.level[1].branches = 8;
  s.level[1].down_angle = 50.0;
  s.level[1].curve_res = 6;
  s.level[1].seg_splits = 0.4;
  s.level[1].split_angle = 30.0;
  s.level[2].branches = 3;
  s.leaves = 4;
  s.leaf_bend = 0.6;
  s.wood_modulus = 0.01;  // GPa: soft, as the hand tree's
  return impl::grow_tree(s, 3);
}

TEST(TreeKernel, ExactStepsSplitPiecesAfterThePiecesTheyGrowFrom) {
  const TreeModel m = split_tree();
  ASSERT_GT(m.tiers(), 4);
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC, gusty_wind(8.0f), 20, 1.0f / 30.0f, m);
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED, gusty_wind(8.0f), 20, 1.0f / 60.0f, m);
}

TEST(TreeKernel, LaggedMatchesReferenceUnderGustyWind) {
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC, gusty_wind(8.0f), 40, 1.0f / 30.0f);
}

TEST(TreeKernel, ExactMatchesReferenceUnderGustyWind) {
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC, gusty_wind(8.0f), 40, 1.0f / 30.0f);
}

TEST(TreeKernel, DampedLaggedMatchesReferenceUnderGustyWind) {
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED, gusty_wind(8.0f), 60, 1.0f / 60.0f);
}

TEST(TreeKernel, DampedExactMatchesReferenceUnderGustyWind) {
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED, gusty_wind(8.0f), 60, 1.0f / 60.0f);
}

// A storm at 30 Hz: the drag's aerodynamic damping at its strongest (cl/shared/tree_math.h,
// boreas_damped_step).
TEST(TreeKernel, DampedExactMatchesReferenceInAStormAt30Hz) {
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED, gusty_wind(25.0f), 60, 1.0f / 30.0f);
}

// The paper's linear load through the same kernel.
TEST(TreeKernel, LinearLoadMatchesReference) {
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC, gusty_wind(8.0f), 30, 1.0f / 30.0f,
                        hand_tree(), BOREAS_TREE_LOAD_LINEAR);
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED, gusty_wind(8.0f), 60, 1.0f / 60.0f, hand_tree(),
                        BOREAS_TREE_LOAD_LINEAR);
}

// Several trees in one batch (roots of their own, levels interleaved across trees) and a
// tree added after steps (the rebuild keeps the others' state).
TEST(TreeKernel, SeveralTreesInOneBatchMatchTheirReferences) {
  const boreas_tree_mode mode = BOREAS_TREE_EXACT;
  auto world = wave_world(gusty_wind(6.0f));
  impl::TreeBatch& batch = world->tree_batch(mode);
  TreeModel small;
  small.species = "small";
  small.branches.push_back(hand_branch(0, -1, 3.0, 0.1, 0.1, 0.0, 0.0, 0.0, 0.0));
  small.branches.push_back(hand_branch(1, 0, 1.0, 0.02, 0.3, 0.5, 0.7, 1.0, 0.8));
  finish_levels(small);
  auto a = instance(1, hand_tree(), dvec3(-5.0, 0.0, 4.0), mode, BOREAS_TREE_DAMPED);
  auto b = instance(2, small, dvec3(6.0, 1.0, 1.0), mode, BOREAS_TREE_QUASI_STATIC);
  batch.add(a);
  batch.add(b);
  ref::TreeReference ra(*a), rb(*b);
  const float dt = 1.0f / 30.0f;
  for (int s = 0; s < 10; ++s) {
    world->step(dt);
    ra.step(dt, mode, reference_wind(*world));
    rb.step(dt, mode, reference_wind(*world));
  }
  auto c = instance(3, hand_tree(), dvec3(0.0, 0.0, -8.0), mode, BOREAS_TREE_QUASI_STATIC);
  batch.add(c);
  ref::TreeReference rc(*c);
  for (int s = 0; s < 10; ++s) {
    world->step(dt);
    ra.step(dt, mode, reference_wind(*world));
    rb.step(dt, mode, reference_wind(*world));
    rc.step(dt, mode, reference_wind(*world));
  }
  EXPECT_LT(compare(batch.branches(1), ra.branches()).position, kRelativeTolerance * tree_size(ra.rest()));
  EXPECT_LT(compare(batch.branches(2), rb.branches()).position, kRelativeTolerance * tree_size(rb.rest()));
  EXPECT_LT(compare(batch.branches(3), rc.branches()).position, kRelativeTolerance * tree_size(rc.rest()));
  batch.remove(1);
  world->step(dt);
  rb.step(dt, mode, reference_wind(*world));
  rc.step(dt, mode, reference_wind(*world));
  EXPECT_LT(compare(batch.branches(2), rb.branches()).position, kRelativeTolerance * tree_size(rb.rest()));
  EXPECT_LT(compare(batch.branches(3), rc.branches()).position, kRelativeTolerance * tree_size(rc.rest()));
}

// Two trunks standing apart (Arbaro's 0BranchDist: BranchModel::local[0], the shape's
// LOCAL_P0), each with a limb and leaves: the kernels place every branch and leaf where the
// reference does, under gusts, in both modes; and each trunk's base stays where it stands
// (tree position + its offset) while its tip moves: the wind bends it about its own base.
TreeModel clump_tree() {
  TreeModel m;
  m.species = "clump";
  m.wood_modulus = 1e7;
  auto apart = [](BranchModel b, dvec3 offset) {  // offset in the trunk's attachment frame
    for (auto& p : b.local)
      for (int c = 0; c < 3; ++c) p[size_t(c)] += offset[c];
    return b;
  };
  // With alpha 0.15 the frame's x is near the vertical; (0, 0.5, 0.4) is mostly horizontal.
  m.branches.push_back(apart(hand_branch(0, -1, 8.5, 0.25, 0.1, 0.5, 0.0, 0.0, 0.15), dvec3(0.0, 0.5, 0.4)));
  m.branches.push_back(apart(hand_branch(0, -1, 7.0, 0.2, -0.15, 1.1, 0.0, 2.3, 0.25), dvec3(0.0, -0.6, 0.2)));
  m.branches.push_back(hand_branch(1, 0, 2.5, 0.07, 0.25, 1.1, 0.6, 0.4, 0.9));
  m.branches.push_back(hand_branch(1, 1, 2.0, 0.06, -0.2, 0.3, 0.7, 2.5, 1.1));
  finish_levels(m);
  auto leaf = [](int parent, double v, double theta, double alpha) {
    LeafModel l;
    l.parent = parent;
    l.v = v;
    l.set_theta(theta);
    l.set_alpha(alpha);
    l.length = 0.08;
    l.width = 0.04;
    l.stem = 0.03;
    return l;
  };
  m.leaves = {leaf(2, 0.5, 0.5, 0.6), leaf(2, 1.0, 3.0, 1.0), leaf(3, 0.4, 1.5, 0.8)};
  return m;
}

TEST(TreeKernel, TrunksStandingApartMatchReference) {
  run_against_reference(BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC, gusty_wind(8.0f), 20, 1.0f / 30.0f,
                        clump_tree());
  run_against_reference(BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED, gusty_wind(8.0f), 60, 1.0f / 30.0f,
                        clump_tree());
}

TEST(TreeKernel, TrunksStandingApartBendAboutTheirOwnBases) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    auto world = wave_world(gusty_wind(12.0f));
    const dvec3 position(3.0, 0.5, -2.0);
    auto tree = instance(1, clump_tree(), position, mode, BOREAS_TREE_DAMPED);
    impl::TreeBatch& batch = world->tree_batch(mode);
    batch.add(tree);
    ref::TreeReference reference(*tree);
    const std::vector<ref::Branch>& rest = reference.rest();
    // The reference's bases: the tree's position plus each offset (turned with its tilted
    // trunk's frame, so within 0.15 m of the ground here), over a metre apart.
    for (int t = 0; t < 2; ++t) EXPECT_NEAR(rest[size_t(t)].curve.p[0].y, position.y, 0.15);
    ASSERT_GT(glm::length(rest[0].curve.p[0] - rest[1].curve.p[0]), 1.0);
    double tip = 0.0;
    for (int s = 0; s < 40; ++s) {
      world->step(1.0f / 30.0f);
      const std::vector<boreas_branch> now = batch.branches(1);
      for (int t = 0; t < 2; ++t) {
        ASSERT_LT(glm::length(d3(now[size_t(t)].control_points[0]) - rest[size_t(t)].curve.p[0]), 1e-5)
            << "step " << s << " trunk " << t;
        tip = std::max(tip, glm::length(d3(now[size_t(t)].control_points[3]) - rest[size_t(t)].curve.p[3]));
      }
    }
    EXPECT_GT(tip, 0.05);  // the trunks bent
    // The mesh sweeps each trunk from where it stands: its first ring (v = 0; the clump's
    // trunks have no flare or lobes) is centred on its base.
    std::vector<boreas_vertex> vertices;
    std::vector<uint32_t> indices;
    batch.mesh(1, &vertices, &indices);
    const impl::TreeLevelParams& lp = tree->params.levels[0];
    size_t first = 0;
    for (int t = 0; t < 2; ++t) {
      dvec3 centre(0.0);
      for (int k = 0; k < lp.sides; ++k) centre += d3(vertices[first + size_t(k)].position) / double(lp.sides);
      EXPECT_LT(glm::length(centre - rest[size_t(t)].curve.p[0]), 1e-4) << "trunk " << t;
      first += size_t(lp.rings + 1) * size_t(lp.sides + 1);
    }
  }
}

// ---- (b) no wind, no motion ---------------------------------------------------------------

TEST(TreeKernel, NoWindNoMotion) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    for (boreas_tree_response response : {BOREAS_TREE_QUASI_STATIC, BOREAS_TREE_DAMPED}) {
      auto world = wave_world({});
      auto tree = instance(1, hand_tree(), dvec3(3.0, 0.5, -2.0), mode, response);
      impl::TreeBatch& batch = world->tree_batch(mode);
      batch.add(tree);
      ref::TreeReference reference(*tree);
      std::vector<boreas_branch> placed = batch.branches(1);
      std::vector<boreas_leaf> placed_leaves = batch.leaves(1);
      for (int s = 0; s < 50; ++s) world->step(1.0f / 30.0f);
      std::vector<boreas_branch> after = batch.branches(1);
      // The unbent placement in double, and the host's own placement at add().
      EXPECT_LT(compare(after, reference.rest()).position, 1e-5) << mode << " " << response;
      EXPECT_LT(compare(after, reference.rest()).orientation, 1e-5);
      EXPECT_LT(compare(after, as_branches(placed)).position, 1e-5);
      std::vector<boreas_leaf> leaves = batch.leaves(1);
      for (size_t j = 0; j < leaves.size(); ++j)
        EXPECT_LT(glm::length(d3(leaves[j].position) - d3(placed_leaves[j].position)), 1e-5);
    }
  }
}

// ---- (c) segment lengths kept --------------------------------------------------------------

TEST(TreeKernel, SegmentLengthsKeptUnderStrongGusts) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    auto world = wave_world(gusty_wind(40.0f));
    TreeModel model = hand_tree();
    auto tree = instance(1, model, dvec3(0.0, 0.0, 0.0), mode, BOREAS_TREE_DAMPED);
    impl::TreeBatch& batch = world->tree_batch(mode);
    batch.add(tree);
    double worst = 0.0, bent = 0.0;
    for (int s = 0; s < 200; ++s) {
      world->step(1.0f / 30.0f);
      std::vector<boreas_branch> bs = batch.branches(1);
      for (size_t b = 0; b < bs.size(); ++b) {
        const BranchModel& m = model.branches[b];
        for (int k = 1; k <= 3; ++k) {
          double want = glm::length(dvec3(m.local[k][0], m.local[k][1], m.local[k][2]) -
                                    dvec3(m.local[k - 1][0], m.local[k - 1][1], m.local[k - 1][2]));
          double got = glm::length(d3(bs[b].control_points[k]) - d3(bs[b].control_points[k - 1]));
          worst = std::max(worst, std::abs(got - want) / want);
          ASSERT_NEAR(got, want, 1e-4 * want) << "step " << s << " branch " << b << " segment " << k;
        }
        // How much the chord P0-P3 changed from the unbent one (did the wind bend it?).
        dvec3 local_tip = dvec3(m.local[3][0], m.local[3][1], m.local[3][2]);
        double chord = glm::length(d3(bs[b].control_points[3]) - d3(bs[b].control_points[0]));
        bent = std::max(bent, std::abs(chord - glm::length(local_tip)) / glm::length(local_tip));
      }
    }
    std::printf("    [%s] worst segment length error %.3g relative; chord changed by up to %.2f\n",
                mode == BOREAS_TREE_LAGGED ? "lagged" : "exact", worst, bent);
    EXPECT_GT(bent, 0.05);  // the wind bent the branches hard
  }
}

// ---- (d) children stay on their parents ------------------------------------------------------

TEST(TreeKernel, ChildrenStayOnTheirParentsCurve) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    auto world = wave_world(gusty_wind(12.0f));
    TreeModel model = hand_tree();
    const dvec3 base(3.0, 0.5, -2.0);
    auto tree = instance(1, model, base, mode, BOREAS_TREE_DAMPED);
    impl::TreeBatch& batch = world->tree_batch(mode);
    batch.add(tree);
    std::vector<boreas_branch> previous = batch.branches(1);
    double worst = 0.0, off_current = 0.0;
    for (int s = 0; s < 60; ++s) {
      world->step(1.0f / 30.0f);
      std::vector<boreas_branch> now = batch.branches(1);
      // The trunk's P0 on the fixed root: the tree's base.
      EXPECT_LT(glm::length(d3(now[0].control_points[0]) - base), 1e-6);
      for (size_t b = 1; b < now.size(); ++b) {
        const BranchModel& m = model.branches[b];
        const std::vector<boreas_branch>& parents = mode == BOREAS_TREE_EXACT ? now : previous;
        dvec3 on = ref::bezier_point(as_branch(parents[m.parent]).curve, m.v);
        double d = glm::length(d3(now[b].control_points[0]) - on);
        worst = std::max(worst, d);
        // Float: a Bezier point of coordinates up to ~12 m rounds at ~1e-6 m.
        ASSERT_LT(d, 1e-5) << "step " << s << " branch " << b;
        dvec3 on_now = ref::bezier_point(as_branch(now[m.parent]).curve, m.v);
        off_current = std::max(off_current, glm::length(d3(now[b].control_points[0]) - on_now));
      }
      previous = now;
    }
    std::printf("    [%s] P0 off its parent's curve by at most %.3g m; off the parent's current curve by %.3g m\n",
                mode == BOREAS_TREE_LAGGED ? "lagged" : "exact", worst, off_current);
    // Lagged children hang from the parent's previous curve, which visibly differs.
    if (mode == BOREAS_TREE_LAGGED) {
      EXPECT_GT(off_current, 1e-3);
    }
  }
}

// ---- (e) leaves stay attached ------------------------------------------------------------------

// The longest leg of a branch's control polygon, m: its curve moves at most 3 times it per
// unit of v.
double leaf_leg(const ref::Branch& b) {
  double leg = 0.0;
  for (int k = 0; k < 3; ++k) leg = std::max(leg, glm::length(b.curve.p[k + 1] - b.curve.p[k]));
  return leg;
}

TEST(TreeKernel, LeavesStayOnTheirBranches) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    auto world = wave_world(gusty_wind(15.0f));
    TreeModel model = hand_tree();
    auto tree = instance(1, model, dvec3(-1.0, 0.0, 2.0), mode, BOREAS_TREE_DAMPED);
    impl::TreeBatch& batch = world->tree_batch(mode);
    batch.add(tree);
    for (int s = 0; s < 40; ++s) {
      world->step(1.0f / 30.0f);
      std::vector<boreas_branch> bs = batch.branches(1);
      std::vector<boreas_leaf> leaves = batch.leaves(1);
      ASSERT_EQ(leaves.size(), model.leaves.size());
      for (size_t j = 0; j < leaves.size(); ++j) {
        const LeafModel& lm = model.leaves[j];
        EXPECT_EQ(leaves[j].branch, lm.parent);
        dvec3 axis = d3(leaves[j].axis), normal = d3(leaves[j].normal);
        EXPECT_NEAR(glm::length(axis), 1.0, 1e-5);
        EXPECT_NEAR(glm::length(normal), 1.0, 1e-5);
        EXPECT_NEAR(glm::dot(axis, normal), 0.0, 1e-5);
        // On the branch as it is after this step (leaves never lag), within the packed
        // leaves' bound (cl/shared/leaf_pack.h) of where the model puts it.
        ref::Branch parent = as_branch(bs[lm.parent]);
        const test::LeafBound bound = test::leaf_bound(parent, lm.stem);
        dvec3 want = ref::bezier_point(parent.curve, lm.v) + lm.stem * axis;
        ASSERT_LT(glm::length(d3(leaves[j].position) - want), 1e-5 + 3.0 * leaf_leg(parent) * test::leaf_v_bound())
            << "step " << s << " leaf " << j;
        // And turned as the reference attaches it to that branch.
        ref::LeafPose pose = ref::leaf_pose(parent, lm);
        EXPECT_LT(glm::length(d3(leaves[j].position) - pose.position), 1e-5 + bound.position);
        EXPECT_LT(glm::length(axis - pose.axis), 1e-5 + bound.axis);
        EXPECT_LT(glm::length(normal - pose.normal), 1e-5 + bound.normal);
      }
    }
  }
}

// ---- (f) damped response -------------------------------------------------------------------

// A single straight vertical trunk (alpha 0: it continues the vertical root) under a
// uniform wind along +x switched on at t = 0. Its bend factor F is horizontal, so from
// the bent last segment d = P3 - P2 = |s3| normalize(s3 + F) with s3 vertical of length
// l3: F_x = l3 d_x / d_y, exactly.
struct SingleBranchRun {
  std::vector<double> f;  // F_x after each step
  double target = 0.0;    // F* = compliance * wind
  double omega = 0.0, zeta = 0.0;
};

SingleBranchRun run_single_branch(boreas_tree_response response, int steps, float dt) {
  const float amplitude = 5.0f;
  auto world = wave_world({wave(1.0f, 0.0f, amplitude, 20.0f, 0.0f, 0.0f)});
  TreeModel m;
  m.species = "single";
  m.branches.push_back(hand_branch(0, -1, 4.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0));
  finish_levels(m);
  auto tree = instance(1, m, dvec3(0.0), BOREAS_TREE_EXACT, response);
  tree->params.load = BOREAS_TREE_LOAD_LINEAR;  // the linear oscillator's analytic response
  impl::TreeBatch& batch = world->tree_batch(BOREAS_TREE_EXACT);
  batch.add(tree);
  SingleBranchRun run;
  const impl::TreeLevelParams& lp = tree->params.levels[0];
  run.target = impl::bend_compliance(m.branches[0], lp) * amplitude;
  run.omega = impl::natural_frequency(m.branches[0], lp, m.wood_modulus);
  run.zeta = lp.damping_ratio;
  const double l3 = 4.0 / 3.0;
  for (int s = 0; s < steps; ++s) {
    world->step(dt);
    boreas_branch b = batch.branches(1)[0];
    dvec3 d = d3(b.control_points[3]) - d3(b.control_points[2]);
    EXPECT_NEAR(d.z, 0.0, 1e-6);
    run.f.push_back(l3 * d.x / d.y);
  }
  return run;
}

TEST(TreeKernel, DampedResponseOvershootsByTheAnalyticAmount) {
  const float dt = 1.0f / 240.0f;
  SingleBranchRun run = run_single_branch(BOREAS_TREE_DAMPED, 240, dt);
  ASSERT_GT(run.target, 0.0);
  const double zeta = run.zeta, w = run.omega;
  ASSERT_LT(zeta, 1.0);
  // At least one full period in the run, and a step much shorter than it.
  const double wd = w * std::sqrt(1.0 - zeta * zeta);
  ASSERT_GT(240 * dt, 2.0 * kPi / wd);
  ASSERT_LT(wd * dt, 0.1);
  double peak = *std::max_element(run.f.begin(), run.f.end());
  double overshoot = peak / run.target - 1.0;
  double analytic = std::exp(-kPi * zeta / std::sqrt(1.0 - zeta * zeta));
  std::printf("    omega %.2f rad/s zeta %.2f: overshoot %.4f, analytic %.4f\n", w, zeta, overshoot, analytic);
  // Sampling at w_d dt < 0.1 misses the continuous peak by < (w_d dt / 2)^2 / 2 of the
  // overshoot (0.13%); 2% leaves room for nothing else.
  EXPECT_NEAR(overshoot, analytic, 0.02 * analytic);
  // The whole trajectory is the step response of x'' + 2 zeta w x' + w^2 x = w^2 F*.
  for (size_t k = 0; k < run.f.size(); ++k) {
    double t = double(k + 1) * double(dt);
    double x = 1.0 - std::exp(-zeta * w * t) *
                         (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t));
    ASSERT_NEAR(run.f[k] / run.target, x, 1e-3) << "step " << k;
  }
}

TEST(TreeKernel, QuasiStaticResponseHasNoOvershoot) {
  SingleBranchRun run = run_single_branch(BOREAS_TREE_QUASI_STATIC, 60, 1.0f / 240.0f);
  ASSERT_GT(run.target, 0.0);
  for (size_t k = 0; k < run.f.size(); ++k) ASSERT_NEAR(run.f[k], run.target, 1e-5 * run.target) << "step " << k;
}

// The reference's response (matrix exponential) against tree_params' closed forms, which
// the batch uploads: under-, critically and over-damped.
TEST(TreeKernel, ResponseStepMatchesClosedForms) {
  for (double zeta : {0.05, 0.15, 0.7, 0.99, 1.0, 1.0005, 1.01, 2.5}) {
    for (double w : {0.5, 7.0, 60.0}) {
      for (double dt : {1.0 / 240.0, 1.0 / 30.0, 0.5}) {
        std::array<double, 4> closed = impl::oscillator_step(w, zeta, dt);
        ref::Response r = ref::response_step(w, zeta, dt);
        double got[4] = {r.a, r.b, r.c, r.d};
        // Within 1e-3 of critical damping tree_params takes the critically damped form,
        // off by O(|zeta - 1|) relative (3e-4 at zeta = 1.0005); elsewhere both are exact.
        const double rel = std::abs(zeta - 1.0) < 1e-3 && zeta != 1.0 ? 1e-3 : 1e-9;
        for (int i = 0; i < 4; ++i)
          EXPECT_NEAR(got[i], closed[i], rel * std::max({1.0, w * w * dt, std::abs(closed[i])}))
              << "zeta " << zeta << " omega " << w << " dt " << dt << " entry " << i;
      }
    }
  }
}

// ---- (g) determinism ---------------------------------------------------------------------

uint64_t run_and_hash(boreas_tree_mode mode) {
  auto world = wave_world(gusty_wind(20.0f));
  impl::TreeBatch& batch = world->tree_batch(mode);
  batch.add(instance(1, hand_tree(), dvec3(3.0, 0.0, -2.0), mode, BOREAS_TREE_DAMPED));
  batch.add(instance(2, hand_tree(), dvec3(-6.0, 0.0, 5.0), mode, BOREAS_TREE_QUASI_STATIC));
  for (int s = 0; s < 30; ++s) world->step(1.0f / 30.0f);
  uint64_t h = 1469598103934665603ull;
  for (uint64_t key : {1, 2}) {
    std::vector<float> state = batch.read_tree_state(key);
    h = fnv1a(state.data(), state.size() * sizeof(float), h);
    std::vector<boreas_leaf> leaves = batch.leaves(key);
    h = fnv1a(leaves.data(), leaves.size() * sizeof(boreas_leaf), h);
  }
  return h;
}

TEST(TreeKernel, SameInputsGiveBitIdenticalState) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    uint64_t a = run_and_hash(mode), b = run_and_hash(mode);
    EXPECT_EQ(a, b) << "mode " << mode;
  }
}

// ---- The shared header's C++ compile against the reference -----------------------------------

BoreasV3 f3(const dvec3& v) { return boreas_v3(float(v.x), float(v.y), float(v.z)); }
dvec3 d3(const BoreasV3& v) { return dvec3(v.x, v.y, v.z); }

TEST(TreeKernel, SharedHeaderAttachAndBendMatchReference) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit01(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    ref::Branch parent;
    dvec3 p(u(rng), u(rng), u(rng));
    dvec3 dir = glm::normalize(dvec3(u(rng), 1.5, u(rng)));
    for (int k = 0; k < 4; ++k) {
      parent.curve.p[k] = p;
      dir = glm::normalize(dir + 0.4 * dvec3(u(rng), u(rng), u(rng)));
      p += (0.5 + unit01(rng)) * dir;
    }
    dvec3 l0 = glm::normalize(parent.curve.p[1] - parent.curve.p[0]);
    dvec3 any(u(rng), u(rng), u(rng));
    parent.o = glm::normalize(any - glm::dot(any, l0) * l0);
    // Rounded to float first, so both sides see the same input.
    BoreasBezier c;
    c.p0 = f3(parent.curve.p[0]);
    c.p1 = f3(parent.curve.p[1]);
    c.p2 = f3(parent.curve.p[2]);
    c.p3 = f3(parent.curve.p[3]);
    BoreasV3 o = f3(parent.o);
    parent.curve.p = {d3(c.p0), d3(c.p1), d3(c.p2), d3(c.p3)};
    parent.o = d3(o);
    double v = unit01(rng), theta = 2.0 * kPi * unit01(rng), alpha = 1.5 * unit01(rng);
    BoreasAttachFrame a = boreas_attach(c, o, float(v), float(std::cos(theta)), float(std::sin(theta)),
                                        float(std::cos(alpha)), float(std::sin(alpha)));
    ref::AttachFrame r = ref::attach(parent, v, theta, alpha);
    EXPECT_LT(glm::length(d3(a.origin) - r.origin), 1e-5);
    EXPECT_LT(glm::length(d3(a.x) - r.x), 1e-5);
    EXPECT_LT(glm::length(d3(a.y) - r.y), 1e-5);
    EXPECT_LT(glm::length(d3(a.z) - r.z), 1e-5);
    // The attach frame is orthonormal and right-handed.
    EXPECT_NEAR(glm::dot(r.x, r.y), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(r.x, r.y) - r.z), 0.0, 1e-12);
    dvec3 seg(u(rng), u(rng), u(rng)), bend(u(rng), u(rng), u(rng)), prev(u(rng), u(rng), u(rng));
    BoreasV3 fb = boreas_bend_point(f3(prev), f3(seg), f3(bend));
    EXPECT_LT(glm::length(d3(fb) - ref::bend_point(d3(f3(prev)), d3(f3(seg)), d3(f3(bend)))), 1e-5);
  }
}

}  // namespace
}  // namespace boreas::test
