// boreas tests: a world whose trees or meadows pass the device's largest allocation splits
// them into chunks (world_chunks.cpp), each a batch whose every buffer fits that allocation.
// A forest split so (the allocation forced small: Runtime::set_max_allocation, as
// BOREAS_MAX_ALLOCATION does) steps to the same bits as the same forest in one chunk, in
// both modes and with levels of detail; its getters, template numbers and one-call records
// are the same; trees added and removed (chunks made after the first steps) fill and empty
// the chunks (an empty one goes, each shrinks by itself); meadows alike; and a tree or a
// meadow bigger than a whole chunk is refused, naming it, with the world left as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"
#include "shared/tree_records.h"
#include "shared/tree_types.h"
#include "support/small_world.h"
#include "support/test_support.h"
#include "trees/tree_batch.h"
#include "world.h"

namespace boreas {
namespace {

using test::make_world_with_wave;
using test::tree_bytes;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;

// Aspens of six templates on a lattice; every third in exact mode where `modes`.
boreas_tree_def aspen(int index, bool modes) {
  boreas_tree_def def = boreas_default_tree_def();
  def.seed = uint64_t(1 + index % 6);
  def.position[0] = float(index % 10) * 6.0f - 27.0f;
  def.position[2] = float(index / 10) * 6.0f - 12.0f;
  def.rotation = 0.37f * float(index);
  def.scale = 0.8f + 0.05f * float(index % 4);
  if (modes && index % 3 == 1) def.mode = BOREAS_TREE_EXACT;
  return def;
}

std::vector<boreas_tree_def> aspens(int count, bool modes) {
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < count; ++i) defs.push_back(aspen(i, modes));
  return defs;
}

// An allocation limit that holds one aspen's leaf records (BOREAS_TREE_LEAF_OUT_PLANES
// floats a leaf), and so the packed leaf planes of about four templates but not six, and the
// state planes of some ten aspens: a forest of a few dozen needs several chunks, and the
// chunks' template spaces are tested as well as their trees'. (A smaller limit, under one
// tree's records, is LeavesWhoseRecordsPassOneAllocationReadBackInRuns's.) Measured on a
// world of one tree of each template (their leaf counts differ by seed).
uint64_t small_allocation() {
  auto probe = make_world_with_wave(windy_wave());
  int64_t most_leaves = 0;
  for (int i = 0; i < 6; ++i) {
    const boreas_tree_id id = probe->add_tree(aspen(i, false));
    most_leaves = std::max<int64_t>(most_leaves, int64_t(probe->tree_leaves(id).size()));
  }
  static_assert(BOREAS_TREE_LEAF_OUT_PLANES >= 4 * BOREAS_TREE_LEAF_PLANES,
                "one tree's records hold at least four trees' packed leaves");
  return uint64_t(most_leaves) * BOREAS_TREE_LEAF_OUT_PLANES * sizeof(float);
}

// Every chunk's buffers within the limit: the trees' state planes (the widest per entry).
void expect_chunks_within(impl::World& world, uint64_t limit) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
    for (const auto& chunk : world.tree_chunks(mode))
      EXPECT_LE(uint64_t(chunk->stride()) * BOREAS_TREE_STATE_PLANES * sizeof(float), limit);
}

size_t chunk_count(impl::World& world, boreas_tree_mode mode) {
  return world.tree_chunks(mode).size();
}

// Both worlds' trees show the same bits, and the same template numbers.
void expect_same_trees(impl::World& a, impl::World& b, const std::vector<boreas_tree_id>& ia,
                       const std::vector<boreas_tree_id>& ib) {
  ASSERT_EQ(ia.size(), ib.size());
  for (size_t t = 0; t < ia.size(); ++t) {
    ASSERT_EQ(tree_bytes(a, ia[t]), tree_bytes(b, ib[t])) << "tree " << t;
    ASSERT_EQ(a.tree_template(ia[t]), b.tree_template(ib[t])) << "tree " << t;
  }
}

