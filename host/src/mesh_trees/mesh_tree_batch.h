// boreas: every imported tree of a world on the device — their branches, vertices, leaves
// and noise in planar tables, stepped together (cl/mesh_tree_branches.cl, then
// cl/mesh_tree_vertices.cl) into one buffer of trunk positions and one of leaf vertices.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "boreas/boreas.h"
#include "colliders/contacts.h"
#include "mesh_trees/mesh_tree_drag.h"
#include "mesh_trees/noise_texture.h"
#include "mesh_trees/tree_model.h"
#include "mesh_trees/wind_weights.h"
#include "runtime/block_space.h"
#include "runtime/runtime.h"
#include "shared/range_table.h"
#include "wind/plant_wind.h"

namespace boreas::impl {

// A checked boreas_mesh_tree_def, strings owned.
struct MeshTreeParams {
  std::string model, trunk_part, leaves_part;
  std::array<float, 3> position{};
  float yaw = 0.0f, scale = 1.0f;
  uint64_t seed = 0;
  float noise_beta = 2.0f, bend_exponent = 2.0f;
  std::array<boreas_mesh_level_def, 4> levels{};
  float leaf_flutter = 0.0f, leaf_turn = 0.0f, flutter_wavelength = 8.0f;
  bool cache = true;
};

// Throws Error (INVALID_ARGUMENT) naming the first bad field.
MeshTreeParams checked_mesh_tree_def(const boreas_mesh_tree_def& def);

// One imported tree as placed: model-space mesh and animation data, and its noise.
struct MeshTreeInstance {
  MeshTreeParams params;
  MeshModel model;
  MeshTreeData data;
  NoiseTexture noise;
  MeshTreeDrag drag;  // its load, from its mesh's areas (mesh_tree_drag.h)
  bool from_cache = false;
  std::string cache_note;  // why the cache could not be used or written, if it could not
  uint64_t key = 0;        // the batch's handle
};

// Counts of a preprocessed tree, as the C API reports them.
boreas_mesh_tree_info describe_mesh_tree(const MeshModel& model, const MeshTreeData& data,
                                         bool from_cache);

// Model space -> world: scale, then yaw about +Y, then the position; place_local leaves
// out the position (the tree's own coordinates, which its tables hold: mesh_tree_types.h).
void place_point(const MeshTreeParams& p, const float in[3], float out[3]);
void place_local(const MeshTreeParams& p, const float in[3], float out[3]);
void place_direction(const MeshTreeParams& p, const float in[3], float out[3]);

// The static tables of a batch of trees in this order (layouts in
// cl/shared/mesh_tree_types.h), placed in the world, with each tree's offsets; trunk_rest
// and leaf_rest are the outputs' rest pose. For the batch and the benchmark's native twin.
struct MeshTreeTables {
  size_t branches = 0, trunk_vertices = 0, leaves_count = 0, leaf_vertices_count = 0;
  std::vector<size_t> first_branch, first_trunk, first_leaf, first_leaf_vertex;  // per tree
  std::vector<float> branch_table;  // BOREAS_MESH_TREE_BRANCH_FLOATS planes
  std::vector<int32_t> links;       // BOREAS_MESH_TREE_BRANCH_INTS planes
  std::vector<float> noise;         // per tree: channel 0, then channel 1
  std::vector<float> trunk;         // BOREAS_MESH_TREE_TRUNK_FLOATS planes
  std::vector<int32_t> trunk_branch;
  std::vector<float> trunk_rest;  // 3 floats per trunk vertex
  std::vector<float> leaves;      // BOREAS_MESH_TREE_LEAF_FLOATS planes
  std::vector<int32_t> leaf_branch;
  std::vector<float> leaf_vertices;  // BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS planes
  std::vector<int32_t> vertex_leaf;
  std::vector<float> leaf_rest;  // 6 floats per leaf vertex: position, normal
  std::vector<float> contact;    // BOREAS_MESH_TREE_CONTACT_FLOATS planes (per branch)
};
MeshTreeTables mesh_tree_tables(const std::vector<const MeshTreeInstance*>& trees);

// The tree planes (BOREAS_MESH_TREE_TREE_*) of a step to `time` (s), `stride` floats apart (at
// least the tree count); fresh: per tree, not stepped yet; a null tree's entries are zero.
std::vector<float> mesh_tree_planes(const std::vector<const MeshTreeInstance*>& trees,
                                    const std::vector<bool>& fresh, double time, size_t stride = 0);

// The events of one step's three kernels, for profiling (the benchmark).
struct MeshTreeStepEvents {
  cl::Event branches, trunk, leaves;
};

// The trees' entries lie in five index spaces (runtime/block_space.h): branches, trunk
// vertices, leaves, leaf vertices and tree slots, each in planes whose stride is the
// space's capacity. Adding a tree writes its own entries at the spaces' ends (growing
// them by doubling, with device copies, when full); removing one leaves holes, which the
// launches run over harmlessly, and packs the spaces once holes pass half. The other
// trees' tables and state are never read back or uploaded again.
class MeshTreeBatch {
 public:
  explicit MeshTreeBatch(Runtime& runtime);

