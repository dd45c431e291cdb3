// boreas: native C++ twins of the imported-tree kernels (cl/mesh_tree_branches.cl,
// cl/mesh_tree_vertices.cl), the yardstick boreas_bench compares them with: the kernels'
// own math (the C++ build of cl/shared/mesh_tree_math.h) on the same planes
// (cl/shared/mesh_tree_types.h) in the layout MeshTreeBatch builds. OpenMP threads
// over blocks of branches or vertices, SIMD within a block; the wind is native_wind_block.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_trees/mesh_tree_batch.h"
#include "native_trees.h"

namespace boreas::bench {

// Imported trees as MeshTreeBatch holds them, on the host: every table planar with the
// batch's strides, state and roll as ping-pong pairs (`current` is the committed one).
struct NativeMeshTrees {
  int nt = 0;                                            // trees
  int nb = 0;                                            // branches
  int nv = 0;                                            // trunk vertices
  int nl = 0;                                            // leaves
  int nlv = 0;                                           // leaf vertices
  std::vector<const impl::MeshTreeInstance*> instances;  // per tree, for the per-step tree table
  std::vector<bool> fresh;                               // per tree: not stepped yet
  std::vector<float> branches;                           // BOREAS_MESH_TREE_BRANCH_FLOATS planes
  std::vector<int32_t> links;                            // BOREAS_MESH_TREE_BRANCH_INTS planes
  std::vector<float> state[2];                           // BOREAS_MESH_TREE_STATE_FLOATS planes
  std::vector<float> roll[2];  // BOREAS_MESH_TREE_ROLL_FLOATS planes of stride nt
  std::vector<float> trees;    // BOREAS_MESH_TREE_TREE_FLOATS planes, per step
  std::vector<float> noise;    // per tree, channel 0 then 1
  std::vector<float> trunk;    // BOREAS_MESH_TREE_TRUNK_FLOATS planes
  std::vector<int32_t> trunk_branch;
  std::vector<float> leaves;  // BOREAS_MESH_TREE_LEAF_FLOATS planes
  std::vector<int32_t> leaf_branch;
  std::vector<float> leaf_vertices;  // BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS planes
  std::vector<int32_t> vertex_leaf;
  std::vector<float> trunk_out;  // 3 floats per trunk vertex (xyz)
  std::vector<float> leaf_out;   // 6 floats per leaf vertex (xyz, normal)
  int current = 0;
};

// The tables of MeshTreeBatch (impl::mesh_tree_tables) for these trees in this order
// (every tree fresh, at rest); trunk_out and leaf_out hold the rest pose. The trees must
// outlive the result.
NativeMeshTrees native_mesh_layout(const std::vector<const impl::MeshTreeInstance*>& trees);

// The tree planes of a step to `time` (s) (impl::mesh_tree_planes).
void native_mesh_tree_params(NativeMeshTrees& t, double time);

// cl/mesh_tree_branches.cl over every branch: state and roll from *_in to *_out.
void native_mesh_branches(const NativeMeshTrees& t, const float* state_in, float* state_out,
                          const float* roll_in, float* roll_out, float dt,
                          const NativeTreeWind& wind);

// boreas_mesh_tree_trunk and boreas_mesh_tree_leaves (cl/mesh_tree_vertices.cl) over every
// vertex, on the state and roll given, into trunk_out and leaf_out.
void native_mesh_trunk(NativeMeshTrees& t, const float* state);
void native_mesh_leaves(NativeMeshTrees& t, const float* state, const float* roll);

// MeshTreeBatch::enqueue_step + commit, natively: the tree planes, the branches, then
// both vertex passes on the new state. pass_seconds, if given, gets the wall time of the
// branch pass (with the tree planes), the trunk pass and the leaf pass added.
void native_mesh_step(NativeMeshTrees& t, double dt, double time, const NativeTreeWind& wind,
                      double pass_seconds[3] = nullptr);

}  // namespace boreas::bench
