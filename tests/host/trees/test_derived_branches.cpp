// boreas tests: derived branches (cl/shared/tree_state.h, boreas_tree_pose) — a settled
// tree's finest level is not stepped but derived by every reader from its parent's current
// pose; what each reader gets must be, bit for bit, what tree_step.cl's carry with hold 1
// would have written (TreeBatch::carry_derived_branches writes exactly that, in a twin world
// with the same history), through blocks moving and heals; and the forest stays
// deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "shared/tree_types.h"
#include "support/test_support.h"
#include "runtime/launch.h"
#include "shared/launch_tiles.h"
#include "trees/tree_batch.h"
#include "trees/tree_record_tiles.h"
#include "trees/tree_tiles.h"
#include "world.h"

namespace boreas {
namespace {

using test::bytes_of;
using test::make_world_with_wave;
using test::tree_bytes;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;
// Past the settle time: the reduced and far trees' finest levels are derived by then.
const int kSettleSteps = int(impl::kSettleTime / double(kDt)) + 20;

// Trees at distances from the focus (the origin) that make them full, reduced and far
// (tree_params' default distances), of distinct seeds (a template each), one in exact mode
// and one damped. Two are California black oaks, a reduced one and a far one: their finest
// level holds split pieces (tree_model.h's step tiers), derived along chains.
std::vector<boreas_tree_def> lod_defs() {
  const float distances[] = {10.0f, 40.0f, 50.0f, 60.0f, 70.0f, 110.0f, 130.0f};
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < 7; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    d.species = "quaking_aspen";
    d.seed = uint64_t(1 + i);
    d.position[0] = distances[i];
    d.position[2] = float(i);
    d.rotation = 0.37f * float(i);
    d.scale = 0.8f + 0.05f * float(i);
    defs.push_back(d);
  }
  defs[3].mode = BOREAS_TREE_EXACT;
  defs[4].response = BOREAS_TREE_DAMPED;
  defs[2].species = defs[5].species = "ca_black_oak";
  return defs;
}

struct Forest {
  std::unique_ptr<impl::World> world;
  std::vector<boreas_tree_id> ids;
};

Forest settled_forest(const std::vector<boreas_tree_def>& defs) {
  Forest f;
  f.world = make_world_with_wave(windy_wave());
  f.ids = f.world->add_trees(defs.data(), int(defs.size()));
  // First every tree up close (a focus point at each: all stepped, bent by the wind), then
  // from the origin: the finest levels of the farther ones are carried, their bend
  // decaying, then derived with what is left of it.
  std::vector<float> near;
  for (const boreas_tree_def& d : defs) near.insert(near.end(), {d.position[0], 1.8f, d.position[2]});
  f.world->set_focus(near.data(), int(defs.size()));
  for (int s = 0; s < 30; ++s) f.world->step(kDt);
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  f.world->set_focus(focus, 1);
  for (int s = 0; s < kSettleSteps; ++s) f.world->step(kDt);
  return f;
}

int64_t derived_branches(impl::World& world) {
  return world.tree_batch(BOREAS_TREE_LAGGED).branches_derived() +
         world.tree_batch(BOREAS_TREE_EXACT).branches_derived();
}

// Every derived branch written by the carry with hold 1, in both batches.
void carry_derived(impl::World& world) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
    world.tree_batch(mode).carry_derived_branches(world.wind().plants());
}

// Everything the readers make of a tree: getters (branches, leaves), the mesh, the branch
// and leaf records.
std::vector<unsigned char> read_everything(impl::World& world, boreas_tree_id id) {
  std::vector<unsigned char> out = tree_bytes(world, id);
  auto append = [&](const std::vector<unsigned char>& b) { out.insert(out.end(), b.begin(), b.end()); };
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
  world.tree_mesh(id, &vertices, &indices);
  append(bytes_of(vertices));
  const size_t branches = world.tree_branches(id).size(), leaves = world.tree_leaves(id).size();
  impl::Runtime& rt = world.runtime();
  std::vector<float> records(branches * BOREAS_TREE_RECORD_FLOATS + leaves * BOREAS_TREE_LEAF_OUT_PLANES);
  cl::Buffer out_buffer = rt.buffer(CL_MEM_READ_WRITE, records.size() * sizeof(float), "records");
  world.enqueue_branch_records(id, out_buffer, 0);
  rt.read(out_buffer, 0, branches * BOREAS_TREE_RECORD_FLOATS * sizeof(float), records.data());
  if (leaves > 0) {
    world.enqueue_leaf_records(id, out_buffer, 0);
    rt.read(out_buffer, 0, leaves * BOREAS_TREE_LEAF_OUT_PLANES * sizeof(float),
            records.data() + branches * BOREAS_TREE_RECORD_FLOATS);
  }
  append(bytes_of(records));
  return out;
}

