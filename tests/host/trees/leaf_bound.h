// boreas tests: how far a packed leaf (cl/shared/leaf_pack.h) may be from the double
// placement it was packed from, on a given parent — the header's stated bounds, plus the
// float rounding the tests already allowed.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>

#include "reference/tree_reference.h"
#include "shared/leaf_pack.h"

namespace boreas::test {

// Each turn's bound, rad: a diamond parameter rounded by half a step turns it by at most
// twice that (leaf_pack.h).
inline double leaf_turn_bound(int bits) { return 4.0 / double(1 << bits); }
// v's bound: half a step of the fixed point.
inline double leaf_v_bound() { return 0.5 / double((1 << BOREAS_LEAF_V_BITS) - 1); }

struct LeafBound {
  double position = 0.0, axis = 0.0, normal = 0.0;  // m, and unit vectors' distance
};

// On `parent` (its curve's speed bounds how far v's error moves the base), with the
// petiole `stem` (m; the axis's error swings the blade's base by stem times it).
inline LeafBound leaf_bound(const impl::reference::Branch& parent, double stem) {
  double leg = 0.0;
  for (int k = 0; k < 3; ++k) leg = std::max(leg, glm::length(parent.curve.p[k + 1] - parent.curve.p[k]));
  LeafBound b;
  b.axis = leaf_turn_bound(BOREAS_LEAF_THETA_BITS) + leaf_turn_bound(BOREAS_LEAF_ALPHA_BITS);
  b.normal = b.axis + leaf_turn_bound(BOREAS_LEAF_ROLL_BITS);
  b.position = 3.0 * leg * leaf_v_bound() + stem * b.axis;
  return b;
}

}  // namespace boreas::test
