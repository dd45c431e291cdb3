// boreas: the world's step and its wind entry points.
#include "world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "boreas/boreas_cl.h"
#include "enum_as_int.h"
#include "errors.h"
#include "mesh_trees/wind_cache.h"
#include "parallel_for.h"
#include "runtime/kernel_defines.h"
#include "shared/mesh_tree_types.h"
#include "shared/tree_types.h"
#include "state_hash.h"
#include "trees/species.h"
#include "validation.h"
#include "wind/wind_params.h"

namespace boreas::impl {

std::vector<WaveParams> checked_waves(const boreas_wave* waves, int count, const char* where,
                                      const char* count_name) {
  if (count < 0)
    fail_argument(std::string(count_name) + " must be >= 0 (got " + std::to_string(count) + ")");
  if (count > BOREAS_WIND_MAX_WAVES)
    fail_argument(std::string(count_name) + " must be <= " + std::to_string(BOREAS_WIND_MAX_WAVES) +
                  " (got " + std::to_string(count) + ")");
  if (count > 0 && waves == nullptr)
    fail_argument(std::string(where) + " is NULL with " + count_name + " " + std::to_string(count));
  std::vector<WaveParams> out;
  out.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i)
    out.push_back(checked_wave(waves[i], std::string(where) + "[" + std::to_string(i) + "]"));
  return out;
}

World::World(const boreas_world_def& def) {
  boreas_grid_def grid = checked_grid(def.grid, "world_def.grid");
  std::vector<WaveParams> initial =
      checked_waves(def.waves, def.wave_count, "world_def.waves", "world_def.wave_count");
  runtime_ = std::make_unique<Runtime>(def.device, def.cache_dir, def.cl_context_properties);
  grid_ = std::make_unique<WindGrid>(*runtime_, grid);
  waves_.set(std::move(initial), 0.0, 0.0);
  upload_waves(waves_, 0.0);
  lagged_ = std::make_unique<TreeBatch>(*runtime_, BOREAS_TREE_LAGGED);
  exact_ = std::make_unique<TreeBatch>(*runtime_, BOREAS_TREE_EXACT);
  underbrush_ = std::make_unique<UnderbrushBatch>(*runtime_);
  mesh_batch_ = std::make_unique<MeshTreeBatch>(*runtime_);
  BOREAS_CL_CHECK(runtime_->queue().finish());
}

void World::upload_waves(const WaveLayers& layers, double t) {
  std::vector<BoreasGpuWave> gpu = layers.gpu_waves(t);
  // Pad with silent waves (amplitude 0) up to the kernels' unrolled slot count.
  int slots = pad_to_slots(gpu, BoreasGpuWave{});
  if (gpu.size() > wave_capacity_ || wave_buffer_() == nullptr) {
    // Allocated before anything is replaced: a refused allocation keeps the old buffer.
    const size_t capacity = std::max<size_t>(gpu.size(), 16);
    cl::Buffer bigger =
        runtime_->buffer(CL_MEM_READ_ONLY, capacity * sizeof(BoreasGpuWave), "wave buffer");
    wave_buffer_ = std::move(bigger);
    wave_capacity_ = capacity;
  }
  if (!gpu.empty()) {
    BOREAS_CL_CHECK(runtime_->queue().enqueueWriteBuffer(
        wave_buffer_, CL_TRUE, 0, gpu.size() * sizeof(BoreasGpuWave), gpu.data()));
  }
  wave_count_ = static_cast<int>(gpu.size());
  wave_slots_ = slots;
}

namespace {

// The device time between the step's stage markers (World::step); zeros where the driver
// cannot profile markers, which is a measurement lost, not a failed step.
boreas_step_stats stage_times(const cl::Event (&marks)[4],
                              std::chrono::steady_clock::duration wall) {
  boreas_step_stats stats{};
  stats.total = std::chrono::duration<double>(wall).count();
  cl_ulong end[4] = {};
  for (int i = 0; i < 4; ++i) {
    if (marks[i].getProfilingInfo(CL_PROFILING_COMMAND_END, &end[i]) != CL_SUCCESS) return stats;
  }
  auto seconds = [&](int a, int b) {
    return end[b] > end[a] ? double(end[b] - end[a]) * 1e-9 : 0.0;
  };
  stats.wind = seconds(0, 1);
  stats.trees = seconds(1, 2);
  stats.underbrush = seconds(2, 3);
  return stats;
}

}  // namespace

