// boreas tests: colliders against generated trees (cl/shared/tree_contact.h, stepped by
// tree_step.cl's contact variant): a branch pushed out of a capsule it started in, its
// spring back as the free damped response, the force on the collider (direction, growth
// with depth, torque), the load its parent takes, determinism, and trees no collider
// reaches left bit for bit as in a world without colliders.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "boreas/boreas.h"
#include "support/test_support.h"
#include "host/trees/hand_built_trees.h"
#include "trees/tree_layout.h"
#include "trees/tree_templates.h"
#include "trees/wind_load.h"
#include "world.h"

namespace {

using boreas::impl::TreeInstance;
using boreas::impl::TreeModel;
using boreas::test::hand_branch;
using V = std::array<double, 3>;

constexpr float kDt = 1.0f / 60.0f;

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double len(V a) { return std::sqrt(dot(a, a)); }

// A sapling: a straight vertical trunk (the root's continuation), 2 m, 3 cm at the base,
// tapering to 0.3 cm; with a level-1 limb, 1 m, leaving it at 0.6 of its height.
TreeModel sapling(bool limb) {
  TreeModel m;
  m.species = "sapling";
  m.branches.push_back(hand_branch(0, -1, 2.0, 0.03, 0.0, 0.0, 0.0, 0.0, 0.0));
  if (limb) m.branches.push_back(hand_branch(1, 0, 1.0, 0.012, 0.0, 0.0, 0.6, 0.0, 1.4));
  boreas::test::finish_levels(m);
  return m;
}

std::shared_ptr<TreeInstance> instance(uint64_t key, const TreeModel& model, V at,
                                       boreas_tree_mode mode, boreas_tree_response response) {
  auto t = std::make_shared<TreeInstance>();
  t->key = key;
  t->model = std::make_shared<const TreeModel>(model);
  t->params.species = model.species;
  t->params.position = at;
  t->params.mode = mode;
  t->params.response = response;
  return t;
}

std::unique_ptr<boreas::impl::World> calm_world() {
  boreas_world_def def = boreas_default_world_def();
  def.grid = boreas::test::calm_grid();
  return std::make_unique<boreas::impl::World>(def);
}

boreas_collider_def capsule(V at, float radius, float half_height) {
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = BOREAS_COLLIDER_CAPSULE;
  for (int a = 0; a < 3; ++a) d.pose.position[a] = float(at[size_t(a)]);
  d.radius = radius;
  d.half_height = half_height;
  return d;
}

// Distance (double) from p to a still, upright capsule's surface: negative inside.
double capsule_distance(const boreas_collider_def& c, V p) {
  const V base = {c.pose.position[0], c.pose.position[1], c.pose.position[2]};
  V q = sub(p, base);
  q[1] -= std::clamp(q[1], -double(c.half_height), double(c.half_height));
  return len(q) - c.radius;
}

// The Bezier curve of a branch record at t, in double.
V curve_point(const boreas_branch& b, double t) {
  const double w = 1.0 - t, k[4] = {w * w * w, 3 * t * w * w, 3 * t * t * w, t * t * t};
  V p{};
  for (int i = 0; i < 4; ++i)
    for (size_t a = 0; a < 3; ++a) p[a] += k[i] * b.control_points[i][a];
  return p;
}

// The least clearance between a branch's surface (its taper; hand branches have no flare,
// bulges or lobes) and the capsule, over 200 points of its curve.
double clearance(const boreas_branch& b, const boreas::impl::BranchModel& model,
                 const boreas_collider_def& c) {
  double least = 1e30;
  for (int s = 0; s <= 200; ++s) {
    const double t = s / 200.0;
    const double r = model.radius * (1.0 - model.taper_depth * std::pow(t, model.taper_exponent));
    least = std::min(least, capsule_distance(c, curve_point(b, t)) - r);
  }
  return least;
}

V tip(const boreas_branch& b) {
  return {b.control_points[3][0], b.control_points[3][1], b.control_points[3][2]};
}

struct Mode {
  boreas_tree_mode mode;
  boreas_tree_response response;
};

class TreeContact : public ::testing::TestWithParam<Mode> {};

// A capsule standing beside the trunk's upper half, overlapping it by 5 cm more than its
// radius there: after 0.5 s (30 steps) the trunk's surface is outside, to 2 mm, and stays
// so for the next 0.5 s.
TEST_P(TreeContact, BranchEndsOutsideTheCapsuleItStartedIn) {
  auto world = calm_world();
  const TreeModel model = sapling(false);
  auto tree = instance(1, model, {0, 0, 0}, GetParam().mode, GetParam().response);
  boreas::impl::TreeBatch& batch = world->tree_batch(GetParam().mode);
  batch.add(tree);
  const boreas_collider_def c = capsule({0.04, 1.7, 0.0}, 0.1f, 0.3f);
  const boreas_collider_id id = world->add_collider(c);
  const double before = clearance(batch.branches(1)[0], model.branches[0], c);
  ASSERT_LT(before, -0.05);  // it starts deep inside
  for (int s = 0; s < 60; ++s) {
    world->step(kDt);
    const double now = clearance(batch.branches(1)[0], model.branches[0], c);
    if (s >= 29) EXPECT_GT(now, -2e-3) << "step " << s;
  }
  // Pushed away from the capsule (-x), and the capsule feels it push back (+x would be into
  // the trunk: the trunk pushes the capsule away from itself, +x).
  EXPECT_LT(tip(batch.branches(1)[0])[0], -0.05);
  const boreas_collider_contact contact = world->collider_contact(id);
  EXPECT_EQ(contact.contacts, 1);
  EXPECT_GT(contact.force[0], 0.0f);
}

// The contact reads the radius the deformer draws (boreas_branch_radius): a tip closed by its
// cap (Arbaro's hemisphere, here over the last 3 cm of a 3 cm cylinder) clears a ball that
// the same cylinder cut flat would touch. The ball sits off the tip's rim at 45 degrees: 5 mm
// into the flat end's ball of the tip's radius, 18 mm clear of the hemisphere.
TEST(TreeContactRadius, ACappedTipClearsABallItsFlatEndWouldTouch) {
  for (bool capped : {false, true}) {
    SCOPED_TRACE(capped ? "capped" : "flat");
    auto world = calm_world();
    TreeModel model = sapling(false);
    model.branches[0].taper_depth = 0.0;
    model.branches[0].tip_cap = capped ? 0.03 / 2.0 : 0.0;
    auto tree = instance(1, model, {0, 0, 0}, BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC);
    boreas::impl::TreeBatch& batch = world->tree_batch(BOREAS_TREE_EXACT);
    batch.add(tree);
    const V rest = tip(batch.branches(1)[0]);
    ASSERT_NEAR(rest[1], 2.0, 1e-5);
    boreas_collider_def ball = boreas_default_collider_def();
    const double out = (0.05 + 0.03 - 0.005) / std::sqrt(2.0);
    ball.pose.position[0] = float(rest[0] + out);
    ball.pose.position[1] = float(rest[1] + out);
    ball.pose.position[2] = float(rest[2]);
    ball.radius = 0.05f;
    const boreas_collider_id id = world->add_collider(ball);
    for (int s = 0; s < 5; ++s) world->step(kDt);
    const double moved = len(sub(tip(batch.branches(1)[0]), rest));
    if (capped) {
      EXPECT_EQ(world->collider_contact(id).contacts, 0);
      EXPECT_LT(moved, 1e-6);
    } else {
      EXPECT_EQ(world->collider_contact(id).contacts, 1);
      EXPECT_GT(moved, 1e-3);
    }
  }
}

// Let go after 1 s, the trunk's bend factor follows the free damped response from where it
// was let go: the exact oscillator step at its own frequency and damping (quasi-static: at
// once to rest). So it returns to its rest shape.
TEST_P(TreeContact, LetGoItSpringsBackAsItsFreeResponse) {
  auto world = calm_world();
  const TreeModel model = sapling(false);
  auto tree = instance(1, model, {0, 0, 0}, GetParam().mode, GetParam().response);
  boreas::impl::TreeBatch& batch = world->tree_batch(GetParam().mode);
  batch.add(tree);
  const boreas_collider_id id = world->add_collider(capsule({0.04, 1.7, 0.0}, 0.1f, 0.3f));
  for (int s = 0; s < 60; ++s) world->step(kDt);
  std::vector<float> motion = batch.read_tree_motion(1);  // planes of stride 2 (root, trunk)
  auto at = [&](const std::vector<float>& m, int plane) { return double(m[size_t(plane) * 2 + 1]); };
  constexpr int kF = BOREAS_TREE_MOTION_F, kDF = BOREAS_TREE_MOTION_DF;
  V f = {at(motion, kF), at(motion, kF + 1), at(motion, kF + 2)},
    u = {at(motion, kDF), at(motion, kDF + 1), at(motion, kDF + 2)};
  ASSERT_GT(len(f), 0.05);
  world->remove_collider(id);
  const boreas::impl::TreeTemplateBlock block =
      boreas::impl::tree_template_block(tree->params, model);
  const double omega = block.omega[1], zeta = block.zeta[1];
  const bool damped = GetParam().response == BOREAS_TREE_DAMPED;
  // Quasi-static: the bend is its target at once.
  const std::array<double, 4> m =
      damped ? boreas::impl::oscillator_step(omega, zeta, kDt) : std::array<double, 4>{};
  const double let_go = len(f);
  double peak_after_2s = 0.0;
  for (int s = 0; s < 240; ++s) {
    world->step(kDt);
    // The free response in double (calm: the target is 0).
    for (size_t a = 0; a < 3; ++a) {
      const double x = f[a], v = u[a];
      f[a] = m[0] * x + m[1] * v;
      u[a] = m[2] * x + m[3] * v;
    }
    motion = batch.read_tree_motion(1);
    for (int a = 0; a < 3; ++a)
      ASSERT_NEAR(at(motion, a), f[size_t(a)], 1e-4 + 1e-4 * len(f)) << "step " << s;
    if (s >= 120) peak_after_2s = std::max(peak_after_2s, std::fabs(at(motion, 0)));
  }
  if (damped) {
    // Within the envelope x0 e^(-zeta omega t) / sqrt(1 - zeta^2) of a release from rest.
    ASSERT_GT(omega, 0.0);
    EXPECT_LT(peak_after_2s,
              let_go * std::exp(-zeta * omega * 2.0) / std::sqrt(1 - zeta * zeta) + 1e-4);
  } else {
    EXPECT_LT(peak_after_2s, 1e-6);
  }
}

// A capsule walking into the trunk at 0.5 m/s until its axis reaches where the trunk stood
// (past that, see ColliderWalkingThroughNeverFlipsTheBranch): once touching, the trunk pushes it back
// (force against its velocity), harder as it goes deeper; the torque is the force's
// moment about its end position (perpendicular to the force: one contact point).
TEST_P(TreeContact, ForceOpposesTheColliderAndGrowsWithDepth) {
  auto world = calm_world();
  const TreeModel model = sapling(false);
  auto tree = instance(1, model, {0, 0, 0}, GetParam().mode, GetParam().response);
  world->tree_batch(GetParam().mode).add(tree);
  boreas_collider_def c = capsule({-0.15, 1.6, 0.0}, 0.1f, 0.2f);
  c.velocity[0] = 0.5f;
  const boreas_collider_id id = world->add_collider(c);
  double last = 0.0;
  int touching = 0, growing = 0;
  for (int s = 0; s < 17; ++s) {
    world->step(kDt);
    const boreas_collider_contact k = world->collider_contact(id);
    if (k.contacts == 0) {
      EXPECT_EQ(touching, 0) << "lost contact at step " << s;
      continue;
    }
    ++touching;
    EXPECT_LT(k.force[0], 0.0f) << "step " << s;
    const V force = {k.force[0], k.force[1], k.force[2]}, torque = {k.torque[0], k.torque[1], k.torque[2]};
    EXPECT_LT(std::fabs(dot(force, torque)), 1e-3 * len(force) * len(torque) + 1e-9);
    const double magnitude = len(force);
    if (magnitude > last) ++growing;
    last = magnitude;
  }
  EXPECT_GT(touching, 8);
  // Quasi-static: every step deeper pushes harder; damped: the bend lags the push, but the
  // force grows over the approach as a whole.
  EXPECT_GE(growing, GetParam().response == BOREAS_TREE_QUASI_STATIC ? touching - 1 : touching / 2);
  EXPECT_GT(last, 1.0);  // newtons: a 3 cm sapling bent by some 20 cm pushes back
}

// A capsule walking through the trunk at 0.5 m/s, 0.32 m, until its axis is 0.17 m past
// where the trunk stood and its far side past the trunk's rest pose (further on, the damped
// trunk, bent 0.6 m at its tip, breaks): the trunk is pushed ahead of it and stays there. It meets the capsule from the capsule's front, so its
// tip stays ahead of the capsule's axis for as long as they touch (a branch that took the
// nearest way out of the capsule would be pushed out behind it once the capsule's middle
// passed its rest axis), and it never jumps: a step moves the tip by a bounded multiple of
// the capsule's own step, 8.3 mm (the push at 0.8 of the height moves the tip about
// 1 / share(0.8) times as far).
TEST_P(TreeContact, ColliderWalkingThroughNeverFlipsTheBranch) {
  auto world = calm_world();
  const TreeModel model = sapling(false);
  auto tree = instance(1, model, {0, 0, 0}, GetParam().mode, GetParam().response);
  boreas::impl::TreeBatch& batch = world->tree_batch(GetParam().mode);
  batch.add(tree);
  boreas_collider_def c = capsule({-0.15, 1.6, 0.0}, 0.1f, 0.2f);
  c.velocity[0] = 0.5f;
  const boreas_collider_id id = world->add_collider(c);
  V last = tip(batch.branches(1)[0]);
  int touching = 0;
  double axis_x = 0.0;
  for (int s = 0; s < 38; ++s) {
    world->step(kDt);
    const V now = tip(batch.branches(1)[0]);
    axis_x = world->collider_pose(id).position[0];
    EXPECT_LT(len(sub(now, last)), 3.0 * 0.5 * kDt) << "step " << s;
    if (world->collider_contact(id).contacts > 0) {
      ++touching;
      EXPECT_GT(now[0], axis_x) << "step " << s << ": the tip is behind the capsule";
    }
    last = now;
  }
  EXPECT_GT(touching, 30);
  // Pushed along with the capsule: its rest pose is clear of the capsule, but the way back
  // is through it.
  EXPECT_GT(last[0], axis_x + 0.1);
}

// A sphere held against the limb: the trunk takes the limb's contact load at the limb's
// base (a step later), bending by share(v) / K_trunk times it, toward where the sphere
// pushes the limb.
// Checked at rest (quasi-static), in both modes.
class TreeContactParent : public ::testing::TestWithParam<boreas_tree_mode> {};

TEST_P(TreeContactParent, ParentTakesTheChildsContactLoad) {
  auto world = calm_world();
  const TreeModel model = sapling(true);
  auto tree = instance(1, model, {0, 0, 0}, GetParam(), BOREAS_TREE_QUASI_STATIC);
  boreas::impl::TreeBatch& batch = world->tree_batch(GetParam());
  batch.add(tree);
  const boreas_branch limb = batch.branches(1)[1];
  const V limb_tip = tip(limb);
  boreas_collider_def ball = boreas_default_collider_def();
  ball.radius = 0.1f;
  // Above the limb's outer part, 3 cm into it: it pushes the limb down.
  const V at = curve_point(limb, 0.8);
  ball.pose.position[0] = float(at[0]);
  ball.pose.position[1] = float(at[1] + 0.1 - 0.03);
  ball.pose.position[2] = float(at[2]);
  const boreas_collider_id id = world->add_collider(ball);
  // The trunk takes the load a step later: compared with the step before the last's force
  // (which the last repeats to a fraction of a per cent: the contact point at a grazing
  // touch is found to a small fraction of the curve, and share(t) follows it).
  boreas_collider_contact before{};
  for (int s = 0; s < 40; ++s) {
    before = world->collider_contact(id);
    world->step(kDt);
  }
  const boreas_collider_contact k = world->collider_contact(id);
  ASSERT_GE(k.contacts, 1);
  EXPECT_GT(k.force[1], 0.0f);  // the limb pushes the ball up
  EXPECT_LT(tip(batch.branches(1)[1])[1], limb_tip[1] - 0.02);
  // The trunk's bend: the limb's load (minus the force on the ball) at v = 0.6, a step
  // later.
  const std::vector<float> motion = batch.read_tree_motion(1);  // stride 3
  const std::vector<double> k_tip = boreas::impl::tip_stiffness(model, tree->params);
  const double w2 = std::pow(2.0 / 3.0, tree->params.bend_exponent);
  const double stiffness = k_tip[0] * (1 + w2) * (1 + w2), v = 0.6;
  const double share = 3 * v * v * (1 - v) * w2 + v * v * v * (1 + w2);
  for (int a = 0; a < 3; ++a) {
    const double want = -double(before.force[a]) * share / stiffness;
    EXPECT_NEAR(k.force[a], before.force[a], 1e-2 * std::fabs(before.force[a]) + 1e-6);
    EXPECT_NEAR(motion[size_t(a) * 3 + 1], want, 1e-3 * std::fabs(want) + 1e-7) << "axis " << a;
  }
  EXPECT_LT(motion[size_t(1) * 3 + 1], 0.0f);  // the trunk bends down with the limb
}

INSTANTIATE_TEST_SUITE_P(Modes, TreeContactParent,
                         ::testing::Values(BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT),
                         [](const ::testing::TestParamInfo<boreas_tree_mode>& p) {
                           return std::string(p.param == BOREAS_TREE_LAGGED ? "Lagged" : "Exact");
                         });

INSTANTIATE_TEST_SUITE_P(
    Modes, TreeContact,
    ::testing::Values(Mode{BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC},
                      Mode{BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED},
                      Mode{BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC},
                      Mode{BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED}),
    [](const ::testing::TestParamInfo<Mode>& p) {
      return std::string(p.param.mode == BOREAS_TREE_LAGGED ? "Lagged" : "Exact") +
             (p.param.response == BOREAS_TREE_DAMPED ? "Damped" : "QuasiStatic");
    });

// ---- Forests of grown trees ---------------------------------------------------------------

// An aspen at the origin with a car-sized box driving into it and a walker crossing it, and
// another aspen 15 m away that neither reaches; in a gusty wind, 60 steps.
struct ForestRun {
  std::vector<float> near_state, far_state;
  std::vector<boreas_collider_contact> contacts;
};

ForestRun run_forest(boreas_tree_mode mode, bool colliders) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = boreas::test::calm_grid();
  boreas_wave wave = boreas_default_wave();
  wave.amplitude = 8.0f;
  def.waves = &wave;
  def.wave_count = 1;
  boreas::impl::World world(def);
  boreas_tree_def t = boreas_default_tree_def();
  t.mode = mode;
  t.response = BOREAS_TREE_DAMPED;
  t.scale = 0.5f;  // a sapling's size
  const boreas_tree_id near = world.add_tree(t);
  t.position[0] = 15.0f;
  const boreas_tree_id far = world.add_tree(t);
  std::vector<boreas_collider_id> ids;
  if (colliders) {
    boreas_collider_def car = boreas_default_collider_def();
    car.shape = BOREAS_COLLIDER_BOX;
    car.half_extents[0] = 2.0f, car.half_extents[1] = 0.7f, car.half_extents[2] = 0.9f;
    car.pose.position[0] = -2.3f, car.pose.position[1] = 0.7f;
    car.velocity[0] = 2.0f;
    ids.push_back(world.add_collider(car));
    boreas_collider_def walker = capsule({0.0, 1.5, -1.5}, 0.25f, 0.6f);
    walker.velocity[2] = 1.4f;
    ids.push_back(world.add_collider(walker));
  }
  ForestRun r;
  for (int s = 0; s < 60; ++s) {
    world.step(kDt);
    for (const boreas_collider_id& id : ids) r.contacts.push_back(world.collider_contact(id));
  }
  r.near_state = world.tree_batch(mode).read_tree_state(world.tree(near).key);
  r.far_state = world.tree_batch(mode).read_tree_state(world.tree(far).key);
  return r;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class TreeContactForest : public ::testing::TestWithParam<boreas_tree_mode> {};

TEST_P(TreeContactForest, SameRunSameBits) {
  const ForestRun a = run_forest(GetParam(), true), b = run_forest(GetParam(), true);
  EXPECT_TRUE(same_bits(a.near_state, b.near_state));
  ASSERT_EQ(a.contacts.size(), b.contacts.size());
  int64_t touching = 0;
  for (size_t i = 0; i < a.contacts.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a.contacts[i], &b.contacts[i], sizeof(boreas_collider_contact)), 0)
        << "contact " << i;
    touching += a.contacts[i].contacts;
  }
  EXPECT_GT(touching, 0);
}

