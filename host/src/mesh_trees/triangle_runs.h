// boreas: the connected runs of triangles of a mesh part (a trunk's branches, the leaves'
// blades), with positions welded across the seams that exporters split.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "mesh_trees/tree_model.h"

namespace boreas::impl {

// The connected runs of triangles of a part: per vertex the index of its run, runs
// numbered in order of their first vertex. Triangles join through a shared vertex or a
// shared edge, positions welded within weld_tolerance (m) but never farther apart than a
// tenth of an edge at either; a single point in common does not join them. For the
// trunk's branches and the leaves' blades alike.
std::vector<int32_t> connected_runs(const MeshPart& part, double weld_tolerance, int* run_count);

// A weld tolerance that suits a part: 1e-5 of its bounding box's diagonal.
double default_weld_tolerance(const MeshPart& part);

// What the branch hierarchy's stages share (branch_hierarchy.cpp lists them).
namespace hierarchy {

// Vertex v's position, m.
inline glm::dvec3 position(const MeshPart& part, uint32_t v) {
  return glm::dvec3(part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]);
}

// A part's welded points and its runs of triangles.
struct Runs {
  std::vector<int32_t> weld;  // per vertex, its welded point
  int points = 0;
  std::vector<int32_t> run;  // per vertex, its run
  int count = 0;
};

// The welded points and the runs of a part (connected_runs, with the welding it used).
Runs find_runs(const MeshPart& part, double weld_tolerance);

}  // namespace hierarchy

}  // namespace boreas::impl
