// boreas tests: the binary ray hierarchies collapsed into wide nodes (host/src/rays/
// bvh_wide.h). The cast walks only the wide nodes, so they must stand for the binary
// hierarchy exactly: every item in one leaf slot with the binary leaf's range, every slot's
// box the binary node's it names, and the wide depth within what the cast's stack
// (BOREAS_RAY_WIDE_STACK) holds, also for the deepest hierarchy the builder makes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "rays/bvh_wide.h"
#include "rays/host_scene.h"

namespace boreas::impl {
namespace {

int word(const float* w) {
  int32_t v;
  std::memcpy(&v, w, sizeof v);
  return v;
}

std::vector<Box> random_boxes(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> at(-50.0f, 50.0f), size(0.01f, 3.0f);
  std::vector<Box> b;
  for (int i = 0; i < n; ++i) {
    const float x = at(rng), y = at(rng), z = at(rng);
    b.push_back({x, y, z, x + size(rng), y + size(rng), z + size(rng)});
  }
  return b;
}

// As test_bvh_depth.cpp's: lines of boxes at doubling distances make the SAH a chain, which
// the builder cuts off at the depth bound.
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

// Walks the wide nodes as a ray that enters every box would, checking each slot against the
// binary node it names; returns the most entries the cast's stack would hold.
int expect_the_binary_hierarchy(const Bvh& bvh, const WideBvh& wide) {
  std::vector<int> seen(bvh.items.size(), 0);
  std::vector<int> stack = {0};  // wide nodes, and -1 for a leaf slot's entry
  int most = 1;
  while (!stack.empty()) {
    const int w = stack.back();
    stack.pop_back();
    if (w < 0) continue;
    const float* node = &wide.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS];
    for (int k = 0; k < 4; ++k) {
      const int g = wide.gather[size_t(w) * 4 + size_t(k)];
      const int a = word(&node[BOREAS_RAY_WIDE_A + k]), count = word(&node[BOREAS_RAY_WIDE_COUNT + k]);
      if (count < 0) {
        EXPECT_EQ(g, -1);
        EXPECT_GT(node[BOREAS_RAY_WIDE_LO + k], node[BOREAS_RAY_WIDE_HI + k]) << "an empty slot's box";
        continue;
      }
      EXPECT_GE(g, 0) << "wide node " << w << " slot " << k;
      if (g < 0) continue;
      const float* b = &bvh.nodes[size_t(g) * BOREAS_RAY_NODE_WORDS];
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(node[BOREAS_RAY_WIDE_LO + 4 * axis + k], b[axis]) << "wide node " << w << " slot " << k;
        EXPECT_EQ(node[BOREAS_RAY_WIDE_HI + 4 * axis + k], b[4 + axis]) << "wide node " << w << " slot " << k;
      }
      EXPECT_EQ(count, word(&b[7]));
      if (count > 0) {
        EXPECT_EQ(a, word(&b[3]));
        for (int i = a; i < a + count; ++i) ++seen[size_t(bvh.items[size_t(i)])];
        stack.push_back(-1);
      } else {
        EXPECT_GT(a, w);
        stack.push_back(a);
      }
    }
    most = std::max(most, int(stack.size()));
  }
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "item " << i;
  return most;
}

TEST(BvhWide, EverySlotIsTheBinaryNodeItNamesAndEveryItemInOneLeaf) {
  for (const int leaf : {kBvhInstanceLeafItems, kBvhLeafItems}) {
    for (const int n : {1, 2, 3, 4, 5, 9, 100, 5000}) {
      const std::vector<Box> boxes = random_boxes(n, unsigned(n));
      const Bvh bvh = build_bvh(boxes, BOREAS_RAY_DEPTH, leaf);
      const WideBvh wide = collapse_bvh(bvh);
      ASSERT_GT(wide.node_count(), 0);
      // A root that is a leaf: one wide node of one slot.
      if (n <= leaf) EXPECT_EQ(wide.node_count(), 1);
      expect_the_binary_hierarchy(bvh, wide);
    }
  }
  EXPECT_EQ(collapse_bvh(build_instance_bvh({})).node_count(), 0);
}

