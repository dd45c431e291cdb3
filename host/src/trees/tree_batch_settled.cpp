// boreas: the settled space (cl/shared/tree_types.h, BOREAS_TREE_SETTLED_*): derived
// branches held apart from the trees' own planes, with only what their pose is derived from.
#include <algorithm>
#include <cstring>
#include <vector>

#include "runtime/cl_check.h"
#include "trees/tree_batch.h"
#include "trees/tree_tiles.h"

namespace boreas::impl {

int32_t TreeBatch::settled_begin(const Slot& slot) const {
  if (slot.settled_first < 0) return slot.count;
  const TreeModel& m = *slot.tree->model;
  return block_index(m.level_begin[size_t(derivable_level(m, slot.lod))]);
}

int32_t TreeBatch::settled_root(const Slot& slot) const {
  if (slot.settled_first < 0) return slot.first;
  return int32_t(entries_.capacity) + slot.settled_first - settled_begin(slot);
}

void TreeBatch::settled_split(uint64_t key, int32_t* own, int32_t* settled_entry) const {
  const Slot& slot = slot_of(key);
  const int32_t begin = settled_begin(slot);
  *own = begin - 1;
  *settled_entry = settled_root(slot) + begin;
}

void TreeBatch::drop_settled() {
  if (settled_entries_.capacity == 0) return;
  for (Slot& slot : slots_) slot.settled_first = -1;
  settled_ = cl::Buffer();
  settled_entries_ = Space{};
  records_stale_ = true;
}

std::vector<TreeBatch::SettledRange> TreeBatch::copy_derived_to_settled() {
  drop_settled();
  std::vector<SettledRange> ranges;
  std::vector<Slot*> settled_slots;
  std::vector<std::vector<float>> marks;
  int64_t end = 1;  // entry 0: the sink, as in every space
  for (Slot& slot : slots_) {
    if (!slot.tree || !slot.derived) continue;
    int32_t begin = 0;
    marks.push_back(derived_marks(slot, &begin));
    SettledRange r;
    r.count = int32_t(marks.back().size() / 4);
    r.own_first = slot.first + block_index(begin);
    r.settled_first = int32_t(end);
    r.static_first = template_of(slot).first + block_index(begin);
    r.scale = float(slot.tree->params.scale);
    ranges.push_back(r);
    settled_slots.push_back(&slot);
    end += r.count;
  }
  // All new before the batch takes it: a failed allocation leaves every reader on the own
  // planes (their marks and motion are never changed here).
  const int64_t capacity = std::max(kMinEntries, end);
  cl::Buffer settled = runtime_.buffer(
      CL_MEM_READ_WRITE, size_t(BOREAS_TREE_SETTLED_PLANES) * size_t(capacity) * sizeof(float),
      "tree settled planes");
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
      settled, 0.0f, 0, size_t(BOREAS_TREE_SETTLED_PLANES) * size_t(capacity) * sizeof(float)));
  for (size_t r = 0; r < ranges.size(); ++r) {
    const SettledRange& s = ranges[r];
    const size_t count = size_t(s.count);
    // Parent, template entry, scale: the marks' planes 1..3 (the state may hold poses now).
    runtime_.write_planes(settled, size_t(capacity), size_t(s.settled_first), marks[r].data() + count,
                          count, count, 3);
    // F and the broken flag, as the last carry left them (equal in both halves).
    runtime_.copy_planes(motion_[current_], size_t(entries_.capacity), size_t(s.own_first), settled,
                         size_t(capacity), size_t(s.settled_first) + size_t(BOREAS_TREE_SETTLED_F) * size_t(capacity),
                         count, 4);
  }
  settled_ = settled;
  settled_entries_ = Space{};
  settled_entries_.end = end;
  settled_entries_.capacity = capacity;
  for (size_t r = 0; r < ranges.size(); ++r) settled_slots[r]->settled_first = ranges[r].settled_first;
  records_stale_ = true;  // the readers' tiles anew, from the settled entries
  return ranges;
}

}  // namespace boreas::impl
