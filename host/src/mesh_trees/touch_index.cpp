// boreas: the touch index's bounding volume hierarchy, built by median splits (see
// touch_index.h).
#include "mesh_trees/touch_index.h"

#include <algorithm>
#include <numeric>

namespace boreas::impl::hierarchy {

using glm::dvec3;

TouchIndex::TouchIndex(const std::vector<MeshBranch>& runs, double tolerance) {
  boxes_.resize(runs.size());
  for (size_t r = 0; r < runs.size(); ++r) {
    const BranchSkeleton& s = runs[r].skeleton;
    double grow = 1.1 * s.max_radius() + tolerance;
    for (const dvec3& p : s.nodes) boxes_[r].add({p - dvec3(grow), p + dvec3(grow)});
  }
  items_.resize(runs.size());
  std::iota(items_.begin(), items_.end(), 0);
  if (!items_.empty()) build(0, int(items_.size()));
}

int TouchIndex::build(int first, int count) {
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Box box, centers;
  for (int i = first; i < first + count; ++i) {
    const Box& b = boxes_[items_[i]];
    box.add(b);
    dvec3 c = 0.5 * (b.lo + b.hi);
    centers.add({c, c});
  }
  nodes_[index].box = box;
  nodes_[index].first = first;
  nodes_[index].count = count;
  if (count <= 4) return index;
  const dvec3 extent = centers.hi - centers.lo;
  const int axis =
      extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
  const int half = count / 2;
  std::nth_element(items_.begin() + first, items_.begin() + first + half,
                   items_.begin() + first + count, [&](int a, int b) {
                     return boxes_[a].lo[axis] + boxes_[a].hi[axis] <
                            boxes_[b].lo[axis] + boxes_[b].hi[axis];
                   });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

}  // namespace boreas::impl::hierarchy
