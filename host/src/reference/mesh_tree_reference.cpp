// boreas: imported-tree sway in double precision (see mesh_tree_reference.h and the
// equations in cl/shared/mesh_tree_math.h).
#include "reference/mesh_tree_reference.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace boreas::reference {

namespace {

using glm::dvec3;

// The drag law's load (mesh_trees/mesh_tree_drag.h), in double.
double load(const impl::MeshTreeInstance& tree, const dvec3& w) {
  return impl::mesh_tree_load(tree.drag, glm::length(w));
}

dvec3 placed_direction(const impl::MeshTreeParams& p, const std::array<float, 3>& v) {
  float out[3];
  impl::place_direction(p, v.data(), out);
  return dvec3(out[0], out[1], out[2]);
}

dvec3 placed_point(const impl::MeshTreeParams& p, const float* v) {
  float out[3];
  impl::place_point(p, v, out);
  return dvec3(out[0], out[1], out[2]);
}

// Sum over the four levels of w_k L(W) (bend_k W_perp / |W| + sway_k (n0 right + n1 up)).
dvec3 displacement(const impl::MeshTreeInstance& tree, const std::vector<dvec3>& wind,
                   const float* weights, int branch, double time) {
  const impl::MeshTreeParams& p = tree.params;
  dvec3 d(0.0);
  for (int k = 0; k < 4; ++k) {
    const impl::MeshTreeBranch& a = tree.data.branches[tree.data.branches[branch].animated_by[k]];
    const dvec3& w = wind[tree.data.branches[branch].animated_by[k]];
    double weight = std::pow(double(weights[k]), double(p.bend_exponent));
    double l = weight * load(tree, w);
    if (l == 0.0) continue;
    dvec3 axis = placed_direction(p, a.axis);
    dvec3 perp = w - glm::dot(w, axis) * axis;
    double clock = double(p.levels[k].frequency) * time;
    clock -= std::floor(clock);
    double n[2];
    impl::sample_noise(tree.noise, a.phase[0] + clock, a.phase[1], n);
    d += l * (double(p.levels[k].bend) * perp / glm::length(w) +
              double(p.levels[k].sway) *
                  (n[0] * placed_direction(p, a.right) + n[1] * placed_direction(p, a.up)));
  }
  return d;
}

}  // namespace

MeshTreePose mesh_tree_pose(const impl::MeshTreeInstance& tree,
                            const std::vector<dvec3>& branch_wind, glm::dvec2 roll, double time) {
  const impl::MeshTreeParams& p = tree.params;
  const impl::MeshTreeData& d = tree.data;
  MeshTreePose pose;
  const impl::MeshPart& trunk = tree.model.trunk;
  for (size_t v = 0; v < trunk.vertex_count(); ++v)
    pose.trunk.push_back(
        placed_point(p, &trunk.positions[3 * v]) +
        displacement(tree, branch_wind, &d.trunk_weights[4 * v], d.trunk_branch[v], time));

  const impl::MeshPart& leaves = tree.model.leaves;
  for (size_t v = 0; v < leaves.vertex_count(); ++v) {
    const int l = d.leaf_of_vertex[v];
    const int b = d.leaf_branch[l];
    const dvec3& w = branch_wind[b];
    const double s = glm::length(w);
    const dvec3 toward = s > 0.0 ? w / s : dvec3(0.0);
    const double ld = load(tree, w);
    // The leaf turns about its petiole from its axis a towards the wind by a fraction f of
    // the way (normalized lerp), as a rigid rotation.
    dvec3 a =
        placed_direction(p, {d.leaf_axis[3 * l], d.leaf_axis[3 * l + 1], d.leaf_axis[3 * l + 2]});
    double f = double(p.leaf_turn) * ld / (1.0 + ld);
    dvec3 turned = glm::normalize((1.0 - f) * a + f * toward);
    dvec3 k = glm::cross(a, turned);
    double c = glm::dot(a, turned);
    auto rotate = [&](const dvec3& x) {
      return c * x + glm::cross(k, x) + k * glm::dot(k, x) / (1.0 + c);
    };
    dvec3 petiole = placed_point(p, &d.leaf_petiole[3 * l]);
    dvec3 rest = placed_point(p, &leaves.positions[3 * v]);
    dvec3 normal = placed_direction(
        p, {leaves.normals[3 * v], leaves.normals[3 * v + 1], leaves.normals[3 * v + 2]});
    double tip = d.leaf_length[l] > 0.0f
                     ? glm::distance(dvec3(leaves.positions[3 * v], leaves.positions[3 * v + 1],
                                           leaves.positions[3 * v + 2]),
                                     dvec3(d.leaf_petiole[3 * l], d.leaf_petiole[3 * l + 1],
                                           d.leaf_petiole[3 * l + 2])) /
                           d.leaf_length[l]
                     : 0.0;
    // The rolling noise: the pattern carried downwind by the roll, anchored at the tree's
    // position (its tables are the tree's own coordinates: mesh_tree_types.h).
    double inv_tile = 1.0 / double(p.flutter_wavelength);
    const dvec3 local = rest - dvec3(p.position[0], p.position[1], p.position[2]);
    double n[2];
    impl::sample_noise(tree.noise, local.x * inv_tile - roll.x, local.z * inv_tile - roll.y, n);
    dvec3 flutter =
        double(p.leaf_flutter) * ld * tip * (n[0] * toward + n[1] * dvec3(0.0, 1.0, 0.0));
    pose.leaves.push_back(petiole + rotate(rest - petiole) + flutter +
                          displacement(tree, branch_wind, &d.leaf_weights[4 * l], b, time));
    pose.leaf_normals.push_back(rotate(normal));
  }
  return pose;
}

}  // namespace boreas::reference
