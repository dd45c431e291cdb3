// boreas: which branches and leaves of a tree each step launch covers (tile lists,
// runtime/launch_tiles.h), by stepping mode and level of detail. One function decides it
// for TreeBatch and the benchmark's native twins alike.
#pragma once

#include <cstdint>

#include "boreas/boreas.h"
#include "runtime/launch_tiles.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

// The lists of a batch's tile set: lagged mode steps list tree_step_list(0) and carries
// tree_carry_list(0) in one launch each; exact mode launches level l's pair in level
// order. Leaves: every step (rate 0), every 2nd step (rate 1, phases 0 and 1) and every
// 4th step (rate 2, phases 0..3).
inline int tree_step_list(int level) { return 2 * level; }
inline int tree_carry_list(int level) { return 2 * level + 1; }
inline int tree_leaf_list(int rate_log2, int phase) {
  return 2 * kMaxTreeLevels + (1 << rate_log2) - 1 + phase;
}
inline constexpr int kTreeListCount = 2 * kMaxTreeLevels + 7;

// Levels of a tree stepped at a level of detail: [0, result) are stepped, the rest carried
// (a tree at kFrozen that still settles is carried whole).
int stepped_levels(const TreeModel& m, TreeLod lod);

// Adds the tiles of one tree whose root is entry `first` and whose leaves start at
// `leaf_first`; its stepped branches' tiles carry `hold` (the resume blend, tree_step.cl).
// Leaves of a tree at reduced or far detail go to the every-2nd or every-4th list, in
// phase `phase` (any int: reduced modulo the rate). The segments, where given, receive
// where the tiles went.
void add_tree_tiles(TileLists& tiles, boreas_tree_mode mode, const TreeModel& m, int64_t first,
                    int64_t leaf_first, TreeLod lod, float hold, int phase, int width,
                    std::vector<TileLists::Segment>* segments = nullptr);

}  // namespace boreas::impl
