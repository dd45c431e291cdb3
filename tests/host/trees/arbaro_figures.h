// boreas tests: the figures a grown tree is compared with Arbaro by (tests/data/arbaro_figures.csv,
// made by tests/tools/ArbaroFigures.java): figures that do not depend on how a generator stores
// the pieces of a split stem. Per level the drawn length (every piece, split clones included)
// and the stems (a stem's first piece and each clone); the height (highest point of any stem);
// the crown width (the mean of the stems' extents along the two horizontal axes); the leaves.
// Stems are sampled at nine points of each Bezier (Arbaro: its segments' ends).
#pragma once

#include <algorithm>
#include <array>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "reference/tree_reference.h"
#include "trees/tree_model.h"

namespace boreas::impl {

struct ArbaroFigures {
  double height = 0.0, width = 0.0, leaves = 0.0;
  std::array<double, 4> length{}, stems{};
};

// Every branch placed unbent at rest on the root (the vertical unit segment at the origin),
// by the independent double-precision reference.
inline std::vector<reference::Branch> rest_branches(const TreeModel& m) {
  reference::Branch root;
  for (int k = 0; k < 4; ++k) root.curve.p[size_t(k)] = glm::dvec3(0.0, k / 3.0, 0.0);
  root.o = glm::dvec3(1.0, 0.0, 0.0);
  std::vector<reference::Branch> rest;
  rest.reserve(m.branches.size());
  for (const BranchModel& b : m.branches) {
    reference::BranchShape shape;
    for (size_t k = 0; k < 4; ++k)
      shape.local[k] = glm::dvec3(b.local[k][0], b.local[k][1], b.local[k][2]);
    shape.v = b.v;
    shape.theta = b.theta;
    shape.alpha = b.alpha;
    rest.push_back(reference::place_branch(b.parent < 0 ? root : rest[size_t(b.parent)], shape));
  }
  return rest;
}

inline ArbaroFigures arbaro_figures(const TreeModel& m) {
  ArbaroFigures f;
  const std::vector<reference::Branch> rest = rest_branches(m);
  constexpr double kBig = std::numeric_limits<double>::max();
  glm::dvec3 lo(kBig), hi(-kBig);
  for (size_t b = 0; b < m.branches.size(); ++b) {
    const BranchModel& br = m.branches[b];
    const size_t l = size_t(std::min(br.level, 3));
    f.length[l] += br.length;
    if (br.split_depth == 0 || br.clone) f.stems[l] += 1.0;
    for (int k = 0; k <= 8; ++k) {
      const glm::dvec3 p = reference::bezier_point(rest[b].curve, k / 8.0);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  f.height = hi.y;
  f.width = 0.5 * ((hi.x - lo.x) + (hi.z - lo.z));
  f.leaves = double(m.leaves.size());
  return f;
}

}  // namespace boreas::impl
