// boreas tests: a tree's bend factors F as the kernels left them (its motion planes), for
// tests that check the wind's load on each branch.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "shared/tree_types.h"
#include "trees/tree_batch.h"
#include "trees/tree_layout.h"
#include "world.h"

namespace boreas::test {

// Each branch's bend factor F (m), in the tree's branch order.
inline std::vector<glm::dvec3> tree_bends(impl::World& world, boreas_tree_id id) {
  const impl::TreeInstance& tree = world.tree(id);
  const std::vector<float> motion = world.tree_batch(tree.params.mode).read_tree_motion(tree.key);
  const size_t n = size_t(tree.model->branch_count()) + 1;
  std::vector<glm::dvec3> out;
  for (size_t b = 0; b < n - 1; ++b) {
    const size_t i = size_t(impl::block_index(int32_t(b)));
    out.emplace_back(motion[(BOREAS_TREE_MOTION_F + 0) * n + i],
                     motion[(BOREAS_TREE_MOTION_F + 1) * n + i],
                     motion[(BOREAS_TREE_MOTION_F + 2) * n + i]);
  }
  return out;
}

}  // namespace boreas::test