// One view's records of every tree (boreas_world_enqueue_tree_records, the default view:
// every tree drawn whole): it poses the drawn trees' derived branches (cl/tree_derive.cl)
// through the out table. Returns the branch and leaf records written.
std::vector<float> view_records(impl::World& world, const std::vector<boreas_tree_id>& ids) {
  size_t branches = 0, leaves = 0;
  for (boreas_tree_id id : ids) {
    branches += world.tree_branches(id).size();
    leaves += world.tree_leaves(id).size();
  }
  impl::Runtime& rt = world.runtime();
  impl::TreeBatch::RecordOutputs out;
  out.branches = rt.buffer(CL_MEM_READ_WRITE, branches * BOREAS_BRANCH_RECORD_FLOATS * 4, "branches");
  out.leaves = rt.buffer(CL_MEM_READ_WRITE, leaves * BOREAS_LEAF_RECORD_FLOATS * 4, "leaves");
  out.impostors = rt.buffer(CL_MEM_READ_WRITE, ids.size() * BOREAS_TREE_IMPOSTOR_RECORD_FLOATS * 4, "impostors");
  out.ranges = rt.buffer(CL_MEM_READ_WRITE, ids.size() * BOREAS_TREE_RANGE_RECORD_INTS * 4, "ranges");
  out.indirect = rt.buffer(CL_MEM_READ_WRITE, BOREAS_TREE_INDIRECT_UINTS * 4, "indirect");
  world.enqueue_tree_records(boreas_default_tree_view_def(), out);
  std::vector<float> records((branches * BOREAS_BRANCH_RECORD_FLOATS + leaves * BOREAS_LEAF_RECORD_FLOATS));
  rt.read(out.branches, 0, branches * BOREAS_BRANCH_RECORD_FLOATS * 4, records.data());
  rt.read(out.leaves, 0, leaves * BOREAS_LEAF_RECORD_FLOATS * 4, records.data() + branches * BOREAS_BRANCH_RECORD_FLOATS);
  return records;
}

// Rays aimed at the middle of each finest-level branch of the trees, from 0.8 m beside it.
std::vector<boreas_ray> rays_at_finest(impl::World& world, const std::vector<boreas_tree_id>& ids) {
  std::vector<boreas_ray> rays;
  for (boreas_tree_id id : ids) {
    const std::vector<boreas_branch> branches = world.tree_branches(id);
    int finest = 0;
    for (const boreas_branch& b : branches) finest = std::max(finest, b.level);
    for (size_t k = 0; k < branches.size(); k += 7) {
      const boreas_branch& b = branches[k];
      if (b.level != finest) continue;
      boreas_ray r{};
      for (int a = 0; a < 3; ++a) {
        // The curve at 1/2: (P0 + 3 P1 + 3 P2 + P3) / 8.
        const float mid = (b.control_points[0][a] + 3.0f * b.control_points[1][a] +
                           3.0f * b.control_points[2][a] + b.control_points[3][a]) / 8.0f;
        r.origin[a] = mid + (a == 2 ? 0.8f : 0.0f);
        r.direction[a] = a == 2 ? -1.0f : 0.0f;
      }
      r.max_distance = 2.0f;
      rays.push_back(r);
    }
  }
  return rays;
}

