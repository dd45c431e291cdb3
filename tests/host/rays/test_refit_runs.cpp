// boreas tests: the refit's runs of nodes (host/src/rays/refit_runs.h). Made in the order
// the kernel makes them (every subtree run, then the top run, each by falling index), every
// inner node must find both children made before it, every node must be made exactly once,
// and a subtree run must hold at most the nodes asked for.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "rays/refit_runs.h"
#include "shared/ray_types.h"

namespace boreas::impl {
namespace {

int word(const float* w) {
  int32_t v;
  std::memcpy(&v, w, sizeof v);
  return v;
}

Bvh random_hierarchy(int boxes, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> at(-10.0f, 10.0f), size(0.0f, 1.0f);
  std::vector<Box> b;
  for (int i = 0; i < boxes; ++i) {
    const float x = at(rng), y = at(rng), z = at(rng);
    b.push_back({x, y, z, x + size(rng), y + size(rng), z + size(rng)});
  }
  return build_bvh(b, BOREAS_RAY_DEPTH);
}

void expect_children_first(const Bvh& bvh, int node_first, int max_run) {
  std::vector<int32_t> order = {-7, -7};  // runs are placed after what the order held
  const RefitRuns runs = refit_runs(bvh, node_first, max_run, &order);
  std::vector<int> made(size_t(bvh.node_count()), 0);
  auto make = [&](const std::array<int32_t, 2>& run) {
    for (int e = run[0]; e < run[0] + run[1]; ++e) {
      const int n = order[size_t(e)] - node_first;
      ASSERT_GE(n, 0);
      ASSERT_LT(n, bvh.node_count());
      const float* w = &bvh.nodes[size_t(n) * BOREAS_RAY_NODE_WORDS];
      if (word(&w[7]) == 0) {
        const int a = word(&w[3]);
        EXPECT_EQ(made[size_t(a)], 1) << "node " << n << " made before its child " << a;
        EXPECT_EQ(made[size_t(a) + 1], 1) << "node " << n << " made before its child " << a + 1;
      }
      ++made[size_t(n)];
    }
  };
  for (const auto& run : runs.subtrees) {
    EXPECT_GE(run[0], 2);
    EXPECT_LE(run[1], max_run);
    make(run);
  }
  make(runs.top);
  // Every node once but the pad (node 1 below an inner root, bvh_build.h), which none reaches.
  const int pads = bvh.node_count() > 1 ? 1 : 0;
  for (int n = 0; n < bvh.node_count(); ++n)
    EXPECT_EQ(made[size_t(n)], pads == 1 && n == 1 ? 0 : 1) << "node " << n;
  EXPECT_EQ(order.size(), size_t(bvh.node_count() - pads) + 2);
}

TEST(RefitRuns, EveryNodeIsMadeOnceAfterItsChildren) {
  for (const int boxes : {1, 3, 5, 100, 5000})
    for (const int max_run : {1, 7, 64, 1024}) {
      SCOPED_TRACE(testing::Message() << boxes << " boxes, runs of " << max_run);
      expect_children_first(random_hierarchy(boxes, unsigned(boxes)), 1000, max_run);
    }
}

TEST(RefitRuns, AHierarchyOfManyRunsSpreadsItsNodesOverThem) {
  const Bvh bvh = random_hierarchy(20000, 3);
  std::vector<int32_t> order;
  const RefitRuns runs = refit_runs(bvh, 0, 1024, &order);
  // Maximal subtrees of at most 1,024 nodes: the cores get several runs, and few nodes are
  // left above them for the top run.
  ASSERT_GE(runs.subtrees.size(), size_t(bvh.node_count() / 1024));
  EXPECT_GE(runs.subtrees.size(), 8u);
  EXPECT_LT(runs.top[1], bvh.node_count() / 100);
}

// Each item names the subtree run that makes its leaf, and every item has one (the update
// refits only the runs whose items' boxes it wrote: ray_scene.cpp, mark_runs).
TEST(RefitRuns, EachItemNamesTheRunThatMakesItsLeaf) {
  for (const int boxes : {1, 5, 5000}) {
    const Bvh bvh = random_hierarchy(boxes, unsigned(boxes) + 1);
    std::vector<int32_t> order;
    const RefitRuns runs = refit_runs(bvh, 0, 64, &order);
    ASSERT_EQ(runs.item_run.size(), bvh.items.size());
    std::vector<int> named(bvh.items.size(), 0);
    for (size_t r = 0; r < runs.subtrees.size(); ++r)
      for (int e = runs.subtrees[r][0]; e < runs.subtrees[r][0] + runs.subtrees[r][1]; ++e) {
        const float* w = &bvh.nodes[size_t(order[size_t(e)]) * BOREAS_RAY_NODE_WORDS];
        for (int k = word(&w[3]); word(&w[7]) > 0 && k < word(&w[3]) + word(&w[7]); ++k) {
          EXPECT_EQ(runs.item_run[size_t(k)], int(r)) << "item " << k;
          ++named[size_t(k)];
        }
      }
    for (size_t k = 0; k < named.size(); ++k) EXPECT_EQ(named[k], 1) << boxes << " boxes, item " << k;
  }
}

TEST(RefitRuns, NoHierarchyMakesNoRuns) {
  std::vector<int32_t> order;
  const RefitRuns runs = refit_runs(build_bvh({}, BOREAS_RAY_DEPTH), 0, 1024, &order);
  EXPECT_TRUE(runs.subtrees.empty());
  EXPECT_EQ(runs.top[1], 0);
  EXPECT_TRUE(order.empty());
}

}  // namespace
}  // namespace boreas::impl
