// boreas: the animation data of an imported tree (Kusternig sec. 5.1.2-5.1.3 and 5.3):
// per-vertex weights for four levels, per-branch phases and motion vectors, and each
// leaf's weights, branch and petiole.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh_trees/branch_hierarchy.h"
#include "mesh_trees/tree_model.h"

namespace boreas::impl {

constexpr int kMeshTreeLevels = 4;  // the paper's four: one float4 of weights per vertex

// One branch's animation data, in model space.
struct MeshTreeBranch {
  int32_t parent = -1;  // -1 for the stem
  int32_t level = 0;    // may exceed 3: such a branch is animated by its level-3 ancestor
  // The branches whose motion moves this branch's vertices, per level 0..3: the ancestor
  // at that level, this branch at its own level, this branch again (with weight 0) below.
  std::array<int32_t, kMeshTreeLevels> animated_by{};
  std::array<float, 2> phase{};   // offset of its noise lookup, in tiles, 0..1
  std::array<float, 3> axis{};    // unit, base -> tip
  std::array<float, 3> up{};      // unit, normal to axis: the noise's second sway direction
  std::array<float, 3> right{};   // unit, up x axis: the noise's first sway direction
  std::array<float, 3> center{};  // m: the skeleton's middle, where the wind is sampled
  std::array<float, 3> base{};    // m
  std::array<float, 3> tip{};     // m
  float length = 0.0f;            // m, of the skeleton
  float radius = 0.0f;            // m, largest along the skeleton
  bool orphan = false;
};

struct MeshTreeData {
  std::vector<MeshTreeBranch> branches;          // levels in order, the stem first
  std::array<float, kMeshTreeLevels> longest{};  // m: longest branch per level (weight 1)
  int levels = 0;                                // levels found in the mesh (may exceed 4)
  int orphans = 0;  // runs that touched no branch and were hung on the nearest

  // Per trunk vertex: weights w_0..w_3 in 0..1, and the branch whose data animates it.
  std::vector<float> trunk_weights;  // 4 per vertex
  std::vector<int32_t> trunk_branch;

  // Per leaf (a connected run of leaf triangles): the weights and branch of the trunk
  // vertex nearest its petiole (sec. 5.3), the petiole (the leaf's vertex nearest the
  // trunk), its unit axis towards the farthest vertex, and that distance.
  std::vector<float> leaf_weights;  // 4 per leaf
  std::vector<int32_t> leaf_branch;
  std::vector<float> leaf_petiole;      // 3 per leaf, m
  std::vector<float> leaf_axis;         // 3 per leaf
  std::vector<float> leaf_length;       // m
  std::vector<int32_t> leaf_of_vertex;  // per leaf vertex
};

// The hierarchy, weights, phases (from seed) and motion vectors of a model. Throws Error
// (INVALID_ARGUMENT) when the trunk has no triangles.
MeshTreeData compute_mesh_tree(const MeshModel& model, uint64_t seed);

}  // namespace boreas::impl
