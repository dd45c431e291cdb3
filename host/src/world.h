// boreas: a world — the runtime on its device, the wind and the plants, and the tables of
// what was added, advanced by step().
//
// A step, in order (enqueued together, finished once); stages 1-5 are the wind's
// (Wind::enqueue_step), 6-7 the plants', which read the wind it hands them (PlantWind):
//  1. time advances; expired primitives and gusts are removed; faded wave sets dropped;
//  2. the wave set's device copy is rewritten for the new time (blend weights, phases);
//  3. a grid that follows the focus moves when the focus has left its middle (its wind
//     copied where the extents overlap, solid boxes laid into the new cells); when a flow
//     primitive came or went, or the grid moved, the steady forcing field is rebuilt
//     (wind_forcing_field.cl);
//  4. the sine sum is evaluated per grid column (wind_sine_slab.cl);
//  5. the force-field grid is updated (wind_grid_step.cl);
//  6. trees: every branch re-attached and bent by the wind just computed (tree_step.cl,
//     one launch for lagged trees, one per level for exact trees), then their leaves
//     (tree_leaves.cl);
//     and imported trees: the wind at every branch low-passed, the trees that colliders
//     meet bent out of them through their branches (mesh_tree_contact.cl), then every
//     trunk and leaf vertex swayed (mesh_tree_branches.cl, mesh_tree_vertices.cl);
//  7. underbrush: every component's center of mass moved toward its equilibrium under
//     gravity, that wind, the colliders and the emitters' impulses (underbrush_step.cl);
//  8. once the plants' new state is kept: sensors, each LiDAR casting the firings of its
//     sweep that fall in the step (sensors/lidar.h), from the poses between its last and
//     the one set, into the plants as they now stand. The casts read the kept state, so
//     they run after the commit: a cast that fails there (device memory, a lost device)
//     leaves every LiDAR as it was but the plants stepped, and the step reports it.
//
// Every mutating call checks all its arguments before it changes anything.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "blobtree/blobtree_instance.h"
#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "colliders/collider.h"
#include "colliders/contacts.h"
#include "mesh_trees/mesh_tree_batch.h"
#include "rays/ray_scene.h"
#include "runtime/runtime.h"
#include "sensors/depth_camera.h"
#include "sensors/lidar.h"
#include "slot_map.h"
#include "trees/tree_batch.h"
#include "trees/tree_templates.h"
#include "underbrush/interaction.h"
#include "underbrush/underbrush_batch.h"
#include "wind/wind.h"

namespace boreas::impl {

class World {
 public:
  explicit World(const boreas_world_def& def);

  void step(float dt);
  double time() const { return time_; }
  const boreas_step_stats& step_stats() const { return step_stats_; }

  // The wind: waves, grid, primitives, gusts, solids, sampling (wind/wind.h). Its changes
  // take the world's time().
  Wind& wind() { return *wind_; }
  const Wind& wind() const { return *wind_; }

  // Trees (every def is checked and the species loaded before anything changes). Trees
  // of equal species and seed share one grown model (trees/tree_templates.h).
  boreas_tree_id add_tree(const boreas_tree_def& def);
  // Errors name defs[i] (name_defs; the batch API) or not (one tree).
  std::vector<boreas_tree_id> add_trees(const boreas_tree_def* defs, int count,
                                        bool name_defs = true);
  void remove_tree(boreas_tree_id id);
  // Mends its broken branches and puts it back at rest (TreeBatch::heal).
  void heal_tree(boreas_tree_id id);
  // Focus points for the trees' levels of detail (xyz packed; none: full detail).
  void set_focus(const float* xyz, int count);
  // Where handed-back positions of meadows and imported trees count from (NULL: 0).
  void set_output_origin(const double* origin);
  const std::array<double, 3>& output_origin() const { return output_origin_; }
  size_t tree_count() const { return trees_.size(); }
  size_t template_count() const { return templates_.size(); }
  const TreeInstance& tree(boreas_tree_id id) { return *trees_.get(id); }
  std::vector<boreas_branch> tree_branches(boreas_tree_id id);
  std::vector<boreas_leaf> tree_leaves(boreas_tree_id id);
  void tree_mesh(boreas_tree_id id, std::vector<boreas_vertex>* vertices,
                 std::vector<uint32_t>* indices);
  // The first chunk of a mode's trees: the only one while they fit in one allocation
  // (tests and benchmarks that add to a batch by hand); tree_chunks: all of them.
  TreeBatch& tree_batch(boreas_tree_mode mode) { return *tree_chunks(mode).front(); }
  const std::vector<std::unique_ptr<TreeBatch>>& tree_chunks(boreas_tree_mode mode) const {
    return chunks_[mode == BOREAS_TREE_EXACT ? 1 : 0];
  }
  // The chunk that holds the tree.
  TreeBatch& tree_batch(const TreeInstance& tree);
  // Tests: the whole models' bytes an add of trees holds before it hands a piece of them to
  // the batches (64 MB; add_tree_pieces), and the most it held at once in the last add.
  void set_add_piece_bytes(size_t bytes) { add_piece_bytes_ = bytes; }
  size_t add_peak_whole_bytes() const { return add_peak_whole_bytes_; }