void World::step(float dt) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (!std::isfinite(dt) || dt <= 0.0f || dt > BOREAS_STEP_MAX_SECONDS)
    fail_argument("dt must be finite and in (0, 3600] s (got " + std::to_string(dt) + ")");
  // The step works on copies and commits them only once the device has finished, so a
  // failure (a kernel variant that does not build, memory) leaves the world as it was.
  double t = time_ + dt;
  FlowField flow = flow_;
  WaveLayers waves = waves_;
  flow.expire(t);
  waves.prune(t);
  SlotMap<boreas_emitter_id, Emitter> emitters = emitters_;
  std::vector<BoreasGpuImpulse> impulses;
  emitters.for_each([&](Emitter& e) {
    std::vector<BoreasGpuImpulse> events = e.events(time_, t);
    impulses.insert(impulses.end(), events.begin(), events.end());
  });
  emitters.keep_if([&](const Emitter& e) { return !e.expired(t); });
  std::vector<BoreasGpuCollider> colliders;
  colliders_.for_each([&](const boreas_collider_def& c) {
    colliders.push_back(BoreasGpuCollider{c.center[0], c.center[1], c.center[2], c.radius});
  });
  // Markers between the stages: on the in-order queue each ends when everything before it
  // has, so their end times split the step's device time by stage.
  cl::Event marks[4];
  try {
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[0]));
    upload_waves(waves, t);
    if (grid_->def().follow_focus && !focus_.empty() && grid_->follow(focus_[0], focus_[2])) {
      std::vector<uint8_t> mask = grid_->solids();
      for (const auto& box : solid_boxes_) rasterize_box(grid_->gpu(), box, mask);
      if (mask != grid_->solids()) grid_->set_solids(mask);
    }
    WindGrid::Forcing forcing;
    forcing.steady_version = flow.steady_version();
    // The primitives are copied only when they changed; the grid keeps their field.
    if (forcing.steady_version != grid_->steady_version()) forcing.steady = flow.steady();
    forcing.varying = flow.varying(t);
    grid_->step(dt, wave_buffer_, wave_count_, wave_slots_, forcing);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[1]));
    TreeWindInput wind = tree_wind();
    lagged_->enqueue_step(dt, wind);
    exact_->enqueue_step(dt, wind);
    mesh_batch_->enqueue_step(dt, t, wind);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[2]));
    underbrush_->enqueue_step(dt, wind, colliders, impulses);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[3]));
    BOREAS_CL_CHECK(runtime_->queue().finish());
  } catch (...) {
    // Nothing enqueued may still read the batches' staging once the next step refills it.
    runtime_->queue().finish();
    restore_waves();
    throw;
  }
  lagged_->commit();
  exact_->commit();
  mesh_batch_->commit();
  underbrush_->commit();
  emitters_ = std::move(emitters);
  flow_ = std::move(flow);
  waves_ = std::move(waves);
  time_ = t;
  step_stats_ = stage_times(marks, std::chrono::steady_clock::now() - wall_start);
  for (const TreeBatch* batch : {lagged_.get(), exact_.get()}) {
    const auto lods = batch->lod_counts();
    for (int l = 0; l < kTreeLodCount; ++l) step_stats_.trees_by_lod[l] += lods[size_t(l)];
    step_stats_.branches_stepped += batch->branches_stepped();
    step_stats_.branches_carried += batch->branches_carried();
  }
  const auto rates = underbrush_->components_by_rate();
  for (int r = 0; r < 4; ++r) step_stats_.components_by_rate[r] = rates[size_t(r)];
}