TEST(WorldChunks, AForestSplitOverChunksStepsToTheSameBitsAsOneInOneBuffer) {
  const uint64_t limit = small_allocation();
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  split->runtime().set_max_allocation(limit);
  const std::vector<boreas_tree_def> defs = aspens(90, true);
  const auto ids_whole = whole->add_trees(defs.data(), int(defs.size()));
  const auto ids_split = split->add_trees(defs.data(), int(defs.size()));
  EXPECT_EQ(chunk_count(*whole, BOREAS_TREE_LAGGED), 1u);
  EXPECT_EQ(chunk_count(*whole, BOREAS_TREE_EXACT), 1u);
  EXPECT_GE(chunk_count(*split, BOREAS_TREE_LAGGED), 3u);
  EXPECT_GE(chunk_count(*split, BOREAS_TREE_EXACT), 2u);
  expect_chunks_within(*split, limit);
  // Levels of detail too: a focus at one side puts the far trees on carried and frozen
  // launches, chunk by chunk.
  const float focus[3] = {-27.0f, 1.8f, -12.0f};
  whole->set_focus(focus, 1);
  split->set_focus(focus, 1);
  for (int s = 0; s < 12; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  EXPECT_EQ(whole->step_stats().branches_stepped, split->step_stats().branches_stepped);
  EXPECT_EQ(whole->step_stats().branches_carried, split->step_stats().branches_carried);
  EXPECT_EQ(whole->state_hash(), split->state_hash());
  expect_same_trees(*whole, *split, ids_whole, ids_split);
}

// With the focus set before the add, each chunk takes its trees' finest levels straight into
// its settled space (trees/tree_batch.h, settling at add), within the limit too; the split
// forest steps to the bits of one whole batch that settled at add as well.
TEST(WorldChunks, AForestSettledAtAddOverChunksStepsToTheSameBitsAsOneInOneBuffer) {
  const uint64_t limit = small_allocation();
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  split->runtime().set_max_allocation(limit);
  const float focus[3] = {-27.0f, 1.8f, -12.0f};
  whole->set_focus(focus, 1);
  split->set_focus(focus, 1);
  const std::vector<boreas_tree_def> defs = aspens(90, true);
  const auto ids_whole = whole->add_trees(defs.data(), int(defs.size()));
  const auto ids_split = split->add_trees(defs.data(), int(defs.size()));
  EXPECT_GE(chunk_count(*split, BOREAS_TREE_LAGGED), 3u);
  expect_chunks_within(*split, limit);
  int64_t settled_whole = 0, settled_split = 0, chunks_settled = 0;
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    for (const auto& chunk : whole->tree_chunks(mode)) settled_whole += chunk->branches_settled();
    for (const auto& chunk : split->tree_chunks(mode)) {
      settled_split += chunk->branches_settled();
      chunks_settled += chunk->branches_settled() > 0 ? 1 : 0;
      const int planes = chunk->motion_planes() == BOREAS_TREE_MOTION_PLANES ? BOREAS_TREE_SETTLED_RATE_PLANES
                                                                             : BOREAS_TREE_SETTLED_PLANES;
      EXPECT_LE(uint64_t(chunk->settled_stride()) * uint64_t(planes) * sizeof(float), limit);
    }
  }
  ASSERT_GT(settled_whole, 0) << "nothing settled at add: the test would prove nothing";
  EXPECT_GE(chunks_settled, 2) << "the chunks did not settle at add";
  EXPECT_EQ(settled_split, settled_whole);
  for (int s = 0; s < 12; ++s) {
    whole->step(kDt);
    split->step(kDt);
    ASSERT_EQ(whole->state_hash(), split->state_hash()) << "step " << s;
  }
  EXPECT_EQ(whole->step_stats().branches_carried, split->step_stats().branches_carried);
  expect_same_trees(*whole, *split, ids_whole, ids_split);
}

