// boreas: a tree batch's room (the capacities of its spaces), taken and given back: how a
// world's add in pieces leaves a refused add's batches with the memory they had.
#include "trees/tree_batch.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace boreas::impl {

TreeBatch::Room TreeBatch::room() const {
  return {entries_.capacity, settled_entries_.capacity, static_entries_.capacity,
          static_leaves_.capacity};
}

void TreeBatch::restore_room(const Room& room) {
  if (room == this->room()) return;
  // Capacity 0: the batch had no buffer of the space yet (a new batch); its trees are gone
  // again, so nothing reads the buffers, and the next add makes them anew with the sink.
  if (room.own == 0) {
    for (int k = 0; k < 2; ++k) state_[k] = motion_[k] = cl::Buffer();
    entries_ = Space{};
  } else if (entries_.capacity != room.own) {
    relayout_trees(room.own, true);
  }
  if (room.template_entries == 0) {
    parents_ = children_ = shape_ = response_ = radius_ = leaves_ = cl::Buffer();
    static_entries_ = Space{};
    static_leaves_ = Space{};
  } else if (static_entries_.capacity != room.template_entries ||
             static_leaves_.capacity != room.template_leaves) {
    relayout_templates(room.template_entries, room.template_leaves, true);
  }
  if (room.settled == 0) {
    drop_settled();
    settled_ = cl::Buffer();
    settled_entries_ = Space{};
  } else if (settled_entries_.capacity != room.settled) {
    relayout_settled(room.settled, true, settled_planes_);
  }
  rebuild_tiles_ = records_stale_ = true;
}

TreeBatch::Room TreeBatch::used_room() const {
  return {entries_.used(), settled_entries_.used(), static_entries_.used(), static_leaves_.used()};
}

void TreeBatch::reserve_room(const Room& want) {
  const SpaceLimits most = space_limits();
  if (want.own > entries_.capacity)
    relayout_trees(std::min(want.own, most.entries), entries_.dead > 0);
  if (want.template_entries > static_entries_.capacity ||
      want.template_leaves > static_leaves_.capacity)
    relayout_templates(
        std::min(std::max(want.template_entries, static_entries_.capacity), most.template_entries),
        std::min(std::max(want.template_leaves, static_leaves_.capacity), most.template_leaves),
        static_entries_.dead > 0 || static_leaves_.dead > 0);
  if (settled_entries_.capacity > 0 && want.settled > settled_entries_.capacity &&
      entries_.capacity + want.settled <= std::numeric_limits<int32_t>::max())
    relayout_settled(want.settled, settled_entries_.dead > 0, settled_planes_);
}

void TreeBatch::fit_room(const Room& before) {
  // Within a quarter of the live entries (a reserve_room that guessed well) it stays.
  auto loose = [](int64_t capacity, int64_t used, int64_t minimum) {
    return capacity > std::max(minimum, used + used / 4);
  };
  const Room now = room();
  if (now.own != before.own && loose(entries_.capacity, entries_.used(), kMinEntries))
    relayout_trees(std::max(kMinEntries, entries_.used()), true);
  if ((now.template_entries != before.template_entries ||
       now.template_leaves != before.template_leaves) &&
      (loose(static_entries_.capacity, static_entries_.used(), kMinTemplateEntries) ||
       loose(static_leaves_.capacity, static_leaves_.used(), kMinTemplateLeaves)))
    relayout_templates(std::max(kMinTemplateEntries, static_entries_.used()),
                       std::max(kMinTemplateLeaves, static_leaves_.used()), true);
  if (now.settled != before.settled && settled_entries_.capacity > 0 &&
      loose(settled_entries_.capacity, settled_entries_.used(), kMinEntries))
    relayout_settled(std::max(kMinEntries, settled_entries_.used()), true, settled_planes_);
}

}  // namespace boreas::impl
