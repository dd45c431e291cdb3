// boreas tests: storms on generated trees (trees/wind_load.h, cl/tree_step.cl). Vogel's
// reconfiguration against its double formula in steady winds of 5, 20 and 40 m/s; no trunk
// or limb breaks at 10 m/s; breaks at 50 m/s, counted the same in two identical worlds with
// equal state hashes; a broken branch hangs along its drag plus weight; a carried branch
// keeps its broken state; heal puts the tree back at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// The device's reconfiguration factor, as a CPU device builds it (polynomial exp2, log2).
#define BOREAS_FAST_MATH 1
#include "boreas/boreas.h"
#include "host/trees/tree_bends.h"
#include "shared/tree_math.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_layout.h"
#include "trees/tree_templates.h"
#include "trees/wind_load.h"
#include "world.h"

namespace boreas {
namespace {

using glm::dvec3;
namespace fs = std::filesystem;

const char* const kSpecies[] = {"black_tupelo", "ca_black_oak", "quaking_aspen", "weeping_willow"};

// The wind of test::steady_wave(1, 0.4, speed): `speed` m/s along (1, 0, 0.4).
dvec3 steady_wind(double speed) { return speed * glm::normalize(dvec3(1.0, 0.0, 0.4)); }

std::unique_ptr<impl::World> storm_world(float speed) {
  return test::make_world_with_wave(test::steady_wave(1.0f, 0.4f, speed));
}

boreas_tree_def storm_def(const char* species, float x = 0.0f) {
  boreas_tree_def def = boreas_default_tree_def();
  def.species = species;
  def.position[0] = x;
  def.mode = BOREAS_TREE_EXACT;  // every level settles in the first step
  return def;
}

// Branch b's broken flag as the kernel left it.
std::vector<int> broken_flags(impl::World& world, boreas_tree_id id) {
  std::vector<int> out;
  for (const boreas_branch& b : world.tree_branches(id)) out.push_back(b.broken);
  return out;
}

// quaking_aspen.json with a wood no wind breaks (the load without breaks to compare).
std::string unbreakable_aspen() {
  const fs::path from =
      fs::path(BOREAS_TEST_DATA_DIR) / ".." / ".." / "host" / "species" / "quaking_aspen.json";
  std::ifstream in(from);
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = std::regex_replace(text.str(), std::regex("\"WoodRupture\": [0-9.]+"),
                                              "\"WoodRupture\": 1000.0");
  const fs::path to = fs::temp_directory_path() / "boreas_storms_unbreakable_aspen.json";
  std::ofstream(to) << json;
  return to.string();
}

TEST(Storms, ReconfigurationIsOneBelowTheReferenceSpeedAndVogelsPowerAbove) {
  EXPECT_EQ(impl::reconfiguration(3.0, -0.8, 8.0), 1.0);
  EXPECT_EQ(impl::reconfiguration(8.0, -0.8, 8.0), 1.0);  // continuous at U_r
  EXPECT_NEAR(impl::reconfiguration(40.0, -0.8, 8.0), std::pow(5.0, -0.8), 1e-15);
  // The device's factor (fast exp2 and log2) against it, exponent 0 exactly 1.
  for (float speed : {1.0f, 8.0f, 9.5f, 20.0f, 40.0f, 75.0f}) {
    EXPECT_NEAR(boreas_reconfiguration(speed, -0.9f, 1.0f / 8.0f),
                impl::reconfiguration(speed, -0.9, 8.0), 1e-5);
    EXPECT_EQ(boreas_reconfiguration(speed, 0.0f, 1.0f / 8.0f), 1.0f);
  }
}

// Quasi-static, exact mode, a uniform steady wind: every branch's bend is its target
// K s |u|^2 R(|u|) along the wind, R with the branch's exponent phi b (the share of its load
// that reconfigures), against the double formula.
TEST(Storms, TargetLoadFollowsVogelsLawAt5And20And40MetresPerSecond) {
  const std::string species = unbreakable_aspen();
  boreas_tree_def def = storm_def(species.c_str());
  def.scale = 1.5f;
  impl::TreeModel m = impl::grow_tree(impl::load_species(species), def.seed);
  impl::TreeParams params;
  const std::vector<double> k = impl::drag_compliance(m, params);
  const std::vector<double> share = impl::reconfiguring_share(m);
  for (double speed : {5.0, 20.0, 40.0}) {
    SCOPED_TRACE(speed);
    auto world = storm_world(float(speed));
    boreas_tree_id id = world->add_tree(def);
    for (int s = 0; s < 4; ++s) world->step(1.0f / 60.0f);
    const std::vector<dvec3> bends = test::tree_bends(*world, id);
    const dvec3 u = steady_wind(speed);
    for (size_t b = 0; b < bends.size(); ++b) {
      const double r = impl::reconfiguration(speed, share[b] * m.vogel_exponent, m.vogel_speed);
      const dvec3 want = k[b] * def.scale * speed * r * u;
      ASSERT_NEAR(glm::length(bends[b] - want), 0.0, 2e-5 * glm::length(want)) << "branch " << b;
    }
    // A tree in a storm takes a load a few times smaller than the u^2 law's: its trunk's.
    const double trunk = glm::length(bends[0]) / (k[0] * def.scale * speed * speed);
    if (speed == 40.0) {
      EXPECT_LT(trunk, 0.4);
      EXPECT_GT(trunk, 0.2);
    }
    if (speed == 5.0) EXPECT_EQ(trunk > 0.999999 && trunk < 1.000001, true) << trunk;
  }
}

// A fresh breeze breaks no branch of any built-in species (the weakest twigs, the oak's,
// go at 10.9 m/s: README, "Storms").
TEST(Storms, NoBranchBreaksAtTenMetresPerSecond) {
  for (const char* species : kSpecies) {
    SCOPED_TRACE(species);
    auto world = storm_world(10.0f);
    boreas_tree_id id = world->add_tree(storm_def(species));
    for (int s = 0; s < 6; ++s) world->step(1.0f / 60.0f);
    const std::vector<boreas_branch> branches = world->tree_branches(id);
    int twigs = 0;
    for (const boreas_branch& b : branches) {
      if (b.level <= 1) EXPECT_EQ(b.broken, 0) << "level " << b.level;
      twigs += b.broken;
    }
    EXPECT_EQ(twigs, 0);
  }
}

// Two identical worlds in a 50 m/s storm: branches break, the same ones, counted the same
// by the step stats as by the flags, and the state hashes agree; they differ from a world
// whose trees did not break (the same storm on unbreakable wood).
TEST(Storms, FiftyMetresPerSecondBreaksBranchesDeterministically) {
  auto run = [](const std::vector<std::string>& species, int64_t* stats_breaks,
                std::vector<std::vector<int>>* flags) {
    auto world = storm_world(50.0f);
    std::vector<boreas_tree_id> ids;
    for (size_t t = 0; t < species.size(); ++t)
      ids.push_back(world->add_tree(storm_def(species[t].c_str(), 30.0f * float(t))));
    *stats_breaks = 0;
    for (int s = 0; s < 10; ++s) {
      world->step(1.0f / 60.0f);
      *stats_breaks += world->step_stats().branches_broken;
    }
    for (boreas_tree_id id : ids) flags->push_back(broken_flags(*world, id));
    return world->state_hash();
  };
  const std::vector<std::string> all(std::begin(kSpecies), std::end(kSpecies));
  int64_t breaks_a = 0, breaks_b = 0;
  std::vector<std::vector<int>> flags_a, flags_b;
  const uint64_t hash_a = run(all, &breaks_a, &flags_a);
  const uint64_t hash_b = run(all, &breaks_b, &flags_b);
  EXPECT_EQ(hash_a, hash_b);
  EXPECT_EQ(breaks_a, breaks_b);
  EXPECT_EQ(flags_a, flags_b);
  int64_t flagged = 0;
  for (const auto& tree : flags_a) {
    int64_t mine = 0;
    for (int f : tree) mine += f;
    EXPECT_GT(mine, 0) << "every species loses branches at 50 m/s";
    flagged += mine;
  }
  EXPECT_EQ(flagged, breaks_a) << "every break counted once, in the step it happened";
  // The broken state is in the hash: the same storm on wood that holds hashes otherwise.
  int64_t none = 0;
  std::vector<std::vector<int>> flags_none;
  const std::string unbreakable = unbreakable_aspen();
  const uint64_t hash_one = run({"quaking_aspen"}, &none, &flags_none);
  const uint64_t hash_held = run({unbreakable}, &none, &flags_none);
  EXPECT_EQ(none, 0);
  EXPECT_NE(hash_one, hash_held);
}

// A broken branch hangs from its base along the load on it: drag (R |u| u times its drag
// over weight) plus weight; its whole chord P0 -> P3 within a milliradian of it.
TEST(Storms, BrokenBranchHangsAlongItsDragPlusWeight) {
  const double speed = 50.0;
  for (const char* species : {"quaking_aspen", "black_tupelo"}) {
    SCOPED_TRACE(species);
    auto world = storm_world(float(speed));
    boreas_tree_def def = storm_def(species);
    def.scale = 0.8f;
    boreas_tree_id id = world->add_tree(def);
    for (int s = 0; s < 6; ++s) world->step(1.0f / 60.0f);
    // The world keeps the model packed; the drag over weight counts the leaves.
    const std::shared_ptr<const impl::TreeModel> whole = impl::whole_model(world->tree(id).model);
    const impl::TreeModel& m = *whole;
    const std::vector<double> hang = impl::drag_per_weight(m);
    const std::vector<double> share = impl::reconfiguring_share(m);
    const dvec3 u = steady_wind(speed);
    int checked = 0;
    const std::vector<boreas_branch> branches = world->tree_branches(id);
    for (size_t b = 0; b < branches.size(); ++b) {
      if (!branches[b].broken) continue;
      const double r = impl::reconfiguration(speed, share[b] * m.vogel_exponent, m.vogel_speed);
      const dvec3 load = hang[b] / def.scale * speed * r * u - dvec3(0.0, 1.0, 0.0);
      const float* p0 = branches[b].control_points[0];
      const float* p3 = branches[b].control_points[3];
      const dvec3 chord(p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]);
      const double angle = std::acos(std::min(1.0, glm::dot(glm::normalize(chord), glm::normalize(load))));
      EXPECT_LT(angle, 1e-3) << "branch " << b;
      ++checked;
    }
    EXPECT_GT(checked, 0);
  }
}

// Broken branches that the levels of detail start carrying keep their flag and their hang;
// heal then puts the whole tree back at rest, every flag 0, as a tree just added.
TEST(Storms, CarriedBranchesStayBrokenAndHealRestoresTheRest) {
  auto world = storm_world(50.0f);
  boreas_tree_def def = storm_def("black_tupelo");
  def.mode = BOREAS_TREE_LAGGED;
  def.lod_distances[0] = 30.0f;
  def.lod_distances[1] = 80.0f;
  def.lod_distances[2] = 1e9f;
  boreas_tree_id id = world->add_tree(def);
  const std::vector<float> rest = world->tree_batch(def.mode).read_tree_state(world->tree(id).key);
  const float near[3] = {0.0f, 2.0f, 0.0f};
  world->set_focus(near, 1);
  for (int s = 0; s < 10; ++s) world->step(1.0f / 60.0f);
  const std::vector<boreas_branch> before = world->tree_branches(id);
  // Past the second distance only the trunk and level 1 are stepped: level 2 and 3 carried.
  const float far[3] = {100.0f, 2.0f, 0.0f};
  world->set_focus(far, 1);
  for (int s = 0; s < 90; ++s) world->step(1.0f / 60.0f);
  EXPECT_GT(world->step_stats().branches_carried, 0);
  const std::vector<boreas_branch> after = world->tree_branches(id);
  int carried_broken = 0;
  for (size_t b = 0; b < before.size(); ++b) {
    EXPECT_GE(after[b].broken, before[b].broken) << "branch " << b << ": a break is for good";
    if (before[b].broken && before[b].level >= 2 && after[b].broken) ++carried_broken;
  }
  EXPECT_GT(carried_broken, 0);
  const uint64_t stormy = world->state_hash();
  world->heal_tree(id);
  const uint64_t healed = world->state_hash();
  EXPECT_NE(stormy, healed);
  impl::TreeBatch& batch = world->tree_batch(def.mode);
  EXPECT_EQ(batch.read_tree_state(world->tree(id).key), rest);
  for (float x : batch.read_tree_motion(world->tree(id).key)) ASSERT_EQ(x, 0.0f);
  for (const boreas_branch& b : world->tree_branches(id)) ASSERT_EQ(b.broken, 0);
}

}  // namespace
}  // namespace boreas
