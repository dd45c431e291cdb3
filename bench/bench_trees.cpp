// boreas benchmarks: the tree rows (boreas_tree_step in both stepping modes,
// boreas_tree_deform, boreas_tree_leaves) on batches of generated trees, each kernel beside
// its native twin.
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "native_trees.h"
#include "runtime/launch.h"
#include "runtime/launch_tiles.h"
#include "shared/tree_records.h"
#include "shared/tree_types.h"
#include "trees/species.h"
#include "trees/tree_batch.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "trees/tree_record_tiles.h"

namespace boreas::bench {

namespace {

// ---- trees (boreas_tree_step, boreas_tree_deform, boreas_tree_leaves) ----

// Compulsory traffic per item; the gathers of the parent's state (15 floats, shared by
// siblings, so mostly cached) are left out.
constexpr double kBytesPerBranchStep = 208.0;  // in: parent index 4, shape 64, response 32,
                                               // motion 24; out: state 60, motion 24
constexpr double kBytesPerVertex = 32.0;       // out: position, normal, uv
constexpr double kBytesPerLeaf = 44.0;         // in: packed placement 8; out: record 36

// Branches per batch (both stepping modes). The deformer runs on the first two (2^20
// branches would make 33 M vertices, 1 GiB of output), the leaves row on the first only (its
// ~1.2 M leaves; the next has ~4.8 M), so the larger batches are built without leaves.
constexpr int kTreeBranchCounts[] = {1 << 16, 1 << 18, 1 << 20, 1 << 22};
constexpr int kTreeDeformBatchMax = 1 << 18;
constexpr int kTreeLeafBatch = 1 << 16;
// A batch's first `count` state entries (its trees' states, relative to their bases:
// cl/shared/tree_origin.h) in world coordinates, as the twin keeps them: each tree's base
// added to its control points (a float add, what the record kernels do).
std::vector<float> world_state_prefix(impl::TreeBatch& batch, const NativeTrees& twin,
                                      const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  const size_t n = size_t(twin.n);
  std::vector<float> state = batch.read_state_prefix(twin.n);
  for (size_t k = 0; k < trees.size(); ++k) {
    const size_t first = size_t(twin.tree_first[k]);
    const size_t end = k + 1 < trees.size() ? size_t(twin.tree_first[k + 1]) : n;
    for (int p = BOREAS_TREE_STATE_P0; p < BOREAS_TREE_STATE_O; ++p) {
      const float at = float(trees[k]->params.position[size_t(p % 3)]);
      for (size_t i = first; i < end; ++i) state[size_t(p) * n + i] += at;
    }
  }
  return state;
}

std::vector<NativeTreeSource> native_sources(
    const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  std::vector<NativeTreeSource> sources;
  for (const auto& t : trees) sources.push_back({&t->params, t->model.get()});
  return sources;
}

// The mesh of a batch as the deformer rows make it: every tree's levels at the levels'
// rings x sides, each (tree, level) a range of one launch over them all (as TreeBatch::mesh
// launches one tree's), into one plane block of `vertices` vertices.
struct DeformLaunch {
  int first = 0, count = 0, rings = 0, sides = 0, vertex_first = 0;
  float scale = 1.0f;
};
struct DeformLayout {
  std::vector<DeformLaunch> launches;
  int vertices = 0;
};

DeformLayout deform_layout(const NativeTrees& t,
                           const std::vector<std::shared_ptr<impl::TreeInstance>>& trees) {
  DeformLayout d;
  for (size_t k = 0; k < trees.size(); ++k) {
    const impl::TreeModel& m = *trees[k]->model;
    for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
      DeformLaunch launch;
      launch.count = m.level_begin[l + 1] - m.level_begin[l];
      if (launch.count <= 0) continue;
      launch.first = t.tree_first[k] + impl::block_index(m.level_begin[l]);
      launch.scale = float(trees[k]->params.scale);
      launch.rings = trees[k]->params.levels[l].rings;
      launch.sides = trees[k]->params.levels[l].sides;
      launch.vertex_first = d.vertices;
      d.vertices += launch.count * (launch.rings + 1) * (launch.sides + 1);
      d.launches.push_back(launch);
    }
  }
  return d;
}

// Everything the tree rows of one batch size share; made by the first of them, kept for
// the others (the fixture slot holds it under one name). The CL side is made by the
// first CL row.
struct TreeFixture : Fixture {
  TreeWindScene wind;
  std::vector<std::shared_ptr<impl::TreeInstance>> trees;  // with their leaves
  NativeTrees native;                                      // what the native rows step
  DeformLayout mesh;
  std::vector<float> native_vertices, native_leaves;
  // CL
  cl::Buffer waves, grid;
  // lagged, exact; then the same on a runtime built at SIMD width 1 (the "before" rows)
  std::unique_ptr<impl::TreeBatch> batch[4];
  std::string step_error[4];
  cl::Buffer waves_w1, grid_w1;
  cl::Buffer vertices, radius, leaves, leaf_out;
  cl::Buffer deform_tiles, leaf_tiles, leaf_table;  // one launch's tiles (and out table)
  cl::Buffer leaf_offsets;  // zero offsets (cl/shared/tree_origin.h): records relative to bases
  size_t deform_tile_count = 0, leaf_tile_count = 0;
  bool deform_checked = false, leaves_checked = false;
  std::string deform_error, leaves_error;