  // Imported trees (Kusternig sec. 5): the def is checked and the model preprocessed (or
  // its cache read) before anything changes.
  boreas_mesh_tree_id add_mesh_tree(const boreas_mesh_tree_def& def);
  void remove_mesh_tree(boreas_mesh_tree_id id);
  boreas_mesh_tree_info mesh_tree_info(boreas_mesh_tree_id id);
  std::vector<boreas_vertex> mesh_tree_vertices(boreas_mesh_tree_id id,
                                                const boreas_mesh_part& part);
  const std::vector<uint32_t>& mesh_tree_indices(boreas_mesh_tree_id id,
                                                 const boreas_mesh_part& part);
  const MeshTreeInstance& mesh_tree(boreas_mesh_tree_id id) { return *mesh_trees_.get(id); }
  MeshTreeBatch& mesh_tree_batch() { return *mesh_batch_; }

  // BlobTree trees: a tree's implicit surface, polygonized (checked, built and meshed
  // before anything is kept).
  boreas_blobtree_id add_blobtree(boreas_tree_id tree, const boreas_blobtree_def& def,
                                  const BlobProgress& progress);
  void remove_blobtree(boreas_blobtree_id id);
  const BlobTreeInstance& blobtree(boreas_blobtree_id id) { return *blobtrees_.get(id); }

  // Underbrush (the def is checked, species loaded and the meadow planted before anything
  // changes).
  boreas_meadow_id add_meadow(const boreas_meadow_def& def);
  std::vector<boreas_meadow_id> add_meadows(const boreas_meadow_def* defs, int count,
                                            bool name_defs = true);
  boreas_meadow_id add_meadow(Meadow meadow);  // planted already (tests place plants by hand)
  void remove_meadow(boreas_meadow_id id);
  std::vector<boreas_component> meadow_components(boreas_meadow_id id);
  std::vector<boreas_meadow_part> meadow_parts(boreas_meadow_id id);
  // Strips of 2 * BOREAS_UB_JOINTS vertices (8 floats each) per component, and their counts.
  void meadow_vertices(boreas_meadow_id id, const float* camera, std::vector<float>* vertices,
                       std::vector<int32_t>* counts);
  // The first chunk of the meadows (world_chunks.cpp): the only one while they fit in
  // one allocation; meadow_chunks: all of them; meadow_batch: the one that holds a meadow.
  UnderbrushBatch& underbrush() { return *meadow_chunks_.front(); }
  const std::vector<std::unique_ptr<UnderbrushBatch>>& meadow_chunks() const {
    return meadow_chunks_;
  }
  UnderbrushBatch& meadow_batch(const MeadowInstance& meadow);
  int meadow_component_count(boreas_meadow_id id) { return meadows_.get(id)->meadow.count; }
  const MeadowInstance& meadow(boreas_meadow_id id) { return *meadows_.get(id); }
  // Colliders (colliders/collider.h): kinematic bodies the step moves by their velocities.
  boreas_collider_id add_collider(const boreas_collider_def& def);
  void remove_collider(boreas_collider_id id);
  void set_collider_position(boreas_collider_id id, const float center[3]);
  void set_collider_pose(boreas_collider_id id, const boreas_pose* pose);
  void set_collider_velocity(boreas_collider_id id, const float* velocity,
                             const float* angular_velocity);
  boreas_pose collider_pose(boreas_collider_id id) { return colliders_.get(id).def.pose; }
  // What the plants did to it over the last step (read back from the batches at the first
  // call after a step).
  boreas_collider_contact collider_contact(boreas_collider_id id);
  boreas_emitter_id add_emitter(const boreas_emitter_def& def);
  void remove_emitter(boreas_emitter_id id);
  void set_emitter_position(boreas_emitter_id id, const float center[3]);

