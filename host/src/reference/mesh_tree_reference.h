// boreas: the double-precision twin of the imported-tree vertex kernels
// (cl/shared/mesh_tree_math.h, cl/mesh_tree_vertices.cl), for tests: the same equations
// in glm::dvec3, from the same placed tables.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "mesh_trees/mesh_tree_batch.h"

namespace boreas::reference {

// One tree's animated vertices at time `time`, given the wind each of its branches feels
// (already low-passed, world space, m/s) and its leaf noise's roll (tiles).
struct MeshTreePose {
  std::vector<glm::dvec3> trunk;   // positions
  std::vector<glm::dvec3> leaves;  // positions
  std::vector<glm::dvec3> leaf_normals;
};

MeshTreePose mesh_tree_pose(const impl::MeshTreeInstance& tree,
                            const std::vector<glm::dvec3>& branch_wind, glm::dvec2 roll,
                            double time);

}  // namespace boreas::reference
