// boreas command: tree poses from boreas_tree_get_branches and boreas_tree_get_leaves.
#include "cli/tree_poses.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace boreas::render {

void read_tree_pose(const boreas::World& world, boreas_tree_id tree, TreePose& pose,
                    bool with_leaves) {
  // The C calls fill buffers kept across frames; the C++ layer would allocate each time.
  static thread_local std::vector<boreas_branch> branches;
  static thread_local std::vector<boreas_leaf> leaves;
  int count = 0;
  boreas::check(boreas_tree_get_branches(world.handle(), tree, nullptr, 0, &count));
  branches.resize(size_t(count));
  boreas::check(boreas_tree_get_branches(world.handle(), tree, branches.data(), count, &count));
  pose.branches.resize(branches.size());
  for (size_t i = 0; i < branches.size(); ++i) {
    TreeCurve& curve = pose.branches[i];
    std::copy(&branches[i].control_points[0][0], &branches[i].control_points[0][0] + 12,
              &curve.points[0][0]);
    curve.level = branches[i].level;
    curve.radius = branches[i].radius;
    curve.broken = branches[i].broken != 0;
  }
  if (!with_leaves) return;
  boreas::check(boreas_tree_get_leaves(world.handle(), tree, nullptr, 0, &count));
  leaves.resize(size_t(count));
  boreas::check(boreas_tree_get_leaves(world.handle(), tree, leaves.data(), count, &count));
  pose.leaves.resize(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) {
    // The middle of the blade.
    const boreas_leaf& leaf = leaves[i];
    for (int a = 0; a < 3; ++a) {
      pose.leaves[i][size_t(a)] = leaf.position[a] + 0.5f * leaf.length * leaf.axis[a];
    }
  }
}

float max_tip_offset(const TreePose& a, const TreePose& b) {
  float offset = 0.0f;
  size_t n = std::min(a.branches.size(), b.branches.size());
  for (size_t i = 0; i < n; ++i) {
    const float* p = a.branches[i].points[3];
    const float* q = b.branches[i].points[3];
    offset = std::max(offset, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return offset;
}

std::string species_label(const std::string& species) {
  std::filesystem::path path(species);
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  std::string label =
      extension == ".xml" || extension == ".json" ? path.stem().string() : path.filename().string();
  std::replace(label.begin(), label.end(), '_', ' ');
  return label;
}

}  // namespace boreas::render
