// boreas tests: small trees built by hand (not grown), so the kernel and deformer tests
// depend on the kernels only.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "trees/tree_model.h"

namespace boreas::test {

// A branch of three equal segments of length/3: the first along +x, the second turned by
// `bend` and the third by 2 `bend`, in a plane tilted by `twist` about x (a 3D curve;
// bend = 0 gives a straight branch). Taper: depth taper_depth, exponent taper_exponent.
inline impl::BranchModel hand_branch(int level, int parent, double length, double radius, double bend,
                                     double twist, double v, double theta, double alpha,
                                     double taper_depth = 0.9, double taper_exponent = 1.0) {
  impl::BranchModel b;
  b.level = level;
  b.parent = parent;
  b.length = length;
  b.radius = radius;
  b.v = v;
  b.theta = theta;
  b.alpha = alpha;
  const double seg = length / 3.0;
  auto dir = [&](double a) {
    return glm::dvec3(std::cos(a), std::sin(a) * std::cos(twist), std::sin(a) * std::sin(twist));
  };
  glm::dvec3 p1 = seg * dir(0.0), p2 = p1 + seg * dir(bend), p3 = p2 + seg * dir(2.0 * bend);
  b.local[0] = {0.0, 0.0, 0.0};
  b.local[1] = {p1.x, p1.y, p1.z};
  b.local[2] = {p2.x, p2.y, p2.z};
  b.local[3] = {p3.x, p3.y, p3.z};
  b.taper_depth = taper_depth;
  b.taper_exponent = taper_exponent;
  return b;
}

// levels and level_begin from the branches (which must be in level order).
inline void finish_levels(impl::TreeModel& m) {
  m.levels = 0;
  for (const impl::BranchModel& b : m.branches) m.levels = std::max(m.levels, b.level + 1);
  for (int l = 0; l <= impl::kMaxTreeLevels; ++l) {
    int first = static_cast<int>(m.branches.size());
    for (size_t i = 0; i < m.branches.size(); ++i)
      if (m.branches[i].level >= l) {
        first = static_cast<int>(i);
        break;
      }
    m.level_begin[l] = first;
  }
}

}  // namespace boreas::test
