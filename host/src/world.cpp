// boreas: the world: its step, in stages, and the tables of what was added.
#include "world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "boreas/boreas_cl.h"
#include "errors.h"
#include "heap_trim.h"
#include "mesh_trees/wind_cache.h"
#include "parallel_for.h"
#include "rays/ray_checks.h"
#include "runtime/caller_buffers.h"
#include "shared/mesh_tree_types.h"
#include "shared/tree_types.h"
#include "state_hash.h"
#include "trees/species.h"
#include "validation.h"

namespace boreas::impl {

World::World(const boreas_world_def& def) {
  const WindSettings wind = checked_wind_settings(def);
  runtime_ = std::make_unique<Runtime>(def.device, def.cache_dir, def.cl_context_properties);
  wind_ = std::make_unique<Wind>(*runtime_, wind, serial_);
  for (int m = 0; m < 2; ++m) {
    template_numbers_[m] = std::make_shared<TemplateNumbers>();
    chunks_[m].push_back(std::make_unique<TreeBatch>(
        *runtime_, m == 1 ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED, template_numbers_[m]));
  }
  meadow_chunks_.push_back(std::make_unique<UnderbrushBatch>(*runtime_, meadow_tile_numbers_));
  mesh_batch_ = std::make_unique<MeshTreeBatch>(*runtime_);
  BOREAS_CL_CHECK(runtime_->queue().finish());
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

void World::check_unlocked() const {
  if (locked_by_)
    fail_argument(std::string("the world is locked: ") + locked_by_ +
                  " on this world is still running (a progress callback must not call into "
                  "the world it reports on)");
}

void World::step(float dt) {
  const auto wall_start = std::chrono::steady_clock::now();
  static_assert(BOREAS_STEP_MAX_SECONDS == 3600.0, "the message spells it 3600");
  if (!std::isfinite(dt) || dt <= 0.0f || dt > BOREAS_STEP_MAX_SECONDS)
    fail_argument("dt must be finite and in (0, 3600] s (got " + std::to_string(dt) + ")");
  // The step works on copies and commits them only once the device has finished, so a
  // failure (a kernel variant that does not build, memory) leaves the world as it was.
  double t = time_ + dt;
  SlotMap<boreas_emitter_id, Emitter> emitters = emitters_;
  std::vector<BoreasGpuImpulse> impulses;
  emitters.for_each([&](Emitter& e) {
    std::vector<BoreasGpuImpulse> events = e.events(time_, t);
    impulses.insert(impulses.end(), events.begin(), events.end());
  });
  emitters.keep_if([&](const Emitter& e) { return !e.expired(t); });
  std::vector<boreas_collider_id> collider_ids;
  const StepColliders colliders = step_colliders(dt, &collider_ids);
  // Markers between the stages: on the in-order queue each ends when everything before it
  // has, so their end times split the step's device time by stage.
  cl::Event marks[4];
  try {
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[0]));
    wind_->enqueue_step(dt, t, focus_);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[1]));
    const PlantWind wind = wind_->plants();
    for (TreeBatch* batch : all_tree_batches()) batch->enqueue_step(dt, wind, colliders);
    mesh_batch_->enqueue_step(dt, t, wind, colliders);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[2]));
    for (UnderbrushBatch* batch : all_meadow_batches())
      batch->enqueue_step(dt, wind, colliders, impulses);
    BOREAS_CL_CHECK(runtime_->queue().enqueueMarkerWithWaitList(nullptr, &marks[3]));
    BOREAS_CL_CHECK(runtime_->queue().finish());
  } catch (...) {
    // Nothing enqueued may still read the batches' staging once the next step refills it.
    runtime_->queue().finish();
    wind_->rollback(time_);
    throw;
  }
  wind_->commit();
  for (TreeBatch* batch : all_tree_batches()) batch->commit();
  mesh_batch_->commit();
  for (UnderbrushBatch* batch : all_meadow_batches()) batch->commit();
  emitters_ = std::move(emitters);
  colliders_.for_each([&](Collider& c) { c.advance(dt); });
  step_collider_ids_ = std::move(collider_ids);
  contacts_read_ = false;
  const double t0 = time_;
  time_ = t;
  ++steps_;
  sense(t0, t);
  step_stats_ = stage_times(marks, std::chrono::steady_clock::now() - wall_start);
  for (const TreeBatch* batch : all_tree_batches()) {
    const auto lods = batch->lod_counts();
    for (int l = 0; l < kTreeLodCount; ++l) step_stats_.trees_by_lod[l] += lods[size_t(l)];
    step_stats_.branches_stepped += batch->branches_stepped();
    step_stats_.branches_carried += batch->branches_carried();
    step_stats_.branches_broken += batch->branches_broken();
  }
  for (const UnderbrushBatch* batch : all_meadow_batches()) {
    const auto rates = batch->components_by_rate();
    for (int r = 0; r < 4; ++r) step_stats_.components_by_rate[r] += rates[size_t(r)];
  }
}

