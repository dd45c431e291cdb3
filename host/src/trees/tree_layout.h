// boreas: how trees are laid out for the tree kernels — every per-branch quantity as a
// plane of floats (cl/shared/tree_types.h), tree-major: each tree owns one contiguous
// block of entries, so adding, moving or removing a tree touches its block only.
//
// A block: entry 0 is the tree's root (a fixed vertical unit segment at the tree's
// position, its O turned by the tree's rotation about the up axis, that the trunk hangs
// from and no launch writes), entry 1 + b is branch b of the model (levels in order, so a
// level of one tree is a contiguous range and parents come before their children). A
// tree's leaves are one contiguous block of the leaf planes. One function builds a block,
// so TreeBatch, the tests and the benchmark's native twins cannot disagree about it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

// One tree's planes, stride `count`, indices local to the block.
struct TreeBlock {
  int32_t count = 1;  // root + branches
  int32_t leaf_count = 0;
  std::vector<int32_t> parents;                     // local index (the root: 0, itself)
  std::vector<float> shape, radius, state, motion;  // state: unbent rest; motion: zero
  std::vector<double> omega, zeta;                  // 0 for quasi-static branches and the root
  std::vector<int32_t> leaf_parents;                // local branch index
  std::vector<float> leaf_shape;                    // stride leaf_count
};

// The block of a tree grown as `model` (a template, at scale 1) and placed by params
// (position, rotation, scale), at rest: the placement uses the kernels' own geometry (the
// C++ build of cl/shared/tree_math.h).
TreeBlock tree_block(const TreeParams& params, const TreeModel& model);

// Local index of branch b's entry in its block.
inline int32_t block_index(int32_t b) { return 1 + b; }

struct TreeLayoutSource {
  const TreeParams* params = nullptr;
  const TreeModel* model = nullptr;
};

// Blocks of several trees packed one after the other (the layout a TreeBatch has after
// adding them to an empty batch in this order): planes of stride n, global indices.
// Entry 0 of the branch planes and of the leaf planes is a sink no tree owns: a vertical
// unit segment at the origin with one unbent child-like shape that re-attaches to itself,
// which the no-op tiles of runtime/launch_tiles.h update harmlessly. Trees follow from 1.
struct TreeLayout {
  int tree_count = 0;
  int branch_count = 0;  // real branches, roots excluded
  int n = 1;             // planes' stride: the sink, roots and branches
  int leaf_count = 0;
  int leaf_n = 1;                        // leaf planes' stride: the sink and the leaves
  std::vector<int32_t> tree_first;       // the root's global index, per tree
  std::vector<int32_t> tree_leaf_first;  // per tree
  std::vector<int32_t> parents;
  std::vector<float> shape, radius, state, motion;
  std::vector<double> omega, zeta;
  std::vector<int32_t> leaf_parents;
  std::vector<float> leaf_shape;

  // Global index of branch b of tree t.
  int32_t branch_index(size_t t, int b) const { return tree_first[t] + block_index(b); }
};

TreeLayout tree_layout(const std::vector<TreeLayoutSource>& trees);

// The response planes (BOREAS_TREE_RESPONSE_*) for a step of dt, from omega and zeta.
std::vector<float> tree_response_planes(const std::vector<double>& omega,
                                        const std::vector<double>& zeta, double dt);

}  // namespace boreas::impl
