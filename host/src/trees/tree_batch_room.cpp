// boreas: a tree batch's room (the capacities of its spaces), taken and given back: how a
// world's add in pieces leaves a refused add's batches with the memory they had.
#include "trees/tree_batch.h"

#include <algorithm>

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

void TreeBatch::fit_room(const Room& before) {
  const Room now = room();
  if (now.own != before.own && entries_.capacity > std::max(kMinEntries, entries_.used()))
    relayout_trees(std::max(kMinEntries, entries_.used()), true);
  if ((now.template_entries != before.template_entries ||
       now.template_leaves != before.template_leaves) &&
      (static_entries_.capacity > std::max(kMinTemplateEntries, static_entries_.used()) ||
       static_leaves_.capacity > std::max(kMinTemplateLeaves, static_leaves_.used())))
    relayout_templates(std::max(kMinTemplateEntries, static_entries_.used()),
                       std::max(kMinTemplateLeaves, static_leaves_.used()), true);
  if (now.settled != before.settled && settled_entries_.capacity > 0 &&
      settled_entries_.capacity > std::max(kMinEntries, settled_entries_.used()))
    relayout_settled(std::max(kMinEntries, settled_entries_.used()), true, settled_planes_);
}

}  // namespace boreas::impl