  bool empty() const { return by_key_.empty(); }

  // Adds the tree (at rest until its first step) or removes it, touching only its own
  // entries; the others' state is kept bit for bit. Nothing changes if this throws.
  // `time` is unused (each step uploads the trees' clocks).
  void add(std::shared_ptr<const MeshTreeInstance> tree, double time);
  void remove(uint64_t key, double time);

  // Enqueues a step to time `time` (s since the world began) in the wind given, the
  // colliders bending the trees their swept bounds meet (mesh_tree_contact.cl); with
  // `events`, each kernel's event is kept there. The per-step upload must finish before
  // the next step is enqueued (finish the queue in between).
  void enqueue_step(double dt, double time, const PlantWind& wind,
                    const StepColliders& colliders, MeshTreeStepEvents* events = nullptr);
  void enqueue_step(double dt, double time, const PlantWind& wind,
                    MeshTreeStepEvents* events = nullptr) {
    enqueue_step(dt, time, wind, StepColliders(), events);
  }
  void commit();

  // What the trees pushed each collider with over the last committed step, added to
  // sums (indexed in that step's collider order): one blocking read of the touched trees'
  // sums, added in tree order.
  void add_contacts(std::vector<ContactSum>* sums);
  // Trees a collider bends or recently bent (they run the contact kernel), for tests.
  size_t trees_in_contact() const { return contact_keys_.size(); }

  // m: the origin of the coordinates positions are read out in (the world's 0 by default;
  // boreas_world_set_output_origin).
  using Origin = std::array<double, 3>;
  // Blocking readbacks of one tree (as of the last commit), relative to output_origin.
  std::vector<boreas_vertex> trunk_vertices(uint64_t key, const Origin& output_origin = {});
  std::vector<boreas_vertex> leaf_vertices(uint64_t key, const Origin& output_origin = {});
  // One tree of a copy: its part's vertices to out from vertex `first` on.
  struct CopyTo {
    uint64_t key;
    size_t first;
  };
  // Enqueues ONE launch copying the listed trees' animated part into out: trunk positions
  // (3 floats each) or leaf positions and normals (6 floats each).
  void enqueue_copy(const std::vector<CopyTo>& trees, boreas_mesh_part part,
                    const cl::Buffer& out, const Origin& output_origin = {});

  // For tests and the benchmark: the wind each branch of a tree feels (3 floats per
  // branch), and how far its leaf noise has rolled (u, v in tiles).
  std::vector<float> branch_wind(uint64_t key);
  std::vector<float> noise_roll(uint64_t key);

