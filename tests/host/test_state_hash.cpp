// Library tests: boreas_world_get_state_hash and determinism. Two worlds built and stepped with
// the same inputs on the same device have bit-identical state (equal hashes) after every
// step, whether their kernels were compiled or read from the binary cache; one input a
// little different, or one more step, changes the hash; reading it changes nothing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/small_world.h"
#include "support/temp_dir.h"

namespace {

struct Inputs {
  float amplitude = 6.0f;
  uint64_t oak_seed = 3;
};

// A small world with something of every simulated kind: a lagged aspen, an exact damped
// oak, an imported tree and a meadow of grass and clover.
boreas_world make_world(const Inputs& in, const std::string& tube_tree) {
  boreas_world world = nullptr;
  EXPECT_EQ(boreas::test::create_small_windy_world(&world, in.amplitude), BOREAS_OK)
      << boreas_last_error();
  boreas_tree_def aspen = boreas_default_tree_def();
  aspen.species = "quaking_aspen";
  aspen.seed = 2;
  aspen.position[0] = -1.0f;
  boreas_tree_def oak = boreas_default_tree_def();
  oak.species = "ca_black_oak";
  oak.seed = in.oak_seed;
  oak.mode = BOREAS_TREE_EXACT;
  oak.response = BOREAS_TREE_DAMPED;
  oak.position[0] = 1.5f;
  boreas_tree_id id{};
  EXPECT_EQ(boreas_world_add_tree(world, &aspen, &id), BOREAS_OK) << boreas_last_error();
  EXPECT_EQ(boreas_world_add_tree(world, &oak, &id), BOREAS_OK) << boreas_last_error();
  boreas_mesh_tree_def mesh = boreas_default_mesh_tree_def();
  mesh.model = tube_tree.c_str();
  mesh.position[2] = 2.0f;
  boreas_mesh_tree_id mesh_id{};
  EXPECT_EQ(boreas_world_add_mesh_tree(world, &mesh, &mesh_id), BOREAS_OK) << boreas_last_error();
  boreas_meadow_def meadow = boreas_default_meadow_def();
  meadow.size[0] = meadow.size[1] = 3.0f;
  meadow.density = 400.0f;
  boreas_meadow_id meadow_id{};
  EXPECT_EQ(boreas_world_add_meadow(world, &meadow, &meadow_id), BOREAS_OK) << boreas_last_error();
  return world;
}

uint64_t hash_of(boreas_world world) {
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(world, &hash), BOREAS_OK) << boreas_last_error();
  return hash;
}

// The hash after each of `steps` steps.
std::vector<uint64_t> run(boreas_world world, int steps) {
  std::vector<uint64_t> hashes;
  for (int s = 0; s < steps; ++s) {
    EXPECT_EQ(boreas_world_step(world, 1.0f / 60.0f), BOREAS_OK) << boreas_last_error();
    hashes.push_back(hash_of(world));
  }
  return hashes;
}

constexpr int kSteps = 12;

class StateHash : public ::testing::Test {
 protected:
  boreas::test::TempDir dir_;
  std::string tube_tree_ = boreas::test::write_tube_tree_obj(dir_.path());
};

TEST_F(StateHash, SameInputsGiveTheSameHashAfterEveryStep) {
  boreas_world a = make_world({}, tube_tree_), b = make_world({}, tube_tree_);
  EXPECT_EQ(hash_of(a), hash_of(b)) << "as built";
  const std::vector<uint64_t> ha = run(a, kSteps), hb = run(b, kSteps);
  EXPECT_EQ(ha, hb);
  // The state moves, and so does its hash: no two steps alike.
  for (int s = 1; s < kSteps; ++s) EXPECT_NE(ha[size_t(s)], ha[size_t(s) - 1]) << "step " << s;
  boreas_world_destroy(a);
  boreas_world_destroy(b);
}

TEST_F(StateHash, ReadingTheHashChangesNothing) {
  boreas_world a = make_world({}, tube_tree_), b = make_world({}, tube_tree_);
  const std::vector<uint64_t> every_step = run(a, kSteps);
  for (int s = 0; s < kSteps; ++s) ASSERT_EQ(boreas_world_step(b, 1.0f / 60.0f), BOREAS_OK);
  EXPECT_EQ(hash_of(b), every_step.back());
  EXPECT_EQ(hash_of(b), hash_of(b));
  boreas_world_destroy(a);
  boreas_world_destroy(b);
}

TEST_F(StateHash, ALittleDifferentInputGivesAnotherHash) {
  boreas_world a = make_world({}, tube_tree_);
  Inputs windier;
  windier.amplitude = 6.0f * 1.001f;
  Inputs other_oak;
  other_oak.oak_seed = 4;
  boreas_world b = make_world(windier, tube_tree_), c = make_world(other_oak, tube_tree_);
  EXPECT_NE(hash_of(a), hash_of(c)) << "another oak, as built";
  const std::vector<uint64_t> ha = run(a, 3), hb = run(b, 3);
  EXPECT_NE(ha.back(), hb.back()) << "wind 0.1 % stronger";
  boreas_world_destroy(a);
  boreas_world_destroy(b);
  boreas_world_destroy(c);
}

// Kernels compiled from source (an empty cache folder) and read back as binaries from it
// give the same state.
TEST_F(StateHash, KernelsFromSourceOrFromTheBinaryCacheAgree) {
  const char* before = std::getenv("BOREAS_CACHE_DIR");
  const std::optional<std::string> saved =
      before ? std::optional<std::string>(before) : std::nullopt;
  const std::string cache = (dir_.path() / "kernel-cache").string();
  ASSERT_EQ(setenv("BOREAS_CACHE_DIR", cache.c_str(), 1), 0);
  boreas_world cold = make_world({}, tube_tree_);
  const std::vector<uint64_t> from_source = run(cold, kSteps);
  boreas_world_destroy(cold);
  boreas_world warm = make_world({}, tube_tree_);
  const std::vector<uint64_t> from_cache = run(warm, kSteps);
  boreas_world_destroy(warm);
  if (saved)
    setenv("BOREAS_CACHE_DIR", saved->c_str(), 1);
  else
    unsetenv("BOREAS_CACHE_DIR");
  EXPECT_FALSE(std::filesystem::is_empty(cache)) << "the first world cached its kernels";
  EXPECT_EQ(from_source, from_cache);
}

TEST(StateHashApi, NullArgumentsAreRefused) {
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(nullptr, &hash), BOREAS_ERROR_INVALID_ARGUMENT);
  boreas_world world = nullptr;
  ASSERT_EQ(boreas::test::create_small_windy_world(&world), BOREAS_OK) << boreas_last_error();
  EXPECT_EQ(boreas_world_get_state_hash(world, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("out"), std::string::npos);
  boreas_world_destroy(world);
}

}  // namespace
