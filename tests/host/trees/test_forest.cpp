// boreas tests: forests — building and changing a world in time proportional to the change
// (byte counters that machine noise cannot blur), batch adds, templates, per-tree getters
// that do not depend on the rest of the world, refusals when the device is full, and the
// simulation's levels of detail (no jumps, determinism, frozen trees at rest).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "host/trees/tree_bends.h"
#include "shared/tree_types.h"
#include "support/temp_dir.h"
#include "support/test_support.h"
#include "trees/tree_batch.h"
#include "trees/tree_templates.h"
#include "world.h"

namespace boreas {
namespace {

using glm::dvec3;
using test::bytes_of;
using test::calm_grid;
using test::expect_error;
using test::make_world_with_wave;
using test::transfer_bytes;
using test::tree_bytes;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;

// A def on a grid of trees 6 m apart; seed picks the template.
boreas_tree_def forest_def(int index, uint64_t seed, const char* species = "quaking_aspen") {
  boreas_tree_def def = boreas_default_tree_def();
  def.species = species;
  def.seed = seed;
  def.position[0] = float(index % 40) * 6.0f;
  def.position[2] = float(index / 40) * 6.0f;
  def.rotation = 0.37f * float(index);
  def.scale = 0.8f + 0.01f * float(index % 30);
  return def;
}

// ---- Building in proportion to the change -------------------------------------------------

TEST(Forest, AddingOrRemovingOneTreeMovesBytesOfOneTree) {
  // The bytes one tree costs alone: added to an empty world.
  auto empty = make_world_with_wave(windy_wave());
  const uint64_t before_empty = transfer_bytes(*empty);
  empty->add_tree(forest_def(0, 1));
  const uint64_t alone = transfer_bytes(*empty) - before_empty;
  ASSERT_GT(alone, 0u);

  // The same tree added to a world of 500 (from 10 templates) that has been stepped.
  auto world = make_world_with_wave(windy_wave());
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 500; ++i) defs.push_back(forest_def(i, uint64_t(1 + i % 10)));
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
  EXPECT_EQ(world->template_count(), 10u);
  for (int s = 0; s < 2; ++s) world->step(kDt);
  uint64_t before = transfer_bytes(*world);
  boreas_tree_id extra = world->add_tree(forest_def(0, 1));
  const uint64_t added = transfer_bytes(*world) - before;
  EXPECT_LE(added, 2 * alone) << "adding one tree to 500 moved " << added
                              << " bytes; alone it moves " << alone;

