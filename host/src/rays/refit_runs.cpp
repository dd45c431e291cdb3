// boreas: the refit's runs of nodes (refit_runs.h).
#include "rays/refit_runs.h"

#include <algorithm>
#include <cstring>
#include <functional>

#include "shared/ray_types.h"

namespace boreas::impl {

namespace {

// A node's int word (the builder stores them bit for bit in its float array).
int word(const Bvh& bvh, int n, int w) {
  int32_t v;
  std::memcpy(&v, &bvh.nodes[size_t(n) * BOREAS_RAY_NODE_WORDS + size_t(w)], sizeof v);
  return v;
}

// A node's first child (inner nodes) and whether it is a leaf.
int first_child(const Bvh& bvh, int n, bool* leaf) {
  *leaf = word(bvh, n, 7) > 0;
  return word(bvh, n, 3);
}

// Appends `nodes` to the order by falling index, as one run.
std::array<int32_t, 2> add_run(std::vector<int32_t> nodes, int node_first, std::vector<int32_t>* order) {
  std::sort(nodes.begin(), nodes.end(), std::greater<int32_t>());
  const std::array<int32_t, 2> run = {int32_t(order->size()), int32_t(nodes.size())};
  for (int32_t n : nodes) order->push_back(node_first + n);
  return run;
}

}  // namespace

RefitRuns refit_runs(const Bvh& bvh, int node_first, int max_run, std::vector<int32_t>* order) {
  RefitRuns runs;
  const int count = bvh.node_count();
  if (count == 0) return runs;
  // Subtree sizes, children (larger indices) first.
  std::vector<int> size(size_t(count), 1);
  for (int n = count - 1; n >= 0; --n) {
    bool leaf;
    const int a = first_child(bvh, n, &leaf);
    if (!leaf) size[size_t(n)] += size[size_t(a)] + size[size_t(a) + 1];
  }
  runs.item_run.assign(bvh.items.size(), -1);
  std::vector<int32_t> top, stack = {0};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    bool leaf;
    const int a = first_child(bvh, n, &leaf);
    if (size[size_t(n)] > max_run) {
      top.push_back(n);
      stack.insert(stack.end(), {a + 1, a});
      continue;
    }
    std::vector<int32_t> subtree, below = {n};
    while (!below.empty()) {
      const int m = below.back();
      below.pop_back();
      subtree.push_back(m);
      const int c = first_child(bvh, m, &leaf);
      if (!leaf) below.insert(below.end(), {c, c + 1});
      else std::fill_n(runs.item_run.begin() + c, word(bvh, m, 7), int32_t(runs.subtrees.size()));
    }
    runs.subtrees.push_back(add_run(std::move(subtree), node_first, order));
  }
  if (!top.empty()) runs.top = add_run(std::move(top), node_first, order);
  return runs;
}

}  // namespace boreas::impl
