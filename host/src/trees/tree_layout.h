// boreas: how a set of trees is laid out for the tree kernels — the index of every branch
// and leaf, and every per-branch quantity as a plane of floats (cl/shared/tree_types.h),
// with the unbent rest state. One function builds it, so TreeBatch and the benchmark's
// native twins cannot disagree about the layout.
//
// Order: first one fixed root entry per tree (a vertical unit segment at the tree's
// position, O along +x, that its trunk hangs from and no launch writes), then the trunks
// of all trees, then every tree's level 1, and so on: a level of all trees is one
// contiguous range. Leaves: every tree's leaves in order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

struct TreeLayoutSource {
  const TreeParams* params = nullptr;
  const TreeModel* model = nullptr;
};

struct TreeLayout {
  int tree_count = 0;
  int branch_count = 0;  // real branches, roots excluded
  int n = 1;             // planes' stride: roots + branches (at least 1)
  int leaf_count = 0;
  int leaf_n = 1;        // leaf planes' stride (at least 1)
  std::array<int32_t, kMaxTreeLevels> level_first{};  // global range of each level
  std::array<int32_t, kMaxTreeLevels> level_count{};
  std::vector<std::array<int32_t, kMaxTreeLevels>> tree_level_first;  // per tree and level
  std::vector<int32_t> tree_leaf_first;                              // per tree
  std::vector<int32_t> parents;
  std::vector<float> shape, radius, state, motion;  // state: unbent rest; motion: zero
  std::vector<double> omega, zeta;                  // 0 for quasi-static branches and roots
  std::vector<int32_t> leaf_parents;
  std::vector<float> leaf_shape;

  // Global index of branch b of tree t (whose model is m).
  int32_t branch_index(size_t t, const TreeModel& m, int b) const {
    int level = m.branches[b].level;
    return tree_level_first[t][level] + (b - m.level_begin[level]);
  }
};

// The layout of these trees and their unbent rest state, placed with the kernels' own
// geometry (the C++ build of cl/shared/tree_math.h).
TreeLayout tree_layout(const std::vector<TreeLayoutSource>& trees);

// The response planes (BOREAS_TREE_RESPONSE_*) for a step of dt, from a layout's omega
// and zeta.
std::vector<float> tree_response_planes(const std::vector<double>& omega, const std::vector<double>& zeta,
                                        double dt);

}  // namespace boreas::impl