  // Removing one (from the middle) and the step after it: the tile lists and nothing else.
  before = transfer_bytes(*world);
  world->remove_tree(ids[250]);
  world->step(kDt);
  const uint64_t removed = transfer_bytes(*world) - before;
  EXPECT_LE(removed, 2 * alone) << "removing one tree of 500 and stepping moved " << removed
                                << " bytes";
  world->remove_tree(extra);
}

TEST(Forest, OtherTreesKeepTheirStateBitForBitThroughAddsAndRemoves) {
  // Two worlds step the same trees A and B; the second also sees trees come and go (one
  // at a time, in batches, from A's template and others, before and after A in memory).
  auto plain = make_world_with_wave(windy_wave());
  auto busy = make_world_with_wave(windy_wave());
  const boreas_tree_def a_def = forest_def(3, 7), b_def = forest_def(9, 2, "black_tupelo");
  boreas_tree_id a0 = plain->add_tree(a_def), b0 = plain->add_tree(b_def);
  std::vector<boreas_tree_def> first = {forest_def(20, 7), forest_def(21, 5)};
  std::vector<boreas_tree_id> early = busy->add_trees(first.data(), 2);
  boreas_tree_id a1 = busy->add_tree(a_def), b1 = busy->add_tree(b_def);
  for (int s = 0; s < 40; ++s) {
    plain->step(kDt);
    busy->step(kDt);
    if (s == 5) busy->remove_tree(early[0]);
    if (s == 10) {
      std::vector<boreas_tree_def> more;
      for (int i = 0; i < 12; ++i) more.push_back(forest_def(30 + i, uint64_t(7 + i % 3)));
      std::vector<boreas_tree_id> added = busy->add_trees(more.data(), int(more.size()));
      busy->remove_tree(added[4]);
      busy->remove_tree(early[1]);
    }
    if (s == 20) {
      // Enough removals to pack the batch (holes past half of it) moves A and B.
      for (int i = 0; i < 30; ++i) busy->add_tree(forest_def(60 + i, 11));
    }
    ASSERT_EQ(tree_bytes(*plain, a0), tree_bytes(*busy, a1)) << "step " << s;
    ASSERT_EQ(tree_bytes(*plain, b0), tree_bytes(*busy, b1)) << "step " << s;
  }
  // Remove everything else and step on: still the same.
  std::vector<boreas_tree_id> others;
  for (int i = 0; i < 60; ++i) others.push_back(busy->add_tree(forest_def(100 + i, 13)));
  for (boreas_tree_id id : others) busy->remove_tree(id);
  for (int s = 0; s < 5; ++s) {
    plain->step(kDt);
    busy->step(kDt);
  }
  EXPECT_EQ(tree_bytes(*plain, a0), tree_bytes(*busy, a1));
  EXPECT_EQ(tree_bytes(*plain, b0), tree_bytes(*busy, b1));
  std::vector<boreas_vertex> va, vb;
  std::vector<uint32_t> ia, ib;
  plain->tree_mesh(a0, &va, &ia);
  busy->tree_mesh(a1, &vb, &ib);
  EXPECT_EQ(bytes_of(va), bytes_of(vb));
  EXPECT_EQ(ia, ib);
}

TEST(Forest, BatchAddIsAllOrNothing) {
  auto world = make_world_with_wave(windy_wave());
  boreas_tree_id keep = world->add_tree(forest_def(0, 1));
  world->step(kDt);
  const std::vector<unsigned char> before = tree_bytes(*world, keep);
  std::vector<boreas_tree_def> defs = {forest_def(1, 1), forest_def(2, 2), forest_def(3, 3)};
  defs[2].scale = -1.0f;
  expect_error([&] { world->add_trees(defs.data(), 3); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"defs[2]", "tree_def.scale"});
  defs[2] = forest_def(3, 3);
  defs[1].species = "no_such_species";
  expect_error([&] { world->add_trees(defs.data(), 3); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"defs[1]", "no_such_species"});
  // Templates grow on every core: when two fail, the error names the first def whose
  // template failed, whatever the threads' timing (here both would grow past the limit).
  test::TempDir dir;
  const std::string exploding = (dir.path() / "exploding.json").string();
  {
    std::ofstream out(exploding);
    out << R"({"format": "boreas-species-1", "name": "exploding", "params": {"Levels": 4,
      "1Branches": 10000, "2Branches": 10000, "3Branches": 10000}})";
  }
  defs[1] = forest_def(2, 2);
  for (int i : {1, 2}) defs[size_t(i)].species = exploding.c_str();
  defs[2].seed = 7;
  for (int repeat = 0; repeat < 3; ++repeat)
    expect_error([&] { world->add_trees(defs.data(), 3); }, BOREAS_ERROR_INVALID_ARGUMENT,
                 {"defs[1]", "exploding", "grows more than"});
  EXPECT_EQ(world->tree_count(), 1u);
  EXPECT_EQ(world->template_count(), 1u);
  EXPECT_EQ(tree_bytes(*world, keep), before);
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), 0);
  EXPECT_TRUE(ids.empty());
  expect_error([&] { world->add_trees(nullptr, 2); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"defs is NULL"});
  expect_error([&] { world->add_trees(defs.data(), -1); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"count"});
}