 private:
  struct Placed {
    std::shared_ptr<const MeshTreeInstance> tree;
    int64_t slot = 0;  // in the tree tables
    int64_t first_branch = 0, first_trunk = 0, first_leaf = 0, first_leaf_vertex = 0;
    Bounds reach;  // mesh_tree_reach
  };
  struct Capacities {
    int64_t branches, trunk, leaves, leaf_vertices, slots;
  };
  const Placed& placed(uint64_t key) const;
  // What moves a tree's vertices from its own coordinates to the output's.
  static std::array<double, 3> shift(const Placed& p, const Origin& output_origin);
  // The step's wave phases at each slot's tree (mesh_tree_branches.cl).
  void upload_phases(const PlantWind& wind);
  void write_tree(const MeshTreeInstance& tree, const Placed& at);
  void write_indices(const std::vector<Placed>& trees, const Capacities& caps,
                     const cl::Buffer& links_to, const cl::Buffer& trunk_branch_to,
                     const cl::Buffer& leaf_branch_to, const cl::Buffer& vertex_leaf_to);
  // New buffers of the capacities given, the trees copied into them on the device where
  // they are, or packed from entry 1 on.
  void relayout(const Capacities& to, bool pack);
  // relayout's steps: the new buffers (zero); where every tree goes in each of the five
  // spaces (branches, trunk, leaves, leaf vertices, slots), the trees as moved; the
  // device copies; then the batch takes the buffers, and after packing the places.
  struct Buffers;
  using Plans = std::array<BlockPlan, 5>;
  Buffers new_buffers(const Capacities& to);
  std::vector<Placed> plan_moves(bool pack, Plans& plans);
  void copy_moves(Buffers& b, const Plans& plans, const Capacities& to);
  void take_buffers(const Buffers& b);
  void take_packed(const Plans& plans, const std::vector<Placed>& moved);
  void enqueue_vertices(const cl::Buffer& state, const cl::Buffer& roll,
                        MeshTreeStepEvents* events = nullptr);
  // Colliders (mesh_tree_batch_contact.cpp): the trees this step bends and the launch
  // (returns whether there is any), then the bends added to those trees' vertices.
  bool enqueue_contacts(double dt, const StepColliders& colliders, const cl::Buffer& state,
                        int next);
  std::unordered_set<uint64_t> quiet_trees();  // of the last kept step's launch
  void enqueue_bends(const cl::Buffer& bend);
  void commit_contacts();

  Runtime& runtime_;
  std::unordered_map<uint64_t, Placed> by_key_;
  BlockSpace branches_, trunk_, leaves_, leaf_vertices_, slots_;
  // Their smallest capacities (branches and leaves; trunk and leaf vertices; trees): a
  // batch's first buffers, and where shrinking stops (runtime/block_space.h).
  static constexpr int64_t kMinBranches = 64, kMinVertices = 256, kMinSlots = 4;
  std::vector<const MeshTreeInstance*> slot_trees_{nullptr};  // by slot; null: hole or sink
  std::vector<bool> fresh_{false};                            // by slot: not stepped yet
  cl::Buffer branch_table_, links_, state_[2], roll_[2], tree_table_, noise_;
  cl::Buffer trunk_table_, trunk_branch_, trunk_out_;
  cl::Buffer leaf_table_, leaf_branch_, leaf_vertex_table_, vertex_leaf_, leaf_out_;
  // enqueue_copy's range table (cl/shared/range_table.h) and its host side.
  cl::Buffer copy_ranges_;
  size_t copy_capacity_ = 0;
  std::vector<BoreasCopyRange> copy_staging_;
  cl::Buffer phases_;
  size_t phase_capacity_ = 0;
  std::vector<float> phase_staging_;
  cl::Buffer contact_table_, bend_[2];
  std::vector<float> tree_staging_;  // the per-step upload, alive until the step finishes
  int current_ = 0;

  // Colliders: the trees in contact by key with the time a collider last met them (kept
  // in slot order for the launch), and the last step's pairs (tree, collider) whose sums
  // pair_out_ holds, half by half as the state.
  struct ContactStaging {
    std::vector<int32_t> active, pairs;
    std::vector<BoreasGpuCollider> colliders;  // per pair, relative to its tree's position
  };
  // The trees in contact, with the steps each has left zeroing its bends once at rest (0:
  // not yet at rest), as kept and as the step being enqueued leaves them.
  std::unordered_map<uint64_t, int> contact_keys_, pending_keys_;
  ContactStaging contact_staging_;
  cl::Buffer active_, colliders_, pair_out_[2], quiet_[2];
  std::vector<int32_t> pair_collider_[2];  // per pair, the collider's index in its step
  std::vector<uint64_t> bent_keys_[2];     // the trees of the step's contact launch
};

}  // namespace boreas::impl