TreeWindInput World::tree_wind() {
  TreeWindInput wind;
  wind.waves = &wave_buffer_;
  wind.wave_count = wave_count_;
  wind.wave_slots = wave_slots_;
  wind.grid = &grid_->current();
  wind.grid_layout = grid_->gpu();
  wind.interpolated = grid_->def().wind_sampling == BOREAS_WIND_SAMPLING_INTERPOLATED;
  return wind;
}

namespace {

// By reference, read as an int (enum_as_int.h): a C caller may pass any int.
void check_mesh_part(const boreas_mesh_part& part) {
  const int value = enum_as_int(part);
  if (value != BOREAS_MESH_TRUNK && value != BOREAS_MESH_LEAVES)
    fail_argument("part must be BOREAS_MESH_TRUNK or BOREAS_MESH_LEAVES (got " +
                  std::to_string(value) + ")");
}

}  // namespace

boreas_mesh_tree_id World::add_mesh_tree(const boreas_mesh_tree_def& def) {
  auto tree = std::make_shared<MeshTreeInstance>();
  tree->params = checked_mesh_tree_def(def);
  ModelPartSelection selection{tree->params.trunk_part, tree->params.leaves_part};
  PreprocessedTree pre = preprocess_tree(tree->params.model, selection, tree->params.seed,
                                         tree->params.cache, &tree->from_cache, &tree->cache_note);
  tree->model = std::move(pre.model);
  tree->data = std::move(pre.data);
  tree->noise =
      make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, tree->params.noise_beta, tree->params.seed);
  tree->key = next_mesh_tree_key_++;
  mesh_batch_->add(tree, time_);
  return mesh_trees_.insert(std::move(tree));
}

boreas_blobtree_id World::add_blobtree(boreas_tree_id tree, const boreas_blobtree_def& def,
                                       const BlobProgress& progress) {
  const TreeInstance& source = *trees_.get(tree);
  BlobTreeParams params = checked_blobtree_def(def);
  auto blob = std::make_shared<BlobTreeInstance>(
      make_blobtree(*runtime_, source, params, progress, &blob_scratch_));
  return blobtrees_.insert(std::move(blob));
}

void World::remove_blobtree(boreas_blobtree_id id) { blobtrees_.erase(id); }

void World::remove_mesh_tree(boreas_mesh_tree_id id) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  mesh_batch_->remove(tree.key, time_);
  mesh_trees_.erase(id);
}

boreas_mesh_tree_info World::mesh_tree_info(boreas_mesh_tree_id id) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  return describe_mesh_tree(tree.model, tree.data, tree.from_cache);
}

std::vector<boreas_vertex> World::mesh_tree_vertices(boreas_mesh_tree_id id,
                                                     const boreas_mesh_part& part) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  check_mesh_part(part);
  return part == BOREAS_MESH_TRUNK ? mesh_batch_->trunk_vertices(tree.key)
                                   : mesh_batch_->leaf_vertices(tree.key);
}

const std::vector<uint32_t>& World::mesh_tree_indices(boreas_mesh_tree_id id,
                                                      const boreas_mesh_part& part) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  check_mesh_part(part);
  return part == BOREAS_MESH_TRUNK ? tree.model.trunk.indices : tree.model.leaves.indices;
}

boreas_tree_id World::add_tree(const boreas_tree_def& def) {
  return add_trees(&def, 1, false).front();
}

