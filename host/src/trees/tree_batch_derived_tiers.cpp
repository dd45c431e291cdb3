// boreas: derived levels written out tier by tier. A finest level with split pieces
// (tree_model.h's step tiers) holds pieces whose parent is a piece of the same level, so a
// launch that writes poses over derived entries must write a piece's parent first: one
// launch per tier, in tier order, each reading only tiers written before it.
#include <algorithm>
#include <cmath>

#include "runtime/cl_check.h"
#include "runtime/launch.h"
#include "shared/tree_types.h"
#include "trees/tree_batch.h"
#include "trees/tree_tiles.h"

namespace boreas::impl {

// The chain a reader walks (cl/shared/tree_state.h) is a finest level's pieces of every
// split depth: its bound is the split depth's.
static_assert(BOREAS_TREE_MAX_CHAIN == kMaxSplitDepth + 1, "tree_types.h's chain bound");

int TreeBatch::add_derived_tier_tiles(TileLists& tiles, const Slot& slot, int32_t object) const {
  const TreeModel& m = *slot.tree->model;
  const int level = m.levels - 1;  // only the finest level is ever derived
  const TreeTileSource at = tile_source(slot);
  TileLists::Shared shared;
  shared.root = slot.first;
  shared.scale = float(at.scale);
  shared.scale_root = float(std::sqrt(at.scale));
  shared.object = object;
  int list = 0;
  for (const TreeTier& t : tree_tiers(m)) {
    if (t.level != level) continue;
    shared.static_first = at.static_first + block_index(t.begin);
    tiles.add(list++, slot.first + block_index(t.begin), t.end - t.begin, int(runtime_.group_size()),
              shared);
  }
  return list;
}

void TreeBatch::write_derived_poses(const Slot& slot) {
  // Its level is stepped or carried again from this step on; the lagged step reads the
  // parents' previous state. Where the level has split pieces, a piece's parent is in the
  // level and held marks: the derived poses go into the current half (copy_to_next_state
  // then gives the other one the same), as cl/tree_derive.cl poses them for readers, but
  // kept (no posed flag is left to write the marks back). Without split pieces the parents
  // are the coarser levels' stored entries, and the step writes the level itself: nothing.
  const TreeModel& m = *slot.tree->model;
  if (!level_has_splits(m, m.levels - 1)) return;
  TileLists tiles(kMaxTreeTiers);
  const int lists = add_derived_tier_tiles(tiles, slot, 1);
  if (lists == 0) return;
  tiles.flush(runtime_);  // a blocking upload: the tiles' ints may go with this call
  // The launches keep their buffers (the tiles', rows) until they have run: no wait here.
  cl::Buffer rows = runtime_.buffer(CL_MEM_READ_WRITE, 2 * sizeof(cl_int), "tree derived rows");
  cl::Kernel& k = runtime_.kernel("tree_derive.cl", "boreas_tree_derive", plane_defines());
  for (int l = 0; l < lists; ++l)
    launch(runtime_, k, Items(tiles.size(l) * runtime_.group_size()), state_[current_],
           motion_[current_], int(entries_.capacity), parents_, shape_,
           int(static_entries_.capacity), tiles.buffer(l), 0, rows, 0, rows, 0);
}

}  // namespace boreas::impl
