// boreas: a tree's skin (boreas_tree_get_joints, boreas_tree_get_skin_weights): joints on
// the branches down to a level, segments + 1 along each curve, in the deformer's own frame
// (cl/shared/tree_math.h), and every mesh vertex and leaf bound to the two joints around
// its place. Pure functions of the public branch and leaf lists (and, for the mesh's rings,
// each piece's tip cap), so a glTF writer, the Blender add-on and the tests all read one
// skeleton.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "boreas/boreas.h"
#include "trees/tree_model.h"

namespace boreas::impl {

struct SkinParams {
  int max_level = 3;
  int segments = 4;
};

// The def checked (NULL: the defaults); errors name the field and its range.
SkinParams checked_skin_def(const boreas_skin_def* def);

// Rings and sides of each level's grid in boreas_tree_get_mesh (levels 0..3).
struct MeshGrid {
  int rings = 0, sides = 0;
};
using LevelGrids = std::array<MeshGrid, 4>;

std::vector<boreas_joint> skin_joints(const std::vector<boreas_branch>& branches,
                                      const SkinParams& p);
// Each branch's tip cap (BranchModel::tip_cap, 0: none) as the device has it, in the order of
// the branch list; a packed model of a capped species is grown again for them (whole_model).
std::vector<float> skin_tip_caps(const std::shared_ptr<const TreeModel>& model);
// The mesh's vertices: ring r of a branch at boreas_ring_v(r, rings, its tip cap).
std::vector<boreas_skin_weight> skin_vertex_weights(const std::vector<boreas_branch>& branches,
                                                    const std::vector<float>& tip_caps,
                                                    const LevelGrids& grids, const SkinParams& p);
std::vector<boreas_skin_weight> skin_leaf_weights(const std::vector<boreas_branch>& branches,
                                                  const std::vector<boreas_leaf>& leaves,
                                                  const SkinParams& p);

}  // namespace boreas::impl