// A batch's templates grow on every core: the trees are the same bytes with one thread
// (BOREAS_THREADS=1) and with several, and a bad BOREAS_THREADS is refused naming itself.
TEST(Forest, BatchAddsGiveTheSameTreesOnOneThreadOrMany) {
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 6; ++i) defs.push_back(forest_def(i, uint64_t(100 + i)));
  auto build = [&](const char* threads) {
    setenv("BOREAS_THREADS", threads, 1);
    auto world = make_world_with_wave(windy_wave());
    std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
    world->step(kDt);
    std::vector<unsigned char> bytes;
    for (boreas_tree_id id : ids) {
      const std::vector<unsigned char> b = tree_bytes(*world, id);
      bytes.insert(bytes.end(), b.begin(), b.end());
    }
    return bytes;
  };
  const std::vector<unsigned char> one = build("1"), four = build("4");
  unsetenv("BOREAS_THREADS");
  EXPECT_FALSE(one.empty());
  EXPECT_EQ(one, four);
  auto world = make_world_with_wave(windy_wave());
  for (const char* bad : {"0", "-2", "two", "4096"}) {
    setenv("BOREAS_THREADS", bad, 1);
    expect_error([&] { world->add_trees(defs.data(), int(defs.size())); },
                 BOREAS_ERROR_INVALID_ARGUMENT, {"BOREAS_THREADS", bad});
    EXPECT_EQ(world->tree_count(), 0u);
  }
  unsetenv("BOREAS_THREADS");
}

TEST(Forest, TemplatesShareOneModelAndGiveEachTreeItsTransformedRestShape) {
  auto world = make_world_with_wave(windy_wave());
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 6; ++i) {
    boreas_tree_def d = forest_def(i, 42);
    d.rotation = 0.9f * float(i) - 2.0f;
    d.scale = 0.5f + 0.3f * float(i);
    defs.push_back(d);
  }
  defs.push_back(forest_def(7, 43));  // another seed: another template
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
  EXPECT_EQ(world->template_count(), 2u);
  EXPECT_EQ(world->tree(ids[0]).model.get(), world->tree(ids[5]).model.get());
  EXPECT_NE(world->tree(ids[0]).model.get(), world->tree(ids[6]).model.get());

  // Tree k's rest shape is tree 0's, moved to its base, turned by the difference of their
  // rotations about +y and scaled by the ratio of their scales.
  const std::vector<boreas_branch> ref = world->tree_branches(ids[0]);
  auto local = [&](const boreas_tree_def& d, const float* p) {
    dvec3 v(p[0] - d.position[0], p[1] - d.position[1], p[2] - d.position[2]);
    const double c = std::cos(d.rotation), s = std::sin(d.rotation);  // undo R_y(rotation)
    return dvec3(c * v.x - s * v.z, v.y, s * v.x + c * v.z) / double(d.scale);
  };
  double height = 0.0;
  for (const boreas_branch& b : ref) height = std::max(height, double(b.control_points[3][1]));
  for (int k = 1; k < 6; ++k) {
    const std::vector<boreas_branch> mine = world->tree_branches(ids[size_t(k)]);
    ASSERT_EQ(mine.size(), ref.size());
    double worst = 0.0;
    for (size_t b = 0; b < ref.size(); ++b) {
      for (int c = 0; c < 4; ++c)
        worst = std::max(worst, glm::length(local(defs[size_t(k)], mine[b].control_points[c]) -
                                            local(defs[0], ref[b].control_points[c])));
      EXPECT_NEAR(mine[b].radius / defs[size_t(k)].scale, ref[b].radius / defs[0].scale,
                  1e-6 * ref[b].radius);
    }
    // Float placement through up to four frames: 1e-5 of the tree's height.
    EXPECT_LT(worst, 1e-5 * height / defs[0].scale) << "tree " << k;
  }
  // The last tree of a template lets it go.
  world->remove_tree(ids[6]);
  EXPECT_EQ(world->template_count(), 1u);
}

TEST(Forest, ATreesGettersDoNotDependOnTheRestOfTheWorld) {
  const boreas_tree_def mine = forest_def(5, 9, "weeping_willow");
  auto alone = make_world_with_wave(windy_wave());
  boreas_tree_id a = alone->add_tree(mine);
  auto crowded = make_world_with_wave(windy_wave());
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 40; ++i) defs.push_back(forest_def(10 + i, uint64_t(i % 4)));
  crowded->add_trees(defs.data(), 20);
  boreas_tree_id b = crowded->add_tree(mine);
  crowded->add_trees(defs.data() + 20, 20);
  for (int s = 0; s < 12; ++s) {
    alone->step(kDt);
    crowded->step(kDt);
  }
  EXPECT_EQ(tree_bytes(*alone, a), tree_bytes(*crowded, b));
  // The readback of one tree reads its ranges only: the bytes of its own planes (state, and
  // motion for the broken flags).
  const uint64_t before = transfer_bytes(*crowded);
  crowded->tree_branches(b);
  const uint64_t read = transfer_bytes(*crowded) - before;
  const size_t entries = size_t(crowded->tree(b).model->branch_count()) + 1;
  const int motion_planes = crowded->tree_batch(crowded->tree(b).params.mode).motion_planes();
  EXPECT_EQ(read, entries * size_t(BOREAS_TREE_STATE_PLANES + motion_planes) * sizeof(float));
}