TEST(WorldChunks, AddsAndRemovesFillAndEmptyTheChunksAndStepToTheSameBits) {
  const uint64_t limit = small_allocation();
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  split->runtime().set_max_allocation(limit);
  const std::vector<boreas_tree_def> defs = aspens(80, false);
  auto ids_whole = whole->add_trees(defs.data(), int(defs.size()));
  auto ids_split = split->add_trees(defs.data(), int(defs.size()));
  const size_t chunks = chunk_count(*split, BOREAS_TREE_LAGGED);
  ASSERT_GE(chunks, 3u);
  const float focus[3] = {-27.0f, 1.8f, 30.0f};
  whole->set_focus(focus, 1);
  split->set_focus(focus, 1);
  for (int s = 0; s < 4; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  // Every other tree goes, then all from the 12th on: the chunks that held only those go
  // with them, and those left shrink with their population.
  const int64_t first_stride = split->tree_batch(BOREAS_TREE_LAGGED).stride();
  auto remove = [&](size_t t) {
    whole->remove_tree(ids_whole[t]);
    split->remove_tree(ids_split[t]);
  };
  for (size_t t = 1; t < 80; t += 2) remove(t);
  for (size_t t = 12; t < 80; t += 2) remove(t);
  EXPECT_LT(chunk_count(*split, BOREAS_TREE_LAGGED), chunks);
  EXPECT_LT(split->tree_batch(BOREAS_TREE_LAGGED).stride(), first_stride) << "chunk 0 shrank";
  // An odd count of steps: the chunks made next start in another phase of the carry rates.
  for (int s = 0; s < 5; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  // New trees fill the room left in the chunks first, then new ones.
  std::vector<boreas_tree_id> live_whole, live_split;
  for (size_t t = 0; t < 12; t += 2) {
    live_whole.push_back(ids_whole[t]);
    live_split.push_back(ids_split[t]);
  }
  const std::vector<boreas_tree_def> more = aspens(70, false);
  for (const boreas_tree_id id : whole->add_trees(more.data(), int(more.size())))
    live_whole.push_back(id);
  for (const boreas_tree_id id : split->add_trees(more.data(), int(more.size())))
    live_split.push_back(id);
  EXPECT_GE(chunk_count(*split, BOREAS_TREE_LAGGED), 3u);
  expect_chunks_within(*split, limit);
  for (int s = 0; s < 6; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  EXPECT_EQ(whole->step_stats().branches_carried, split->step_stats().branches_carried);
  EXPECT_GT(split->step_stats().branches_carried, 0);
  EXPECT_EQ(whole->state_hash(), split->state_hash());
  expect_same_trees(*whole, *split, live_whole, live_split);
}

TEST(WorldChunks, OneCallRecordsOfASplitForestAreTheSameTreesRecords) {
  const uint64_t limit = small_allocation();
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  split->runtime().set_max_allocation(limit);
  const std::vector<boreas_tree_def> defs = aspens(60, true);
  const auto ids = whole->add_trees(defs.data(), int(defs.size()));
  ASSERT_EQ(split->add_trees(defs.data(), int(defs.size())).size(), ids.size());
  ASSERT_GE(chunk_count(*split, BOREAS_TREE_LAGGED), 2u);
  for (int s = 0; s < 3; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  size_t branches = 0, leaves = 0;
  for (boreas_tree_id id : ids) {
    branches += whole->tree_branches(id).size();
    leaves += whole->tree_leaves(id).size();
  }
  // What one call writes, read back: the indirect words, and per tree (by its range) its
  // branch and leaf records.
  struct Written {
    std::vector<uint32_t> indirect;
    std::vector<std::vector<unsigned char>> by_tree;
  };
  auto call = [&](impl::World& world) {
    cl::Context& context = world.runtime().context();
    const size_t bf = BOREAS_BRANCH_RECORD_FLOATS * 4, lf = BOREAS_LEAF_RECORD_FLOATS * 4;
    impl::TreeBatch::RecordOutputs out;
    out.branches = cl::Buffer(context, CL_MEM_READ_WRITE, branches * bf);
    out.leaves = cl::Buffer(context, CL_MEM_READ_WRITE, leaves * lf);
    out.impostors =
        cl::Buffer(context, CL_MEM_READ_WRITE, ids.size() * BOREAS_TREE_IMPOSTOR_WORDS * 4);
    out.ranges = cl::Buffer(context, CL_MEM_READ_WRITE, ids.size() * BOREAS_TREE_RANGE_WORDS * 4);
    out.indirect = cl::Buffer(context, CL_MEM_READ_WRITE, BOREAS_TREE_INDIRECT_WORDS * 4);
    world.enqueue_tree_records(boreas_default_tree_view_def(), out);
    Written w;
    w.indirect.resize(BOREAS_TREE_INDIRECT_WORDS);
    world.runtime().read(out.indirect, 0, w.indirect.size() * 4, w.indirect.data());
    std::vector<int32_t> ranges(ids.size() * BOREAS_TREE_RANGE_WORDS);
    world.runtime().read(out.ranges, 0, ranges.size() * 4, ranges.data());
    std::vector<unsigned char> b(branches * bf), l(leaves * lf);
    world.runtime().read(out.branches, 0, b.size(), b.data());
    world.runtime().read(out.leaves, 0, l.size(), l.data());
    w.by_tree.resize(ids.size());
    for (uint32_t r = 0; r < w.indirect[BOREAS_TREE_INDIRECT_RANGES]; ++r) {
      const int32_t* rg = &ranges[size_t(r) * BOREAS_TREE_RANGE_WORDS];
      size_t t = 0;
      while (t < ids.size() && int32_t(ids[t].index) != rg[BOREAS_TREE_RANGE_ID_INDEX]) ++t;
      EXPECT_LT(t, ids.size()) << "range " << r << " names a tree of the world";
      if (t == ids.size()) continue;
      std::vector<unsigned char>& bytes = w.by_tree[t];
      const size_t b0 = size_t(rg[BOREAS_TREE_RANGE_BRANCH_FIRST]) * bf,
                   l0 = size_t(rg[BOREAS_TREE_RANGE_LEAF_FIRST]) * lf;
      bytes.assign(b.begin() + ptrdiff_t(b0),
                   b.begin() + ptrdiff_t(b0 + size_t(rg[BOREAS_TREE_RANGE_BRANCH_COUNT]) * bf));
      bytes.insert(bytes.end(), l.begin() + ptrdiff_t(l0),
                   l.begin() + ptrdiff_t(l0 + size_t(rg[BOREAS_TREE_RANGE_LEAF_COUNT]) * lf));
      for (int k : {BOREAS_TREE_RANGE_LEAVES, BOREAS_TREE_RANGE_LEAF_STRIDE})
        bytes.push_back((unsigned char)rg[k]);
    }
    return w;
  };
  const Written a = call(*whole), b = call(*split);
  // The same counts (the records of other chunks follow on, nothing is lost or doubled),
  // and each tree's records the same bits wherever they landed.
  EXPECT_EQ(a.indirect, b.indirect);
  EXPECT_EQ(a.indirect[BOREAS_TREE_INDIRECT_RANGES], uint32_t(ids.size()));
  for (size_t t = 0; t < ids.size(); ++t) {
    ASSERT_FALSE(a.by_tree[t].empty()) << "tree " << t;
    ASSERT_EQ(a.by_tree[t], b.by_tree[t]) << "tree " << t;
  }
}

// A tree whose leaf records pass one allocation (its planes do not): the leaf getter makes
// them in runs of tiles through a scratch buffer of the largest allocation, and reads the
// same bits as a world without the limit.
TEST(WorldChunks, LeavesWhoseRecordsPassOneAllocationReadBackInRuns) {
  auto whole = make_world_with_wave(windy_wave());
  auto limited = make_world_with_wave(windy_wave());
  const boreas_tree_def def = aspen(0, false);
  const boreas_tree_id a = whole->add_tree(def);
  const size_t leaves = whole->tree_leaves(a).size();
  ASSERT_GT(leaves, 10000u);
  // A third of the tree's records: three runs at least.
  limited->runtime().set_max_allocation(uint64_t(leaves) * BOREAS_TREE_LEAF_OUT_PLANES * sizeof(float) / 3);
  const boreas_tree_id b = limited->add_tree(def);
  for (int s = 0; s < 6; ++s) {
    whole->step(kDt);
    limited->step(kDt);
  }
  EXPECT_EQ(tree_bytes(*whole, a), tree_bytes(*limited, b));
  const std::vector<boreas_leaf> want = whole->tree_leaves(a), got = limited->tree_leaves(b);
  ASSERT_EQ(want.size(), got.size());
  EXPECT_EQ(std::memcmp(want.data(), got.data(), want.size() * sizeof(boreas_leaf)), 0);
}

TEST(WorldChunks, ATreeBiggerThanAChunkIsRefusedNamingItAndNothingChanges) {
  auto world = make_world_with_wave(windy_wave());
  const std::vector<boreas_tree_def> defs = aspens(4, false);
  const auto kept = world->add_trees(defs.data(), 2);
  world->step(kDt);
  const uint64_t hash = world->state_hash();
  // Less than one aspen's state planes (some 1,200 entries of 15 floats).
  world->runtime().set_max_allocation(32 * 1024);
  try {
    world->add_trees(defs.data(), int(defs.size()));
    FAIL() << "an aspen in 32 KiB buffers was taken";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_OUT_OF_MEMORY);
    const std::string what = e.what();
    EXPECT_NE(what.find("defs[0]"), std::string::npos) << what;
    EXPECT_NE(what.find("32768 bytes"), std::string::npos) << what;
  }
  EXPECT_EQ(world->tree_count(), kept.size());
  EXPECT_EQ(chunk_count(*world, BOREAS_TREE_LAGGED), 1u);
  EXPECT_EQ(world->state_hash(), hash);
}

TEST(WorldChunks, BoreasMaxAllocationLowersTheLargestBufferAndIsChecked) {
  const uint64_t device = make_world_with_wave(windy_wave())->runtime().max_allocation();
  {
    test::ScopedEnv limit("BOREAS_MAX_ALLOCATION", "3M");
    EXPECT_EQ(make_world_with_wave(windy_wave())->runtime().max_allocation(),
              std::min<uint64_t>(device, 3u << 20));
  }
  test::ScopedEnv bad("BOREAS_MAX_ALLOCATION", "3 MB");
  try {
    make_world_with_wave(windy_wave());
    FAIL() << "a bad BOREAS_MAX_ALLOCATION was taken";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(e.what()).find("BOREAS_MAX_ALLOCATION"), std::string::npos) << e.what();
  }
}

TEST(WorldChunks, ACollidersPushBackSurvivesItsChunkGoing) {
  const uint64_t limit = small_allocation();
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  split->runtime().set_max_allocation(limit);
  const std::vector<boreas_tree_def> defs = aspens(90, false);
  const auto ids_whole = whole->add_trees(defs.data(), int(defs.size()));
  const auto ids_split = split->add_trees(defs.data(), int(defs.size()));
  // A sphere in the crown of a tree of the last chunk, which no other tree reaches.
  const impl::TreeBatch* last = split->tree_chunks(BOREAS_TREE_LAGGED).back().get();
  ASSERT_NE(last, split->tree_chunks(BOREAS_TREE_LAGGED).front().get());
  size_t touched = 0;
  while (&split->tree_batch(split->tree(ids_split[touched])) != last) ++touched;
  boreas_collider_def c = boreas_default_collider_def();
  c.radius = 1.2f;
  c.pose.position[0] = defs[touched].position[0] + 0.3f;
  c.pose.position[1] = 4.0f;
  c.pose.position[2] = defs[touched].position[2];
  const boreas_collider_id cw = whole->add_collider(c), cs = split->add_collider(c);
  for (int s = 0; s < 3; ++s) {
    whole->step(kDt);
    split->step(kDt);
  }
  // Every tree of that chunk goes before the contact is read: the chunk goes with them.
  const size_t chunks = chunk_count(*split, BOREAS_TREE_LAGGED);
  for (size_t t = 0; t < ids_split.size(); ++t)
    if (&split->tree_batch(split->tree(ids_split[t])) == last) {
      whole->remove_tree(ids_whole[t]);
      split->remove_tree(ids_split[t]);
    }
  EXPECT_EQ(chunk_count(*split, BOREAS_TREE_LAGGED), chunks - 1);
  const boreas_collider_contact a = whole->collider_contact(cw), b = split->collider_contact(cs);
  EXPECT_GT(a.contacts, 0);
  EXPECT_EQ(a.contacts, b.contacts);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NE(a.force[0] + a.force[1] + a.force[2], 0.0f);
    EXPECT_NEAR(a.force[k], b.force[k], 1e-5f * (1.0f + std::fabs(a.force[k])));
    EXPECT_NEAR(a.torque[k], b.torque[k], 1e-5f * (1.0f + std::fabs(a.torque[k])));
  }
}

// Through the C API, as an engine would: the same forest stepped in a world whose largest
// buffer BOREAS_MAX_ALLOCATION sets to 4 MiB (some 56 aspens' state planes a chunk) and in
// one without it.
uint64_t c_api_forest_hash(const char* max_allocation) {
  test::ScopedEnv limit("BOREAS_MAX_ALLOCATION", max_allocation);
  boreas_world world = nullptr;
  EXPECT_EQ(test::create_small_windy_world(&world), BOREAS_OK) << boreas_last_error();
  if (!world) return 0;
  const std::vector<boreas_tree_def> defs = aspens(150, true);
  EXPECT_EQ(boreas_world_add_trees(world, defs.data(), int(defs.size()), nullptr), BOREAS_OK)
      << boreas_last_error();
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  EXPECT_EQ(boreas_world_set_focus(world, focus, 1), BOREAS_OK);
  for (int s = 0; s < 6; ++s) EXPECT_EQ(boreas_world_step(world, kDt), BOREAS_OK);
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(world, &hash), BOREAS_OK);
  boreas_world_destroy(world);
  return hash;
}

