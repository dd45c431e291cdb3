// boreas: the binned-SAH builder of ray hierarchies (bvh_build.h).
#include "rays/bvh_build.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "errors.h"
#include "shared/ray_types.h"

namespace boreas::impl {

namespace {

constexpr int kBins = 16;

Box union_of(const Box& a, const Box& b) {
  return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]),
          std::max(a[3], b[3]), std::max(a[4], b[4]), std::max(a[5], b[5])};
}

float area(const Box& b) {
  const float x = std::max(b[3] - b[0], 0.0f), y = std::max(b[4] - b[1], 0.0f),
              z = std::max(b[5] - b[2], 0.0f);
  return x * y + y * z + z * x;
}

float centroid(const Box& b, int axis) { return 0.5f * (b[size_t(axis)] + b[size_t(axis) + 3]); }

struct Builder {
  const std::vector<Box>& boxes;
  int max_depth;
  int leaf_items;
  Bvh out;

  void write_node(int node, const Box& b, int a, int count) {
    float* w = &out.nodes[size_t(node) * BOREAS_RAY_NODE_WORDS];
    w[0] = b[0], w[1] = b[1], w[2] = b[2];
    std::memcpy(&w[3], &a, sizeof a);
    w[4] = b[3], w[5] = b[4], w[6] = b[5];
    std::memcpy(&w[7], &count, sizeof count);
  }
  int new_nodes(int n) {
    const int first = out.node_count();
    out.nodes.resize(out.nodes.size() + size_t(n) * BOREAS_RAY_NODE_WORDS);
    return first;
  }
  // Where to split items [first, first + count): the SAH's best bin boundary along the
  // widest axis of the centroids, or the middle by count. Returns the split's item index.
  int split(int first, int count, int depth) {
    int32_t* it = &out.items[size_t(first)];
    Box cb = empty_box();
    for (int i = 0; i < count; ++i) {
      const Box& b = boxes[size_t(it[i])];
      const float c[3] = {centroid(b, 0), centroid(b, 1), centroid(b, 2)};
      grow_box(cb, c);
    }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (cb[size_t(a) + 3] - cb[size_t(a)] > cb[size_t(axis) + 3] - cb[size_t(axis)]) axis = a;
    const float lo = cb[size_t(axis)], extent = cb[size_t(axis) + 3] - lo;
    // The SAH leaves a side at most count - 1 items, one level down: within the bound
    // only while halving could still place those; else halve now (which always can,
    // build_bvh checked the root, and each halving keeps it so).
    if (!(extent > 0.0f) || depth + 1 + bvh_halving_depth(count - 1, leaf_items) > max_depth)
      return split_by_count(first, count, axis);
    auto bin_of = [&](int32_t item) {
      const int b = int((centroid(boxes[size_t(item)], axis) - lo) / extent * kBins);
      return std::clamp(b, 0, kBins - 1);
    };
    std::array<Box, kBins> bin_box;
    bin_box.fill(empty_box());
    std::array<int, kBins> bin_count{};
    for (int i = 0; i < count; ++i) {
      const int b = bin_of(it[i]);
      bin_box[size_t(b)] = union_of(bin_box[size_t(b)], boxes[size_t(it[i])]);
      ++bin_count[size_t(b)];
    }
    // Cost of splitting after bin k: left area x count + right area x count.
    std::array<float, kBins> left_cost{};
    Box acc = empty_box();
    int n = 0;
    for (int k = 0; k < kBins - 1; ++k) {
      acc = union_of(acc, bin_box[size_t(k)]);
      n += bin_count[size_t(k)];
      left_cost[size_t(k)] = area(acc) * float(n);
    }
    float best = std::numeric_limits<float>::infinity();
    int best_k = -1;
    acc = empty_box();
    n = 0;
    for (int k = kBins - 1; k > 0; --k) {
      acc = union_of(acc, bin_box[size_t(k)]);
      n += bin_count[size_t(k)];
      const float cost = left_cost[size_t(k) - 1] + area(acc) * float(n);
      if (n < count && n > 0 && cost < best) best = cost, best_k = k;
    }
    if (best_k < 0) return split_by_count(first, count, axis);
    int32_t* mid = std::partition(it, it + count, [&](int32_t item) { return bin_of(item) < best_k; });
    return first + int(mid - it);
  }
  int split_by_count(int first, int count, int axis) {
    int32_t* it = &out.items[size_t(first)];
    std::nth_element(it, it + count / 2, it + count, [&](int32_t a, int32_t b) {
      const float ca = centroid(boxes[size_t(a)], axis), cb = centroid(boxes[size_t(b)], axis);
      return ca < cb || (ca == cb && a < b);
    });
    return first + count / 2;
  }
  Box build(int node, int first, int count, int depth) {
    if (count <= leaf_items) {
      Box b = empty_box();
      for (int i = 0; i < count; ++i) b = union_of(b, boxes[size_t(out.items[size_t(first + i)])]);
      write_node(node, b, first, count);
      return b;
    }
    const int mid = split(first, count, depth);
    const int children = new_nodes(2);
    const Box b = union_of(build(children, first, mid - first, depth + 1),
                           build(children + 1, mid, first + count - mid, depth + 1));
    write_node(node, b, children, 0);
    return b;
  }
};

}  // namespace