TEST(Forest, AWorldTooLargeForTheDeviceIsRefusedAndLeftAsItWas) {
  auto world = make_world_with_wave(windy_wave());
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 8; ++i) defs.push_back(forest_def(i, 3));
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), 8);
  world->step(kDt);
  const std::vector<unsigned char> before = tree_bytes(*world, ids[3]);
  // The device holds what it holds now and 1 MiB more: 2,000 more aspens do not fit.
  world->runtime().set_memory_limit(world->runtime().memory_in_use() + (1u << 20));
  std::vector<boreas_tree_def> many;
  for (int i = 0; i < 2000; ++i) many.push_back(forest_def(8 + i, 3));
  expect_error([&] { world->add_trees(many.data(), int(many.size())); }, BOREAS_ERROR_OUT_OF_MEMORY,
               {"trees (", "needs", "bytes", "more on"});
  EXPECT_EQ(world->tree_count(), 8u);
  EXPECT_EQ(tree_bytes(*world, ids[3]), before);
  world->step(kDt);  // and it still steps
  // Through the C API: the status, and the message naming the sizes.
  boreas_world_def def = boreas_default_world_def();
  def.grid = calm_grid();
  boreas_world w = nullptr;
  ASSERT_EQ(boreas_world_create(&def, &w), BOREAS_OK);
  test::ScopedEnv limit("BOREAS_DEVICE_MEMORY", "1M");
  boreas_world small = nullptr;
  ASSERT_EQ(boreas_world_create(&def, &small), BOREAS_OK);
  EXPECT_EQ(boreas_world_add_trees(small, many.data(), 200, nullptr), BOREAS_ERROR_OUT_OF_MEMORY);
  EXPECT_NE(std::string(boreas_last_error()).find("bytes"), std::string::npos)
      << boreas_last_error();
  boreas_world_destroy(small);
  boreas_world_destroy(w);
}

TEST(Forest, SixtyFourBitPlaneOffsetsGiveTheSameTrees) {
  // The kernels' 64-bit plane offsets (forests past 2^31 floats) on a small world: the same
  // trees as with int offsets, bit for bit.
  auto narrow = make_world_with_wave(windy_wave());
  auto wide = make_world_with_wave(windy_wave());
  wide->tree_batch(BOREAS_TREE_LAGGED).force_wide_planes(true);
  std::vector<boreas_tree_def> defs = {forest_def(0, 1), forest_def(1, 2, "black_tupelo")};
  std::vector<boreas_tree_id> a = narrow->add_trees(defs.data(), 2),
                              b = wide->add_trees(defs.data(), 2);
  for (int s = 0; s < 5; ++s) {
    narrow->step(kDt);
    wide->step(kDt);
  }
  for (size_t k = 0; k < a.size(); ++k)
    EXPECT_EQ(tree_bytes(*narrow, a[k]), tree_bytes(*wide, b[k]));
  std::vector<boreas_vertex> va, vb;
  std::vector<uint32_t> ia, ib;
  narrow->tree_mesh(a[1], &va, &ia);
  wide->tree_mesh(b[1], &vb, &ib);
  EXPECT_EQ(bytes_of(va), bytes_of(vb));
}

// ---- Levels of detail ----------------------------------------------------------------------

// A steady wind (no gusts, no travelling crests): trees come to rest bent.
std::unique_ptr<impl::World> steady_world() {
  boreas_world_def def = boreas_default_world_def();
  def.grid = calm_grid();
  boreas_wave w = test::steady_wave(1.0f, 0.3f, 12.0f);
  def.waves = &w;
  def.wave_count = 1;
  return std::make_unique<impl::World>(def);
}