  impl::PlantWind cl_wind(bool width_one = false) const {
    return width_one ? wind.cl(waves_w1, grid_w1) : wind.cl(waves, grid);
  }
};

TreeFixture& tree_fixture(int branches) {
  return fixture<TreeFixture>("trees/" + std::to_string(branches), [&] {
    auto f = std::make_unique<TreeFixture>();
    f->trees = bench_trees(branches, f->wind.def);
    // No row reads their leaves: the twin's layout leaves them out (the batches do too).
    if (branches != kTreeLeafBatch) f->trees = leafless_trees(f->trees);
    f->native = native_tree_layout(native_sources(f->trees));
    f->mesh = deform_layout(f->native, f->trees);
    f->native_vertices.assign(size_t(BOREAS_TREE_VERTEX_PLANES) * f->mesh.vertices, 0.0f);
    f->native_leaves.assign(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * f->native.leaf_n, 0.0f);
    return f;
  });
}

// The CL batch of a mode, checked once against the native twin: the layout (the batch's
// rest state against native_tree_layout's) and one step from rest.
void make_tree_batch(impl::Runtime& rt, TreeFixture& f, bool exact, bool width_one = false) {
  const int m = (exact ? 1 : 0) + (width_one ? 2 : 0);
  if (f.batch[m]) return;
  cl::Buffer& waves = width_one ? f.waves_w1 : f.waves;
  cl::Buffer& grid = width_one ? f.grid_w1 : f.grid;
  if (!waves()) {
    waves = upload(rt, CL_MEM_READ_ONLY, f.wind.device.padded.data(),
                   f.wind.device.padded.size() * sizeof(BoreasGpuWave));
    grid = upload(rt, CL_MEM_READ_ONLY, f.wind.cells.data(), f.wind.cells.size() * sizeof(float));
  }
  auto batch = leafless_batch(rt, exact ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED, f.trees);
  NativeTrees twin = native_tree_layout(native_sources(leafless_trees(f.trees)));
  std::string layout = disagreement(
      "rest states", max_difference(world_state_prefix(*batch, twin, f.trees), twin.state[0]), "m");
  batch->enqueue_step(kStepSeconds, f.cl_wind(width_one), impl::StepColliders{});
  BOREAS_CL_CHECK(rt.queue().finish());
  batch->commit();
  native_trees_step(twin, exact, kStepSeconds, f.wind.native());
  std::string step =
      disagreement("tree steps",
                   max_difference(world_state_prefix(*batch, twin, f.trees), twin.state[twin.current]), "m");
  f.step_error[m] = !layout.empty() ? layout : step;
  f.batch[m] = std::move(batch);
}

std::string tree_step_key(int branches, bool exact) {
  return std::to_string(branches) + (exact ? "/exact" : "/lagged");
}

// `count` walkers (capsules 0.25 m in radius, 1.8 m tall, at 1.4 m/s) each pressed 0.3 m
// from the base of a tree spread over the fixture's (so each touches one tree), as
// World::step_colliders lists them for a step.
impl::StepColliders walkers(const TreeFixture& f, int count) {
  impl::StepColliders out;
  out.dt = kStepSeconds;
  for (int k = 0; k < count && !f.trees.empty(); ++k) {
    const auto& at = f.trees[size_t(k) * f.trees.size() / size_t(count)]->params.position;
    impl::Collider c;
    c.def = boreas_default_collider_def();
    c.def.shape = BOREAS_COLLIDER_CAPSULE;
    c.def.radius = 0.25f;
    c.def.half_height = 0.65f;
    c.def.pose.position[0] = float(at[0] + 0.3);
    c.def.pose.position[1] = float(at[1] + 0.9);
    c.def.pose.position[2] = float(at[2]);
    c.def.velocity[2] = 1.4f;
    out.add(c);
  }
  return out;
}

// width_one: on a runtime whose kernels are built at SIMD width 1 (before issue 22).
// colliders: walkers (above) among the trees, each touching one.
void tree_step_cl(benchmark::State& state, int branches, bool exact, bool width_one = false,
                  int colliders_count = 0) {
  impl::Runtime* rt = width_one ? width_one_runtime_or_skip(state) : runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, exact, width_one);
  const int m = (exact ? 1 : 0) + (width_one ? 2 : 0);
  if (skipped_for(state, f.step_error[m])) return;
  impl::TreeBatch& batch = *f.batch[m];
  const impl::PlantWind wind = f.cl_wind(width_one);
  const impl::StepColliders colliders = walkers(f, colliders_count);
  cl::CommandQueue& q = rt->queue();
  // As World::step runs it (enqueue_step, finish, commit), timed by the library's own
  // launch events: from the first launch's start to the last one's end (markers would
  // measure the queue's wait on some drivers).
  auto launch = [&] {
    impl::TreeStepEvents events;
    batch.enqueue_step(kStepSeconds, wind, colliders, &events);
    batch.commit();
    ClSpan span;
    span.first = events.branches.front();
    span.last = events.branches.back();
    return span;
  };
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(q.finish());
  time_cl_span(state, *rt, "BM_TreeStep", branches, kBytesPerBranchStep,
               tree_step_key(branches, exact) +
                   (colliders_count > 0 ? "/colliders" + std::to_string(colliders_count) : ""),
               launch);
}

