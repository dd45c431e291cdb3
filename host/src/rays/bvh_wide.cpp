// boreas: collapsing a binary ray hierarchy into wide nodes (bvh_wide.h).
#include "rays/bvh_wide.h"

#include <cstring>

// The cast's own pack and decode (the polynomial math the CPU kernels take, as host_scene.h).
#ifndef BOREAS_FAST_MATH
#define BOREAS_FAST_MATH 1
#endif
#include "shared/ray_wide.h"

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

  // Slot k of wide node w as binary node n: its box into `box` (6 floats a slot), its a and
  // count (a leaf's items, or the wide node made of n below it).
  void put_slot(int w, int k, int n, float* box) {
    for (int axis = 0; axis < 3; ++axis) {
      box[6 * k + axis] = node(n)[axis];
      box[6 * k + 3 + axis] = node(n)[4 + axis];
    }
    const int32_t a = leaf(n) ? word(n, 3) : make(n), count = leaf(n) ? word(n, 7) : 0;
    set_slot(w, k, a, count);
    out.gather[size_t(w) * 4 + size_t(k)] = n;
  }

  void set_slot(int w, int k, int32_t a, int count) {
    const size_t at = size_t(w) * BOREAS_RAY_WIDE_WORDS;
    std::memcpy(&out.nodes[at + BOREAS_RAY_WIDE_A + size_t(k)], &a, sizeof a);
    const auto c = static_cast<signed char>(count);
    std::memcpy(reinterpret_cast<unsigned char*>(&out.nodes[at + BOREAS_RAY_WIDE_COUNT]) + k, &c, 1);
  }

  // The wide node of binary node n (inner, or the root as a leaf): its slots first empty,
  // its boxes packed once its slots are known (boreas_ray_wide_pack, as the gather packs).
  int make(int n) {
    static_assert(kBvhLeafItems <= 127 && kBvhInstanceLeafItems <= 127, "a count is a signed byte");
    const int w = out.node_count();
    out.gather.resize(out.gather.size() + 4, -1);
    out.nodes.resize(out.nodes.size() + BOREAS_RAY_WIDE_WORDS, 0.0f);
    const Box e = empty_box();
    float box[24];
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < 6; ++i) box[6 * k + i] = e[size_t(i)];
      set_slot(w, k, -1, -1);
    }
    if (leaf(n)) {
      put_slot(w, 0, n, box);
    } else {
      int k = 0;
      for (const int c : {word(n, 3), word(n, 3) + 1}) {
        if (leaf(c)) {
          put_slot(w, k++, c, box);
        } else {
          put_slot(w, k++, word(c, 3), box);
          put_slot(w, k++, word(c, 3) + 1, box);
        }
      }
    }
    boreas_ray_wide_pack(&out.nodes[size_t(w) * BOREAS_RAY_WIDE_WORDS], box);
    return w;
  }
};

}  // namespace

Box wide_slot_box(const float* node, int k) {
  Box b;
  for (int side = 0; side < 6; ++side) {
    const BoreasRayF4 v = boreas_ray_wide_side(node, side);
    float lanes[4];
    std::memcpy(lanes, &v, sizeof lanes);
    b[size_t(side)] = lanes[k];
  }
  return b;
}

WideBvh collapse_bvh(const Bvh& bvh) {
  Collapser c{bvh, {}};
  if (bvh.node_count() > 0) c.make(0);
  return std::move(c.out);
}

}  // namespace boreas::impl
