// boreas: an imported tree's drag from its mesh's areas (mesh_tree_drag.h).
#include "mesh_trees/mesh_tree_drag.h"

#include <cmath>

#include "trees/wind_load.h"
#include "wind/air.h"

namespace boreas::impl {
namespace {

constexpr double kPi = 3.14159265358979323846;

double surface_area(const MeshPart& part) {
  double area = 0.0;
  const std::vector<float>& p = part.positions;
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    const size_t a = 3 * size_t(part.indices[t]), b = 3 * size_t(part.indices[t + 1]),
                 c = 3 * size_t(part.indices[t + 2]);
    const double u[3] = {p[b] - double(p[a]), p[b + 1] - double(p[a + 1]), p[b + 2] - double(p[a + 2])};
    const double v[3] = {p[c] - double(p[a]), p[c + 1] - double(p[a + 1]), p[c + 2] - double(p[a + 2])};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

}  // namespace

MeshTreeDrag mesh_tree_drag(const MeshModel& model) {
  MeshTreeDrag d;
  d.leaf_area = surface_area(model.leaves);
  d.stem_area = surface_area(model.trunk) / kPi;
  const double leaves = kLeafDragCoefficient * d.leaf_area;
  const double drag_area = leaves + kWoodDragCoefficient * d.stem_area;
  d.vogel_b = drag_area > 0.0 ? leaves / drag_area * kMeshTreeVogelExponent : 0.0;
  // L = 0.8 D(|u|) / D(10 m/s), D = 1/2 rho C_d A |u|^2 R: the tree's own drag, normalized.
  const double at_reference = 0.5 * kAirDensity * drag_area * kMeshTreeReferenceSpeed *
                              kMeshTreeReferenceSpeed *
                              reconfiguration(kMeshTreeReferenceSpeed, d.vogel_b, kMeshTreeVogelSpeed);
  if (drag_area > 0.0)
    d.load_per_speed2 = kMeshTreeLoadAtReference * 0.5 * kAirDensity * drag_area / at_reference;
  return d;
}

double mesh_tree_load(const MeshTreeDrag& drag, double speed) {
  return drag.load_per_speed2 * speed * speed *
         reconfiguration(speed, drag.vogel_b, kMeshTreeVogelSpeed);
}

}  // namespace boreas::impl