std::vector<boreas_tree_id> World::add_trees(const boreas_tree_def* defs, int count,
                                             bool name_defs) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > 0 && defs == nullptr)
    fail_argument("defs is NULL with count " + std::to_string(count));
  // A bad BOREAS_THREADS is refused before anything, not blamed on a def.
  if (count > 1) (void)host_threads();
  auto named = [&](int i, const Error& e) {
    if (!name_defs) throw e;
    fail(e.status(), "defs[" + std::to_string(i) + "]: " + e.what());
  };
  // 1. Every def checked and every species read, in order; the templates this call needs
  //    and no living tree has are listed to grow. Nothing changes yet.
  struct Grow {
    Species species;
    uint64_t seed = 0;
    int def = 0;  // the first def that needs it, for the error's name
    std::shared_ptr<const TreeModel> model;
  };
  struct Template {
    std::shared_ptr<const TreeModel> model;  // null until grown
    std::string key;
    int grow = -1;  // its entry in `grows`, or -1 when a living tree has it
  };
  std::vector<Grow> grows;
  std::unordered_map<std::string, Template> needed;  // by species name and seed
  std::vector<std::shared_ptr<TreeInstance>> all;
  all.reserve(size_t(count));
  std::vector<Template*> template_of(static_cast<size_t>(count));  // into `needed` (stable)
  for (int i = 0; i < count; ++i) {
    auto tree = std::make_shared<TreeInstance>();
    try {
      tree->params = checked_tree_def(defs[i]);
      const std::string local = tree->params.species + "\n" + std::to_string(tree->params.seed);
      auto it = needed.find(local);
      if (it == needed.end()) {
        const SpeciesSource source = read_species_source(tree->params.species);
        Template t;
        t.key = source.key + "\n" + std::to_string(tree->params.seed);
        if (auto known = templates_.find(t.key); known != templates_.end())
          t.model = known->second.lock();
        if (!t.model) {
          t.grow = int(grows.size());
          grows.push_back({parse_species_source(source), tree->params.seed, i, nullptr});
        }
        it = needed.emplace(local, std::move(t)).first;
      }
      template_of[size_t(i)] = &it->second;
    } catch (const Error& e) {
      named(i, e);
    }
    all.push_back(std::move(tree));
  }
  // 2. The new templates grown on every core (each a pure function of species and seed,
  //    at scale 1: each tree's scale is applied where it is laid out); a failure names the
  //    first def whose template failed, whatever the threads' timing.
  try {
    parallel_for(grows.size(), [&](size_t g) {
      grows[g].model =
          std::make_shared<const TreeModel>(grow_tree(grows[g].species, grows[g].seed, 1.0));
    });
  } catch (const Error& e) {
    int first = count;
    for (const Grow& g : grows)
      if (!g.model) first = std::min(first, g.def);
    named(first, e);
  }
  for (auto& [local, t] : needed)
    if (t.grow >= 0) t.model = grows[size_t(t.grow)].model;
  std::vector<std::shared_ptr<const TreeInstance>> added[2];
  uint64_t key = next_tree_key_;
  for (int i = 0; i < count; ++i) {
    TreeInstance& tree = *all[size_t(i)];
    tree.model = template_of[size_t(i)]->model;
    tree.template_key = template_of[size_t(i)]->key;
    tree.key = key++;
    added[tree.params.mode == BOREAS_TREE_EXACT ? 1 : 0].push_back(all[size_t(i)]);
  }
  // The batches take them whole or not at all; a failure in the second takes the first's
  // back out.
  lagged_->add(added[0]);
  try {
    exact_->add(added[1]);
  } catch (...) {
    for (const auto& t : added[0]) lagged_->remove(t->key);
    throw;
  }
  next_tree_key_ = key;
  for (auto& [local, t] : needed) templates_[t.key] = t.model;
  std::vector<boreas_tree_id> ids;
  ids.reserve(all.size());
  for (auto& t : all) ids.push_back(trees_.insert(std::move(t)));
  return ids;
}

void World::remove_tree(boreas_tree_id id) {
  std::shared_ptr<const TreeInstance> tree = trees_.get(id);
  tree_batch(tree->params.mode).remove(tree->key);
  trees_.erase(id);
  // The last tree of its template lets the template go.
  if (tree->model.use_count() == 1) templates_.erase(tree->template_key);
}