TEST(DerivedBranches, ReadersGetWhatTheCarryWithHoldOneWrites) {
  const std::vector<boreas_tree_def> defs = lod_defs();
  Forest derived = settled_forest(defs), carried = settled_forest(defs);
  ASSERT_GT(derived_branches(*derived.world), 0) << "no branch is derived: the test would prove nothing";
  const std::vector<boreas_ray> rays = rays_at_finest(*derived.world, derived.ids);
  ASSERT_GT(rays.size(), 50u);
  // The twin's derived branches written as the carry writes them: nothing derived there.
  carry_derived(*carried.world);
  EXPECT_EQ(derived_branches(*carried.world), 0);
  // The one-call view first (the derived world's drawn branches posed through its out
  // table, then read by every per-tree reader below as they stand).
  EXPECT_TRUE(view_records(*derived.world, derived.ids) == view_records(*carried.world, carried.ids));
  for (size_t t = 0; t < defs.size(); ++t)
    EXPECT_TRUE(read_everything(*derived.world, derived.ids[t]) ==
                read_everything(*carried.world, carried.ids[t]))
        << "tree " << t;
  // Rays: each world's structure built at its first cast, from its own state (the host's
  // layout reads the getters' poses, the refit kernel the device's).
  std::vector<boreas_hit> a(rays.size()), b(rays.size());
  derived.world->cast_rays(rays.data(), int(rays.size()), a.data());
  carried.world->cast_rays(rays.data(), int(rays.size()), b.data());
  int hits = 0;
  for (const boreas_hit& h : a) hits += h.kind != BOREAS_HIT_NONE;
  EXPECT_GT(hits, int(rays.size()) / 2) << "the rays missed their branches";
  // The hits but their object ids (each world numbers its ids with generations of its own).
  for (size_t r = 0; r < rays.size(); ++r) {
    a[r].object = b[r].object = boreas_object_id{};
    EXPECT_EQ(std::memcmp(&a[r], &b[r], sizeof(boreas_hit)), 0)
        << "ray " << r << ": " << a[r].distance << " m, part " << a[r].part << " against "
        << b[r].distance << " m, part " << b[r].part;
  }
  // Readers pose the derived branches they read many times (cl/tree_derive.cl): the poses
  // must not outlive their state. Two more steps, then the same reads as in a third world
  // of the same history that nothing read before.
  Forest unread = settled_forest(defs);
  for (int s = 0; s < 2; ++s) {
    derived.world->step(kDt);
    unread.world->step(kDt);
  }
  for (size_t t = 0; t < defs.size(); ++t)
    EXPECT_TRUE(read_everything(*derived.world, derived.ids[t]) ==
                read_everything(*unread.world, unread.ids[t]))
        << "tree " << t << " two steps on";
}

TEST(DerivedBranches, OnlySettledFinestLevelsAreDerivedAndSteppedAgainUpClose) {
  auto world = make_world_with_wave(windy_wave());
  std::vector<boreas_tree_def> defs = lod_defs();
  defs.resize(3);  // full, reduced, reduced
  const std::vector<boreas_tree_id> ids = world->add_trees(defs.data(), 3);
  const float focus[3] = {0.0f, 1.8f, 0.0f};
  world->set_focus(focus, 1);
  world->step(kDt);
  impl::TreeBatch& batch = world->tree_batch(BOREAS_TREE_LAGGED);
  EXPECT_EQ(batch.branches_derived(), 0) << "derived before its bend settled";
  const boreas_step_stats first = world->step_stats();
  for (int s = 0; s < kSettleSteps; ++s) world->step(kDt);
  int64_t finest = 0;
  for (int t = 1; t < 3; ++t) {
    const impl::TreeModel& m = *world->tree(ids[size_t(t)]).model;
    finest += m.branch_count() - m.level_begin[size_t(m.levels - 1)];
  }
  EXPECT_EQ(batch.branches_derived(), finest);
  // Derived branches count as carried (not stepped) in the step's figures.
  EXPECT_EQ(world->step_stats().branches_stepped, first.branches_stepped);
  EXPECT_EQ(world->step_stats().branches_carried, first.branches_carried);
  // Up close every level is stepped again, from where it was drawn: no branch jumps.
  const std::vector<boreas_branch> before = world->tree_branches(ids[1]);
  const float near[3] = {defs[1].position[0], 1.8f, 0.0f};
  world->set_focus(near, 1);
  world->step(kDt);
  EXPECT_EQ(batch.branches_derived(), 0);
  const std::vector<boreas_branch> after = world->tree_branches(ids[1]);
  double moved = 0.0;
  for (size_t b = 0; b < before.size(); ++b)
    for (int a = 0; a < 3; ++a)
      moved = std::max(moved, double(std::abs(after[b].control_points[3][a] - before[b].control_points[3][a])));
  EXPECT_LT(moved, 0.02) << "a tip jumped when its level was stepped again (m)";
  for (const boreas_branch& b : after)
    for (int k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a) ASSERT_TRUE(std::isfinite(b.control_points[k][a]));
}