boreas_mesh_tree_id World::add_mesh_tree(const boreas_mesh_tree_def& def) {
  auto tree = std::make_shared<MeshTreeInstance>();
  tree->params = checked_mesh_tree_def(def);
  ModelPartSelection selection{tree->params.trunk_part, tree->params.leaves_part};
  PreprocessedTree pre = preprocess_tree(tree->params.model, selection, tree->params.seed,
                                         tree->params.cache, &tree->from_cache, &tree->cache_note);
  tree->model = std::move(pre.model);
  tree->data = std::move(pre.data);
  tree->drag = mesh_tree_drag(tree->model);
  tree->noise =
      make_noise_texture(BOREAS_MESH_TREE_NOISE_SIZE, tree->params.noise_beta, tree->params.seed);
  tree->key = next_mesh_tree_key_++;
  mesh_batch_->add(tree, time_);
  ++changes_;
  return mesh_trees_.insert(std::move(tree));
}

boreas_blobtree_id World::add_blobtree(boreas_tree_id tree, const boreas_blobtree_def& def,
                                       const BlobProgress& progress) {
  const TreeInstance& source = *trees_.get(tree);
  BlobTreeParams params = checked_blobtree_def(def);
  const Lock lock(*this, "boreas_world_add_blobtree");  // progress runs the caller's code
  auto blob = std::make_shared<BlobTreeInstance>(
      make_blobtree(*runtime_, source, params, progress, &blob_scratch_));
  ++changes_;
  return blobtrees_.insert(std::move(blob));
}

void World::remove_blobtree(boreas_blobtree_id id) {
  blobtrees_.erase(id);
  ++changes_;
}

void World::remove_mesh_tree(boreas_mesh_tree_id id) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  mesh_batch_->remove(tree.key, time_);
  mesh_trees_.erase(id);
  ++changes_;
}

boreas_mesh_tree_info World::mesh_tree_info(boreas_mesh_tree_id id) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  return describe_mesh_tree(tree.model, tree.data, tree.from_cache);
}

std::vector<boreas_vertex> World::mesh_tree_vertices(boreas_mesh_tree_id id,
                                                     const boreas_mesh_part& part) {
  const MeshTreeInstance& tree = *mesh_trees_.get(id);
  check_mesh_part(part);
  return part == BOREAS_MESH_TRUNK ? mesh_batch_->trunk_vertices(tree.key, output_origin_)
                                   : mesh_batch_->leaf_vertices(tree.key, output_origin_);
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
  // Every def checked and every species read, in order; nothing changes yet. Then the
  // templates this call needs and no living tree has are grown and the trees handed to
  // the batches a piece at a time, all or none (add_tree_pieces).
  TreeTemplates::Request request(templates_);
  std::vector<std::shared_ptr<TreeInstance>> all;
  all.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    auto tree = std::make_shared<TreeInstance>();
    try {
      tree->params = checked_tree_def(defs[i]);
      request.add(tree->params, i);
    } catch (const Error& e) {
      named(i, e);
    }
    tree->key = next_tree_key_ + uint64_t(i);  // in the call's order, whatever the pieces
    all.push_back(std::move(tree));
  }
  add_tree_pieces(request, all, name_defs, named);
  next_tree_key_ += uint64_t(count);
  templates_.keep(request);
  std::vector<boreas_tree_id> ids;
  ids.reserve(all.size());
  for (auto& t : all) {
    TreeBatch& batch = tree_batch(*t);
    const uint64_t key = t->key;
    const boreas_tree_id id = trees_.insert(std::move(t));
    batch.set_tree_id(key, id.index, id.generation);  // for the view records' ranges
    ids.push_back(id);
  }
  ++changes_;
  // Growing left the whole models and their blocks' staging freed in every thread's arena.
  if (request.grown() > 1) trim_heap();
  return ids;
}