void World::set_focus(const float* xyz, int count) {
  if (count < 0) fail_argument("focus count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > 0 && xyz == nullptr)
    fail_argument("focus points are NULL with count " + std::to_string(count));
  std::vector<double> points(size_t(3) * size_t(count));
  for (int i = 0; i < 3 * count; ++i) {
    if (!std::isfinite(xyz[i]))
      fail_argument("focus points[" + std::to_string(i) + "] (point " + std::to_string(i / 3) +
                    ", " + "xyz"[i % 3] + ") must be finite (got " + std::to_string(xyz[i]) + ")");
    points[size_t(i)] = xyz[i];
  }
  lagged_->set_focus(points);
  exact_->set_focus(points);
  underbrush_->set_focus(points);
  focus_ = std::move(points);
}

std::vector<boreas_branch> World::tree_branches(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  return tree_batch(tree.params.mode).branches(tree.key);
}

std::vector<boreas_leaf> World::tree_leaves(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  return tree_batch(tree.params.mode).leaves(tree.key);
}

void World::tree_mesh(boreas_tree_id id, std::vector<boreas_vertex>* vertices,
                      std::vector<uint32_t>* indices) {
  const TreeInstance& tree = *trees_.get(id);
  tree_batch(tree.params.mode).mesh(tree.key, vertices, indices);
}

boreas_meadow_id World::add_meadow(const boreas_meadow_def& def) {
  return add_meadows(&def, 1, false).front();
}

std::vector<boreas_meadow_id> World::add_meadows(const boreas_meadow_def* defs, int count,
                                                 bool name_defs) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > 0 && defs == nullptr)
    fail_argument("defs is NULL with count " + std::to_string(count));
  // Every meadow checked and planted before anything changes; one upload for all.
  std::vector<std::shared_ptr<const MeadowInstance>> planted;
  uint64_t key = next_meadow_key_;
  for (int i = 0; i < count; ++i) {
    auto meadow = std::make_shared<MeadowInstance>();
    try {
      meadow->meadow = plant_meadow(checked_meadow_def(defs[i]));
    } catch (const Error& e) {
      if (!name_defs) throw;
      fail(e.status(), "defs[" + std::to_string(i) + "]: " + e.what());
    }
    meadow->key = key++;
    planted.push_back(std::move(meadow));
  }
  underbrush_->add(planted);
  next_meadow_key_ = key;
  std::vector<boreas_meadow_id> ids;
  ids.reserve(planted.size());
  for (auto& m : planted) ids.push_back(meadows_.insert(std::move(m)));
  return ids;
}

boreas_meadow_id World::add_meadow(Meadow planted) {
  auto meadow = std::make_shared<MeadowInstance>();
  meadow->meadow = std::move(planted);
  meadow->key = next_meadow_key_++;
  // The batch changes only once the meadow is on the device; the slot is taken only after.
  underbrush_->add(meadow);
  return meadows_.insert(std::move(meadow));
}

void World::remove_meadow(boreas_meadow_id id) {
  uint64_t key = meadows_.get(id)->key;
  underbrush_->remove(key);
  meadows_.erase(id);
}

uint64_t World::state_hash() {
  StateHash h;
  h.value(time_);
  h.values(grid_->read());
  trees_.for_each([&](const std::shared_ptr<const TreeInstance>& tree) {
    TreeBatch& batch = tree_batch(tree->params.mode);
    h.values(batch.read_tree_state(tree->key));
    h.values(batch.read_tree_motion(tree->key));
  });
  mesh_trees_.for_each([&](const std::shared_ptr<const MeshTreeInstance>& tree) {
    h.values(mesh_batch_->branch_wind(tree->key));
    h.values(mesh_batch_->trunk_vertices(tree->key));
    h.values(mesh_batch_->leaf_vertices(tree->key));
  });
  meadows_.for_each([&](const std::shared_ptr<const MeadowInstance>& meadow) {
    h.values(underbrush_->read_meadow_state(meadow->key));
  });
  return h.digest();
}

std::vector<boreas_component> World::meadow_components(boreas_meadow_id id) {
  return underbrush_->components(meadows_.get(id)->key);
}

std::vector<boreas_meadow_part> World::meadow_parts(boreas_meadow_id id) {
  return underbrush_->parts(meadows_.get(id)->key);
}

void World::meadow_vertices(boreas_meadow_id id, const float* camera, std::vector<float>* vertices,
                            std::vector<int32_t>* counts) {
  if (camera) check_position(camera, "camera");
  underbrush_->vertices(meadows_.get(id)->key, camera, vertices, counts);
}

