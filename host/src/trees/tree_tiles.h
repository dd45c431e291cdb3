// boreas: which branches and leaves of a tree each step launch covers (tile lists,
// runtime/launch_tiles.h), by stepping mode and level of detail. One function decides it
// for TreeBatch and the benchmark's native twins alike.
#pragma once

#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "runtime/launch_tiles.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"

namespace boreas::impl {

// The lists of a batch's tile set. Stepped branches: lagged mode launches
// tree_step_list(0) once a step, exact mode step tier t's list in tier order (a tier is a
// level's pieces of one split depth, TreeModel::tier_begin, so a piece is placed on the
// new state of the piece it grows from). Carried branches (levels of detail) are updated
// every step (a settling tree), every 4th step (reduced) or every 8th (far), each tree in a
// phase of its own so the work spreads evenly: carry list (tier, rate, phase) is launched
// in the steps where step % rate == phase, tier by tier in both modes (cl/tree_step.cl).
// (Leaves have none: they are made when read, cl/tree_leaves.cl.)
//
// The rates: a carried twig moves with its parent's frame, so between its updates it lags
// its parent by the parent's motion over the skipped steps — a few cm at 60 Hz, below a
// pixel at the distances of those levels (30 m: 3 cm a pixel of a 1080p, 60-degree view).
// Carrying costs what stepping does (the attachment dominates, not the wind): the rates,
// not carrying itself, are what a level of detail saves.
inline constexpr int kCarryRates[3] = {1, 4, 8};
inline int tree_step_list(int tier) { return tier; }
inline int tree_carry_list(int tier, int rate, int phase) {
  return kMaxTreeTiers + 13 * tier + (rate == 1 ? 0 : rate == 4 ? 1 : 5) + phase;
}
inline constexpr int kTreeListCount = kMaxTreeTiers + 13 * kMaxTreeTiers;

// A model's step tiers: its tier_begin/tier_level, or one per level for a model built
// without them (levels alone are tiers when nothing splits).
struct TreeTier {
  int32_t begin, end, level;
};
std::vector<TreeTier> tree_tiers(const TreeModel& m);
// How often a level of detail updates its carried branches.
inline int carry_rate(TreeLod lod) {
  return lod == TreeLod::kReduced ? 4 : lod == TreeLod::kFar ? 8 : 1;
}

// Levels of a tree stepped at a level of detail: [0, result) are stepped, the rest carried
// (a tree at kFrozen that still settles is carried whole).
int stepped_levels(const TreeModel& m, TreeLod lod);
// The level a tree's derived branches are (cl/shared/tree_state.h: its finest, when that is
// carried at this level of detail and is not the trunk), or m.levels where none can be.
int derivable_level(const TreeModel& m, TreeLod lod);
// Whether some branch of `level` grows from a branch of the same level: a split piece
// (tree_model.h: a level of more than one step tier; a model without tiers has none).
// Derived, such a level is posed tier by tier (a piece after its parent).
bool level_has_splits(const TreeModel& m, int level);

// Where one tree's data are: its own entries (root at `first`), its template block's
// (`static_first`), and its scale.
struct TreeTileSource {
  int64_t first = 0;
  int64_t static_first = 0;
  double scale = 1.0;
  int32_t object = 0;  // its tiles' BOREAS_TILE_OBJECT (contact launches: its touched tree)
};

// Adds the tiles of one tree of model m (the stepped branches' carry `hold`, the resume
// blend of tree_step.cl), its carried ones in phase `phase` (any int: reduced modulo the
// rate), none for its derived level (`derived`: derivable_level's branches are derived,
// nothing steps them). The segments, where given, receive where the tiles went.
void add_tree_tiles(TileLists& tiles, boreas_tree_mode mode, const TreeModel& m,
                    const TreeTileSource& at, TreeLod lod, float hold, int phase, int width,
                    std::vector<TileLists::Segment>* segments = nullptr, bool derived = false);

}  // namespace boreas::impl
