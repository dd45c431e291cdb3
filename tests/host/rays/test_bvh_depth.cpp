// boreas tests: the ray hierarchies' depth bound (cl/shared/ray_types.h, BOREAS_RAY_TOP_DEPTH
// and BOREAS_RAY_DEPTH; host/src/rays/bvh_build.cpp). A traversal's stack holds 3 depth / 2
// + 1 nodes (cl/shared/ray_cast.h, four wide), so no leaf may lie deeper than the bound, whatever the placement: a line of boxes
// (three, along the axes) at ever doubling distances makes the SAH peel a few boxes a
// level (a chain), and coincident boxes leave it nothing to bin.
// Each hierarchy must also stay a hierarchy: every box in exactly one leaf, every node's box
// holding its children's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "rays/bvh_build.h"
#include "shared/ray_types.h"

namespace boreas::impl {
namespace {

int word(const float* w) {
  int32_t v;
  std::memcpy(&v, w, sizeof v);
  return v;
}

// Unit boxes along the three axes, the k-th of each line 2^k m from the origin: the SAH's
// best split along the widest axis peels the few farthest boxes of that line off into a
// side of their own, a level each time (the rest of the line sits in a box half as long),
// so the hierarchy is a chain about a third as deep as the lines are long.
std::vector<Box> doubling_lines(int n) {
  std::vector<Box> b;
  for (int axis = 0; axis < 3; ++axis) {
    float at = 1.0f;
    for (int k = 0; k < n; ++k, at *= 2.0f) {
      Box x = {0, 0, 0, 1, 1, 1};
      x[size_t(axis)] += at;
      x[size_t(axis) + 3] += at;
      b.push_back(x);
    }
  }
  return b;
}

std::vector<Box> coincident(int n) { return std::vector<Box>(size_t(n), Box{0, 0, 0, 1, 1, 1}); }

// Every box in exactly one leaf, no leaf over kBvhLeafItems, every inner node's box holding
// its two children's, every leaf's holding its boxes.
void expect_a_hierarchy(const Bvh& bvh, const std::vector<Box>& boxes) {
  std::vector<int> seen(boxes.size(), 0);
  std::vector<int32_t> stack = {0};
  auto holds = [](const float* outer, const float* inner) {
    return outer[0] <= inner[0] && outer[1] <= inner[1] && outer[2] <= inner[2] &&
           outer[4] >= inner[4] && outer[5] >= inner[5] && outer[6] >= inner[6];
  };
  while (!stack.empty()) {
    const float* w = &bvh.nodes[size_t(stack.back()) * BOREAS_RAY_NODE_WORDS];
    stack.pop_back();
    const int a = word(&w[3]), count = word(&w[7]);
    if (count == 0) {
      for (int c = a; c < a + 2; ++c) {
        EXPECT_TRUE(holds(w, &bvh.nodes[size_t(c) * BOREAS_RAY_NODE_WORDS])) << "node " << c;
        stack.push_back(c);
      }
      continue;
    }
    EXPECT_LE(count, kBvhLeafItems);
    for (int i = a; i < a + count; ++i) {
      const int item = bvh.items[size_t(i)];
      ++seen[size_t(item)];
      const Box& b = boxes[size_t(item)];
      const float as_node[7] = {b[0], b[1], b[2], 0.0f, b[3], b[4], b[5]};
      EXPECT_TRUE(holds(w, as_node)) << "box " << item;
    }
  }
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "box " << i;
}

TEST(BvhDepth, HalvingDepthCountsLevels) {
  // Halving by count, the bound's own measure, against a count's leaves: 4 items a leaf.
  EXPECT_EQ(bvh_halving_depth(4), 0);
  EXPECT_EQ(bvh_halving_depth(5), 1);
  EXPECT_EQ(bvh_halving_depth(8), 1);
  EXPECT_EQ(bvh_halving_depth(9), 2);
  EXPECT_EQ(bvh_halving_depth(int64_t(4) << 31), 31);
  EXPECT_EQ(bvh_halving_depth((int64_t(4) << 31) + 1), 32);
}

TEST(BvhDepth, DoublingLinesWouldPassTheTopStack) {
  // The placement is degenerate indeed: bound only as the builder bound it before (48
  // levels, then halving), its chain goes deeper than the top stack's 31 levels: a traversal
  // of it would have written past that stack.
  EXPECT_GT(bvh_depth(build_bvh(doubling_lines(60), 48)), BOREAS_RAY_TOP_DEPTH);
}

TEST(BvhDepth, DoublingLinesStayWithinEachBound) {
  for (int n : {2, 17, 40, 60}) {
    const std::vector<Box> line = doubling_lines(n);
    for (int bound : {BOREAS_RAY_TOP_DEPTH, BOREAS_RAY_DEPTH, 6}) {
      SCOPED_TRACE(testing::Message() << n << " boxes, bound " << bound);
      const Bvh bvh = build_bvh(line, bound);
      EXPECT_LE(bvh_depth(bvh), bound);
      expect_a_hierarchy(bvh, line);
    }
  }
}

// The most entries a four-wide traversal (cl/shared/ray_cast.h, boreas_ray_push_wide) holds
// below node n and its pushes, popped from an otherwise empty stack, for a ray that enters
// every box, the deepest candidate popped last of all: k candidates pushed, then one of
// them popped with k - 1 left under it.
int wide_stack_peak(const Bvh& bvh, int n) {
  const float* w = &bvh.nodes[size_t(n) * BOREAS_RAY_NODE_WORDS];
  if (word(&w[7]) > 0) return 0;
  std::vector<int> candidates;
  for (int c = word(&w[3]); c < word(&w[3]) + 2; ++c) {
    const float* child = &bvh.nodes[size_t(c) * BOREAS_RAY_NODE_WORDS];
    if (word(&child[7]) > 0) {
      candidates.push_back(c);
    } else {
      candidates.push_back(word(&child[3]));
      candidates.push_back(word(&child[3]) + 1);
    }
  }
  const int k = int(candidates.size());
  int peak = k;
  for (int c : candidates) peak = std::max(peak, k - 1 + wide_stack_peak(bvh, c));
  return peak;
}

TEST(BvhDepth, TheWideTraversalFitsItsStack) {
  // Chains as deep as each bound lets them and full halvings (4 << bound coincident boxes,
  // every leaf at the bound, up to 4096 boxes): the root's entry and everything below it
  // within BOREAS_RAY_WIDE_STACK of the bound, which a full halving reaches.
  for (int bound : {BOREAS_RAY_TOP_DEPTH, BOREAS_RAY_DEPTH, 7, 6, 2, 1}) {
    SCOPED_TRACE(testing::Message() << "bound " << bound);
    for (int n : {2, 17, 40, 60}) {
      if (bound <= 10 && 3 * n > 4 << bound) continue;  // more than the bound holds
      const Bvh bvh = build_bvh(doubling_lines(n), bound);
      EXPECT_LE(std::max(1, wide_stack_peak(bvh, 0)), BOREAS_RAY_WIDE_STACK(bound)) << n << " boxes";
    }
    const int boxes = bound <= 10 ? 4 << bound : 4096;
    const int peak = std::max(1, wide_stack_peak(build_bvh(coincident(boxes), bound), 0));
    if (bound <= 10) EXPECT_EQ(peak, BOREAS_RAY_WIDE_STACK(bound));
    else EXPECT_LE(peak, BOREAS_RAY_WIDE_STACK(bound));
  }
}

TEST(BvhDepth, CoincidentBoxesAreHalved) {
  const std::vector<Box> same = coincident(1000);
  const Bvh bvh = build_bvh(same, BOREAS_RAY_TOP_DEPTH);
  EXPECT_EQ(bvh_depth(bvh), bvh_halving_depth(1000));
  expect_a_hierarchy(bvh, same);
}

TEST(BvhDepth, MoreBoxesThanTheBoundHoldsAreRefused) {
  // 4 boxes a leaf, 2 levels: 16 fit, 17 do not.
  EXPECT_LE(bvh_depth(build_bvh(coincident(16), 2)), 2);
  EXPECT_THROW(build_bvh(coincident(17), 2), std::exception);
}

}  // namespace
}  // namespace boreas::impl
