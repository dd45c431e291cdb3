// boreas: an instance's binary hierarchy (bvh_build.h) collapsed into wide nodes, four
// child boxes a node stored together (cl/shared/ray_types.h, BOREAS_RAY_WIDE_*), which the
// cast tests as one 4-lane operation (cl/shared/ray_wide.h).
//
// A wide node stands for a binary inner node at an even depth: its slots are its children's
// children, a child that is a leaf standing in a slot for itself (so two to four slots; the
// rest empty). A binary root that is a leaf makes one wide node of one slot. The binary
// nodes stay what the refit updates (refit_runs.h); each slot keeps which binary node it
// is, and cl/ray_wide.cl copies the refitted boxes into the slots after each refit.
// Halving the depth this way keeps the cast's stack bound (BOREAS_RAY_WIDE_STACK).
#pragma once

#include <cstdint>
#include <vector>

#include "rays/bvh_build.h"

namespace boreas::impl {

struct WideBvh {
  // BOREAS_RAY_WIDE_WORDS words a node, root first, boxes as the binary nodes had them;
  // a slot's a relative to this hierarchy (wide node or item).
  std::vector<float> nodes;
  // Four a node: the binary node (relative) whose box each slot holds, -1 for an empty slot.
  std::vector<int32_t> gather;
  int node_count() const { return int(gather.size() / 4); }
};

// The wide nodes of `bvh` (none when it is empty).
WideBvh collapse_bvh(const Bvh& bvh);

}  // namespace boreas::impl