std::vector<dvec3> tips(impl::World& world, boreas_tree_id id) {
  std::vector<dvec3> out;
  for (const boreas_branch& b : world.tree_branches(id))
    out.emplace_back(b.control_points[3][0], b.control_points[3][1], b.control_points[3][2]);
  return out;
}

// Each branch's bend factor F (m), from the tree's motion planes.
std::vector<dvec3> bends(impl::World& world, boreas_tree_id id) {
  return test::tree_bends(world, id);
}

// How far a tip may move in one step when F moves by df and the parent is still. Eq. 17
// places P2' = P1 + L2 n(d2 + w2 F) and P3' = P2' + L3 n(d3 + F) (n: normalize, |d_i| = L_i),
// and |dn(v)/dv| = 1/|v| with |v| >= L - |F|, so the tip moves by at most
// df (w2 L2 / (L2 - w2 |F|) + L3 / (L3 - |F|)), plus 5 % for second-order terms.
double tip_bound(double df, double f, const boreas_branch& b) {
  auto segment = [&](int k) {
    return glm::length(dvec3(b.control_points[k][0] - b.control_points[k - 1][0],
                             b.control_points[k][1] - b.control_points[k - 1][1],
                             b.control_points[k][2] - b.control_points[k - 1][2]));
  };
  const double w2 = std::pow(2.0 / 3.0, 1.8), l2 = segment(2), l3 = segment(3);
  return 1.05 * df *
             (w2 * l2 / std::max(l2 - w2 * f, 1e-3 * l2) + l3 / std::max(l3 - f, 1e-3 * l3)) +
         1e-6;
}

TEST(ForestLod, ChangingLevelNeverMakesABranchJump) {
  auto world = steady_world();
  boreas_tree_def def = forest_def(0, 4);
  def.position[0] = def.position[2] = 0.0f;
  def.rotation = 0.0f;
  def.scale = 1.0f;
  boreas_tree_id id = world->add_tree(def);
  const float near_focus[3] = {0.0f, 1.8f, 5.0f}, reduced_focus[3] = {0.0f, 1.8f, 50.0f};
  world->set_focus(near_focus, 1);
  for (int s = 0; s < 30; ++s) world->step(kDt);  // at rest in the steady wind
  const std::vector<dvec3> bent = tips(*world, id);
  const std::vector<dvec3> bent_f = bends(*world, id);
  const std::vector<boreas_branch> shape = world->tree_branches(id);
  // The world keeps the model packed: the branches' levels from the whole one.
  const std::shared_ptr<const impl::TreeModel> whole = impl::whole_model(world->tree(id).model);
  const impl::TreeModel& m = *whole;
  const int finest = m.levels - 1;

  // Full -> reduced: the finest level's bend decays by exp(-r dt / tau) per update (every
  // r-th step), so its tips move by at most tip_bound((1 - exp(-r dt / tau)) |F|) per step
  // (the parents are still: the wind is steady), never by the whole bend at once.
  world->set_focus(reduced_focus, 1);
  std::vector<std::vector<dvec3>> path{bent};
  for (int s = 0; s < 600; ++s) {
    world->step(kDt);
    path.push_back(tips(*world, id));
  }
  EXPECT_EQ(world->step_stats().trees_by_lod[1], 1);
  // Reduced trees update their carried level every carry_rate steps, by that many steps.
  const int rate = impl::carry_rate(impl::TreeLod::kReduced);
  const double carry_step = 1.0 - std::exp(-double(rate) * double(kDt) / impl::kCarryTimeConstant);
  double largest_path = 0.0, largest_step = 0.0;
  for (size_t b = 0; b < bent.size(); ++b) {
    const double whole = glm::length(path.back()[b] - bent[b]);
    if (m.branches[b].level != finest) {
      EXPECT_LT(whole, 1e-5) << "branch " << b << " of a stepped level moved";
      continue;
    }
    largest_path = std::max(largest_path, whole);
    for (size_t s = 1; s < path.size(); ++s) {
      const double moved = glm::length(path[s][b] - path[s - 1][b]);
      largest_step = std::max(largest_step, moved);
      const double f = glm::length(bent_f[b]);
      ASSERT_LE(moved, tip_bound(carry_step * f, f, shape[b]))
          << "branch " << b << " step " << s << ": |F| " << f << " m";
    }
  }
  EXPECT_GT(largest_path, 1e-3)
      << "the finest level did not change pose: the test would prove nothing";
  EXPECT_LT(largest_step, 0.25 * largest_path) << "a tip covered a quarter of its way in one step";

  // Reduced -> full: the finest level eases back into the wind from where it is, moving F
  // by (1 - exp(-dt / tau_resume)) of its distance to the wind's target per step.
  const std::vector<dvec3> rest_f = bends(*world, id);
  world->set_focus(near_focus, 1);
  const double resume_step = 1.0 - std::exp(-double(kDt) / impl::kResumeTimeConstant);
  std::vector<std::vector<dvec3>> back{path.back()};
  for (int s = 0; s < 90; ++s) {
    world->step(kDt);
    back.push_back(tips(*world, id));
  }
  for (size_t b = 0; b < bent.size(); ++b) {
    if (m.branches[b].level != finest) continue;
    const double whole = glm::length(back.front()[b] - bent[b]);
    const double df = glm::length(bent_f[b] - rest_f[b]);
    const double f = std::max(glm::length(bent_f[b]), glm::length(rest_f[b]));
    for (size_t s = 1; s < back.size(); ++s)
      ASSERT_LE(glm::length(back[s][b] - back[s - 1][b]), tip_bound(resume_step * df, f, shape[b]))
          << "branch " << b << " step " << s;
    EXPECT_LT(glm::length(back.back()[b] - bent[b]), 1e-4 + 0.01 * whole)
        << "branch " << b << " did not return";
  }
}