TEST(DerivedBranches, BlocksMovingAndHealsKeepWhatTheyRead) {
  // Two forests with one history; in one, the first trees are removed (their blocks and
  // templates packed away: the derived marks name entries, written again) and a kept tree
  // is healed in both: the kept trees must read the same bits in both.
  const std::vector<boreas_tree_def> defs = lod_defs();
  Forest moved = settled_forest(defs), still = settled_forest(defs);
  ASSERT_GT(derived_branches(*moved.world), 0);
  impl::TreeBatch& batch = moved.world->tree_batch(BOREAS_TREE_LAGGED);
  const uint64_t kept_key = moved.world->tree(moved.ids[6]).key;
  const int32_t where = batch.branch_index(kept_key, 0);
  for (size_t t = 0; t < 5; ++t)
    if (t != 3) moved.world->remove_tree(moved.ids[t]);  // 3 is in the exact batch
  ASSERT_NE(batch.branch_index(kept_key, 0), where) << "no block moved: the test would prove nothing";
  for (size_t t : {5u, 6u, 3u})
    EXPECT_TRUE(read_everything(*moved.world, moved.ids[t]) == read_everything(*still.world, still.ids[t]))
        << "tree " << t;
  moved.world->heal_tree(moved.ids[6]);
  still.world->heal_tree(still.ids[6]);
  for (int s = 0; s < 3; ++s) {
    moved.world->step(kDt);
    still.world->step(kDt);
  }
  for (size_t t : {5u, 6u, 3u})
    EXPECT_TRUE(read_everything(*moved.world, moved.ids[t]) == read_everything(*still.world, still.ids[t]))
        << "tree " << t << " after a heal and steps";
}

// The deformer and leaf records derive lane by lane at the CPU's SIMD width and one branch a
// work-item on GPUs (boreas_tree_gather_pose) where nothing posed the branches first: every
// width reads a settled forest alike, bit for bit, posed (cl/tree_derive.cl) or not.
TEST(DerivedBranches, EverySimdWidthReadsTheSameDerivedBranches) {
  const std::vector<boreas_tree_def> defs = lod_defs();
  auto run = [&](int width, bool posing) {
    test::ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    Forest f = settled_forest(defs);
    EXPECT_EQ(f.world->runtime().simd_width(), width);
    EXPECT_GT(derived_branches(*f.world), 0);
    for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
      f.world->tree_batch(mode).set_posing(posing);
    std::vector<unsigned char> all;
    for (boreas_tree_id id : f.ids) {
      const std::vector<unsigned char> b = read_everything(*f.world, id);
      all.insert(all.end(), b.begin(), b.end());
    }
    return all;
  };
  const std::vector<unsigned char> scalar = run(1, false);
  EXPECT_TRUE(run(16, false) == scalar) << "lane by lane";
  EXPECT_TRUE(run(16, true) == scalar) << "posed";
}

// The settled space (tree_types.h, BOREAS_TREE_SETTLED_*): a reader's entry index past the
// own planes' stride is a settled entry, derived from its inputs held there. Each reader's
// settled form against its marked form, bit for bit: the branch records (one branch a
// work-item, boreas_tree_pose) and the deformer (at the device's width, gathered lane by
// lane: boreas_tree_gather_pose) over each derived range, read once from the own entries
// and once from their copies in the settled space.
struct SettledReads {
  std::vector<float> records, vertices;
};

