// boreas: settling at add — trees whose level of detail derives their finest level go
// straight into the settled space when added, so a forest seen from a focus never holds
// its finest levels in the own planes (152 bytes an entry against 28-40), not even while
// add() runs (trees/tree_batch.h).
#include <algorithm>
#include <limits>
#include <vector>

#include "errors.h"
#include "runtime/cl_check.h"
#include "trees/tree_batch.h"
#include "trees/tree_batch_new_trees.h"
#include "trees/tree_tiles.h"

namespace boreas::impl {

bool TreeBatch::settles_at_add(const TreeInstance& tree) const {
  // What settle_slots would do after its first kSettleTime of steps: a finest level its
  // level of detail derives, no collider touching it (none has met a new tree yet). Its
  // carry from rest would keep F, dF/dt and the broken flag at 0 (tree_step.cl: F h, with
  // F 0), so the settled entries start as they would end.
  if (!settling_ || !derivation_ || settled_copy_) return false;
  const TreeModel& m = *tree.model;
  return derivable_level(m, lod_of(tree.params)) < m.levels;
}

bool TreeBatch::settled_room(int64_t need, int64_t own_capacity) {
  const int planes = settled_planes();
  if (settled_entries_.fits(need) && settled_planes_ == planes) return true;
  // The settled buffer within the device's largest allocation, and every reader index (the
  // own stride plus a settled entry) within int.
  const uint64_t largest = runtime_.max_allocation();
  const int64_t by_bytes = largest > 0 ? int64_t(largest / (uint64_t(planes) * sizeof(float)))
                                       : std::numeric_limits<int64_t>::max();
  const int64_t most =
      std::min<int64_t>(by_bytes, std::numeric_limits<int32_t>::max() - own_capacity);
  try {
    const int64_t capacity = settled_entries_.grown(need, kMinEntries, most);
    if (settled_entries_.used() + need > capacity) return false;
    relayout_settled(capacity, settled_entries_.dead > 0, planes);
  } catch (const Error&) {
    return false;
  }
  return true;
}

void TreeBatch::plan_settling(const Trees& trees, NewTrees& n) {
  n.tree_own.resize(trees.size());
  n.tree_settled.assign(trees.size(), -1);
  int64_t own = 0, settled = 0;
  for (size_t t = 0; t < trees.size(); ++t) {
    const TreeModel& m = *trees[t]->model;
    n.tree_own[t] = n.tree_count[t];
    if (!settles_at_add(*trees[t])) {
      own += n.tree_own[t];
      continue;
    }
    const int32_t begin = m.level_begin[size_t(derivable_level(m, lod_of(trees[t]->params)))];
    n.tree_settled[t] = settled;
    settled += n.tree_own[t] - block_index(begin);
    n.tree_own[t] = block_index(begin);
    own += n.tree_own[t];
  }
  // The own planes' stride once make_room has grown them for the own entries.
  const int64_t own_capacity = entries_.fits(own)
                                   ? entries_.capacity
                                   : entries_.grown(own, kMinEntries, space_limits().entries);
  if (settled > 0 && settled_room(settled, own_capacity)) {
    n.need = own;
    n.settled_need = settled;
    n.settled_at = settled_entries_.end;
    return;
  }
  // Refused (or none settles): every tree whole in the own planes, as before.
  for (size_t t = 0; t < trees.size(); ++t) n.tree_own[t] = n.tree_count[t];
  n.tree_settled.assign(trees.size(), -1);
  n.settled_need = 0;
}

void TreeBatch::write_new_settled(const Trees& trees, const NewTrees& n) {
  if (n.settled_need == 0) return;
  // Their inputs (parent entry, template entry, scale) in pieces of at most add_piece_
  // entries (a piece at least one tree); F, the broken flag and dF/dt 0 (as a carry from
  // rest leaves them), filled on the device.
  const size_t c = size_t(settled_entries_.capacity);
  auto settled_of = [&](size_t t) { return n.tree_count[t] - n.tree_own[t]; };
  std::vector<float> inputs;
  for (size_t t = 0; t < trees.size();) {
    size_t end = t;
    int64_t count = 0;
    while (end < trees.size() && (count == 0 || count + settled_of(end) <= add_piece_))
      count += settled_of(end++);
    inputs.assign(3 * size_t(count), 0.0f);
    int64_t at = -1;
    for (int64_t k = 0; t < end; ++t) {
      if (n.tree_settled[t] < 0) continue;
      if (at < 0) at = n.tree_settled[t];
      const TreeInstance& tree = *trees[t];
      const TreeModel& m = *tree.model;
      const int64_t tp = n.tree_template[t];
      const int32_t static_first = tp >= 0 ? templates_[size_t(tp)].first
                                           : int32_t(n.static_at + n.fresh[size_t(-1 - tp)].first);
      derived_inputs(m, derivable_level(m, lod_of(tree.params)), int32_t(n.tree_first[t]),
                     static_first, float(tree.params.scale), inputs.data(), size_t(count),
                     size_t(k), true);
      k += settled_of(t);
    }
    if (count > 0)
      runtime_.write_planes(settled_, c, size_t(n.settled_at + at), inputs.data(), size_t(count),
                            size_t(count), 3);
  }
  for (int p = BOREAS_TREE_SETTLED_F; p < settled_planes_; ++p)
    BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
        settled_, 0.0f, (size_t(p) * c + size_t(n.settled_at)) * sizeof(float),
        size_t(n.settled_need) * sizeof(float)));
}

}  // namespace boreas::impl
