// boreas: a bounding volume hierarchy over boxes, built on the host — each instance's
// (from its primitives' boxes at the time it enters the ray structure; refitted on the
// device afterwards, host/src/rays/ray_scene.h) and the one over the instances (every
// cast that updates).
//
// Top-down, binned surface area heuristic (Wald, "On fast construction of SAH-based
// bounding volume hierarchies", 2007): 16 bins of centroids along the widest axis. Leaves
// hold up to kBvhLeafItems primitives; past kBvhMaxDepth levels the split is by count
// (halves), so a traversal's stack (cl/shared/ray_cast.h) always suffices.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shared/ray_types.h"

namespace boreas::impl {

using Box = std::array<float, 6>;  // min xyz, max xyz

inline constexpr int kBvhLeafItems = 4;
inline constexpr int kBvhMaxDepth = 48;

struct Bvh {
  // BOREAS_RAY_NODE_WORDS words a node (cl/shared/ray_types.h), root first; node and item
  // indices relative to this hierarchy (the scene offsets them).
  std::vector<float> nodes;
  std::vector<int32_t> items;  // primitive indices, each leaf's a contiguous range
  int node_count() const { return int(nodes.size() / BOREAS_RAY_NODE_WORDS); }
};

// The hierarchy over boxes (empty boxes, min > max, are kept: they cost a leaf slot).
// No boxes: an empty hierarchy (node_count() 0).
Bvh build_bvh(const std::vector<Box>& boxes);

// Box b widened to hold p.
void grow_box(Box& b, const float p[3]);
Box empty_box();

}  // namespace boreas::impl