void World::remove_tree(boreas_tree_id id) {
  std::shared_ptr<const TreeInstance> tree = trees_.get(id);
  TreeBatch& batch = tree_batch(*tree);
  // A chunk past the first goes once empty (its buffers with it), what its trees pushed the
  // colliders with in the last step read first (before anything changes: it may fail).
  auto& chunks = chunks_[tree->params.mode == BOREAS_TREE_EXACT ? 1 : 0];
  const bool drop = batch.tree_count() == 1 && &batch != chunks.front().get();
  if (drop) read_contacts();
  batch.remove(tree->key);
  if (drop)
    chunks.erase(
        std::find_if(chunks.begin(), chunks.end(),
                     [&](const std::unique_ptr<TreeBatch>& c) { return c.get() == &batch; }));
  trees_.erase(id);
  templates_.release(tree->model, tree->template_key);
  ++changes_;
}

void World::heal_tree(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  tree_batch(tree).heal(tree.key);
  ++changes_;
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
  for (TreeBatch* batch : all_tree_batches()) batch->set_focus(points);
  for (UnderbrushBatch* batch : all_meadow_batches()) batch->set_focus(points);
  focus_ = std::move(points);
}

std::vector<boreas_branch> World::tree_branches(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  return tree_batch(tree).branches(tree.key, output_origin_);
}

std::vector<boreas_leaf> World::tree_leaves(boreas_tree_id id) {
  const TreeInstance& tree = *trees_.get(id);
  return tree_batch(tree).leaves(tree.key, output_origin_);
}

void World::tree_mesh(boreas_tree_id id, std::vector<boreas_vertex>* vertices,
                      std::vector<uint32_t>* indices) {
  const TreeInstance& tree = *trees_.get(id);
  tree_batch(tree).mesh(tree.key, vertices, indices, output_origin_);
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
  std::vector<std::shared_ptr<MeadowInstance>> planted;
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
  add_to_meadow_chunks(UnderbrushBatch::Meadows(planted.begin(), planted.end()), name_defs);
  next_meadow_key_ = key;
  std::vector<boreas_meadow_id> ids;
  ids.reserve(planted.size());
  for (auto& m : planted) {
    drop_uploaded(m->meadow);
    ids.push_back(meadows_.insert(std::move(m)));
  }
  ++changes_;
  // Planting and staging the components left their transients freed in the arenas
  // (bench/RESULTS.md, issue 39's twelfth round: aspens).
  if (!ids.empty()) trim_heap();
  return ids;
}

boreas_meadow_id World::add_meadow(Meadow planted) {
  auto meadow = std::make_shared<MeadowInstance>();
  meadow->meadow = std::move(planted);
  meadow->key = next_meadow_key_++;
  // The batch changes only once the meadow is on the device; the slot is taken only after.
  add_to_meadow_chunks({meadow}, false);
  drop_uploaded(meadow->meadow);
  ++changes_;
  return meadows_.insert(std::move(meadow));
}

void World::remove_meadow(boreas_meadow_id id) {
  const std::shared_ptr<const MeadowInstance> meadow = meadows_.get(id);
  UnderbrushBatch& batch = meadow_batch(*meadow);
  // A chunk past the first goes once empty, its contacts read first (as the trees').
  const bool drop = batch.meadow_count() == 1 && &batch != meadow_chunks_.front().get();
  if (drop) read_contacts();
  batch.remove(meadow->key);
  if (drop)
    meadow_chunks_.erase(
        std::find_if(meadow_chunks_.begin(), meadow_chunks_.end(),
                     [&](const std::unique_ptr<UnderbrushBatch>& c) { return c.get() == &batch; }));
  meadows_.erase(id);
  ++changes_;
}

uint64_t World::state_hash() {
  StateHash h;
  h.value(time_);
  h.values(wind_->grid().read());
  trees_.for_each([&](const std::shared_ptr<const TreeInstance>& tree) {
    TreeBatch& batch = tree_batch(*tree);
    h.values(batch.read_tree_state(tree->key));
    h.values(batch.read_tree_motion(tree->key));
  });
  mesh_trees_.for_each([&](const std::shared_ptr<const MeshTreeInstance>& tree) {
    h.values(mesh_batch_->branch_wind(tree->key));
    h.values(mesh_batch_->trunk_vertices(tree->key));
    h.values(mesh_batch_->leaf_vertices(tree->key));
  });
  meadows_.for_each([&](const std::shared_ptr<const MeadowInstance>& meadow) {
    h.values(meadow_batch(*meadow).read_meadow_state(meadow->key));
  });
  lidars_.for_each([&](const Lidar& lidar) { lidar.hash(&h); });
  return h.digest();
}