void tree_step_native(benchmark::State& state, int branches, bool exact) {
  TreeFixture& f = tree_fixture(branches);
  const NativeTreeWind wind = f.wind.native();
  auto run = [&] { native_trees_step(f.native, exact, kStepSeconds, wind); };
  run();
  time_native(state, "BM_TreeStep", branches, kBytesPerBranchStep, run,
              tree_step_key(branches, exact));
}

// The deformer over a batch's state (the lagged batch's, as stepped by its rows), one
// launch per (tree, level) as TreeBatch::mesh makes them.
// The launches are many and small (a tree's level each): the threads share them out, and
// each twin runs on its thread alone (OpenMP does not nest by default).
void deform_native_all(TreeFixture& f, const float* state, float* out) {
  const NativeTrees& t = f.native;
  const std::vector<DeformLaunch>& launches = f.mesh.launches;
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t k = 0; k < launches.size(); ++k) {
    const DeformLaunch& d = launches[k];
    // Each tree's template block sits at its own entries in the twin's layout.
    native_tree_deform(state, t.n, t.radius.data(), t.n, d.first, d.first, d.count, d.scale,
                       d.rings, d.sides, out, f.mesh.vertices, d.vertex_first);
  }
}

void deform_cl(benchmark::State& state, int branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, false);
  if (skipped_for(state, f.step_error[0])) return;
  impl::TreeBatch& batch = *f.batch[0];
  cl::Kernel& kernel = rt->kernel("tree_deform.cl", "boreas_tree_deform");
  // The twin's template planes (one block per tree, at its entries): the batch keeps its
  // own private, and the deformer reads only the radius functions.
  if (!f.deform_checked)
    f.radius = upload(*rt, CL_MEM_READ_ONLY, f.native.radius.data(),
                      f.native.radius.size() * sizeof(float));
  if (!f.deform_checked) {
    // Each tree's template block sits at its own entries in the twin's layout.
    std::vector<impl::DeformRange> ranges;
    for (const DeformLaunch& d : f.mesh.launches) {
      impl::DeformRange r;
      r.first = r.static_first = d.first;
      r.count = d.count;
      r.rings = d.rings;
      r.sides = d.sides;
      r.scale = d.scale;
      r.out_first = d.vertex_first;
      ranges.push_back(r);
    }
    const std::vector<int32_t> tiles = impl::deform_tiles(ranges, int(rt->group_size()));
    f.deform_tile_count = tiles.size() / BOREAS_TILE_INTS;
    f.deform_tiles = upload(*rt, CL_MEM_READ_ONLY, tiles.data(), tiles.size() * sizeof(int32_t));
  }
  // One launch over every (tree, level); rt->simd_width() vertices per work-item, as
  // TreeBatch::mesh launches it.
  auto launch = [&] {
    ClSpan span;
    span.first = span.last = impl::launch(
        *rt, kernel,
        impl::Items(f.deform_tile_count * rt->group_size()).per_work_item(size_t(rt->simd_width())),
        // No branch of this batch is derived (it has no focus): the shape (given the radius
        // planes, of the same stride) is never read, nor a settled space or posed planes
        // (none: stride 0).
        batch.state_buffer(), batch.motion_buffer(), batch.stride(), f.radius, f.radius,
        f.native.n, f.radius, 0, f.radius, 0, f.deform_tiles, 0, f.vertices,
        f.mesh.vertices, 0);
    return span;
  };
  if (!f.deform_checked) {
    f.vertices = rt->buffer(CL_MEM_READ_WRITE,
                            size_t(BOREAS_TREE_VERTEX_PLANES) * f.mesh.vertices * sizeof(float));
    launch();
    std::vector<float> got(size_t(BOREAS_TREE_VERTEX_PLANES) * f.mesh.vertices);
    BOREAS_CL_CHECK(rt->queue().enqueueReadBuffer(f.vertices, CL_TRUE, 0,
                                                  got.size() * sizeof(float), got.data()));
    std::vector<float> want(got.size());
    std::vector<float> state_planes = batch.read_state_prefix(f.native.n);
    deform_native_all(f, state_planes.data(), want.data());
    f.deform_error = disagreement("deformed vertices", max_difference(got, want), "(m or unit)");
    f.deform_checked = true;
  }
  if (skipped_for(state, f.deform_error)) return;
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(rt->queue().finish());
  time_cl_span(state, *rt, "BM_Deform", f.mesh.vertices, kBytesPerVertex, std::to_string(branches),
               launch);
}

