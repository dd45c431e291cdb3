// boreas: collapsing a binary ray hierarchy into wide nodes (bvh_wide.h).
#include "rays/bvh_wide.h"

#include <cstring>

#include "shared/ray_types.h"

namespace boreas::impl {

namespace {

struct Collapser {
  const Bvh& bvh;
  WideBvh out;

  const float* node(int n) const { return &bvh.nodes[size_t(n) * BOREAS_RAY_NODE_WORDS]; }
  int word(int n, int w) const {
    int32_t v;
    std::memcpy(&v, &node(n)[w], sizeof v);
    return v;
  }
  bool leaf(int n) const { return word(n, 7) > 0; }

  // Slot k of wide node w as binary node n (its box; a leaf's items or the wide node
  // made of n below it).
  void put_slot(int w, int k, int n) {
    const size_t at = size_t(w) * BOREAS_RAY_WIDE_WORDS;
    for (int axis = 0; axis < 3; ++axis) {
      out.nodes[at + BOREAS_RAY_WIDE_LO + size_t(4 * axis + k)] = node(n)[axis];
      out.nodes[at + BOREAS_RAY_WIDE_HI + size_t(4 * axis + k)] = node(n)[4 + axis];
    }
    const int32_t a = leaf(n) ? word(n, 3) : make(n), count = leaf(n) ? word(n, 7) : 0;
    std::memcpy(&out.nodes[at + BOREAS_RAY_WIDE_A + size_t(k)], &a, sizeof a);
    std::memcpy(&out.nodes[at + BOREAS_RAY_WIDE_COUNT + size_t(k)], &count, sizeof count);
    out.gather[size_t(w) * 4 + size_t(k)] = n;
  }

  // The wide node of binary node n (inner, or the root as a leaf): its slots first empty.
  int make(int n) {
    const int w = out.node_count();
    out.gather.resize(out.gather.size() + 4, -1);
    out.nodes.resize(out.nodes.size() + BOREAS_RAY_WIDE_WORDS);
    const Box e = empty_box();
    const int32_t none = -1;
    for (int k = 0; k < 4; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        out.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS + BOREAS_RAY_WIDE_LO + size_t(4 * axis + k)] = e[size_t(axis)];
        out.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS + BOREAS_RAY_WIDE_HI + size_t(4 * axis + k)] = e[size_t(axis) + 3];
      }
      std::memcpy(&out.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS + BOREAS_RAY_WIDE_A + size_t(k)], &none, sizeof none);
      std::memcpy(&out.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS + BOREAS_RAY_WIDE_COUNT + size_t(k)], &none, sizeof none);
    }
    if (leaf(n)) {
      put_slot(w, 0, n);
      return w;
    }
    int k = 0;
    for (const int c : {word(n, 3), word(n, 3) + 1}) {
      if (leaf(c)) {
        put_slot(w, k++, c);
      } else {
        put_slot(w, k++, word(c, 3));
        put_slot(w, k++, word(c, 3) + 1);
      }
    }
    return w;
  }
};

}  // namespace

WideBvh collapse_bvh(const Bvh& bvh) {
  Collapser c{bvh, {}};
  if (bvh.node_count() > 0) c.make(0);
  return std::move(c.out);
}

}  // namespace boreas::impl
