// boreas: the surfaces of a part's runs of triangles as one graph, and geodesic distances
// over it (for the branch skeletons, stage 2 of the branch hierarchy).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "mesh_trees/tree_model.h"
#include "mesh_trees/triangle_runs.h"

namespace boreas::impl::hierarchy {

// A distance not yet reached.
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The runs' surfaces as one graph for geodesic distances: a node per welded point of a
// run (seam duplicates are one node; a point that two runs share is a node in each), an
// edge per triangle edge.
struct SurfaceGraph {
  std::vector<glm::dvec3> position;  // per node, m
  std::vector<std::vector<int32_t>> nodes_of_run;
  std::vector<uint32_t> first;  // node n's edges: neighbor[first[n], first[n + 1])
  std::vector<int32_t> neighbor;
};

// The graph of a part's runs (find_runs).
SurfaceGraph surface_graph(const MeshPart& part, const Runs& runs);

// Dijkstra over the edges from source through its run (distance must be infinite on the
// run's nodes); returns the farthest node reached.
int32_t geodesic(const SurfaceGraph& g, int32_t source, std::vector<double>* distance);

}  // namespace boreas::impl::hierarchy