SettledReads read_ranges(impl::World& world, impl::TreeBatch& batch,
                         const std::vector<impl::TreeBatch::SettledRange>& ranges, bool settled) {
  impl::Runtime& rt = world.runtime();
  const int n = batch.stride(), group = int(rt.group_size()), width = rt.simd_width();
  constexpr int kRings = 3, kSides = 5;
  std::vector<int32_t> tiles;
  std::vector<impl::DeformRange> deform;
  int records = 0, vertices = 0;
  for (const impl::TreeBatch::SettledRange& r : ranges) {
    const int first = settled ? n + r.settled_first : r.own_first;
    for (int at = 0; at < r.count; at += group) {
      int32_t tile[BOREAS_TILE_INTS] = {};
      tile[BOREAS_TILE_FIRST] = first + at;
      tile[BOREAS_TILE_COUNT] = std::min(group, r.count - at);
      tile[BOREAS_TILE_STATIC] = r.static_first + at;
      tile[BOREAS_TILE_ROOT] = first - 1 - records;  // record i - ROOT - 1: the k-th read
      std::memcpy(&tile[BOREAS_TILE_SCALE], &r.scale, sizeof(float));
      tiles.insert(tiles.end(), tile, tile + BOREAS_TILE_INTS);
    }
    impl::DeformRange d;
    d.first = first;
    d.static_first = r.static_first;
    d.count = r.count;
    d.rings = kRings;
    d.sides = kSides;
    d.scale = r.scale;
    d.out_first = vertices;
    deform.push_back(d);
    records += r.count;
    vertices += r.count * (kRings + 1) * (kSides + 1);
  }
  auto upload = [&](const std::vector<int32_t>& ints) {
    cl::Buffer b = rt.buffer(CL_MEM_READ_ONLY, ints.size() * sizeof(int32_t), "test tiles");
    rt.write(b, 0, ints.size() * sizeof(int32_t), ints.data());
    return b;
  };
  SettledReads out;
  out.records.resize(size_t(records) * BOREAS_TREE_RECORD_FLOATS);
  cl::Buffer record_buffer = rt.buffer(CL_MEM_READ_WRITE, out.records.size() * sizeof(float), "records");
  cl::Buffer record_tiles = upload(tiles);
  // The tiles' object is 0: its row of the readers' offsets (cl/shared/tree_origin.h) zero,
  // so the records are relative to their trees' bases as the state is.
  const std::vector<float> zeros(BOREAS_TREE_OFFSET_FLOATS, 0.0f);
  cl::Buffer zero_offsets = rt.buffer(CL_MEM_READ_ONLY, zeros.size() * sizeof(float), "offsets");
  rt.write(zero_offsets, 0, zeros.size() * sizeof(float), zeros.data());
  impl::launch(rt, rt.kernel("export_records.cl", "boreas_export_branch_records"),
               impl::Items(tiles.size() / BOREAS_TILE_INTS * size_t(group)), batch.state_buffer(),
               batch.motion_buffer(), n, batch.shape_buffer(), batch.radius_buffer(),
               batch.static_stride(), batch.settled_buffer(), batch.settled_stride(),
               batch.settled_buffer(), 0, record_tiles, 0, record_tiles, 1, record_buffer, 0,
               zero_offsets);
  rt.read(record_buffer, 0, out.records.size() * sizeof(float), out.records.data());
  const std::vector<int32_t> deform_ints = impl::deform_tiles(deform, group);
  out.vertices.resize(size_t(vertices) * BOREAS_TREE_VERTEX_PLANES);
  cl::Buffer vertex_buffer = rt.buffer(CL_MEM_READ_WRITE, out.vertices.size() * sizeof(float), "vertices");
  cl::Buffer deform_tiles = upload(deform_ints);
  impl::launch(rt, rt.kernel("tree_deform.cl", "boreas_tree_deform"),
               impl::Items(deform_ints.size() / BOREAS_TILE_INTS * size_t(group)).per_work_item(size_t(width)),
               batch.state_buffer(), batch.motion_buffer(), n, batch.shape_buffer(),
               batch.radius_buffer(), batch.static_stride(), batch.settled_buffer(),
               batch.settled_stride(), batch.settled_buffer(), 0, deform_tiles, 0, vertex_buffer,
               vertices, 0);
  rt.read(vertex_buffer, 0, out.vertices.size() * sizeof(float), out.vertices.data());
  return out;
}

TEST(DerivedBranches, ReadersGetTheSameBitsFromTheSettledSpace) {
  Forest f = settled_forest(lod_defs());
  impl::World& world = *f.world;
  int ranges_read = 0;
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT}) {
    impl::TreeBatch& batch = world.tree_batch(mode);
    if (batch.branches_derived() == 0) continue;
    const std::vector<impl::TreeBatch::SettledRange> ranges = batch.copy_derived_to_settled();
    ASSERT_GT(batch.settled_stride(), 0);
    ranges_read += int(ranges.size());
    const SettledReads own = read_ranges(world, batch, ranges, false);
    const SettledReads settled = read_ranges(world, batch, ranges, true);
    EXPECT_TRUE(own.records == settled.records) << "branch records, mode " << int(mode);
    EXPECT_TRUE(own.vertices == settled.vertices) << "deformer, mode " << int(mode);
    // They were read from the settled planes: a settled F changed changes what is read.
    const float bent = 0.25f;
    world.runtime().write(batch.settled_buffer(),
                          (size_t(BOREAS_TREE_SETTLED_F) * size_t(batch.settled_stride()) +
                           size_t(ranges[0].settled_first)) * sizeof(float),
                          sizeof(float), &bent);
    const SettledReads moved = read_ranges(world, batch, ranges, true);
    EXPECT_FALSE(std::equal(own.records.begin(), own.records.begin() + BOREAS_TREE_RECORD_FLOATS,
                            moved.records.begin()))
        << "the settled planes were not read, mode " << int(mode);
    EXPECT_TRUE(std::equal(own.records.begin() + BOREAS_TREE_RECORD_FLOATS, own.records.end(),
                           moved.records.begin() + BOREAS_TREE_RECORD_FLOATS));
  }
  EXPECT_GT(ranges_read, 1) << "no derived range: the test would prove nothing";
}