namespace {

static_assert(BOREAS_BRANCH_RECORD_FLOATS == BOREAS_TREE_STATE_PLANES + BOREAS_TREE_RADIUS_PLANES,
              "cl/export_records.cl writes the state planes, then the radius planes");
static_assert(BOREAS_LEAF_RECORD_FLOATS == BOREAS_TREE_LEAF_OUT_PLANES, "cl/export_records.cl");

// Refuses a renderer's buffer that cannot hold `records` records of `record_bytes` from
// record `first` on, naming what it was for and both sizes.
void check_holds(const cl::Buffer& buffer, size_t first, size_t records, size_t record_bytes,
                 const char* what) {
  if (buffer() == nullptr) fail_argument(std::string(what) + " buffer is NULL");
  size_t size = 0;
  BOREAS_CL_CHECK(buffer.getInfo(CL_MEM_SIZE, &size));
  const size_t need = (first + records) * record_bytes;
  if (first > size || need > size)
    fail_argument(std::string(what) + " buffer holds " + std::to_string(size) + " bytes; records " +
                  std::to_string(first) + ".." + std::to_string(first + records) + " need " +
                  std::to_string(need));
}

}  // namespace

void World::enqueue_branch_records(boreas_tree_id id, const cl::Buffer& out, size_t first) {
  const TreeInstance& tree = *trees_.get(id);
  check_holds(out, first, tree.model->branches.size(), BOREAS_BRANCH_RECORD_FLOATS * sizeof(float),
              "branch record");
  tree_batch(tree.params.mode).enqueue_branch_records(tree.key, out, first);
}

void World::enqueue_leaf_records(boreas_tree_id id, const cl::Buffer& out, size_t first) {
  const TreeInstance& tree = *trees_.get(id);
  check_holds(out, first, tree.model->leaves.size(), BOREAS_LEAF_RECORD_FLOATS * sizeof(float),
              "leaf record");
  tree_batch(tree.params.mode).enqueue_leaf_records(tree.key, out, first);
}

void World::enqueue_meadow_vertices(boreas_meadow_id id, const float* camera,
                                    const cl::Buffer& vertices, const cl::Buffer& counts,
                                    size_t first) {
  const MeadowInstance& m = *meadows_.get(id);
  if (camera) check_position(camera, "camera");
  const size_t n = size_t(m.meadow.count);
  check_holds(vertices, first, n, BOREAS_MEADOW_VERTEX_STRIDE * sizeof(boreas_meadow_vertex),
              "meadow vertex");
  check_holds(counts, first, n, sizeof(int32_t), "strip count");
  underbrush_->enqueue_vertices(m.key, camera, vertices, counts, first);
}

void World::enqueue_mesh_tree_vertices(boreas_mesh_tree_id id, const boreas_mesh_part& part,
                                       const cl::Buffer& out, size_t first) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  check_mesh_part(part);
  if (part == BOREAS_MESH_TRUNK) {
    check_holds(out, first, tree.model.trunk.vertex_count(),
                BOREAS_MESH_TRUNK_VERTEX_FLOATS * sizeof(float), "mesh trunk vertex");
  } else {
    check_holds(out, first, tree.model.leaves.vertex_count(),
                BOREAS_MESH_LEAF_VERTEX_FLOATS * sizeof(float), "mesh leaf vertex");
  }
  mesh_batch_->enqueue_copy(tree.key, part, out, first);
}

boreas_collider_id World::add_collider(const boreas_collider_def& def) {
  return colliders_.insert(checked_collider_def(def));
}

void World::remove_collider(boreas_collider_id id) { colliders_.erase(id); }

void World::set_collider_position(boreas_collider_id id, const float center[3]) {
  boreas_collider_def& c = colliders_.get(id);
  check_position(center, "center");
  for (int a = 0; a < 3; ++a) c.center[a] = center[a];
}