void deform_native(benchmark::State& state, int branches) {
  TreeFixture& f = tree_fixture(branches);
  const float* planes = f.native.state[f.native.current].data();
  auto run = [&] { deform_native_all(f, planes, f.native_vertices.data()); };
  run();
  time_native(state, "BM_Deform", f.mesh.vertices, kBytesPerVertex, run, std::to_string(branches));
}

// The leaves of every tree, made as a renderer asks for them: one launch per tree into one
// records buffer (TreeBatch::enqueue_leaf_records), each tree's template block at the
// tree's own entries in the twin's layout.
void leaves_cl(benchmark::State& state, int branches) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  TreeFixture& f = tree_fixture(branches);
  make_tree_batch(*rt, f, false);
  if (skipped_for(state, f.step_error[0])) return;
  impl::TreeBatch& batch = *f.batch[0];
  const NativeTrees& t = f.native;
  cl::Kernel& kernel = rt->kernel("tree_leaves.cl", "boreas_tree_leaves");
  if (!f.leaves_checked) {
    f.leaves =
        upload(*rt, CL_MEM_READ_ONLY, t.leaves.data(), t.leaves.size() * sizeof(int32_t));
    f.leaf_out = rt->buffer(CL_MEM_READ_WRITE,
                            size_t(BOREAS_TREE_LEAF_OUT_PLANES) * t.leaf_n * sizeof(float));
  }
  if (!f.leaves_checked) {
    // Every tree's leaves as tiles of one list, each tree's records at its leaves' place in
    // the twin's layout (its row of the out table, all leaves kept).
    impl::TileLists tiles(1);
    std::vector<int32_t> table(size_t(t.tree_count + 1) * BOREAS_TREE_OUT_INTS, 0);
    const float one = 1.0f;
    for (int k = 0; k < t.tree_count; ++k) {
      const int first = t.tree_leaf_first[size_t(k)];
      const int count =
          (k + 1 < t.tree_count ? t.tree_leaf_first[size_t(k) + 1] : t.leaf_n) - first;
      impl::TileShared shared;
      shared.static_first = first;
      shared.root = t.tree_first[size_t(k)];
      shared.scale = t.tree_scale[size_t(k)];
      shared.value = t.tree_leaf_petiole[size_t(k)];
      shared.object = k + 1;
      tiles.add(0, 0, count, int(rt->group_size() * rt->simd_width()), shared);
      int32_t* row = &table[size_t(k + 1) * BOREAS_TREE_OUT_INTS];
      row[BOREAS_TREE_OUT_KIND] = BOREAS_TREE_KIND_DRAWN;
      row[BOREAS_TREE_OUT_KEPT] = row[BOREAS_TREE_OUT_LEAVES] = count;
      row[BOREAS_TREE_OUT_LEAF_FIRST] = first;
      row[BOREAS_TREE_OUT_INVERSE] = 1;
      std::memcpy(&row[BOREAS_TREE_OUT_FACTOR], &one, sizeof one);
    }
    f.leaf_tile_count = tiles.size(0);
    f.leaf_tiles = upload(*rt, CL_MEM_READ_ONLY, tiles.list(0).data(),
                          tiles.list(0).size() * sizeof(int32_t));
    f.leaf_table = upload(*rt, CL_MEM_READ_ONLY, table.data(), table.size() * sizeof(int32_t));
    const std::vector<float> offsets(size_t(t.tree_count + 1) * BOREAS_TREE_OFFSET_FLOATS, 0.0f);
    f.leaf_offsets = upload(*rt, CL_MEM_READ_ONLY, offsets.data(), offsets.size() * sizeof(float));
  }
  // One launch over every tree's leaves: a group's work-items per tile, rt->simd_width()
  // leaves each, as TreeBatch launches its leaf records.
  auto launch = [&] {
    ClSpan span;
    span.first = span.last = impl::launch(
        *rt, kernel, impl::Items(f.leaf_tile_count * rt->group_size()),
        // No branch of this batch is derived (it has no focus): the shape (given the leaves'
        // planes) is never read, nor a settled space or posed planes (none: stride 0).
        batch.state_buffer(), batch.motion_buffer(), batch.stride(), f.leaves, t.leaf_n,
        f.leaves, 0, f.leaves, 0, f.leaves, t.leaf_n, f.leaf_tiles,
        0, f.leaf_table, 0, f.leaf_out, 0, f.leaf_offsets);
    return span;
  };
  if (!f.leaves_checked) {
    launch();
    std::vector<float> got(size_t(BOREAS_TREE_LEAF_OUT_PLANES) * t.leaf_n, 0.0f);
    rt->read(f.leaf_out, 0, got.size() * sizeof(float), got.data());
    std::vector<float> want(got.size(), 0.0f);
    std::vector<float> state_planes = batch.read_state_prefix(t.n);
    for (int k = 0; k < t.tree_count; ++k) {
      const int first = t.tree_leaf_first[size_t(k)];
      const int count =
          (k + 1 < t.tree_count ? t.tree_leaf_first[size_t(k) + 1] : t.leaf_n) - first;
      native_tree_leaves(state_planes.data(), t.n, t.leaves.data(), t.leaf_n, first, count,
                         t.tree_first[size_t(k)], t.tree_leaf_petiole[size_t(k)], want.data(),
                         first);
    }
    // Record 0 (the layout's sink leaf) is no tree's.
    std::fill_n(got.begin(), BOREAS_TREE_LEAF_OUT_PLANES, 0.0f);
    f.leaves_error = disagreement("leaves", max_difference(got, want), "(m or unit)");
    f.leaves_checked = true;
  }
  if (skipped_for(state, f.leaves_error)) return;
  for (int i = 0; i < 3; ++i) launch();
  BOREAS_CL_CHECK(rt->queue().finish());
  time_cl_span(state, *rt, "BM_TreeLeaves", t.leaf_count, kBytesPerLeaf, std::to_string(branches),
               launch);
}