// Every reader of a tree (getters, mesh, records, the view's records, rays' refit) over a
// settled space: what it reads from the settled copies of the derived ranges is what the
// carry with hold 1 writes (a twin world's, as above); the next step lets the copies go
// and reads the own planes again.
TEST(DerivedBranches, ReadersOfTheSettledSpaceGetWhatTheCarryWithHoldOneWrites) {
  const std::vector<boreas_tree_def> defs = lod_defs();
  Forest settled = settled_forest(defs), carried = settled_forest(defs);
  const std::vector<boreas_ray> rays = rays_at_finest(*settled.world, settled.ids);
  int64_t copied = 0;
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
    for (const auto& r : settled.world->tree_batch(mode).copy_derived_to_settled()) copied += r.count;
  ASSERT_EQ(copied, derived_branches(*settled.world));
  ASSERT_GT(copied, 0) << "no branch is settled: the test would prove nothing";
  carry_derived(*carried.world);
  EXPECT_TRUE(view_records(*settled.world, settled.ids) == view_records(*carried.world, carried.ids));
  for (size_t t = 0; t < defs.size(); ++t)
    EXPECT_TRUE(read_everything(*settled.world, settled.ids[t]) ==
                read_everything(*carried.world, carried.ids[t]))
        << "tree " << t;
  std::vector<boreas_hit> a(rays.size()), b(rays.size());
  settled.world->cast_rays(rays.data(), int(rays.size()), a.data());
  carried.world->cast_rays(rays.data(), int(rays.size()), b.data());
  for (size_t r = 0; r < rays.size(); ++r) {
    a[r].object = b[r].object = boreas_object_id{};
    EXPECT_EQ(std::memcmp(&a[r], &b[r], sizeof(boreas_hit)), 0) << "ray " << r;
  }
  // They read the settled planes: a settled F bent there shows in the view's records.
  impl::TreeBatch& lagged = settled.world->tree_batch(BOREAS_TREE_LAGGED);
  const float bent = 0.25f;
  settled.world->runtime().write(lagged.settled_buffer(),
                                 (size_t(BOREAS_TREE_SETTLED_F) * size_t(lagged.settled_stride()) + 1) * sizeof(float),
                                 sizeof(float), &bent);
  EXPECT_FALSE(view_records(*settled.world, settled.ids) == view_records(*carried.world, carried.ids));
  Forest unread = settled_forest(defs);
  for (int s = 0; s < 2; ++s) {
    settled.world->step(kDt);
    unread.world->step(kDt);
  }
  // The copies are gone: what the space holds now is the derived levels settled by the
  // steps (tree_batch.h, set_settling), as in the world nothing read.
  EXPECT_EQ(settled.world->tree_batch(BOREAS_TREE_LAGGED).branches_settled(),
            unread.world->tree_batch(BOREAS_TREE_LAGGED).branches_settled());
  for (size_t t = 0; t < defs.size(); ++t)
    EXPECT_TRUE(read_everything(*settled.world, settled.ids[t]) ==
                read_everything(*unread.world, unread.ids[t]))
        << "tree " << t << " two steps on";
}

TEST(DerivedBranches, SameInputsGiveTheSameStateHash) {
  const std::vector<boreas_tree_def> defs = lod_defs();
  Forest a = settled_forest(defs), b = settled_forest(defs);
  ASSERT_GT(derived_branches(*a.world), 0);
  EXPECT_EQ(a.world->state_hash(), b.world->state_hash());
  // And after further steps, as trees keep being derived.
  for (int s = 0; s < 30; ++s) {
    a.world->step(kDt);
    b.world->step(kDt);
  }
  EXPECT_EQ(a.world->state_hash(), b.world->state_hash());
}

}  // namespace
}  // namespace boreas
