// boreas: the runs' tubes in a bounding volume hierarchy, for finding the runs that a
// branch's end may touch (stage 3 of the branch hierarchy, see branch_hierarchy.cpp).
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <vector>

#include "mesh_trees/branch_hierarchy.h"

namespace boreas::impl::hierarchy {

// An axis-aligned box, m.
struct Box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

  void add(const Box& o) {
    lo = glm::min(lo, o.lo);
    hi = glm::max(hi, o.hi);
  }
  bool near(const glm::dvec3& p, double margin) const {
    return glm::all(glm::greaterThanEqual(p, lo - glm::dvec3(margin))) &&
           glm::all(glm::lessThanEqual(p, hi + glm::dvec3(margin)));
  }
};

// The runs' tubes grown by the distance at which they touch, in a bounding volume
// hierarchy: the runs that an end may touch, without a test against every thicker run.
class TouchIndex {
 public:
  TouchIndex(const std::vector<MeshBranch>& runs, double tolerance);

  // Calls f(run) for each run whose grown box lies within margin of p.
  template <class F>
  void near(const glm::dvec3& p, double margin, F f) const {
    if (nodes_.empty()) return;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.box.near(p, margin)) continue;
      if (n.left < 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if (boxes_[items_[i]].near(p, margin)) f(items_[i]);
      } else {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
  }

 private:
  struct Node {
    Box box;
    int first = 0, count = 0;   // its items
    int left = -1, right = -1;  // its children; -1 for a leaf
  };

  // A node over items [first, first + count), split at the median of their boxes' centers
  // on the axis they spread most along; returns its index.
  int build(int first, int count);

  std::vector<Box> boxes_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
};

}  // namespace boreas::impl::hierarchy