Box empty_box() {
  const float inf = std::numeric_limits<float>::infinity();
  return {inf, inf, inf, -inf, -inf, -inf};
}

void grow_box(Box& b, const float p[3]) {
  for (int a = 0; a < 3; ++a) {
    b[size_t(a)] = std::min(b[size_t(a)], p[a]);
    b[size_t(a) + 3] = std::max(b[size_t(a) + 3], p[a]);
  }
}

void write_pad_node(float* w) {
  const Box e = empty_box();
  const int32_t first = 0, count = 1;
  w[0] = e[0], w[1] = e[1], w[2] = e[2];
  std::memcpy(&w[3], &first, sizeof first);
  w[4] = e[3], w[5] = e[4], w[6] = e[5];
  std::memcpy(&w[7], &count, sizeof count);
}

int bvh_halving_depth(int64_t count, int leaf_items) {
  int depth = 0;
  for (; count > leaf_items; count = (count + 1) / 2) ++depth;
  return depth;
}

int bvh_depth(const Bvh& bvh) {
  if (bvh.node_count() == 0) return -1;
  int deepest = 0;
  std::vector<std::pair<int32_t, int>> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, depth);
    const float* w = &bvh.nodes[size_t(node) * BOREAS_RAY_NODE_WORDS];
    int32_t a, count;
    std::memcpy(&a, &w[3], sizeof a);
    std::memcpy(&count, &w[7], sizeof count);
    if (count == 0) stack.insert(stack.end(), {{a, depth + 1}, {a + 1, depth + 1}});
  }
  return deepest;
}

Bvh build_bvh(const std::vector<Box>& boxes, int max_depth, int leaf_items) {
  Builder b{boxes, max_depth, leaf_items, {}};
  if (boxes.empty()) return std::move(b.out);
  if (bvh_halving_depth(int64_t(boxes.size()), leaf_items) > max_depth)
    fail(BOREAS_ERROR_OUT_OF_MEMORY,
         "rays: " + std::to_string(boxes.size()) + " boxes in one hierarchy pass what " +
             std::to_string(max_depth) + " levels (a traversal's stack) can hold");
  b.out.items.resize(boxes.size());
  std::iota(b.out.items.begin(), b.out.items.end(), 0);
  b.new_nodes(1);
  // The pad (bvh_build.h): every pair of children from an even index on.
  if (boxes.size() > size_t(leaf_items)) {
    const int pad = b.new_nodes(1);
    write_pad_node(&b.out.nodes[size_t(pad) * BOREAS_RAY_NODE_WORDS]);
  }
  b.build(0, 0, int(boxes.size()), 0);
  return std::move(b.out);
}

Bvh build_instance_bvh(const std::vector<Box>& boxes) {
  return build_bvh(boxes, BOREAS_RAY_DEPTH, kBvhInstanceLeafItems);
}

}  // namespace boreas::impl