  // Device records written into a renderer's buffers (boreas_cl.h): enqueued only; each
  // checks that `out` holds them from `first` on.
  void enqueue_branch_records(boreas_tree_id tree, const cl::Buffer& out, size_t first);
  void enqueue_leaf_records(boreas_tree_id tree, const cl::Buffer& out, size_t first);
  // A view's records of every tree (boreas_world_enqueue_tree_records): the view checked,
  // then each chunk's launches, the lagged chunks' counts first.
  void enqueue_tree_records(const boreas_tree_view_def& view,
                            const TreeBatch::RecordOutputs& out);
  // boreas_tree_get_template.
  int tree_template(boreas_tree_id tree);
  // Any list of meadows' strips or imported trees' vertices in one launch (world_vertices.cpp,
  // boreas_cl.h): every entry checked, its range against the buffers and the ranges
  // disjoint, before anything is enqueued; `named`: failures name the entry's index (the
  // list calls; the single-object calls are lists of one and need not).
  void enqueue_meadow_vertices(const boreas_meadow_id* meadows, const size_t* firsts, int count,
                               const float* camera, const cl::Buffer& vertices,
                               const cl::Buffer& counts, bool named);
  void enqueue_mesh_tree_vertices(const boreas_mesh_tree_id* trees, const size_t* firsts,
                                  int count, const boreas_mesh_part& part, const cl::Buffer& out,
                                  bool named);

  // The simulated state as one number (boreas_world_get_state_hash): time, the grid's cells,
  // every tree's state and motion, every imported tree's branch wind and swayed vertices,
  // every meadow's state, in the order they were added. Reads it all back (blocking).
  uint64_t state_hash();

  // Rays (boreas_world_cast_rays): the nearest hit along each ray as of the last step.
  // rays are checked before anything is cast (errors name the ray's index).
  void cast_rays(const boreas_ray* rays, int count, boreas_hit* hits);
  // The same, rays read from and hits written to device buffers (boreas_cl.h).
  void enqueue_cast_rays(const cl::Buffer& rays, size_t first_ray, int count,
                         const cl::Buffer& hits, size_t first_hit);
  // What the ray structure reads of this world now; its lists of objects only when
  // `objects` (the structure is to be rebuilt).
  RaySources ray_sources(bool objects);
  // The ray structure made current for rays within `reach` (made at the first call): what
  // both casts do first; benchmarks call it to time the update apart and read the
  // structure back (RayScene::host_copy).
  RayScene& update_rays(const RayReach& reach);

  // Sensors (sensors/): spinning LiDARs cast every step; a depth image on demand.
  boreas_lidar_id add_lidar(const boreas_lidar_def& def);
  void remove_lidar(boreas_lidar_id id);
  void set_lidar_pose(boreas_lidar_id id, const boreas_pose* pose);
  const Lidar& lidar(boreas_lidar_id id) { return lidars_.get(id); }
  void capture_depth(const boreas_depth_camera_def& camera, float* depth,
                     boreas_pixel_label* labels);

  Runtime& runtime() { return *runtime_; }

  // A world is locked while one of its calls runs the caller's code (a progress callback):
  // a call into the same world from there (a callback that steps the world it reports
  // on) is refused, as Box2D's locked world refuses, instead of corrupting the call in
  // progress. The C API checks every call on entry (check_unlocked).
  void check_unlocked() const;

 private:
  // Held while the caller's code may run; call names the entry point in the refusal.
  class Lock {
   public:
    Lock(World& world, const char* call) : world_(world) { world_.locked_by_ = call; }
    ~Lock() { world_.locked_by_ = nullptr; }
    Lock(const Lock&) = delete;
    Lock& operator=(const Lock&) = delete;

   private:
    World& world_;
  };
  const char* locked_by_ = nullptr;
  // This world's number among the process's worlds: in every id it issues, so an id
  // handed to another world is caught.
  const uint32_t serial_ = claim_world_serial();
  std::unique_ptr<Runtime> runtime_;
  std::unique_ptr<Wind> wind_;
  std::unique_ptr<RayScene> rays_;  // made at the first cast
  uint64_t changes_ = 0;            // objects added and removed, for the ray structure
  uint64_t steps_ = 0;              // steps taken
  std::vector<double> focus_;  // the focus points, 3 per point
  std::array<double, 3> output_origin_{};  // m (boreas_world_set_output_origin)
  double time_ = 0.0;
  boreas_step_stats step_stats_{};