void World::set_output_origin(const double* origin) {
  std::array<double, 3> o{};
  if (origin) {
    for (int a = 0; a < 3; ++a) {
      check_range(origin[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                  "origin[" + std::to_string(a) + "]");
      o[size_t(a)] = origin[a];
    }
  }
  output_origin_ = o;
}

std::vector<boreas_component> World::meadow_components(boreas_meadow_id id) {
  const MeadowInstance& m = *meadows_.get(id);
  return meadow_batch(m).components(m.key, output_origin_);
}

std::vector<boreas_meadow_part> World::meadow_parts(boreas_meadow_id id) {
  const MeadowInstance& m = *meadows_.get(id);
  return meadow_batch(m).parts(m.key);
}

void World::meadow_vertices(boreas_meadow_id id, const float* camera, std::vector<float>* vertices,
                            std::vector<int32_t>* counts) {
  if (camera) check_position(camera, "camera");
  const MeadowInstance& m = *meadows_.get(id);
  meadow_batch(m).vertices(m.key, camera, vertices, counts, output_origin_);
}

namespace {

static_assert(BOREAS_BRANCH_RECORD_FLOATS == BOREAS_TREE_RECORD_FLOATS &&
                  BOREAS_TREE_RECORD_BROKEN == BOREAS_TREE_STATE_PLANES + BOREAS_TREE_RADIUS_TIP_CAP &&
                  BOREAS_TREE_RADIUS_TIP_CAP + 1 == BOREAS_TREE_RADIUS_BULGE_PHASE &&
                  BOREAS_TREE_RADIUS_BULGE_PHASE + 1 == BOREAS_TREE_RADIUS_PLANES &&
                  BOREAS_TREE_RECORD_BULGE_PHASE < BOREAS_TREE_RECORD_FLOATS,
              "cl/export_records.cl writes the state planes, the radius planes but the cap and "
              "the phase, the flag, the cap, the phase");
static_assert(BOREAS_LEAF_RECORD_FLOATS == BOREAS_TREE_LEAF_OUT_PLANES, "cl/export_records.cl");

}  // namespace

void World::enqueue_branch_records(boreas_tree_id id, const cl::Buffer& out, size_t first) {
  const TreeInstance& tree = *trees_.get(id);
  check_buffer_holds(out, first, size_t(tree.model->branch_count()),
                     BOREAS_BRANCH_RECORD_FLOATS * sizeof(float), "branch record");
  tree_batch(tree).enqueue_branch_records(tree.key, out, first, output_origin_);
}

void World::enqueue_leaf_records(boreas_tree_id id, const cl::Buffer& out, size_t first) {
  const TreeInstance& tree = *trees_.get(id);
  check_buffer_holds(out, first, size_t(tree.model->leaf_count()),
                     BOREAS_LEAF_RECORD_FLOATS * sizeof(float), "leaf record");
  tree_batch(tree).enqueue_leaf_records(tree.key, out, first, output_origin_);
}

boreas_collider_id World::add_collider(const boreas_collider_def& def) {
  Collider c;
  c.def = checked_collider_def(def, "collider_def");
  return colliders_.insert(c);
}

void World::remove_collider(boreas_collider_id id) { colliders_.erase(id); }

void World::set_collider_position(boreas_collider_id id, const float center[3]) {
  Collider& c = colliders_.get(id);
  check_position(center, "center");
  for (int a = 0; a < 3; ++a) {
    c.def.pose.position[a] = center[a];
    c.def.pose.origin[a] = 0.0;  // center is a world position (boreas.h)
  }
}

void World::set_collider_pose(boreas_collider_id id, const boreas_pose* pose) {
  Collider& c = colliders_.get(id);
  if (!pose) fail_argument("pose is NULL");
  boreas_collider_def d = c.def;
  d.pose = *pose;
  c.def = checked_collider_def(d, "collider");
}

void World::set_collider_velocity(boreas_collider_id id, const float* velocity,
                                  const float* angular_velocity) {
  Collider& c = colliders_.get(id);
  boreas_collider_def d = c.def;
  for (int a = 0; a < 3; ++a) {
    if (velocity) d.velocity[a] = velocity[a];
    if (angular_velocity) d.angular_velocity[a] = angular_velocity[a];
  }
  c.def = checked_collider_def(d, "collider");
}

StepColliders World::step_colliders(double dt, std::vector<boreas_collider_id>* ids) {
  StepColliders out;
  out.dt = dt;
  colliders_.for_each_id([&](boreas_collider_id id, const Collider& c) {
    ids->push_back(id);
    out.add(c);
  });
  return out;
}

boreas_collider_contact World::collider_contact(boreas_collider_id id) {
  colliders_.get(id);  // a stale or foreign id is refused
  read_contacts();
  boreas_collider_contact out{};
  for (size_t i = 0; i < step_collider_ids_.size(); ++i) {
    const boreas_collider_id& s = step_collider_ids_[i];
    if (s.index != id.index || s.generation != id.generation) continue;
    for (int a = 0; a < 3; ++a) {
      out.force[a] = float(contacts_[i].force[size_t(a)]);
      out.torque[a] = float(contacts_[i].torque[size_t(a)]);
    }
    out.contacts = int32_t(std::min<int64_t>(contacts_[i].contacts, INT32_MAX));
  }
  return out;
}

void World::read_contacts() {
  if (contacts_read_) return;
  std::vector<ContactSum> sums(step_collider_ids_.size());
  for (TreeBatch* batch : all_tree_batches()) batch->add_contacts(&sums);
  for (UnderbrushBatch* batch : all_meadow_batches()) batch->add_contacts(&sums);
  mesh_batch_->add_contacts(&sums);
  contacts_ = std::move(sums);
  contacts_read_ = true;
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
  for (int a = 0; a < 3; ++a) {
    e.def.center[a] = center[a];
    e.def.origin[a] = 0.0;  // center is a world position (boreas.h)
  }
}

}  // namespace boreas::impl