TEST_P(TreeContactForest, TreeNoColliderReachesIsAsWithoutColliders) {
  const ForestRun with = run_forest(GetParam(), true), without = run_forest(GetParam(), false);
  EXPECT_TRUE(same_bits(with.far_state, without.far_state));
  EXPECT_FALSE(same_bits(with.near_state, without.near_state));  // the near one was pushed
}

INSTANTIATE_TEST_SUITE_P(Modes, TreeContactForest,
                         ::testing::Values(BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT),
                         [](const ::testing::TestParamInfo<boreas_tree_mode>& p) {
                           return std::string(p.param == BOREAS_TREE_LAGGED ? "Lagged" : "Exact");
                         });

// Every built-in species' children lie in at most two runs (tree_types.h), so the contact
// loads reach every parent: the template blocks build.
TEST(TreeContactLayout, BuiltInSpeciesChildrenFitTwoRuns) {
  for (int s = 0; boreas_builtin_species(s); ++s) {
    boreas_tree_def def = boreas_default_tree_def();
    def.species = boreas_builtin_species(s);
    const boreas::impl::TreeParams params = boreas::impl::checked_tree_def(def);
    const boreas::impl::Species species =
        boreas::impl::parse_species_source(boreas::impl::read_species_source(params.species));
    const TreeModel m = boreas::impl::grow_tree(species, params.seed, 1.0);
    boreas::impl::TreeTemplateBlock b;
    ASSERT_NO_THROW(b = boreas::impl::tree_template_block(params, m)) << def.species;
    // Each branch is some parent's child exactly once.
    std::vector<int> seen(size_t(b.count), 0);
    const size_t n = size_t(b.count);
    for (size_t p = 0; p < n; ++p)
      for (int run = 0; run < 2; ++run)
        for (int c = 0; c < b.children[(1 + 2 * size_t(run)) * n + p]; ++c)
          ++seen[size_t(b.children[2 * size_t(run) * n + p] + c)];
    for (size_t i = 2; i < n; ++i) ASSERT_EQ(seen[i], 1) << def.species << " entry " << i;
    EXPECT_GT(b.reach, 1.0);
  }
}

}  // namespace

