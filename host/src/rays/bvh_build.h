// boreas: a bounding volume hierarchy over boxes, built on the host — each instance's
// (from its primitives' boxes at the time it enters the ray structure; refitted on the
// device afterwards, host/src/rays/ray_scene.h) and the one over the instances (every
// cast that updates).
//
// Top-down, binned surface area heuristic (Wald, "On fast construction of SAH-based
// bounding volume hierarchies", 2007): 16 bins of centroids along the widest axis. Leaves
// hold up to kBvhLeafItems primitives (the instances' hierarchies kBvhInstanceLeafItems). No leaf lies deeper than the depth asked for (the
// traversal's stack bound, BOREAS_RAY_TOP_DEPTH or BOREAS_RAY_DEPTH, cl/shared/ray_types.h):
// where the SAH's split could leave a side more items than halving by count can place
// within that depth (a line of boxes spaced ever wider makes a chain), the split is by
// count (halves) instead.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shared/ray_types.h"

namespace boreas::impl {

using Box = std::array<float, 6>;  // min xyz, max xyz

inline constexpr int kBvhLeafItems = 4;
// An instance's hierarchy (build_instance_bvh) holds two a leaf, not four: the cast tests a
// wide node's four slots at once (bvh_wide.h), so a leaf's items cost their records' loads
// (a tree's band also its curve's) where a smaller leaf's box would have turned the ray
// away first (bench/RESULTS.md, "Issue 37, tenth round: wide": 4 -> 2 cut the cast's CPU by
// about a tenth on trees/1 and a sixth on trees/10, the update's grew by a tenth; 1 gained
// no more on trees/10 and lost on trees/1). Its binary nodes about double.
inline constexpr int kBvhInstanceLeafItems = 2;

// Node 1 of a hierarchy whose root is inner is a pad that nothing points at, so that each
// pair of children (nodes a and a + 1, allocated together) starts at an even index: with the
// scene's buffers holding each hierarchy from an even node (ray_scene.cpp), a pair's two
// 32-byte nodes share one 64-byte cache line, which the traversal's box tests of both
// children then load once (the nodes' loads were the cast's largest share of misses:
// bench/RESULTS.md, "Issue 37, seventh round: rays4").
struct Bvh {
  // BOREAS_RAY_NODE_WORDS words a node (cl/shared/ray_types.h), root first; node and item
  // indices relative to this hierarchy (the scene offsets them).
  std::vector<float> nodes;
  std::vector<int32_t> items;  // primitive indices, each leaf's a contiguous range
  int node_count() const { return int(nodes.size() / BOREAS_RAY_NODE_WORDS); }
};

// The hierarchy over boxes (empty boxes, min > max, are kept: they cost a leaf slot), its
// leaves at most max_depth deep (the root at depth 0). No boxes: an empty hierarchy
// (node_count() 0). More boxes than halving places within max_depth: BOREAS_ERROR_OUT_OF_MEMORY.
// Leaves hold up to leaf_items boxes.
Bvh build_bvh(const std::vector<Box>& boxes, int max_depth, int leaf_items = kBvhLeafItems);

// An instance's hierarchy: within BOREAS_RAY_DEPTH, kBvhInstanceLeafItems a leaf.
Bvh build_instance_bvh(const std::vector<Box>& boxes);

// A pad node: a leaf of one item (item 0) with an empty box, which no ray enters and no
// refit reaches (refit_runs.h walks from the root).
void write_pad_node(float* w);

// How deep halving by count puts the leaves below a node of `count` items.
int bvh_halving_depth(int64_t count, int leaf_items = kBvhLeafItems);

// The depth of the hierarchy's deepest leaf (the root at depth 0; -1 when empty).
int bvh_depth(const Bvh& bvh);

// Box b widened to hold p.
void grow_box(Box& b, const float p[3]);
Box empty_box();

}  // namespace boreas::impl
