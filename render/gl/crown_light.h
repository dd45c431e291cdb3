// boreas render: how much sky light reaches a leaf inside its own crown, from where it sits
// at rest — a stand-in for the per-vertex occlusion Kusternig precomputes, shared by the
// generated trees' leaves and the imported trees' leaves.
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace boreas::render {

// An axis-aligned box that starts empty.
struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
  void add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  bool empty() const { return min.x > max.x; }
};

// About a third at the crown's center, all of it at the rim, and more on top than
// underneath (the sky is brighter than the ground). In [0, 1].
float leaf_occlusion(const glm::vec3& p, const Bounds& crown);

}  // namespace boreas::render