boreas_emitter_id World::add_emitter(const boreas_emitter_def& def) {
  Emitter e;
  e.def = checked_emitter_def(def);
  e.start = time_;
  return emitters_.insert(e);
}

void World::remove_emitter(boreas_emitter_id id) { emitters_.erase(id); }

void World::set_emitter_position(boreas_emitter_id id, const float center[3]) {
  Emitter& e = emitters_.get(id);
  check_position(center, "center");
  for (int a = 0; a < 3; ++a) e.def.center[a] = center[a];
}

void World::restore_waves() noexcept {
  try {
    upload_waves(waves_, time_);
  } catch (...) {
    // Best effort: the device is failing already, and the caller gets the first error.
  }
}

void World::set_waves(const boreas_wave* waves, int count, float blend_seconds) {
  if (!std::isfinite(blend_seconds) || blend_seconds < 0.0f)
    fail_argument("blend_seconds must be finite and >= 0 (got " + std::to_string(blend_seconds) +
                  ")");
  std::vector<WaveParams> checked = checked_waves(waves, count, "waves", "count");
  WaveLayers next = waves_;
  next.set(std::move(checked), blend_seconds, time_);
  try {
    upload_waves(next, time_);
  } catch (...) {
    restore_waves();
    throw;
  }
  waves_ = std::move(next);
}

boreas_primitive_id World::add_primitive(const boreas_flow_primitive& p) {
  return flow_.add_primitive(checked_primitive(p, "primitive"), time_);
}

boreas_gust_id World::add_gust(const boreas_gust& g) {
  return flow_.add_gust(checked_gust(g, "gust"), time_);
}

void World::remove_primitive(boreas_primitive_id id) { flow_.remove(id); }

void World::remove_gust(boreas_gust_id id) { flow_.remove(id); }

void World::add_solid_box(const float min[3], const float max[3]) {
  if (!min || !max) fail_argument("solid box min or max is NULL");
  for (int i = 0; i < 3; ++i) {
    check_finite(min[i], "min[" + std::to_string(i) + "]");
    check_finite(max[i], "max[" + std::to_string(i) + "]");
    if (min[i] > max[i])
      fail_argument("solid box min[" + std::to_string(i) + "] = " + std::to_string(min[i]) +
                    " exceeds max[" + std::to_string(i) + "] = " + std::to_string(max[i]));
  }
  const std::array<float, 6> box = {min[0], min[1], min[2], max[0], max[1], max[2]};
  std::vector<uint8_t> mask = grid_->solids();
  rasterize_box(grid_->gpu(), box, mask);
  solid_boxes_.reserve(solid_boxes_.size() + 1);  // a failure below leaves the list as it was
  grid_->set_solids(mask);
  solid_boxes_.push_back(box);
}

void World::rasterize_box(const BoreasGpuGrid& g, const std::array<float, 6>& box,
                          std::vector<uint8_t>& mask) {
  const double origin[3] = {g.origin_x, g.origin_y, g.origin_z};
  const int n[3] = {g.nx, g.ny, g.nz};
  // The cells whose centers may lie in the box, along each axis: [lo, hi], a cell wider
  // than the rounding could make it (the test per cell below decides). Only those are
  // visited: a small box in a large grid costs its own cells.
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const double h = g.cell_size, last = double(n[a] - 1);
    lo[a] = int(std::clamp(std::ceil((box[size_t(a)] - origin[a]) / h - 0.5) - 1.0, 0.0, last));
    hi[a] =
        int(std::clamp(std::floor((box[size_t(a) + 3] - origin[a]) / h - 0.5) + 1.0, -1.0, last));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const double c[3] = {origin[0] + (i + 0.5) * g.cell_size,
                             origin[1] + (j + 0.5) * g.cell_size,
                             origin[2] + (k + 0.5) * g.cell_size};
        bool inside = true;
        for (int a = 0; a < 3; ++a)
          inside = inside && c[a] >= box[size_t(a)] && c[a] <= box[size_t(a) + 3];
        if (inside) mask[(size_t(k) * size_t(g.ny) + size_t(j)) * size_t(g.nx) + size_t(i)] = 1;
      }
}

