// boreas: weights, phases, motion vectors and leaf assignment for an imported tree
// (Kusternig sec. 5.1.2-5.1.3, 5.3).
#include "mesh_trees/wind_weights.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh_trees/triangle_runs.h"
#include "trees/tree_random.h"

namespace boreas::impl {

namespace {

using glm::dvec3;

dvec3 position(const MeshPart& part, uint32_t v) {
  return dvec3(part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]);
}

std::array<float, 3> to_array(const dvec3& v) { return {float(v.x), float(v.y), float(v.z)}; }

// Nearest trunk vertex by a uniform grid of about four vertices per occupied cell,
// searched in growing shells of cells until no closer cell can remain.
class NearestVertex {
 public:
  explicit NearestVertex(const MeshPart& part) : part_(part) {
    lo_ = dvec3(std::numeric_limits<double>::max());
    dvec3 hi(-std::numeric_limits<double>::max());
    for (uint32_t v = 0; v < part.vertex_count(); ++v) {
      lo_ = glm::min(lo_, position(part, v));
      hi = glm::max(hi, position(part, v));
    }
    dvec3 extent = glm::max(hi - lo_, dvec3(1e-9));
    double volume = extent.x * extent.y * extent.z;
    cell_ = std::cbrt(volume * 4.0 / double(std::max<size_t>(part.vertex_count(), 1)));
    cell_ = std::max(cell_, 1e-3 * std::max({extent.x, extent.y, extent.z}));
    for (int a = 0; a < 3; ++a) cells_[a] = std::max(1, int(std::ceil(extent[a] / cell_)));
    for (uint32_t v = 0; v < part.vertex_count(); ++v)
      grid_[key(cell_of(position(part, v)))].push_back(v);
  }

  uint32_t nearest(const dvec3& p, double* distance) const {
    glm::ivec3 c = cell_of(p);
    uint32_t best = 0;
    double best_d2 = std::numeric_limits<double>::max();
    int max_shell = std::max({cells_[0], cells_[1], cells_[2]}) + 1;
    for (int shell = 0; shell <= max_shell; ++shell) {
      for (int i = c.x - shell; i <= c.x + shell; ++i)
        for (int j = c.y - shell; j <= c.y + shell; ++j)
          for (int k = c.z - shell; k <= c.z + shell; ++k) {
            if (std::max({std::abs(i - c.x), std::abs(j - c.y), std::abs(k - c.z)}) != shell)
              continue;
            auto it = grid_.find(key({i, j, k}));
            if (it == grid_.end()) continue;
            for (uint32_t v : it->second) {
              dvec3 d = position(part_, v) - p;
              double d2 = glm::dot(d, d);
              if (d2 < best_d2 || (d2 == best_d2 && v < best)) best_d2 = d2, best = v;
            }
          }
      // Every point outside this shell is at least shell * cell away.
      double reach = double(shell) * cell_;
      if (best_d2 < reach * reach) break;
    }
    *distance = std::sqrt(best_d2);
    return best;
  }

 private:
  glm::ivec3 cell_of(const dvec3& p) const {
    dvec3 c = glm::floor((p - lo_) / cell_);
    return {int(std::clamp(c.x, -1e6, 1e6)), int(std::clamp(c.y, -1e6, 1e6)),
            int(std::clamp(c.z, -1e6, 1e6))};
  }
  static int64_t key(const glm::ivec3& c) {
    return (int64_t(c.x) + (1 << 20)) | ((int64_t(c.y) + (1 << 20)) << 21) |
           ((int64_t(c.z) + (1 << 20)) << 42);
  }

