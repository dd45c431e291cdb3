// boreas command: what summary.json says about a scene's trees, meadows and colliders, the
// same for the slice view and the 3D view.
#pragma once

#include <vector>

#include "boreas/boreas.hpp"
#include "cli/run_summary.h"
#include "image/tree_view.h"
#include "scene/scene.h"
#include "view/meadow_frames.h"

namespace boreas::render {

// A tree as grown: its species, position and the counts of its rest pose.
// leaves: the tree's leaf count, or -1 to count rest.leaves.
TreeStats tree_stats(const SceneTree& tree, const TreePose& rest, int leaves = -1);
// The same from the counts alone (boreas_tree_get_branches, boreas_tree_get_leaves).
TreeStats tree_stats(const SceneTree& tree, int branches, int leaves);

// summary.mesh_trees: each imported tree's model, position and what its preprocessing found.
void add_mesh_tree_stats(const boreas::World& world, const Scene& scene,
                         const std::vector<boreas_mesh_tree_id>& ids, RunSummary& summary);

// summary.meadows: each meadow's species as planted, rectangle, density and components.
void add_meadow_stats(const Scene& scene, const FrameMeadows& meadows, RunSummary& summary);

// summary.colliders: each ball's radius, start, velocity and where it is at summary.sim_time.
void add_collider_stats(const Scene& scene, RunSummary& summary);

}  // namespace boreas::render