namespace {

// Levels of detail: a tree a collider's box reaches but whose branches it does not touch
// keeps its level (no full detail for it); once a collider pushes one of its branches, it is
// stepped at full detail from the next step on, and the push is felt.
TEST(TreeContactDetail, FullDetailOnlyForATreeACollidersPushes) {
  boreas_world world = nullptr;
  boreas_world_def wd = boreas_default_world_def();
  ASSERT_EQ(boreas_world_create(&wd, &world), BOREAS_OK) << boreas_last_error();
  boreas_tree_def tree = boreas_default_tree_def();  // an aspen at the origin
  tree.lod_distances[0] = 5.0f;
  tree.lod_distances[1] = 10.0f;
  tree.lod_distances[2] = 1000.0f;
  ASSERT_EQ(boreas_world_add_tree(world, &tree, nullptr), BOREAS_OK) << boreas_last_error();
  const float focus[3] = {40.0f, 0.0f, 0.0f};  // far: the tree is stepped at "far" detail
  ASSERT_EQ(boreas_world_set_focus(world, focus, 1), BOREAS_OK);
  // A ball on the ground 4 m out: inside the box of all the tree can bend into, under its
  // crown, touching nothing.
  boreas_collider_def ball = boreas_default_collider_def();
  ball.pose.position[0] = 4.0f;
  boreas_collider_id id{};
  ASSERT_EQ(boreas_world_add_collider(world, &ball, &id), BOREAS_OK);
  boreas_step_stats stats{};
  for (int s = 0; s < 3; ++s) ASSERT_EQ(boreas_world_step(world, 1.0f / 60.0f), BOREAS_OK);
  ASSERT_EQ(boreas_world_get_step_stats(world, &stats), BOREAS_OK);
  EXPECT_EQ(stats.trees_by_lod[0], 0) << "reached, untouched: not forced to full detail";
  EXPECT_EQ(stats.trees_by_lod[2], 1);
  boreas_collider_contact contact{};
  ASSERT_EQ(boreas_collider_get_contact(world, id, &contact), BOREAS_OK);
  EXPECT_EQ(contact.contacts, 0);
  // Into the trunk, 1 m up: pushed, and then stepped whole.
  boreas_pose into = boreas_default_pose();
  into.position[1] = 1.0f;
  ASSERT_EQ(boreas_collider_set_pose(world, id, &into), BOREAS_OK);
  for (int s = 0; s < 3; ++s) ASSERT_EQ(boreas_world_step(world, 1.0f / 60.0f), BOREAS_OK);
  ASSERT_EQ(boreas_world_get_step_stats(world, &stats), BOREAS_OK);
  EXPECT_EQ(stats.trees_by_lod[0], 1) << "pushed: full detail";
  ASSERT_EQ(boreas_collider_get_contact(world, id, &contact), BOREAS_OK);
  EXPECT_GT(contact.contacts, 0);
  EXPECT_GT(std::hypot(contact.force[0], contact.force[2]), 0.0f);
  boreas_world_destroy(world);
}

}  // namespace
