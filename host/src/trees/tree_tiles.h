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
// order. Leaves follow their branches every step at full detail, every 4th step reduced
// and every 16th step far (kLeafRate), each tree in a phase of its own so the work spreads
// evenly over the steps: list tree_leaf_list(rate, phase) is launched in the steps where
// step % rate == phase.
inline int tree_step_list(int level) { return 2 * level; }
inline int tree_carry_list(int level) { return 2 * level + 1; }
inline constexpr int kLeafRates[3] = {1, 4, 16};
inline int tree_leaf_list(int rate, int phase) {
  return 2 * kMaxTreeLevels + (rate == 1 ? 0 : rate == 4 ? 1 : 5) + phase;
}
inline constexpr int kTreeListCount = 2 * kMaxTreeLevels + 1 + 4 + 16;
// The leaves' rate at a level of detail (a tree that settles before it freezes: 1).
inline int leaf_rate(TreeLod lod) {
  return lod == TreeLod::kReduced ? 4 : lod == TreeLod::kFar ? 16 : 1;
}

// Levels of a tree stepped at a level of detail: [0, result) are stepped, the rest carried
// (a tree at kFrozen that still settles is carried whole).
int stepped_levels(const TreeModel& m, TreeLod lod);

// Where one tree's data are: its own entries (root at `first`, leaves from `leaf_first`),
// its template block's (`static_first`, `static_leaf_first`), and its scale.
struct TreeTileSource {
  int64_t first = 0;
  int64_t leaf_first = 0;
  int64_t static_first = 0;
  int64_t static_leaf_first = 0;
  double scale = 1.0;
};

// Adds the tiles of one tree of model m; its stepped branches' tiles carry `hold` (the
// resume blend, tree_step.cl). Its leaves go to the list of its level of detail's rate,
// in phase `phase` (any int: reduced modulo the rate). The segments, where given, receive
// where the tiles went.
void add_tree_tiles(TileLists& tiles, boreas_tree_mode mode, const TreeModel& m,
                    const TreeTileSource& at, TreeLod lod, float hold, int phase, int width,
                    std::vector<TileLists::Segment>* segments = nullptr);

}  // namespace boreas::impl
