// boreas: what the host prepares for colliders against imported trees
// (cl/shared/mesh_tree_contact.h says the model): each branch's contact spheres, weights,
// compliance and frequency, and the box a tree can reach, so that only trees a collider's
// swept bounds meet pay for it.
#pragma once

#include <cstddef>
#include <vector>

#include "colliders/collider.h"
#include "mesh_trees/mesh_tree_batch.h"

namespace boreas::impl {

// Green wood's modulus, Pa: the species' default (trees/species.h, the Wood Handbook's
// green-wood values of 5-10 GPa for most hardwoods). Imported meshes name no species.
inline constexpr double kMeshTreeWoodModulus = 7e9;

// The tree's contact table (BOREAS_MESH_TREE_CONTACT_* planes, `stride` entries apart) for
// its branches from entry `first` on, placed in the world.
void place_contact_table(const MeshTreeInstance& tree, std::vector<float>& planes, size_t stride,
                         size_t first);

// The wind speed (m/s) a mesh tree's reach box is made for: 75 m/s, above the sustained
// winds of the strongest hurricanes.
inline constexpr double kMeshTreeReachSpeed = 75.0;

// The world box that the tree's vertices stay within in winds up to kMeshTreeReachSpeed
// (its rest box grown by the largest displacement the load there gives).
Bounds mesh_tree_reach(const MeshTreeInstance& tree);

}  // namespace boreas::impl
