// boreas tests: what a forest's one call a frame (boreas_world_enqueue_tree_records) costs
// and what it writes for trees whose finest level is derived or settled. Its launches are
// a fixed number per batch (a chunk of one mode), counted by the runtime, whatever the
// number of trees (trees/tree_batch_view.cpp lists them); a call that finds no tree changed
// builds no table over the trees on the host; and the records it writes of settled and
// derived trees are the per-tree calls' bits, as they are for stepped ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "shared/tree_records.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "trees/tree_batch.h"
#include "world.h"

namespace boreas {
namespace {

using test::make_world_with_wave;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;
constexpr boreas_tree_mode kModes[] = {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT};
// tree_batch_view.cpp's launches of a batch that holds trees: cull with offsets, derived
// poses, settled poses, branch records, leaf records, settled poses undone.
constexpr uint64_t kMostLaunchesPerBatch = 6;

// Aspens of six templates, 3 m apart in rows of 40 along x from x = 20 m: with the focus at
// the origin the nearest stand within lod_distances[0] (30 m, stepped whole), the others'
// finest level derived (settled where settling). Every third in exact mode.
std::vector<boreas_tree_def> stand(int count) {
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < count; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    d.seed = uint64_t(1 + i % 6);
    d.position[0] = 20.0f + 3.0f * float(i % 40);
    d.position[2] = 3.0f * float(i / 40);
    d.rotation = 0.37f * float(i);
    d.scale = 0.8f + 0.05f * float(i % 4);
    if (i % 3 == 1) d.mode = BOREAS_TREE_EXACT;
    defs.push_back(d);
  }
  return defs;
}

struct Forest {
  std::unique_ptr<impl::World> world;
  std::vector<boreas_tree_id> ids;
};

// The stand added with the focus at the origin already set (settled at add where settling),
// then stepped a little in the wind; max_allocation > 0 forces chunks of that size.
Forest seen_stand(int count, bool settling, uint64_t max_allocation = 0) {
  Forest f;
  f.world = make_world_with_wave(windy_wave());
  if (max_allocation > 0) f.world->runtime().set_max_allocation(max_allocation);
  for (boreas_tree_mode mode : kModes) f.world->tree_batch(mode).set_settling(settling);
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  f.world->set_focus(focus, 1);
  const std::vector<boreas_tree_def> defs = stand(count);
  f.ids = f.world->add_trees(defs.data(), int(defs.size()));
  for (int s = 0; s < 3; ++s) f.world->step(kDt);
  return f;
}

int64_t settled_branches(impl::World& world) {
  int64_t n = 0;
  for (boreas_tree_mode mode : kModes)
    for (const auto& chunk : world.tree_chunks(mode)) n += chunk->branches_settled();
  return n;
}

int64_t derived_branches(impl::World& world) {
  int64_t n = 0;
  for (boreas_tree_mode mode : kModes)
    for (const auto& chunk : world.tree_chunks(mode)) n += chunk->branches_derived();
  return n;
}

size_t batches_with_trees(impl::World& world) {
  size_t n = 0;
  for (boreas_tree_mode mode : kModes)
    for (const auto& chunk : world.tree_chunks(mode)) n += chunk->empty() ? 0 : 1;
  return n;
}

// Output buffers of the given records' room (a call fills them up to their end).
impl::TreeBatch::RecordOutputs outputs(impl::World& world, size_t branches, size_t leaves, size_t trees) {
  impl::Runtime& rt = world.runtime();
  impl::TreeBatch::RecordOutputs out;
  out.branches = rt.buffer(CL_MEM_READ_WRITE, std::max<size_t>(branches, 1) * BOREAS_BRANCH_RECORD_FLOATS * 4, "branches");
  out.leaves = rt.buffer(CL_MEM_READ_WRITE, std::max<size_t>(leaves, 1) * BOREAS_LEAF_RECORD_FLOATS * 4, "leaves");
  out.impostors = rt.buffer(CL_MEM_READ_WRITE, std::max<size_t>(trees, 1) * BOREAS_TREE_IMPOSTOR_WORDS * 4, "impostors");
  out.ranges = rt.buffer(CL_MEM_READ_WRITE, std::max<size_t>(trees, 1) * BOREAS_TREE_RANGE_WORDS * 4, "ranges");
  out.indirect = rt.buffer(CL_MEM_READ_WRITE, BOREAS_TREE_INDIRECT_WORDS * 4, "indirect");
  return out;
}

// A view that draws the trees of x < 26 m (the stand's first two columns) and culls the
// rest, so a call's records stay small however many trees there are.
boreas_tree_view_def near_columns() {
  boreas_tree_view_def view = boreas_default_tree_view_def();
  view.planes[0][0] = -1.0f;
  view.planes[0][3] = 26.0f;
  return view;
}

// The launches of one view call (the second: the first also builds what later calls keep),
// into buffers small enough for a world split by a small allocation limit (the call fills
// them up to their end; how much it writes does not change what it launches).
uint64_t launches_of_a_call(impl::World& world) {
  const impl::TreeBatch::RecordOutputs out = outputs(world, 1024, 8192, 64);
  world.enqueue_tree_records(near_columns(), out);
  world.runtime().queue().finish();
  const uint64_t before = world.runtime().traffic().launches;
  world.enqueue_tree_records(near_columns(), out);
  world.runtime().queue().finish();
  return world.runtime().traffic().launches - before;
}

// 100 and 1,000 trees, stepped, derived and settled, in both modes: the same launches, at
// most kMostLaunchesPerBatch for each of the two batches; an empty world, one.
TEST(TreeRecordsCost, LaunchesOfAViewCallDoNotGrowWithTheTreeCount) {
  Forest few = seen_stand(100, true), many = seen_stand(1000, true);
  ASSERT_GT(settled_branches(*few.world), 0) << "nothing settled: the test would prove less";
  ASSERT_GT(derived_branches(*few.world), 0);
  ASSERT_EQ(batches_with_trees(*few.world), 2u);
  ASSERT_EQ(batches_with_trees(*many.world), 2u);
  const uint64_t a = launches_of_a_call(*few.world), b = launches_of_a_call(*many.world);
  std::printf("launches of a view call: 100 trees %llu, 1,000 trees %llu (two batches)\n",
              (unsigned long long)a, (unsigned long long)b);
  EXPECT_EQ(a, b);
  EXPECT_LE(a, 2 * kMostLaunchesPerBatch);
  EXPECT_GE(a, 2 * 3u) << "at least offsets, branch and leaf records per batch";
  auto empty = make_world_with_wave(windy_wave());
  EXPECT_EQ(launches_of_a_call(*empty), 1u) << "the offsets, to zero the counts";
}

// A world split over chunks (the allocation forced small, about ten aspens' state a chunk):
// the launches are per chunk and mode that holds trees, at most kMostLaunchesPerBatch each,
// so they grow with the chunks (with the world's size over the device's largest buffer),
// not with the trees of a chunk.
TEST(TreeRecordsCost, LaunchesOfASplitWorldAreAFixedNumberPerChunk) {
  auto probe = make_world_with_wave(windy_wave());
  int64_t most_leaves = 0;
  const std::vector<boreas_tree_def> six = stand(6);
  for (const boreas_tree_def& d : six)
    most_leaves = std::max<int64_t>(most_leaves, int64_t(probe->tree_leaves(probe->add_tree(d)).size()));
  const uint64_t limit = uint64_t(most_leaves) * BOREAS_TREE_LEAF_OUT_PLANES * sizeof(float);
  Forest split = seen_stand(60, true, limit);
  const size_t chunks = batches_with_trees(*split.world);
  ASSERT_GT(chunks, 2u) << "not split: the test would prove nothing";
  const uint64_t launches = launches_of_a_call(*split.world);
  std::printf("launches of a view call: %llu over %zu chunk batches (limit %llu bytes)\n",
              (unsigned long long)launches, chunks, (unsigned long long)limit);
  EXPECT_LE(launches, chunks * kMostLaunchesPerBatch) << chunks << " chunks with trees";
  EXPECT_GE(launches, chunks * 3u);
}

// A call per frame over a forest where nothing changed (steps between, the same origin)
// walks no tree on the host: the readers' offsets and the posed tiles are kept. A tree
// added, or another output origin, builds them again.
TEST(TreeRecordsCost, ACallWithNothingChangedWalksNoTree) {
  Forest f = seen_stand(100, true);
  ASSERT_GT(settled_branches(*f.world), 0);
  const impl::TreeBatch::RecordOutputs out = outputs(*f.world, 4096, 65536, 64);
  const impl::Runtime::Traffic& t = f.world->runtime().traffic();
  f.world->enqueue_tree_records(near_columns(), out);
  const uint64_t first = t.table_rows_built;
  EXPECT_GT(first, 0u) << "the first call builds its tables";
  for (int s = 0; s < 3; ++s) {
    f.world->step(kDt);
    f.world->enqueue_tree_records(near_columns(), out);
    EXPECT_EQ(t.table_rows_built, first) << "frame " << s;
  }
  const double origin[3] = {10.0, 0.0, -5.0};
  f.world->set_output_origin(origin);
  f.world->enqueue_tree_records(near_columns(), out);
  const uint64_t moved = t.table_rows_built;
  EXPECT_GT(moved, first) << "another origin, the offsets anew";
  f.world->enqueue_tree_records(near_columns(), out);
  EXPECT_EQ(t.table_rows_built, moved);
  boreas_tree_def def = stand(1)[0];
  def.position[2] = -6.0f;
  f.world->add_tree(def);
  f.world->enqueue_tree_records(near_columns(), out);
  EXPECT_GT(t.table_rows_built, moved) << "a tree added, the tables anew";
  f.world->runtime().queue().finish();
}

// Every drawn tree's records from the one call equal its per-tree calls' bits, for a stand
// whose far trees' finest level is derived (settling off) or settled (on), after steps in
// the wind and again after the focus walked (some trees woken, others settled).
void expect_view_equals_per_tree(Forest& f, const char* what) {
  impl::World& w = *f.world;
  size_t branches = 0, leaves = 0;
  for (boreas_tree_id id : f.ids) {
    branches += w.tree_branches(id).size();
    leaves += w.tree_leaves(id).size();
  }
  const impl::TreeBatch::RecordOutputs out = outputs(w, branches, leaves, f.ids.size());
  w.enqueue_tree_records(boreas_default_tree_view_def(), out);
  std::vector<uint32_t> indirect(BOREAS_TREE_INDIRECT_WORDS);
  w.runtime().read(out.indirect, 0, indirect.size() * 4, indirect.data());
  ASSERT_EQ(indirect[BOREAS_TREE_INDIRECT_RANGES], f.ids.size()) << what;
  std::vector<int32_t> ranges(f.ids.size() * BOREAS_TREE_RANGE_WORDS);
  w.runtime().read(out.ranges, 0, ranges.size() * 4, ranges.data());
  std::vector<float> b(branches * BOREAS_BRANCH_RECORD_FLOATS), l(leaves * BOREAS_LEAF_RECORD_FLOATS);
  w.runtime().read(out.branches, 0, b.size() * 4, b.data());
  w.runtime().read(out.leaves, 0, l.size() * 4, l.data());
  int differing = 0;
  for (size_t r = 0; r < f.ids.size(); ++r) {
    const int32_t* rg = &ranges[r * BOREAS_TREE_RANGE_WORDS];
    const auto it = std::find_if(f.ids.begin(), f.ids.end(), [&](boreas_tree_id id) {
      return int32_t(id.index) == rg[BOREAS_TREE_RANGE_ID_INDEX];
    });
    ASSERT_NE(it, f.ids.end()) << what << ": range " << r;
    const size_t nb = size_t(rg[BOREAS_TREE_RANGE_BRANCH_COUNT]), nl = size_t(rg[BOREAS_TREE_RANGE_LEAF_COUNT]);
    ASSERT_EQ(nl, w.tree_leaves(*it).size()) << what << ": every leaf kept";
    const impl::TreeBatch::RecordOutputs one = outputs(w, nb, nl, 1);
    w.enqueue_branch_records(*it, one.branches, 0);
    w.enqueue_leaf_records(*it, one.leaves, 0);
    std::vector<float> ob(nb * BOREAS_BRANCH_RECORD_FLOATS), ol(nl * BOREAS_LEAF_RECORD_FLOATS);
    if (nb > 0) w.runtime().read(one.branches, 0, ob.size() * 4, ob.data());
    if (nl > 0) w.runtime().read(one.leaves, 0, ol.size() * 4, ol.data());
    const bool same_branches = std::memcmp(ob.data(), &b[size_t(rg[BOREAS_TREE_RANGE_BRANCH_FIRST]) * BOREAS_BRANCH_RECORD_FLOATS],
                                           ob.size() * 4) == 0;
    const bool same_leaves = std::memcmp(ol.data(), &l[size_t(rg[BOREAS_TREE_RANGE_LEAF_FIRST]) * BOREAS_LEAF_RECORD_FLOATS],
                                         ol.size() * 4) == 0;
    if (!same_branches || !same_leaves) ++differing;
    EXPECT_TRUE(same_branches) << what << ": branch records of tree " << it->index;
    EXPECT_TRUE(same_leaves) << what << ": leaf records of tree " << it->index;
  }
  EXPECT_EQ(differing, 0) << what;
}

TEST(TreeRecordsCost, SettledAndDerivedTreesRecordsAreThePerTreeCallsBits) {
  for (bool settling : {false, true}) {
    Forest f = seen_stand(24, settling);
    // Without settling, a far tree's finest level is derived once carried kSettleTime.
    if (!settling)
      for (int s = 0; s < int(impl::kSettleTime / double(kDt)) + 20; ++s) f.world->step(kDt);
    ASSERT_GT(derived_branches(*f.world), 0) << "nothing derived: the test would prove nothing";
    if (settling) ASSERT_GT(settled_branches(*f.world), 0) << "nothing settled";
    const char* what = settling ? "settled" : "derived";
    expect_view_equals_per_tree(f, what);
    for (int s = 0; s < 5; ++s) f.world->step(kDt);
    expect_view_equals_per_tree(f, what);
    // The focus walks into the stand: near trees wake, those behind settle.
    const float focus[3] = {50.0f, 1.8f, 3.0f};
    f.world->set_focus(focus, 1);
    for (int s = 0; s < 3; ++s) f.world->step(kDt);
    expect_view_equals_per_tree(f, what);
  }
}

}  // namespace
}  // namespace boreas