void leaves_native(benchmark::State& state, int branches) {
  TreeFixture& f = tree_fixture(branches);
  const NativeTrees& t = f.native;
  const float* planes = t.state[t.current].data();
  auto run = [&] {
    for (int k = 0; k < t.tree_count; ++k) {
      const int first = t.tree_leaf_first[size_t(k)];
      const int count =
          (k + 1 < t.tree_count ? t.tree_leaf_first[size_t(k) + 1] : t.leaf_n) - first;
      native_tree_leaves(planes, t.n, t.leaves.data(), t.leaf_n, first, count,
                         t.tree_first[size_t(k)], t.tree_leaf_petiole[size_t(k)],
                         f.native_leaves.data(), first);
    }
  };
  run();
  time_native(state, "BM_TreeLeaves", t.leaf_count, kBytesPerLeaf, run, std::to_string(branches));
}

}  // namespace

void register_trees_benchmarks() {
  for (int n : kTreeBranchCounts) {
    const std::string branches = std::to_string(n);
    for (bool exact : {false, true}) {
      const std::string mode = exact ? "/exact" : "/lagged";
      add("BM_TreeStep/native/" + branches + mode, [=](auto& s) { tree_step_native(s, n, exact); });
      add("BM_TreeStep/cl/" + branches + mode, [=](auto& s) { tree_step_cl(s, n, exact); });
      add("BM_TreeStep/cl_w1/" + branches + mode,
          [=](auto& s) { tree_step_cl(s, n, exact, true); });
      add("BM_TreeStep/cl_colliders10/" + branches + mode,
          [=](auto& s) { tree_step_cl(s, n, exact, false, 10); });
    }
    if (n <= kTreeDeformBatchMax) {
      add("BM_Deform/native/" + branches, [=](auto& s) { deform_native(s, n); });
      add("BM_Deform/cl/" + branches, [=](auto& s) { deform_cl(s, n); });
    }
    if (n == kTreeLeafBatch) {
      add("BM_TreeLeaves/native/" + branches, [=](auto& s) { leaves_native(s, n); });
      add("BM_TreeLeaves/cl/" + branches, [=](auto& s) { leaves_cl(s, n); });
    }
  }
}

}  // namespace boreas::bench
