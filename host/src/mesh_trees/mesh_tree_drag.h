// boreas: the wind's load on an imported tree as the drag every plant takes, 1/2 rho C_d A
// |u|^2 R(|u|) (trees/wind_load.h), from the areas of the mesh's leaves and trunk.
//
// An imported tree has no beams to bend: its vertices move by the artist's amplitudes
// (boreas_mesh_level_def's bend and sway, m at 10 m/s) times a load L. L is the tree's drag
// divided by its drag in 10 m/s, times 0.8 (what the earlier artist's load q / (1 + q / 4),
// q = (|u| / 10 m/s)^2, gave there), so a 10 m/s wind looks as it did; above and below, L
// follows the drag law: the square of the speed, times Vogel's reconfiguration R of the
// leafy share. The areas: a leaf catches the wind on its blade (its triangles' area, C_d
// 0.5), a stem on its silhouette (its surface over pi, a cylinder's 2 r L of 2 pi r L, C_d
// 1.2); the leaves' share phi of the drag takes Vogel's exponent, phi b (the first-order
// match of (1 - phi) + phi R, as a generated tree's carried load; the stems' drag grows as
// U^2). Mesh trees have no species: b and U_r are a leafy broadleaf's, -0.8 above 8 m/s.
// The area only sets phi: the amplitudes are the artist's, so L is a ratio.
#pragma once

#include "mesh_trees/tree_model.h"

namespace boreas::impl {

inline constexpr double kMeshTreeVogelExponent = -0.8;
inline constexpr double kMeshTreeVogelSpeed = 8.0;      // m/s
inline constexpr double kMeshTreeReferenceSpeed = 10.0;  // m/s: BOREAS_MESH_TREE_REFERENCE_SPEED
inline constexpr double kMeshTreeLoadAtReference = 0.8;  // 1 / (1 + 1 / 4)

// The defaults are a tree of no area's: the bare drag law, 0.8 at 10 m/s.
struct MeshTreeDrag {
  double leaf_area = 0.0;  // m^2 at scale 1: the leaves' blades
  double stem_area = 0.0;  // m^2 at scale 1: the trunk's silhouette (surface / pi)
  double vogel_b = 0.0;    // phi * kMeshTreeVogelExponent
  double load_per_speed2 =  // L / (|u|^2 R(|u|)), 1 / (m/s)^2
      kMeshTreeLoadAtReference / (kMeshTreeReferenceSpeed * kMeshTreeReferenceSpeed);
};

MeshTreeDrag mesh_tree_drag(const MeshModel& model);

// L at wind speed `speed` m/s (double: the reference's and the tests').
double mesh_tree_load(const MeshTreeDrag& drag, double speed);

}  // namespace boreas::impl