namespace boreas::impl {

RaySources World::ray_sources(bool objects) {
  RaySources s;
  s.objects = objects;
  s.solid_boxes = &wind_->solid_boxes();
  s.mesh_batch = mesh_batch_.get();
  s.underbrush = all_meadow_batches();
  s.changes = changes_;
  s.steps = steps_;
  s.origin = output_origin_;
  if (!objects) return s;
  trees_.for_each_id([&](boreas_tree_id id, const std::shared_ptr<const TreeInstance>& t) {
    s.trees.push_back({id, t.get(), &tree_batch(*t)});
  });
  mesh_trees_.for_each_id([&](boreas_mesh_tree_id id, const std::shared_ptr<const MeshTreeInstance>& t) {
    s.mesh_trees.push_back({id, t.get()});
  });
  meadows_.for_each_id([&](boreas_meadow_id id, const std::shared_ptr<const MeadowInstance>& m) {
    s.meadows.push_back({id, m.get()});
  });
  blobtrees_.for_each_id([&](boreas_blobtree_id id, const std::shared_ptr<const BlobTreeInstance>& b) {
    s.blobtrees.push_back({id, b.get()});
  });
  return s;
}

RayScene& World::update_rays(const RayReach& reach) {
  if (!rays_) rays_ = std::make_unique<RayScene>(*runtime_);
  rays_->update(ray_sources(!rays_->current(changes_, wind_->solid_boxes(), output_origin_)),
                reach);
  return *rays_;
}

void World::cast_rays(const boreas_ray* rays, int count, boreas_hit* hits) {
  const RayReach reach = checked_rays(rays, count, hits);
  if (count == 0) return;
  update_rays(reach);
  const size_t n = size_t(count);
  cl::Buffer in = runtime_->buffer(CL_MEM_READ_ONLY, n * sizeof(boreas_ray), "rays");
  cl::Buffer out = runtime_->buffer(CL_MEM_WRITE_ONLY, n * sizeof(boreas_hit), "hits");
  runtime_->write(in, 0, n * sizeof(boreas_ray), rays);
  rays_->enqueue_cast(in, 0, count, out, 0);
  runtime_->read(out, 0, n * sizeof(boreas_hit), hits);
}

void World::enqueue_cast_rays(const cl::Buffer& rays, size_t first_ray, int count,
                              const cl::Buffer& hits, size_t first_hit) {
  const RayReach reach = checked_device_rays(*runtime_, rays, first_ray, count, hits, first_hit);
  if (count == 0) return;
  update_rays(reach).enqueue_cast(rays, first_ray, count, hits, first_hit);
}

}  // namespace boreas::impl
