// boreas: every imported tree of a world on the device — their branches, vertices, leaves
// and noise in planar tables, stepped together (cl/mesh_wind_branches.cl, then
// cl/mesh_wind_vertices.cl) into one buffer of trunk positions and one of leaf vertices.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "mesh_wind/noise_texture.h"
#include "mesh_wind/tree_model.h"
#include "mesh_wind/wind_weights.h"
#include "runtime/runtime.h"
#include "trees/tree_batch.h"

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
  MeshWindData data;
  NoiseTexture noise;
  bool from_cache = false;
  std::string cache_note;  // why the cache could not be used or written, if it could not
  uint64_t key = 0;        // the batch's handle
};

// Counts of a preprocessed tree, as the C API reports them.
boreas_mesh_tree_info describe_mesh_tree(const MeshModel& model, const MeshWindData& data,
                                         bool from_cache);

// Model space -> world: scale, then yaw about +Y, then the position.
void place_point(const MeshTreeParams& p, const float in[3], float out[3]);
void place_direction(const MeshTreeParams& p, const float in[3], float out[3]);

// The static tables of a batch of trees in this order (layouts in
// cl/shared/mesh_wind_types.h), placed in the world, with each tree's offsets; trunk_rest
// and leaf_rest are the outputs' rest pose. For the batch and the benchmark's native twin.
struct MeshWindTables {
  size_t branches = 0, trunk_vertices = 0, leaves_count = 0, leaf_vertices_count = 0;
  std::vector<size_t> first_branch, first_trunk, first_leaf, first_leaf_vertex;  // per tree
  std::vector<float> branch_table;  // BOREAS_MW_BRANCH_FLOATS planes
  std::vector<int32_t> links;       // BOREAS_MW_BRANCH_INTS planes
  std::vector<float> noise;         // per tree: channel 0, then channel 1
  std::vector<float> trunk;         // BOREAS_MW_TRUNK_FLOATS planes
  std::vector<int32_t> trunk_branch;
  std::vector<float> trunk_rest;  // 3 floats per trunk vertex
  std::vector<float> leaves;      // BOREAS_MW_LEAF_FLOATS planes
  std::vector<int32_t> leaf_branch;
  std::vector<float> leaf_vertices;  // BOREAS_MW_LEAF_VERTEX_FLOATS planes
  std::vector<int32_t> vertex_leaf;
  std::vector<float> leaf_rest;  // 6 floats per leaf vertex: position, normal
};
MeshWindTables mesh_wind_tables(const std::vector<const MeshTreeInstance*>& trees);

// The tree planes (BOREAS_MW_TREE_*) of a step to `time` (s); fresh: per tree, not stepped
// yet.
std::vector<float> mesh_wind_tree_params(const std::vector<const MeshTreeInstance*>& trees,
                                         const std::vector<bool>& fresh, double time);

// The events of one step's three kernels, for profiling (the benchmark).
struct MeshWindStepEvents {
  cl::Event branches, trunk, leaves;
};

class MeshTreeBatch {
 public:
  explicit MeshTreeBatch(Runtime& runtime);

  bool empty() const { return trees_.empty(); }
  size_t trunk_vertex_count() const { return trunk_vertices_; }
  size_t leaf_vertex_count() const { return leaf_vertices_; }

  // Rebuilds every table with the tree added (or removed) and the others' state kept; the
  // new tree stands at rest until its first step. Nothing changes if this throws.
  void add(std::shared_ptr<const MeshTreeInstance> tree, double time);
  void remove(uint64_t key, double time);

  // Enqueues a step to time `time` (s since the world began) in the wind given; with
  // `events`, each kernel's event is kept there. The per-step upload must finish before
  // the next step is enqueued (finish the queue in between).
  void enqueue_step(double dt, double time, const TreeWindInput& wind,
                    MeshWindStepEvents* events = nullptr);
  void commit();

  // Blocking readbacks of one tree (world space, as of the last commit).
  std::vector<boreas_vertex> trunk_vertices(uint64_t key);
  std::vector<boreas_vertex> leaf_vertices(uint64_t key);
  // Enqueues a copy of one tree's animated part into out from vertex `first` on: trunk
  // positions (3 floats each) or leaf positions and normals (6 floats each).
  void enqueue_copy(uint64_t key, boreas_mesh_part part, const cl::Buffer& out, size_t first);

  // For tests and the benchmark: the wind each branch of a tree feels (3 floats per
  // branch), and how far its leaf noise has rolled (u, v in tiles).
  std::vector<float> branch_wind(uint64_t key);
  std::vector<float> noise_roll(uint64_t key);

 private:
  struct Placed {
    std::shared_ptr<const MeshTreeInstance> tree;
    int index = 0;  // in the tree tables
    size_t first_branch = 0, first_trunk = 0, first_leaf = 0, first_leaf_vertex = 0;
    bool fresh = true;
  };
  const Placed& placed(uint64_t key) const;
  void rebuild(std::vector<Placed> trees, double time);
  void enqueue_vertices(const cl::Buffer& state, const cl::Buffer& roll,
                        MeshWindStepEvents* events = nullptr);

  Runtime& runtime_;
  std::vector<Placed> trees_;
  size_t branches_ = 0, trunk_vertices_ = 0, leaves_ = 0, leaf_vertices_ = 0;
  cl::Buffer branch_table_, links_, state_[2], roll_[2], tree_table_, noise_;
  cl::Buffer trunk_, trunk_branch_, trunk_out_;
  cl::Buffer leaf_table_, leaf_branch_, leaf_vertex_table_, vertex_leaf_, leaf_out_;
  std::vector<float> tree_staging_;  // the per-step upload, alive until the step finishes
  int current_ = 0;
};

}  // namespace boreas::impl