// An empty slot's box (the builder's empty box, min inf, max -inf) passes the slab test,
// which does not ask which side is which; its a is -1, which the cast would take for leaf
// slot 0 of wide node 0 (~-1 is 0): it must never be pushed.
TEST(BvhWide, AnEmptySlotIsNeverPushed) {
  const std::vector<Box> boxes = {{0, 0, 0, 1, 1, 1}, {2, 0, 0, 3, 1, 1}, {4, 0, 0, 5, 1, 1}};
  const WideBvh wide = collapse_bvh(build_bvh(boxes, BOREAS_RAY_DEPTH, 1));
  ASSERT_EQ(wide.node_count(), 1);
  ASSERT_EQ(std::count(wide.gather.begin(), wide.gather.end(), -1), 1) << "three slots, one empty";
  BoreasRayScene s{};
  s.wide = wide.nodes.data();
  // Along the row through all three boxes, and the same ray above them all.
  for (const float y : {0.5f, 5.0f}) {
    const BoreasRay r = boreas_ray_make(boreas_v3(-1.0f, y, 0.5f),
                                        boreas_v3_normalize(boreas_v3(1.0f, 0.01f, 0.01f)));
    int stack[BOREAS_RAY_WIDE_STACK], top = 0;
    float enter[BOREAS_RAY_WIDE_STACK];
    boreas_ray_push_slots(&r, &s, 0, 0, wide.nodes.data(), 0, INFINITY, stack, enter, &top);
    // Entered: the three slots in use, each once (a leaf slot as ~(4 w + slot)).
    std::vector<int> pushed(stack, stack + top), expected;
    for (int k = 0; y < 1.0f && k < 4; ++k) {
      const int count = word(&wide.nodes[size_t(BOREAS_RAY_WIDE_COUNT + k)]);
      if (count >= 0) expected.push_back(count > 0 ? ~k : word(&wide.nodes[size_t(BOREAS_RAY_WIDE_A + k)]));
    }
    std::sort(pushed.begin(), pushed.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(pushed, expected) << "y " << y;
  }
}

// The cast visits a wide node's entered slots nearest first: pushed farthest lowest, and of
// two the ray enters at one distance the lower slot lower (the order a stable sort by
// distance gives, which the hits' ties follow). Four leaf slots along a ray on x, two at
// one distance, and the same with one slot off the ray and one behind its reach.
TEST(BvhWide, SlotsArePushedFarthestFirstTiesInSlotOrder) {
  struct Case {
    float lo[4], hi[4];  // the slots' x sides (y and z: [0, 1])
    float t_max;
    std::vector<int> order;  // the slots pushed, bottom first
  };
  const std::vector<Case> cases = {
      {{4, 2, 4, 6}, {5, 3, 5, 7}, INFINITY, {3, 0, 2, 1}},
      {{4, 2, 4, 6}, {5, 3, 5, 7}, 5.5f, {0, 2, 1}},
      {{2, 2, 2, 2}, {3, 3, 3, 3}, INFINITY, {0, 1, 2, 3}},
      {{6, 4, 2, 8}, {7, 5, 3, 9}, INFINITY, {3, 0, 1, 2}},
  };
  for (size_t c = 0; c < cases.size(); ++c) {
    float node[BOREAS_RAY_WIDE_WORDS] = {};
    for (int k = 0; k < 4; ++k) {
      node[BOREAS_RAY_WIDE_LO + k] = cases[c].lo[k];
      node[BOREAS_RAY_WIDE_HI + k] = cases[c].hi[k];
      node[BOREAS_RAY_WIDE_HI + 4 + k] = node[BOREAS_RAY_WIDE_HI + 8 + k] = 1.0f;
      const int32_t a = 10 * k, count = 1;
      std::memcpy(&node[BOREAS_RAY_WIDE_A + k], &a, sizeof a);
      std::memcpy(&node[BOREAS_RAY_WIDE_COUNT + k], &count, sizeof count);
    }
    BoreasRayScene s{};
    s.wide = node;
    const BoreasRay r = boreas_ray_make(boreas_v3(-1.0f, 0.5f, 0.5f), boreas_v3(1.0f, 0.0f, 0.0f));
    int stack[BOREAS_RAY_WIDE_STACK], top = 0;
    float enter[BOREAS_RAY_WIDE_STACK];
    boreas_ray_push_slots(&r, &s, 0, 0, node, 0, cases[c].t_max, stack, enter, &top);
    std::vector<int> pushed;
    for (int i = 0; i < top; ++i) {
      pushed.push_back(~stack[i]);
      EXPECT_EQ(enter[i], cases[c].lo[~stack[i]] + 1.0f) << "case " << c << ", slot " << ~stack[i];
    }
    EXPECT_EQ(pushed, cases[c].order) << "case " << c;
  }
}

// The cast's stack bound, 3 (D / 2) + 4 for binary leaves at most D deep
// (BOREAS_RAY_WIDE_STACK at D = BOREAS_RAY_DEPTH), on chains the builder cuts off at the
// depth asked for (their leaves reach it).
TEST(BvhWide, TheDeepestHierarchiesFitTheCastsStack) {
  const std::vector<Box> boxes = doubling_lines(100);
  for (const int depth : {9, 10, 13, 16}) {
    const Bvh bvh = build_bvh(boxes, depth);
    ASSERT_EQ(bvh_depth(bvh), depth);
    const int most = expect_the_binary_hierarchy(bvh, collapse_bvh(bvh));
    EXPECT_LE(most, 3 * (depth / 2) + 4) << "depth " << depth;
  }
  EXPECT_EQ(BOREAS_RAY_WIDE_STACK, 3 * (BOREAS_RAY_DEPTH / 2) + 4);
}

}  // namespace
}  // namespace boreas::impl
