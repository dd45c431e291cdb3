// Library tests: what boreas.h promises about threads. Different worlds run on different
// threads at once (each world used by one thread at a time), each getting the state it
// would get alone (the same hash, step by step, as a world built and stepped on this
// thread); boreas_last_error() is per thread; the library's own worker threads (a batch of
// distinct trees grows on every core) give the same trees as one call per tree. These
// tests carry the label `threads`: `make test SANITIZE=thread` runs them under
// ThreadSanitizer.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "boreas/boreas.h"
#include "support/small_world.h"

namespace {

constexpr int kSteps = 12;

// A world of its own per thread: a tree, a small meadow and a gust, the wind strength
// depending on `which` so the threads' worlds differ. Returns the hash after every step.
std::vector<uint64_t> run_world(int which, std::string* error) {
  std::vector<uint64_t> hashes;
  boreas_world world = nullptr;
  auto fail = [&](const char* what) {
    *error = std::string(what) + ": " + boreas_last_error();
    boreas_world_destroy(world);
    return std::vector<uint64_t>{};
  };
  if (boreas::test::create_small_windy_world(&world, 4.0f + which) != BOREAS_OK)
    return fail("create");
  boreas_tree_def tree = boreas_default_tree_def();
  tree.seed = 1 + uint64_t(which % 3);
  tree.mode = which % 2 ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED;
  if (boreas_world_add_tree(world, &tree, nullptr) != BOREAS_OK) return fail("add_tree");
  boreas_meadow_def meadow = boreas_default_meadow_def();
  meadow.size[0] = meadow.size[1] = 1.5f;
  meadow.density = 150.0f;
  meadow.center[0] = 2.0f;
  if (boreas_world_add_meadow(world, &meadow, nullptr) != BOREAS_OK) return fail("add_meadow");
  boreas_gust_def gust = boreas_default_gust_def();
  if (boreas_wind_add_gust(world, &gust, nullptr) != BOREAS_OK) return fail("add_gust");
  for (int s = 0; s < kSteps; ++s) {
    if (boreas_world_step(world, 1.0f / 30.0f) != BOREAS_OK) return fail("step");
    float p[6] = {0.0f, 1.0f, 0.0f, 2.0f, 0.3f, 0.0f}, out[6];
    if (boreas_wind_sample(world, p, 2, out) != BOREAS_OK) return fail("sample");
    uint64_t hash = 0;
    if (boreas_world_get_state_hash(world, &hash) != BOREAS_OK) return fail("hash");
    hashes.push_back(hash);
  }
  boreas_world_destroy(world);
  return hashes;
}

TEST(Threads, WorldsOnDifferentThreadsStepAsTheyWouldAlone) {
  constexpr int kWorlds = 4;
  std::vector<std::vector<uint64_t>> alone(kWorlds);
  for (int i = 0; i < kWorlds; ++i) {
    std::string error;
    alone[size_t(i)] = run_world(i, &error);
    ASSERT_EQ(alone[size_t(i)].size(), size_t(kSteps)) << error;
  }
  std::vector<std::vector<uint64_t>> together(kWorlds);
  std::vector<std::string> errors(kWorlds);
  std::vector<std::thread> threads;
  for (int i = 0; i < kWorlds; ++i)
    threads.emplace_back([&, i] { together[size_t(i)] = run_world(i, &errors[size_t(i)]); });
  for (std::thread& t : threads) t.join();
  for (int i = 0; i < kWorlds; ++i) {
    EXPECT_TRUE(errors[size_t(i)].empty()) << "world " << i << ": " << errors[size_t(i)];
    EXPECT_EQ(together[size_t(i)], alone[size_t(i)]) << "world " << i << " differs on its thread";
  }
  EXPECT_NE(alone[0], alone[1]) << "the worlds were meant to differ";
}

TEST(Threads, TheLastErrorBelongsToTheCallingThread) {
  // Each thread fails in its own way and must read its own message back, however the
  // other threads' calls interleave with its own.
  constexpr int kThreads = 4;
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&, i] {
      for (int round = 0; round < 200; ++round) {
        const float dt = -1.0f - float(i);  // refused, and the message quotes it
        if (boreas_world_step(nullptr, 0.1f) != BOREAS_ERROR_INVALID_ARGUMENT) ++wrong;
        const std::string mine = boreas_last_error();
        if (mine.find("world is NULL") == std::string::npos) ++wrong;
        boreas_world_def def = boreas_default_world_def();
        def.grid.cell_size = dt;
        boreas_world w = nullptr;
        if (boreas_world_create(&def, &w) != BOREAS_ERROR_INVALID_ARGUMENT) ++wrong;
        if (std::string(boreas_last_error()).find(std::to_string(int(dt))) == std::string::npos)
          ++wrong;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(wrong.load(), 0);
}

TEST(Threads, ABatchOfDistinctTreesGrownOnEveryCoreMatchesOneCallPerTree) {
  // boreas_world_add_trees grows distinct (species, seed) pairs on worker threads; the
  // trees must be the ones single adds make.
  constexpr int kTrees = 6;
  std::vector<boreas_tree_def> defs(kTrees);
  for (int i = 0; i < kTrees; ++i) {
    defs[size_t(i)] = boreas_default_tree_def();
    defs[size_t(i)].species = i % 2 ? "quaking_aspen" : "weeping_willow";
    defs[size_t(i)].seed = 10 + uint64_t(i);
    defs[size_t(i)].scale = 0.5f;
    defs[size_t(i)].position[0] = 3.0f * float(i);
  }
  boreas_world batch = nullptr, single = nullptr;
  ASSERT_EQ(boreas::test::create_small_windy_world(&batch), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas::test::create_small_windy_world(&single), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_world_add_trees(batch, defs.data(), kTrees, nullptr), BOREAS_OK)
      << boreas_last_error();
  for (const boreas_tree_def& d : defs)
    ASSERT_EQ(boreas_world_add_tree(single, &d, nullptr), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 3; ++s) {
    ASSERT_EQ(boreas_world_step(batch, 1.0f / 30.0f), BOREAS_OK);
    ASSERT_EQ(boreas_world_step(single, 1.0f / 30.0f), BOREAS_OK);
    uint64_t a = 0, b = 0;
    ASSERT_EQ(boreas_world_get_state_hash(batch, &a), BOREAS_OK);
    ASSERT_EQ(boreas_world_get_state_hash(single, &b), BOREAS_OK);
    EXPECT_EQ(a, b) << "step " << s;
  }
  boreas_world_destroy(batch);
  boreas_world_destroy(single);
}

}  // namespace
