// boreas: the branch hierarchy of a tree mesh that has no bones or branch data (Kusternig
// sec. 5.1.1): branches are connected runs of triangles, the thickest is the stem, and
// each branch's parent is the branch of the level above that it grows out of.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh_trees/branch_skeleton.h"
#include "mesh_trees/tree_model.h"

namespace boreas::impl {

struct MeshBranch {
  std::vector<uint32_t> vertices;  // trunk vertex indices in this run of triangles
  BranchSkeleton skeleton;         // oriented base -> tip
  int parent = -1;                 // index in MeshHierarchy::branches; -1 for the stem
  int level = 0;                   // 0 stem, 1, 2, ... (no limit here)
  double attach_arc = 0.0;         // m along the parent's skeleton where the base sits
  bool orphan = false;             // touched no branch; hung on the nearest one instead
};

struct MeshHierarchy {
  std::vector<MeshBranch> branches;       // levels in order, the stem first
  std::vector<int32_t> branch_of_vertex;  // per trunk vertex
  int levels = 0;                         // deepest level + 1
  int orphans = 0;
};

// Positions closer than weld_tolerance (m) count as one when finding runs of triangles
// (exporters duplicate vertices along uv and normal seams). Throws Error
// (INVALID_ARGUMENT) when the trunk has no triangles.
MeshHierarchy build_branch_hierarchy(const MeshPart& trunk, double weld_tolerance);

}  // namespace boreas::impl