TEST(ForestLod, LevelsFollowTheDistancesAndFrozenTreesRest) {
  auto world = steady_world();
  std::vector<boreas_tree_def> defs;
  const float distances[] = {10.0f, 50.0f, 120.0f, 400.0f};  // full, reduced, far, frozen
  for (int i = 0; i < 4; ++i) {
    boreas_tree_def d = forest_def(0, 4);
    d.position[0] = distances[i];
    d.position[2] = 0.0f;
    defs.push_back(d);
  }
  std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), 4);
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  world->set_focus(focus, 1);
  world->step(kDt);
  const boreas_step_stats stats = world->step_stats();
  for (int l = 0; l < 4; ++l) EXPECT_EQ(stats.trees_by_lod[l], 1) << "level " << l;
  const impl::TreeModel& m = *world->tree(ids[0]).model;
  const int64_t all = int64_t(m.branch_count());
  // Full: all stepped; reduced: all but the finest; far: trunk and level 1; settling: all carried.
  EXPECT_EQ(stats.branches_stepped, all + m.level_begin[size_t(m.levels - 1)] +
                                        m.level_begin[size_t(std::min(m.levels, 2))]);
  EXPECT_EQ(stats.branches_stepped + stats.branches_carried, 4 * all);
  // Past the settle time the frozen tree is not stepped, and stays exactly where it is,
  // which is its rest pose (the bend decayed for 3 s, 6 time constants).
  for (int s = 0; s < int(impl::kSettleTime / kDt) + 5; ++s) world->step(kDt);
  const std::vector<unsigned char> frozen = tree_bytes(*world, ids[3]);
  world->step(kDt);
  world->step(kDt);
  EXPECT_EQ(tree_bytes(*world, ids[3]), frozen);
  EXPECT_EQ(world->step_stats().branches_stepped + world->step_stats().branches_carried, 3 * all);
  auto rest_world = steady_world();
  boreas_tree_def calm = defs[3];
  boreas_tree_id rest_id = rest_world->add_tree(calm);  // at rest, never stepped
  const std::vector<dvec3> rest = tips(*rest_world, rest_id), now = tips(*world, ids[3]);
  double worst = 0.0, bend = 0.0;
  auto bent_world = steady_world();
  boreas_tree_id bent_id = bent_world->add_tree(calm);
  for (int s = 0; s < 30; ++s) bent_world->step(kDt);
  const std::vector<dvec3> bent = tips(*bent_world, bent_id);
  for (size_t b = 0; b < rest.size(); ++b) {
    worst = std::max(worst, glm::length(now[b] - rest[b]));
    bend = std::max(bend, glm::length(bent[b] - rest[b]));
  }
  EXPECT_LT(worst, 0.01 * bend + 1e-5)
      << "the frozen tree is not at rest (bend in the wind " << bend << " m)";
  // Coming nearer wakes it.
  const float near[3] = {400.0f, 1.8f, 0.0f};
  world->set_focus(near, 1);
  world->step(kDt);
  EXPECT_EQ(world->step_stats().trees_by_lod[0], 1);
  EXPECT_EQ(world->step_stats().trees_by_lod[3], 3);  // the others are past 250 m now
}