  const MeshPart& part_;
  dvec3 lo_;
  double cell_ = 1.0;
  int cells_[3] = {1, 1, 1};
  std::unordered_map<int64_t, std::vector<uint32_t>> grid_;
};

dvec3 skeleton_point(const BranchSkeleton& s, double arc) {
  for (size_t i = 0; i + 1 < s.nodes.size(); ++i) {
    if (arc <= s.arc[i + 1] || i + 2 == s.nodes.size()) {
      double span = s.arc[i + 1] - s.arc[i];
      double u = span > 0.0 ? std::clamp((arc - s.arc[i]) / span, 0.0, 1.0) : 0.0;
      return s.nodes[i] + u * (s.nodes[i + 1] - s.nodes[i]);
    }
  }
  return s.nodes.front();
}

// The sway directions: two unit vectors normal to the branch. A branch off the vertical
// sways up-down and sideways; for a near-vertical one (the stem) "up" is the model's X.
void motion_vectors(const dvec3& axis, MeshTreeBranch* b) {
  dvec3 ref = std::abs(axis.y) < 0.9 ? dvec3(0.0, 1.0, 0.0) : dvec3(1.0, 0.0, 0.0);
  dvec3 up = glm::normalize(ref - glm::dot(ref, axis) * axis);
  dvec3 right = glm::cross(up, axis);
  b->axis = to_array(axis);
  b->up = to_array(up);
  b->right = to_array(right);
}

using LevelWeights = std::array<float, kMeshTreeLevels>;

// A branch's own weight at arc length `arc`: 0..1 along it, normalized by its level's
// longest branch.
float own_weight(const MeshTreeData& d, const MeshBranch& b, double arc) {
  float longest = d.longest[b.level];
  return longest > 0.0f ? float(std::clamp(arc / longest, 0.0, 1.0)) : 0.0f;
}

// Every branch's animation data (d->branches), and the weights at each branch's base, taken
// from its parent at the attachment point; parents come first (levels in order), so theirs
// are always known (fig. 6).
std::vector<LevelWeights> describe_branches(const MeshHierarchy& h, uint64_t seed,
                                            MeshTreeData* d) {
  const int n = int(h.branches.size());
  std::vector<LevelWeights> base_weights(n);
  d->branches.resize(n);
  for (int i = 0; i < n; ++i) {
    const MeshBranch& b = h.branches[i];
    MeshTreeBranch& w = d->branches[i];
    w.parent = b.parent;
    w.level = b.level;
    w.orphan = b.orphan;
    base_weights[i].fill(0.0f);
    if (b.parent >= 0) {
      const MeshBranch& p = h.branches[b.parent];
      base_weights[i] = base_weights[b.parent];
      if (p.level < kMeshTreeLevels) base_weights[i][p.level] = own_weight(*d, p, b.attach_arc);
    }
    for (int k = 0; k < kMeshTreeLevels; ++k) {
      bool from_parent = b.parent >= 0 && (k < b.level || b.level >= kMeshTreeLevels);
      w.animated_by[k] = from_parent ? d->branches[b.parent].animated_by[k] : i;
    }
    TreeRandom random(seed, uint64_t(i), 0x6d657368ull /* "mesh" */);
    w.phase = {float(random.uniform01()), float(random.uniform01())};
    const BranchSkeleton& s = b.skeleton;
    dvec3 along = s.nodes.back() - s.nodes.front();
    dvec3 axis = glm::length(along) > 0.0 ? glm::normalize(along) : dvec3(0.0, 1.0, 0.0);
    motion_vectors(axis, &w);
    w.center = to_array(skeleton_point(s, 0.5 * s.length()));
    w.base = to_array(s.nodes.front());
    w.tip = to_array(s.nodes.back());
    w.length = float(s.length());
    w.radius = float(s.max_radius());
  }
  return base_weights;
}

// Vertices: the base weights, with the branch's own level running 0..1 along it
// (linear in arc length, normalized by the level's longest branch). Branches beyond
// level 3 keep their base weights: they move with the point they grow from.
void weigh_trunk(const MeshHierarchy& h, const MeshPart& trunk,
                 const std::vector<LevelWeights>& base_weights, MeshTreeData* d) {
  d->trunk_weights.resize(4 * trunk.vertex_count());
  d->trunk_branch.resize(trunk.vertex_count());
  for (uint32_t v = 0; v < trunk.vertex_count(); ++v) {
    int bi = h.branch_of_vertex[v];
    const MeshBranch& b = h.branches[bi];
    LevelWeights w = base_weights[bi];
    if (b.level < kMeshTreeLevels) {
      double arc, distance, radius;
      b.skeleton.nearest(position(trunk, v), &arc, &distance, &radius);
      w[b.level] = own_weight(*d, b, arc);
    }
    std::copy(w.begin(), w.end(), d->trunk_weights.begin() + 4 * v);
    d->trunk_branch[v] = bi;
  }
}

// Each leaf's petiole (its vertex nearest the trunk) and that trunk vertex.
struct Petioles {
  std::vector<uint32_t> petiole, trunk_vertex;
};

Petioles find_petioles(const MeshPart& leaves, const MeshPart& trunk,
                       const std::vector<int32_t>& leaf_of_vertex, int leaf_count) {
  NearestVertex nearest(trunk);
  std::vector<double> best(leaf_count, std::numeric_limits<double>::max());
  std::vector<uint32_t> petiole(leaf_count, 0), trunk_vertex(leaf_count, 0);
  for (uint32_t v = 0; v < leaves.vertex_count(); ++v) {
    double distance;
    uint32_t t = nearest.nearest(position(leaves, v), &distance);
    int leaf = leaf_of_vertex[v];
    if (distance < best[leaf]) best[leaf] = distance, petiole[leaf] = v, trunk_vertex[leaf] = t;
  }
  return {std::move(petiole), std::move(trunk_vertex)};
}

// Leaves: each run of leaf triangles is a leaf; its petiole is its vertex nearest the
// trunk, and it takes that trunk vertex's weights and branch (sec. 5.3).
void assign_leaves(const MeshPart& leaves, const MeshPart& trunk, MeshTreeData* d) {
  int leaf_count = 0;
  d->leaf_of_vertex = connected_runs(leaves, default_weld_tolerance(leaves), &leaf_count);
  const auto [petiole, trunk_vertex] = find_petioles(leaves, trunk, d->leaf_of_vertex, leaf_count);
  std::vector<double> reach(leaf_count, 0.0);
  std::vector<dvec3> farthest(leaf_count);
  for (uint32_t v = 0; v < leaves.vertex_count(); ++v) {
    int leaf = d->leaf_of_vertex[v];
    double r = glm::distance(position(leaves, v), position(leaves, petiole[leaf]));
    if (r > reach[leaf]) reach[leaf] = r, farthest[leaf] = position(leaves, v);
  }
  d->leaf_weights.resize(4 * leaf_count);
  d->leaf_branch.resize(leaf_count);
  d->leaf_petiole.resize(3 * leaf_count);
  d->leaf_axis.resize(3 * leaf_count);
  d->leaf_length.resize(leaf_count);
  for (int leaf = 0; leaf < leaf_count; ++leaf) {
    uint32_t t = trunk_vertex[leaf];
    std::copy_n(d->trunk_weights.begin() + 4 * t, 4, d->leaf_weights.begin() + 4 * leaf);
    d->leaf_branch[leaf] = d->trunk_branch[t];
    dvec3 p = position(leaves, petiole[leaf]);
    dvec3 axis = reach[leaf] > 0.0 ? (farthest[leaf] - p) / reach[leaf] : dvec3(0.0, 1.0, 0.0);
    for (int a = 0; a < 3; ++a) {
      d->leaf_petiole[3 * leaf + a] = float(p[a]);
      d->leaf_axis[3 * leaf + a] = float(axis[a]);
    }
    d->leaf_length[leaf] = float(reach[leaf]);
  }
}

}  // namespace

MeshTreeData compute_mesh_tree(const MeshModel& model, uint64_t seed) {
  MeshHierarchy h = build_branch_hierarchy(model.trunk, default_weld_tolerance(model.trunk));
  MeshTreeData d;
  d.levels = h.levels;
  d.orphans = h.orphans;
  for (const MeshBranch& b : h.branches)
    if (b.level < kMeshTreeLevels)
      d.longest[b.level] = std::max(d.longest[b.level], float(b.skeleton.length()));
  const std::vector<LevelWeights> base_weights = describe_branches(h, seed, &d);
  weigh_trunk(h, model.trunk, base_weights, &d);
  if (model.leaves.vertex_count() == 0) return d;
  assign_leaves(model.leaves, model.trunk, &d);
  return d;
}

}  // namespace boreas::impl
