// boreas command: the trees of a world as the frames draw them, read back through the
// public API once per frame.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "image/tree_view.h"

namespace boreas::render {

// Reads the tree's branches and (with `leaves`) leaves as of the last step into pose,
// reusing its storage; without, pose.leaves is left as it is.
void read_tree_pose(const boreas::World& world, boreas_tree_id tree, TreePose& pose,
                    bool leaves = true);

// How far (m) the farthest branch end moved between two poses of one tree.
float max_tip_offset(const TreePose& a, const TreePose& b);

// "quaking_aspen" -> "quaking aspen"; "dir/my_oak.xml" -> "my oak": a species for a label.
std::string species_label(const std::string& species);

}  // namespace boreas::render
