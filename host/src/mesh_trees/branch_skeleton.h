// boreas: a branch's skeleton, fit to its run of triangles (stage 2 of the branch
// hierarchy, see branch_hierarchy.cpp): a polyline from its base to its tip with radii.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

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

namespace hierarchy {

struct SurfaceGraph;

// The skeleton of a run: its points sliced by their nearest point on the rough polyline,
// each slice's center and radius from a circle fit across the polyline there. The ends
// reach the run's extreme points along the end slices' directions. nodes: the run's nodes
// of g (SurfaceGraph::nodes_of_run); area: its triangles' surface, m^2; distance: scratch,
// one per node of g.
BranchSkeleton make_skeleton(const SurfaceGraph& g, const std::vector<int32_t>& nodes, double area,
                             std::vector<double>* distance);

// Turns the skeleton end for end (base <-> tip).
void reverse(BranchSkeleton* s);

}  // namespace hierarchy

}  // namespace boreas::impl
