// boreas: how trees are laid out for the tree kernels — every per-branch quantity as a
// plane of floats (cl/shared/tree_types.h), in blocks of consecutive entries, so adding,
// moving or removing a tree touches its blocks only.
//
// A tree's data come in two parts:
//  - its template block (TreeTemplateBlock): what every tree grown from the same model
//    with the same physics shares — each branch's parent (as a local index), unpositioned
//    control points at scale 1, attachment, compliance, radius functions, response, and
//    the leaves' parents and placement (8 bytes a leaf, cl/shared/leaf_pack.h). A forest of 10,000 trees from 20 templates holds
//    20 of these;
//  - its own state: the animated control points and bend (tree_state.h), and its leaves.
// In both, entry 0 is the tree's root (a fixed vertical unit segment at the tree's
// position, its O turned by the tree's rotation about the up axis, that the trunk hangs
// from and no launch writes), entry 1 + b is branch b of the model (levels in order, so a
// level of one tree is a contiguous range and parents come before their children). The
// kernels scale the template's lengths by the tree's scale (tiles carry it).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

// A template block: planes of stride `count` (entries) or `leaf_count` (leaves).
struct TreeTemplateBlock {
  int32_t count = 1;  // root + branches
  int32_t leaf_count = 0;
  std::vector<int32_t> parents;       // local index (the root: 0, itself)
  std::vector<int32_t> children;      // BOREAS_TREE_CHILD_PLANES planes, local indices
  std::vector<float> shape, radius;   // at scale 1; compliance of the template at scale 1
  std::vector<double> omega, zeta;    // damped: at the params' scale; else (and the root) 0
  // The leaves' parents and placement, packed: BOREAS_TREE_LEAF_PLANES int planes
  // (cl/shared/leaf_pack.h); what they share, the petiole, once (m at scale 1).
  std::vector<int32_t> leaves;
  float leaf_petiole = 0.0f;
  std::vector<float> rest;  // the state at rest of the tree at the origin, unturned, scale 1
  // How far from its base any branch's surface can be, m at scale 1, however it bends (a
  // branch keeps its polygon's length): the colliders' broadphase.
  double reach = 0.0;
  // What the view records read (TreeBatch::tree_view), measured from the whole model here,
  // since the block's rest and a kept model's leaves are let go once on the device: the
  // trunk's rest tip (the rest state's P3 of entry 1; 0 for a root alone), m at scale 1;
  // its leaves' mean length x width (m^2: the box of a blade, what the thinning rule
  // measures, not the blade's own area) and farthest reach past their branch's axis
  // (petiole and blade, m), at scale 1.
  float trunk_rest_tip[3] = {0.0f, 0.0f, 0.0f};
  double leaf_area = 0.0, leaf_reach = 0.0;
};

// The template block of `model` (grown at scale 1) with the physics of params (bend
// exponent, levels, response; the scale only for a damped response's frequencies). The
// rest placement uses the kernels' own geometry (the C++ build of cl/shared/tree_math.h).
TreeTemplateBlock tree_template_block(const TreeParams& params, const TreeModel& model);

// The state at rest of a tree at the origin, unturned, at scale 1 (a block's `rest`), from
// its template block's shape planes (at least BOREAS_TREE_SHAPE_SIN_ALPHA + 1 of them) and
// parents, stride parents.size(): the root, and every branch unbent on its parent. The
// planes hold what the placement reads, so the device's copy of a block gives the same.
std::vector<float> rest_state(const std::vector<float>& shape, const std::vector<int32_t>& parents);
// The state at rest of a tree placed by params (position, rotation about +y, scale):
// a rest state (rest_state) scaled, turned and moved, into its entries of planes of
// stride `stride` from entry `first`.
// Only its first `entries` entries where fewer than the block's (a tree whose finest level
// settles at add keeps only the entries before it: trees/tree_batch.h).
void place_rest(const std::vector<float>& rest, const TreeParams& params, float* state,
                size_t stride, size_t first, size_t entries = SIZE_MAX);

// A block's children planes (BOREAS_TREE_CHILD_PLANES, stride parents.size()) from its
// parents: each entry's children as at most two runs of local indices (tree_types.h), the
// root's none. More than two runs is refused (BOREAS_ERROR_INTERNAL naming `what`).
std::vector<int32_t> tree_children(const std::vector<int32_t>& parents, const std::string& what);

// Local index of branch b's entry in its blocks.
inline int32_t block_index(int32_t b) { return 1 + b; }
// Entries of a model's blocks: the root and every branch.
inline int32_t block_entries(const TreeModel& m) { return block_index(m.branch_count()); }

struct TreeLayoutSource {
  const TreeParams* params = nullptr;
  const TreeModel* model = nullptr;
};

// Several trees packed one after the other, each with its own template block at the same
// indices as its state (the simplest layout the kernels accept; a TreeBatch shares
// template blocks, but lays its trees' states out exactly so when they are added to an
// empty batch in one call). Entry 0 of the branch and of the leaf planes is a sink no tree
// owns: a vertical unit segment at the origin whose shape re-attaches it to itself,
// unbent, and a leaf on it; the no-op tiles of runtime/launch_tiles.h update it harmlessly.
struct TreeLayout {
  int tree_count = 0;
  int branch_count = 0;  // real branches, roots excluded
  int n = 1;             // planes' stride: the sink, roots and branches
  int leaf_count = 0;
  int leaf_n = 1;                        // leaf planes' stride: the sink and the leaves
  std::vector<int32_t> tree_first;       // the root's index, per tree
  std::vector<int32_t> tree_leaf_first;  // per tree
  std::vector<float> tree_scale;         // per tree
  std::vector<float> tree_leaf_petiole;  // per tree: its leaves' petiole, m (scaled)
  // Template planes (parents local to their tree's root entry).
  std::vector<int32_t> parents;
  std::vector<float> shape, radius;
  std::vector<double> omega, zeta;
  std::vector<int32_t> leaves;  // BOREAS_TREE_LEAF_PLANES int planes, stride leaf_n
  // The trees' own planes: state at rest, zero motion.
  std::vector<float> state, motion;

  // Index of branch b of tree t.
  int32_t branch_index(size_t t, int b) const { return tree_first[t] + block_index(b); }
};

TreeLayout tree_layout(const std::vector<TreeLayoutSource>& trees);

// The response planes (BOREAS_TREE_RESPONSE_*) for a step of dt, from omega and zeta.
std::vector<float> tree_response_planes(const std::vector<double>& omega,
                                        const std::vector<double>& zeta, double dt);

}  // namespace boreas::impl
