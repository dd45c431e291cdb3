// boreas tests: the ray hierarchies' depth bound (cl/shared/ray_types.h, BOREAS_RAY_TOP_DEPTH
// and BOREAS_RAY_DEPTH; host/src/rays/bvh_build.cpp). A traversal's stack holds depth + 1
// nodes (cl/shared/ray_cast.h), so no leaf may lie deeper than the bound, whatever the placement: a line of boxes
// (three, along the axes) at ever doubling distances makes the SAH peel a few boxes a
// level (a chain), and coincident boxes leave it nothing to bin.
// Each hierarchy must also stay a hierarchy: every box in exactly one leaf, every node's box
// holding its children's, each pair of children from an even node.
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
      // Pairs from even indices, sharing a cache line (bvh_build.h's pad).
      EXPECT_EQ(a % 2, 0) << "children from node " << a;
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
  // levels, then halving), its chain goes deeper than the top stack held (32 entries, 31
  // levels): a traversal of it would have written past that stack.
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