TEST(WorldChunks, TheCApiStepsASplitForestToTheSameHash) {
  EXPECT_EQ(c_api_forest_hash(nullptr), c_api_forest_hash("4M"));
}

boreas_meadow_def meadow(int index) {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.center[0] = float(index % 4) * 6.0f - 9.0f;
  d.center[2] = float(index / 4) * 6.0f - 9.0f;
  d.size[0] = d.size[1] = 5.0f;
  d.density = 300.0f;
  d.seed = uint64_t(1 + index);
  return d;
}

TEST(WorldChunks, MeadowsSplitOverChunksStepToTheSameBitsAsInOne) {
  auto whole = make_world_with_wave(windy_wave());
  auto split = make_world_with_wave(windy_wave());
  std::vector<boreas_meadow_def> defs;
  for (int i = 0; i < 12; ++i) defs.push_back(meadow(i));
  // Chunks of two meadows: their component planes (the frame's 14 floats a component, the
  // widest) or their shape tables, whichever is larger: the first six make three chunks.
  auto ids_whole = whole->add_meadows(defs.data(), 6);
  uint64_t most = 0;
  for (boreas_meadow_id id : ids_whole) {
    const impl::Meadow& m = whole->meadow(id).meadow;
    most =
        std::max({most, uint64_t(m.count) * 14 * sizeof(float), m.tables.size() * sizeof(float)});
  }
  split->runtime().set_max_allocation(5 * most / 2);
  auto ids_split = split->add_meadows(defs.data(), 6);
  EXPECT_EQ(whole->meadow_chunks().size(), 1u);
  EXPECT_GE(split->meadow_chunks().size(), 3u);
  // Levels of detail (tiles stepped every 4th and 16th step in phases), and the rest of
  // the meadows added after an odd count of steps, into new chunks.
  const float focus[3] = {-9.0f, 1.8f, -9.0f};
  whole->set_focus(focus, 1);
  split->set_focus(focus, 1);
  auto step_both = [&](int steps) {
    for (int s = 0; s < steps; ++s) {
      whole->step(kDt);
      split->step(kDt);
    }
  };
  step_both(7);
  for (boreas_meadow_id id : whole->add_meadows(defs.data() + 6, 6)) ids_whole.push_back(id);
  for (boreas_meadow_id id : split->add_meadows(defs.data() + 6, 6)) ids_split.push_back(id);
  EXPECT_GE(split->meadow_chunks().size(), 5u);
  step_both(9);
  EXPECT_GT(split->step_stats().components_by_rate[1] + split->step_stats().components_by_rate[2],
            0);
  for (int r = 0; r < 4; ++r)
    EXPECT_EQ(whole->step_stats().components_by_rate[r], split->step_stats().components_by_rate[r]);
  // Two meadows go (a chunk of its own empties and goes), one comes back.
  const size_t chunks = split->meadow_chunks().size();
  for (size_t k : {2u, 3u}) {
    whole->remove_meadow(ids_whole[k]);
    split->remove_meadow(ids_split[k]);
  }
  EXPECT_LT(split->meadow_chunks().size(), chunks);
  ids_whole[2] = whole->add_meadow(defs[2]);
  ids_split[2] = split->add_meadow(defs[2]);
  step_both(6);
  EXPECT_EQ(whole->state_hash(), split->state_hash());
  for (size_t k = 0; k < ids_whole.size(); ++k) {
    if (k == 3) continue;
    ASSERT_EQ(test::bytes_of(whole->meadow_components(ids_whole[k])),
              test::bytes_of(split->meadow_components(ids_split[k])))
        << "meadow " << k;
  }
}

TEST(WorldChunks, AMeadowBiggerThanAChunkIsRefusedNamingIt) {
  auto world = make_world_with_wave(windy_wave());
  const std::vector<boreas_meadow_def> defs = {meadow(0), meadow(1)};
  world->add_meadows(defs.data(), 1);
  const uint64_t hash = world->state_hash();
  world->runtime().set_max_allocation(16 * 1024);  // some 290 components of 14 floats
  try {
    world->add_meadows(defs.data(), 2);
    FAIL() << "a meadow of thousands of components in 16 KiB buffers was taken";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_OUT_OF_MEMORY);
    EXPECT_NE(std::string(e.what()).find("defs[0]"), std::string::npos) << e.what();
  }
  EXPECT_EQ(world->meadow_chunks().size(), 1u);
  EXPECT_EQ(world->state_hash(), hash);
}

}  // namespace
}  // namespace boreas
