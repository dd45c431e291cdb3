// boreas: a tree's step launches by mode and level of detail (tree_tiles.h).
#include "trees/tree_tiles.h"

#include <algorithm>

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

void add_tree_tiles(TileLists& tiles, boreas_tree_mode mode, const TreeModel& m, int64_t first,
                    int64_t leaf_first, TreeLod lod, float hold, int phase, int width,
                    std::vector<TileLists::Segment>* segments) {
  auto add = [&](int list, int64_t from, int64_t count, float value) {
    if (count <= 0) return;
    TileLists::Segment s = tiles.add(list, from, count, width, value);
    if (segments) segments->push_back(s);
  };
  const int stepped = stepped_levels(m, lod);
  const int64_t base = first + 1;  // the trunk's entry, after the root
  if (mode == BOREAS_TREE_LAGGED) {
    const int64_t split = m.level_begin[size_t(stepped)];
    add(tree_step_list(0), base, split, hold);
    add(tree_carry_list(0), base + split, int64_t(m.branches.size()) - split, 0.0f);
  } else {
    for (int l = 0; l < m.levels; ++l) {
      const int64_t a = m.level_begin[size_t(l)], b = m.level_begin[size_t(l) + 1];
      if (l < stepped)
        add(tree_step_list(l), base + a, b - a, hold);
      else
        add(tree_carry_list(l), base + a, b - a, 0.0f);
    }
  }
  const int rate_log2 = lod == TreeLod::kReduced ? 1 : lod == TreeLod::kFar ? 2 : 0;
  add(tree_leaf_list(rate_log2, phase & ((1 << rate_log2) - 1)), leaf_first,
      int64_t(m.leaves.size()), 0.0f);
}

}  // namespace boreas::impl
