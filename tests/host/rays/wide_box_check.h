// boreas tests: a wide node's stored slot box (cl/shared/ray_wide.h) against the box it
// stands for: it holds it (rounded outward), and no tighter stored box would (one step
// less on any side would cut into it), so the rounding is outward and no more.
#pragma once

#include <gtest/gtest.h>

#include "rays/bvh_wide.h"
#include "rays/host_scene.h"

namespace boreas::test {

// Slot k of `node` against box b (min xyz at 0..2, max xyz at 4..6, a binary node's).
inline void expect_stored_box_holds(const float* node, int k, const float* b) {
  const impl::Box s = impl::wide_slot_box(node, k);
  const auto* q = reinterpret_cast<const unsigned char*>(node + BOREAS_RAY_WIDE_Q);
  for (int axis = 0; axis < 3; ++axis) {
    const float origin = node[BOREAS_RAY_WIDE_ORIGIN + axis], step = boreas_ray_wide_step(node, axis);
    const int lo = q[4 * axis + k], hi = q[4 * (axis + 3) + k];
    EXPECT_LE(s[size_t(axis)], b[axis]) << "slot " << k << " axis " << axis;
    EXPECT_GE(s[size_t(axis) + 3], b[4 + axis]) << "slot " << k << " axis " << axis;
    if (lo < 255) EXPECT_GT(origin + float(lo + 1) * step, b[axis]) << "slot " << k << " axis " << axis;
    if (hi > 0) EXPECT_LT(origin + float(hi - 1) * step, b[4 + axis]) << "slot " << k << " axis " << axis;
  }
}

}  // namespace boreas::test