TEST(ForestLod, SameInputsGiveBitIdenticalForests) {
  auto run = [] {
    auto world = make_world_with_wave(windy_wave());
    std::vector<boreas_tree_def> defs;
    for (int i = 0; i < 30; ++i) defs.push_back(forest_def(i, uint64_t(i % 3)));
    defs[4].mode = BOREAS_TREE_EXACT;
    defs[7].response = BOREAS_TREE_DAMPED;
    std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
    std::vector<unsigned char> all;
    for (int s = 0; s < 40; ++s) {
      const float focus[3] = {float(s) * 3.0f, 1.8f, 10.0f};
      world->set_focus(focus, 1);
      world->step(kDt);
    }
    for (boreas_tree_id id : ids) {
      std::vector<unsigned char> b = tree_bytes(*world, id);
      all.insert(all.end(), b.begin(), b.end());
    }
    return all;
  };
  EXPECT_EQ(run(), run());
}

// The tree step and the leaf records run BOREAS_W items per work-item at the CPU's SIMD
// width and one on GPUs (cl/shared/simd_width.h), from one source: every width must give
// a forest the same branch and leaf bits, with tiles cut short (a tree level of a few
// branches), both modes and responses, and levels of detail changing as the focus moves
// (carried branches).
TEST(ForestLod, EverySimdWidthGivesTheSameForestBitForBit) {
  auto run = [](int width) {
    test::ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    auto world = make_world_with_wave(windy_wave());
    EXPECT_EQ(world->runtime().simd_width(), width);
    std::vector<boreas_tree_def> defs;
    for (int i = 0; i < 12; ++i) defs.push_back(forest_def(i, uint64_t(i % 3)));
    defs[4].mode = BOREAS_TREE_EXACT;
    defs[7].response = BOREAS_TREE_DAMPED;
    std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), int(defs.size()));
    for (int s = 0; s < 30; ++s) {
      const float focus[3] = {float(s) * 3.0f, 1.8f, 10.0f};
      world->set_focus(focus, 1);
      world->step(kDt);
    }
    std::vector<unsigned char> all;
    for (boreas_tree_id id : ids) {
      std::vector<unsigned char> b = tree_bytes(*world, id);
      all.insert(all.end(), b.begin(), b.end());
    }
    return all;
  };
  const std::vector<unsigned char> scalar = run(1);
  for (int width : {8, 16}) EXPECT_TRUE(run(width) == scalar) << "width " << width;
}

TEST(ForestLod, FocusPointsAreChecked) {
  auto world = make_world_with_wave(windy_wave());
  const float bad[3] = {0.0f, NAN, 0.0f};
  expect_error([&] { world->set_focus(bad, 1); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"points[1]", "point 0, y"});
  expect_error([&] { world->set_focus(nullptr, 2); }, BOREAS_ERROR_INVALID_ARGUMENT, {"NULL"});
  expect_error([&] { world->set_focus(bad, -1); }, BOREAS_ERROR_INVALID_ARGUMENT, {"count"});
  boreas_tree_def def = forest_def(0, 1);
  def.lod_distances[1] = 5.0f;  // decreasing
  expect_error([&] { world->add_tree(def); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"lod_distances[1] must not be below lod_distances[0]"});
  def = forest_def(0, 1);
  def.lod_distances[0] = NAN;
  expect_error([&] { world->add_tree(def); }, BOREAS_ERROR_INVALID_ARGUMENT, {"lod_distances[0]"});
}

}  // namespace
}  // namespace boreas