void World::set_solid_mask(const uint8_t* mask, int64_t count) {
  if (mask == nullptr && count == 0) {
    grid_->set_solids(std::vector<uint8_t>(static_cast<size_t>(grid_->cell_count()), 0));
    solid_boxes_.clear();
    return;
  }
  if (grid_->def().follow_focus)
    fail_argument(
        "the grid follows the focus (grid.follow_focus): its solids must be boxes "
        "(boreas_wind_add_solid_box), since a cell mask has no place once the grid "
        "moves; only NULL with count 0 (clear) is taken");
  if (mask == nullptr) fail_argument("solid mask is NULL with count > 0");
  if (count != grid_->cell_count())
    fail_argument("solid mask count must equal the grid's cell count " +
                  std::to_string(grid_->cell_count()) + " (got " + std::to_string(count) + ")");
  grid_->set_solids(std::vector<uint8_t>(mask, mask + count));
  solid_boxes_.clear();
}

void World::sample(const float* xyz, int count, float* force_xyz, bool as_plants) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > BOREAS_WIND_SAMPLE_MAX_POINTS)
    fail_argument("count must be <= " + std::to_string(BOREAS_WIND_SAMPLE_MAX_POINTS) +
                  " per call (got " + std::to_string(count) + "); split the batch");
  if (count == 0) return;
  if (!xyz || !force_xyz) fail_argument("xyz or force_xyz is NULL");
  for (int i = 0; i < 3 * count; ++i) {
    if (!std::isfinite(xyz[i]))
      fail_argument("xyz[" + std::to_string(i) + "] (point " + std::to_string(i / 3) +
                    ") must be finite (got " + std::to_string(xyz[i]) + ")");
  }
  size_t n = static_cast<size_t>(count);
  size_t bytes = n * 3 * sizeof(float);
  if (n > point_capacity_) {
    // Both allocated before either is replaced: a refused allocation keeps the old pair.
    const size_t capacity = std::max<size_t>(n, 1024);
    cl::Buffer points =
        runtime_->buffer(CL_MEM_READ_ONLY, capacity * 3 * sizeof(float), "sample points");
    cl::Buffer results =
        runtime_->buffer(CL_MEM_WRITE_ONLY, capacity * 3 * sizeof(float), "sample results");
    points_ = std::move(points);
    results_ = std::move(results);
    point_capacity_ = capacity;
  }
  // The kernel reads and writes planes (x..., y..., z...): see wind_sample_points.cl.
  planar_.resize(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) planar_[a * n + i] = xyz[3 * i + a];
  cl::CommandQueue& q = runtime_->queue();
  // Exact (boreas_wind_sample), or as the plants' kernels sample it where as_plants.
  TreeWindInput wind = tree_wind();
  wind.interpolated = wind.interpolated && as_plants;
  cl::Kernel& kernel =
      runtime_->kernel("wind_sample_points.cl", "boreas_wind_sample_points", wind.defines());
  BOREAS_CL_CHECK(q.enqueueWriteBuffer(points_, CL_TRUE, 0, bytes, planar_.data()));
  BOREAS_CL_CHECK(kernel.setArg(0, points_));
  BOREAS_CL_CHECK(kernel.setArg(1, results_));
  BOREAS_CL_CHECK(kernel.setArg(2, count));
  BOREAS_CL_CHECK(kernel.setArg(3, wave_buffer_));
  BOREAS_CL_CHECK(kernel.setArg(4, wave_count_));
  BOREAS_CL_CHECK(kernel.setArg(5, grid_->current()));
  BOREAS_CL_CHECK(kernel.setArg(6, grid_->gpu()));
  const size_t global = simd_global_size(n, runtime_->simd_width());
  BOREAS_CL_CHECK(q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global)));
  BOREAS_CL_CHECK(q.enqueueReadBuffer(results_, CL_TRUE, 0, bytes, planar_.data()));
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) force_xyz[3 * i + a] = planar_[a * n + i];
}

}  // namespace boreas::impl
