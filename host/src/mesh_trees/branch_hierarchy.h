// boreas: the branch hierarchy of a tree mesh that has no bones or branch data (Kusternig
// sec. 5.1.1): branches are connected runs of triangles, the thickest is the stem, and
// each branch's parent is the branch of the level above that it grows out of.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "mesh_trees/tree_model.h"

namespace boreas::impl {

// A branch's skeleton: a polyline from its base to its tip along the smooth curve through
// the centers of its rings (circles fit to slices of its vertices along its own length),
// with the radius at each node.
struct BranchSkeleton {
  std::vector<glm::dvec3> nodes;  // base first
  std::vector<double> radii;      // m, per node
  std::vector<double> arc;        // m, arc length from the base to each node

  double length() const { return arc.empty() ? 0.0 : arc.back(); }
  double max_radius() const;
  // The point of the polyline nearest p: its arc length from the base, its distance from
  // p, and the radius there (linear between nodes).
  void nearest(const glm::dvec3& p, double* arc_length, double* distance, double* radius) const;
};

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

// The connected runs of triangles of a part: per vertex the index of its run, runs
// numbered in order of their first vertex. Triangles join through a shared vertex or a
// shared edge, positions welded within weld_tolerance (m) but never farther apart than a
// tenth of an edge at either; a single point in common does not join them. For the
// trunk's branches and the leaves' blades alike.
std::vector<int32_t> connected_runs(const MeshPart& part, double weld_tolerance, int* run_count);

// A weld tolerance that suits a part: 1e-5 of its bounding box's diagonal.
double default_weld_tolerance(const MeshPart& part);

}  // namespace boreas::impl
