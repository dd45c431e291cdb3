// boreas tests: planes a tree batch holds only where they are needed.
// Still batches (cl/shared/tree_types.h): a batch with no damped template holds neither
// dF/dt planes nor response planes (a quasi-static branch's are 0 for good), and its step is
// built without them (BOREAS_TREE_STILL); the first damped tree brings them
// (TreeBatch::hold_rates), and the last one's going lets them go (release_rates). Children planes (read by the contact launch alone) are made when
// a collider first touches a tree of the batch (TreeBatch::make_children). What every tree
// shows must not depend on either: quasi-static trees in a still batch step to the bits they
// step to in a batch holding a damped tree's planes, a damped tree added to a still batch to
// the bits it gets in one that held them from the start, and a touched tree to the same bits
// whether its children were written with its block or made from its parents later, and
// quasi-static trees of a batch that held a damped tree go on as if it never had.
#include <gtest/gtest.h>

#include <vector>

#include "boreas/boreas.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "trees/tree_batch.h"
#include "world.h"

namespace boreas {
namespace {

using test::bytes_of;
using test::make_world_with_wave;
using test::tree_bytes;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;

boreas_tree_def aspen(float x, uint64_t seed, boreas_tree_mode mode, boreas_tree_response response) {
  boreas_tree_def d = boreas_default_tree_def();
  d.species = "quaking_aspen";
  d.seed = seed;
  d.position[0] = x;
  d.position[2] = 0.3f * x;
  d.rotation = 0.37f * float(seed);
  d.scale = 0.8f + 0.05f * float(seed);
  d.mode = mode;
  d.response = response;
  return d;
}

// Quasi-static trees in both modes at distances from the focus (the origin) that make them
// full, reduced and far (tree_params' default distances): stepped, carried and, once
// settled, derived branches.
std::vector<boreas_tree_def> quasi_static_defs() {
  std::vector<boreas_tree_def> defs;
  const float distances[] = {8.0f, 45.0f, 70.0f, 120.0f};
  for (int i = 0; i < 4; ++i) {
    defs.push_back(aspen(distances[i], uint64_t(1 + i), BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC));
    defs.push_back(aspen(distances[i] + 3.0f, uint64_t(5 + i), BOREAS_TREE_EXACT, BOREAS_TREE_QUASI_STATIC));
  }
  return defs;
}

// Everything a tree shows (branches, leaves) and its motion planes, as raw bytes.
std::vector<unsigned char> shown(impl::World& world, boreas_tree_id id) {
  std::vector<unsigned char> out = tree_bytes(world, id);
  const impl::TreeInstance& tree = world.tree(id);
  const std::vector<unsigned char> motion =
      bytes_of(world.tree_batch(tree.params.mode).read_tree_motion(tree.key));
  out.insert(out.end(), motion.begin(), motion.end());
  return out;
}

struct Forest {
  std::unique_ptr<impl::World> world;
  std::vector<boreas_tree_id> still, late;
  std::vector<std::vector<unsigned char>> middle;  // the still trees before the late ones
};

// The quasi-static trees stepped 60 steps (what they show then kept) (past the settle time at the far ones: 4 s is
// 240 steps, so those are carried, not yet derived; the DerivedBranches tests cover
// derivation with a damped tree in the batch), then a damped tree of each mode added and
// 60 steps more. With `early`, damped trees of both modes (other seeds, far off) are there
// from the start, so both batches hold the damped planes throughout.
Forest run(bool early) {
  Forest r;
  r.world = make_world_with_wave(windy_wave());
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  r.world->set_focus(focus, 1);
  // The damped ones after the others, so that those have the same keys (their carry
  // phases follow them) and entries in both runs.
  std::vector<boreas_tree_def> defs = quasi_static_defs();
  const size_t count = defs.size();
  if (early) {
    defs.push_back(aspen(-200.0f, 21, BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED));
    defs.push_back(aspen(-230.0f, 22, BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED));
  }
  r.still = r.world->add_trees(defs.data(), int(defs.size()));
  r.still.resize(count);
  for (boreas_tree_mode m : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
    EXPECT_EQ(r.world->tree_batch(m).motion_planes(),
              early ? BOREAS_TREE_MOTION_PLANES : BOREAS_TREE_MOTION_STILL_PLANES);
  for (int s = 0; s < 60; ++s) r.world->step(kDt);
  for (boreas_tree_id id : r.still) r.middle.push_back(shown(*r.world, id));
  const boreas_tree_def d[2] = {aspen(12.0f, 31, BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED),
                                aspen(16.0f, 32, BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED)};
  r.late = r.world->add_trees(d, 2);
  for (boreas_tree_mode m : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
    EXPECT_EQ(r.world->tree_batch(m).motion_planes(), BOREAS_TREE_MOTION_PLANES);
  for (int s = 0; s < 60; ++s) r.world->step(kDt);
  return r;
}

TEST(StillBatches, TreesShowTheSameBitsWhetherOrNotTheirBatchHoldsDampedPlanes) {
  Forest plain = run(false), held = run(true);
  for (size_t t = 0; t < plain.still.size(); ++t) {
    EXPECT_EQ(plain.middle[t], held.middle[t]) << "tree " << t << ", one batch still";
    EXPECT_EQ(shown(*plain.world, plain.still[t]), shown(*held.world, held.still[t])) << "tree " << t;
  }
  // The damped trees added to still batches: their planes came zero, their response was
  // written (they move: their dF/dt is not all zero).
  for (size_t t = 0; t < plain.late.size(); ++t) {
    EXPECT_EQ(shown(*plain.world, plain.late[t]), shown(*held.world, held.late[t])) << "late " << t;
    const impl::TreeInstance& tree = plain.world->tree(plain.late[t]);
    const std::vector<float> motion =
        plain.world->tree_batch(tree.params.mode).read_tree_motion(tree.key);
    const size_t n = motion.size() / BOREAS_TREE_MOTION_PLANES;
    bool moving = false;
    for (size_t i = size_t(BOREAS_TREE_MOTION_DF) * n; i < motion.size(); ++i) moving |= motion[i] != 0.0f;
    EXPECT_TRUE(moving) << "late " << t;
  }
}

// The damped trees removed after 30 steps: the batches are still again, and the quasi-static
// trees go on to the bits of a world that never held a damped tree. Every tree is stepped
// (bent) up close until then, and from then on the farther ones carried from that bend, so
// their F must come through the new planes whole.
TEST(StillBatches, ABatchIsStillAgainOnceItsLastDampedTreeGoes) {
  auto stepped = [](bool damped) {
    Forest r;
    r.world = make_world_with_wave(windy_wave());
    std::vector<boreas_tree_def> defs = quasi_static_defs();
    std::vector<float> near;
    for (const boreas_tree_def& d : defs) near.insert(near.end(), {d.position[0], 1.8f, d.position[2]});
    r.world->set_focus(near.data(), int(defs.size()));
    const size_t count = defs.size();
    if (damped) {
      defs.push_back(aspen(12.0f, 21, BOREAS_TREE_LAGGED, BOREAS_TREE_DAMPED));
      defs.push_back(aspen(16.0f, 22, BOREAS_TREE_EXACT, BOREAS_TREE_DAMPED));
    }
    std::vector<boreas_tree_id> ids = r.world->add_trees(defs.data(), int(defs.size()));
    for (int s = 0; s < 30; ++s) r.world->step(kDt);
    EXPECT_EQ(r.world->tree_batch(BOREAS_TREE_LAGGED).motion_planes(),
              damped ? BOREAS_TREE_MOTION_PLANES : BOREAS_TREE_MOTION_STILL_PLANES);
    const float focus[3] = {0.0f, 1.8f, 0.0f};
    r.world->set_focus(focus, 1);
    for (size_t t = count; t < ids.size(); ++t) r.world->remove_tree(ids[t]);
    ids.resize(count);
    for (boreas_tree_mode m : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
      EXPECT_EQ(r.world->tree_batch(m).motion_planes(), BOREAS_TREE_MOTION_STILL_PLANES);
    for (int s = 0; s < 30; ++s) r.world->step(kDt);
    r.still = ids;
    return r;
  };
  Forest was = stepped(true), never = stepped(false);
  for (size_t t = 0; t < was.still.size(); ++t)
    EXPECT_EQ(shown(*was.world, was.still[t]), shown(*never.world, never.still[t])) << "tree " << t;
}

// An upright capsule beside the trunk of the aspen at x (aspen() puts it at z = 0.3 x).
boreas_collider_def capsule(float x, float y, float radius, float half_height) {
  boreas_collider_def d = boreas_default_collider_def();
  d.shape = BOREAS_COLLIDER_CAPSULE;
  d.pose.position[0] = x;
  d.pose.position[1] = y;
  d.pose.position[2] = 0.3f * x;
  d.radius = radius;
  d.half_height = half_height;
  return d;
}

// A tree touched by a capsule in its crown (its branches near the trunk between 4.5 and 7.5 m), added after 30 steps to a world whose other tree
// is touched from the start (`early`: the batch's children exist when its block comes) or
// not (they are made from the parents at its first touch); then 40 steps.
struct Touched {
  std::unique_ptr<impl::World> world;
  boreas_tree_id tree{};
  boreas_collider_id collider{};
  boreas_collider_contact first{};  // its capsule's contacts after the tree's first step
};

Touched touched(bool early) {
  Touched r;
  r.world = make_world_with_wave(windy_wave());
  const boreas_tree_def first = aspen(0.0f, 3, BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC);
  r.world->add_tree(first);
  if (early) r.world->add_collider(capsule(0.2f, 6.0f, 0.15f, 1.5f));
  r.collider = r.world->add_collider(capsule(30.2f, 6.0f, 0.15f, 1.5f));
  for (int s = 0; s < 30; ++s) r.world->step(kDt);
  r.tree = r.world->add_tree(aspen(30.0f, 4, BOREAS_TREE_LAGGED, BOREAS_TREE_QUASI_STATIC));
  r.world->step(kDt);
  r.first = r.world->collider_contact(r.collider);
  for (int s = 1; s < 40; ++s) r.world->step(kDt);
  return r;
}

TEST(ChildrenPlanes, ATouchedTreeShowsTheSameBitsWhetherItsChildrenCameWithItsBlockOrLater) {
  Touched with = touched(true), later = touched(false);
  EXPECT_EQ(shown(*with.world, with.tree), shown(*later.world, later.tree));
  EXPECT_GE(with.first.contacts, 2) << "the capsule meets several branches";
  EXPECT_EQ(bytes_of(std::vector<boreas_collider_contact>{with.first}),
            bytes_of(std::vector<boreas_collider_contact>{later.first}));
  EXPECT_EQ(bytes_of(std::vector<boreas_collider_contact>{with.world->collider_contact(with.collider)}),
            bytes_of(std::vector<boreas_collider_contact>{later.world->collider_contact(later.collider)}));
}

}  // namespace
}  // namespace boreas
