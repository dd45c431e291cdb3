// boreas: a tree's step launches by mode and level of detail (tree_tiles.h).
#include "trees/tree_tiles.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

int stepped_levels(const TreeModel& m, TreeLod lod) {
  switch (lod) {
    case TreeLod::kFull:
      return m.levels;
    case TreeLod::kReduced:
      return std::max(1, m.levels - 1);  // the finest level carried
    case TreeLod::kFar:
      return std::min(m.levels, 2);  // trunk and level 1 only
    case TreeLod::kFrozen:
      return 0;
  }
  return m.levels;
}

bool level_has_splits(const TreeModel& m, int level) {
  return std::count(m.tier_level.begin(), m.tier_level.end(), level) > 1;
}

int derivable_level(const TreeModel& m, TreeLod lod) {
  // A split piece's parent is a piece of the same level, derived too: readers derive the
  // chain (cl/shared/tree_state.h), and a level stepped again gets its poses written first
  // (TreeBatch::write_derived_poses), so its step never reads a mark as a parent's curve.
  const int finest = m.levels - 1;
  return finest >= 1 && stepped_levels(m, lod) <= finest ? finest : m.levels;
}

std::vector<TreeTier> tree_tiers(const TreeModel& m) {
  std::vector<TreeTier> tiers;
  if (m.tier_level.empty()) {
    for (int l = 0; l < m.levels; ++l)
      tiers.push_back({m.level_begin[size_t(l)], m.level_begin[size_t(l) + 1], l});
  } else {
    for (size_t k = 0; k < m.tier_level.size(); ++k)
      tiers.push_back({m.tier_begin[k], m.tier_begin[k + 1], m.tier_level[k]});
  }
  return tiers;
}

void add_tree_tiles(TileLists& tiles, boreas_tree_mode mode, const TreeModel& m,
                    const TreeTileSource& at, TreeLod lod, float hold, int phase, int width,
                    std::vector<TileLists::Segment>* segments, bool derived) {
  TileLists::Shared shared;
  shared.root = int32_t(at.first);
  shared.scale = float(at.scale);
  shared.scale_root = float(std::sqrt(at.scale));
  shared.object = at.object;
  // Branches from offset `from` of the tree's blocks (1: the trunk, after the root).
  auto add = [&](int list, int64_t from, int64_t count, float value) {
    if (count <= 0) return;
    shared.static_first = at.static_first + from;
    shared.value = value;
    TileLists::Segment s = tiles.add(list, at.first + from, count, width, shared);
    if (segments) segments->push_back(s);
  };
  const int stepped = stepped_levels(m, lod);
  const int rate = carry_rate(lod);
  const int carry_phase = phase & (rate - 1);
  const int carried_end = derived ? derivable_level(m, lod) : m.levels;
  if (mode == BOREAS_TREE_LAGGED) add(tree_step_list(0), 1, m.level_begin[size_t(stepped)], hold);
  const std::vector<TreeTier> tiers = tree_tiers(m);
  for (int k = 0; k < int(tiers.size()); ++k) {
    const TreeTier& t = tiers[size_t(k)];
    if (t.level >= carried_end) continue;
    if (t.level >= stepped)
      add(tree_carry_list(k, rate, carry_phase), 1 + t.begin, t.end - t.begin, 0.0f);
    else if (mode == BOREAS_TREE_EXACT)
      add(tree_step_list(k), 1 + t.begin, t.end - t.begin, hold);
  }
}

}  // namespace boreas::impl