  // The trees of each mode (lagged, exact) in chunks: batches whose buffers each fit the
  // device's largest allocation (world_chunks.cpp says why chunks are whole batches).
  // Chunk 0 always exists; later ones are made when an add does not fit the earlier ones
  // and dropped once empty. The chunks of a mode share their template numbers.
  std::vector<std::unique_ptr<TreeBatch>> chunks_[2];
  std::shared_ptr<TemplateNumbers> template_numbers_[2];
  // Every chunk of both modes, lagged first, in chunk order.
  std::vector<TreeBatch*> all_tree_batches() const;
  // add_trees' hand-over: each mode's trees into its chunks, first fit in chunk order, all
  // or none (on a failure every chunk is as it was). def_index: each tree's index in the
  // call, for an error that names it (name_defs as in add_trees).
  // Its order: as given, or by template where the trees need more than the first chunk.
  void order_for_chunks(const TreeBatch::Trees& trees, const std::vector<int>& def_index,
                        TreeBatch::Trees* ordered, std::vector<int>* index) const;
  void add_to_tree_chunks(const TreeBatch::Trees (&trees)[2],
                          const std::vector<int> (&def_index)[2], bool name_defs);
  // add_trees' growth and hand-over (world_tree_pieces.cpp): the request's templates grown
  // a round at a time on every core; once the whole models held pass add_piece_bytes_ (or
  // all are grown), the trees of those templates go to the chunks and the models are
  // packed, so an add holds at most that many bytes of whole models (and a round) above
  // what it keeps, whatever its count. All or none: a failure takes the earlier pieces'
  // trees back out and gives every chunk back the room it had (named: add_trees' naming
  // of a def's error, which throws).
  void add_tree_pieces(TreeTemplates::Request& request,
                       const std::vector<std::shared_ptr<TreeInstance>>& all, bool name_defs,
                       const std::function<void(int, const Error&)>& named);
  // After the first piece: the rest of the call's room made at once (world_tree_pieces.cpp).
  void reserve_for_the_rest(const TreeBatch::Room (&before)[2], size_t trees, size_t taken);
  size_t add_piece_bytes_ = size_t(64) << 20;
  size_t add_peak_whole_bytes_ = 0;
  SlotMap<boreas_tree_id, std::shared_ptr<const TreeInstance>> trees_{serial_};
  uint64_t next_tree_key_ = 1;
  TreeTemplates templates_;
  std::unique_ptr<MeshTreeBatch> mesh_batch_;
  SlotMap<boreas_mesh_tree_id, std::shared_ptr<const MeshTreeInstance>> mesh_trees_{serial_};
  uint64_t next_mesh_tree_key_ = 1;
  SlotMap<boreas_blobtree_id, std::shared_ptr<const BlobTreeInstance>> blobtrees_{serial_};
  BlobScratch blob_scratch_;  // the field grid kept between polygonizations
  // The meadows in chunks, as the trees (chunk 0 always; the tiles' phase numbers shared).
  std::vector<std::unique_ptr<UnderbrushBatch>> meadow_chunks_;
  std::shared_ptr<PlaceNumbers> meadow_tile_numbers_ = std::make_shared<PlaceNumbers>();
  std::vector<UnderbrushBatch*> all_meadow_batches() const;
  // The meadows into the chunks, first fit in their order, all or none (errors name
  // defs[i] where name_defs).
  void add_to_meadow_chunks(const UnderbrushBatch::Meadows& meadows, bool name_defs);
  SlotMap<boreas_meadow_id, std::shared_ptr<const MeadowInstance>> meadows_{serial_};
  uint64_t next_meadow_key_ = 1;
  SlotMap<boreas_collider_id, Collider> colliders_{serial_};
  // The last step's colliders in kernel order, and their contacts once read.
  std::vector<boreas_collider_id> step_collider_ids_;
  std::vector<ContactSum> contacts_;
  bool contacts_read_ = true;
  // Reads them from the batches (once after a step: blocking).
  void read_contacts();
  SlotMap<boreas_emitter_id, Emitter> emitters_{serial_};
  SlotMap<boreas_lidar_id, Lidar> lidars_{serial_};

  // The colliders as the step over dt sees them (kernel order) and their ids.
  StepColliders step_colliders(double dt, std::vector<boreas_collider_id>* ids);
  // Stage 8 of step(): every LiDAR casts its firings in [t0, t1) into the state just kept.
  void sense(double t0, double t1);
};

}  // namespace boreas::impl
