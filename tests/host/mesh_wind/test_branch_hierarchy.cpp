// boreas tests: branch hierarchy, weights, phases, motion vectors and leaf assignment of
// imported tree meshes (Kusternig sec. 5.1, 5.3) on meshes of known structure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "boreas/boreas.h"
#include "errors.h"
#include "host/mesh_wind/tube_trees.h"
#include "mesh_wind/wind_weights.h"

namespace boreas {
namespace {

using impl::MeshWindData;

// Which tube each found branch is, by one of its vertices.
std::vector<int> tube_of_branch(const test::TubeTree& tree, const impl::MeshHierarchy& h) {
  std::vector<int> tube(h.branches.size(), -1);
  for (int t = 0; t < int(tree.tubes.size()); ++t)
    tube[h.branch_of_vertex[tree.tubes[t].first_vertex]] = t;
  return tube;
}

TEST(BranchHierarchy, FindsEveryBranchItsParentAndLevel) {
  test::TubeTree tree = test::make_tube_tree();
  impl::MeshHierarchy h = impl::build_branch_hierarchy(
      tree.model.trunk, impl::default_weld_tolerance(tree.model.trunk));
  ASSERT_EQ(h.branches.size(), tree.tubes.size());
  EXPECT_EQ(h.levels, 5);
  EXPECT_EQ(h.orphans, 0);
  std::vector<int> tube = tube_of_branch(tree, h);
  for (int b = 0; b < int(h.branches.size()); ++b) {
    ASSERT_GE(tube[b], 0) << "branch " << b << " has none of the tubes' first vertices";
    const test::Tube& t = tree.tubes[tube[b]];
    EXPECT_EQ(h.branches[b].level, t.level) << "tube " << tube[b];
    int parent_tube = h.branches[b].parent < 0 ? -1 : tube[h.branches[b].parent];
    EXPECT_EQ(parent_tube, t.parent) << "tube " << tube[b];
    if (b > 0) EXPECT_GE(h.branches[b].level, h.branches[b - 1].level) << "levels in order";
    // Every vertex of the tube belongs to the branch: one run of triangles is one branch.
    for (uint32_t v = t.first_vertex; v < t.first_vertex + t.vertex_count; ++v)
      ASSERT_EQ(h.branch_of_vertex[v], b);
  }
}

TEST(BranchHierarchy, SkeletonRunsFromBaseToTip) {
  test::TubeTree tree = test::make_tube_tree();
  impl::MeshHierarchy h = impl::build_branch_hierarchy(
      tree.model.trunk, impl::default_weld_tolerance(tree.model.trunk));
  std::vector<int> tube = tube_of_branch(tree, h);
  for (int b = 0; b < int(h.branches.size()); ++b) {
    const test::Tube& t = tree.tubes[tube[b]];
    const impl::BranchSkeleton& s = h.branches[b].skeleton;
    // The ends are the extreme vertices along the axis: off the axis ends by at most the
    // end rings' radii.
    EXPECT_LT(glm::distance(s.nodes.front(), t.base), t.r_base * 1.01 + 1e-6) << "tube " << tube[b];
    EXPECT_LT(glm::distance(s.nodes.back(), test::tube_point(t, 1.0)), t.r_tip * 1.01 + 1e-6);
    EXPECT_NEAR(s.length(), t.length, 0.02 * t.length);
    EXPECT_NEAR(s.max_radius(), t.r_base, 0.15 * t.r_base);
    if (h.branches[b].parent >= 0) {
      const test::Tube& p = tree.tubes[t.parent];
      EXPECT_NEAR(h.branches[b].attach_arc, glm::distance(t.base, p.base), 0.05 * p.length);
    }
  }
}

TEST(BranchHierarchy, EmptyTrunkIsAnError) {
  impl::MeshPart empty;
  try {
    impl::build_branch_hierarchy(empty, 1e-6);
    FAIL() << "no error";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(e.what()).find("no triangles"), std::string::npos) << e.what();
  }
}

TEST(MeshWindWeights, EachLevelIsNormalizedToItsLongestBranch) {
  test::TubeTree tree = test::make_tube_tree();
  MeshWindData d = impl::compute_mesh_wind(tree.model, 7);
  for (int k = 0; k < impl::kMeshWindLevels; ++k) {
    float lo = 1.0f, hi = 0.0f;
    for (size_t v = 0; v < d.trunk_branch.size(); ++v) {
      if (d.branches[d.trunk_branch[v]].level != k) continue;
      lo = std::min(lo, d.trunk_weights[4 * v + k]);
      hi = std::max(hi, d.trunk_weights[4 * v + k]);
    }
    EXPECT_NEAR(hi, 1.0f, 1e-6f) << "level " << k;  // the longest branch's tip
    EXPECT_NEAR(lo, 0.0f, 1e-6f) << "level " << k;  // a base
  }
  // Equal limbs: each reaches 1 at its tip; the deeper levels' weights are 0 on the stem.
  for (size_t v = 0; v < d.trunk_branch.size(); ++v) {
    int level = d.branches[d.trunk_branch[v]].level;
    for (int k = level + 1; k < impl::kMeshWindLevels; ++k)
      ASSERT_EQ(d.trunk_weights[4 * v + k], 0.0f);
    for (int k = 0; k < 4; ++k)
      ASSERT_TRUE(d.trunk_weights[4 * v + k] >= 0.0f && d.trunk_weights[4 * v + k] <= 1.0f);
  }
}

// Continuity across a joint: a child's base ring carries the weights of the parent's
// surface next to it (fig. 6), and its own level starts at 0.
TEST(MeshWindWeights, ContinuousAcrossJoints) {
  test::TubeTree tree = test::make_tube_tree();
  MeshWindData d = impl::compute_mesh_wind(tree.model, 7);
  const impl::MeshPart& trunk = tree.model.trunk;
  auto pos = [&](uint32_t v) {
    return glm::dvec3(trunk.positions[3 * v], trunk.positions[3 * v + 1],
                      trunk.positions[3 * v + 2]);
  };
  int checked = 0;
  for (const test::Tube& t : tree.tubes) {
    if (t.parent < 0) continue;
    const test::Tube& p = tree.tubes[t.parent];
    int level = std::min(t.level, 3);
    for (uint32_t v = t.first_vertex; v < t.first_vertex + 9; ++v) {  // the base ring
      uint32_t nearest = p.first_vertex;
      for (uint32_t u = p.first_vertex; u < p.first_vertex + p.vertex_count; ++u)
        if (glm::distance(pos(u), pos(v)) < glm::distance(pos(nearest), pos(v))) nearest = u;
      for (int k = 0; k < level; ++k) {
        // The parent's weight changes by its ring spacing over the longest branch between
        // its own nearest vertex and the attachment point: 1/6 of its length at most.
        double step = p.length / 6.0 / d.longest[std::min(p.level, 3)];
        EXPECT_NEAR(d.trunk_weights[4 * v + k], d.trunk_weights[4 * nearest + k], step + 1e-6)
            << "tube level " << t.level << " weight " << k;
      }
      if (t.level < 4) EXPECT_LT(d.trunk_weights[4 * v + t.level], 1e-3f);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 16 * 9);
}

TEST(MeshWindWeights, DeepBranchesMoveWithTheirLevelThreeParent) {
  test::TubeTree tree = test::make_tube_tree();
  MeshWindData d = impl::compute_mesh_wind(tree.model, 7);
  int deep = -1;
  for (int b = 0; b < int(d.branches.size()); ++b)
    if (d.branches[b].level == 4) deep = b;
  ASSERT_GE(deep, 0);
  const impl::MeshWindBranch& b = d.branches[deep];
  EXPECT_EQ(b.animated_by, d.branches[b.parent].animated_by);
  EXPECT_EQ(b.animated_by[3], b.parent);
  // Constant weights over the whole twig: those where it grows from its parent.
  std::vector<float> first;
  for (size_t v = 0; v < d.trunk_branch.size(); ++v) {
    if (d.trunk_branch[v] != deep) continue;
    std::vector<float> w(d.trunk_weights.begin() + 4 * v, d.trunk_weights.begin() + 4 * v + 4);
    if (first.empty()) first = w;
    ASSERT_EQ(w, first);
  }
  EXPECT_GT(first[3], 0.3f);  // it grows half-way along its parent
}

TEST(MeshWindWeights, AncestorsPhasesAndMotionVectors) {
  test::TubeTree tree = test::make_tube_tree();
  MeshWindData d = impl::compute_mesh_wind(tree.model, 7);
  MeshWindData again = impl::compute_mesh_wind(tree.model, 7);
  MeshWindData other = impl::compute_mesh_wind(tree.model, 8);
  int differing = 0;
  for (int i = 0; i < int(d.branches.size()); ++i) {
    const impl::MeshWindBranch& b = d.branches[i];
    // The chain: level k is the ancestor at level k, the branch itself from its level on.
    int a = i;
    for (int k = std::min(b.level, 3); k >= 0; --k) {
      while (d.branches[a].level > k) a = d.branches[a].parent;
      if (b.level <= 3) EXPECT_EQ(b.animated_by[k], a);
    }
    for (int k = b.level + 1; k < 4; ++k) EXPECT_EQ(b.animated_by[k], i);
    glm::dvec3 axis(b.axis[0], b.axis[1], b.axis[2]), up(b.up[0], b.up[1], b.up[2]),
        right(b.right[0], b.right[1], b.right[2]);
    EXPECT_NEAR(glm::length(axis), 1.0, 1e-6);
    EXPECT_NEAR(glm::length(up), 1.0, 1e-6);
    EXPECT_NEAR(glm::dot(axis, up), 0.0, 1e-6);
    EXPECT_NEAR(glm::dot(glm::cross(up, axis), right), 1.0, 1e-6);
    EXPECT_TRUE(b.phase[0] >= 0.0f && b.phase[0] < 1.0f && b.phase[1] >= 0.0f && b.phase[1] < 1.0f);
    EXPECT_EQ(b.phase, again.branches[i].phase);
    differing += b.phase != other.branches[i].phase;
  }
  EXPECT_EQ(differing, int(d.branches.size()));
}

TEST(MeshWindWeights, LeavesTakeTheTrunkVertexNearestTheirPetiole) {
  test::TubeTree tree = test::make_tube_tree();
  MeshWindData d = impl::compute_mesh_wind(tree.model, 7);
  ASSERT_EQ(d.leaf_branch.size(), tree.leaf_twig.size());
  impl::MeshHierarchy h = impl::build_branch_hierarchy(
      tree.model.trunk, impl::default_weld_tolerance(tree.model.trunk));
  std::vector<int> tube = tube_of_branch(tree, h);
  for (size_t leaf = 0; leaf < d.leaf_branch.size(); ++leaf) {
    const test::Tube& twig = tree.tubes[tree.leaf_twig[leaf]];
    EXPECT_EQ(tube[d.leaf_branch[leaf]], tree.leaf_twig[leaf]);
    // At the twig's tip: its own weight near the top of the level.
    EXPECT_GT(d.leaf_weights[4 * leaf + 3], 0.9f * float(twig.length / d.longest[3]));
    glm::dvec3 axis(d.leaf_axis[3 * leaf], d.leaf_axis[3 * leaf + 1], d.leaf_axis[3 * leaf + 2]);
    // From the petiole (a corner at the base) to the far corner: the diagonal.
    EXPECT_NEAR(glm::dot(axis, twig.dir), 0.12 / std::hypot(0.12, 0.06), 1e-5);
    EXPECT_NEAR(d.leaf_length[leaf], std::hypot(0.12, 0.06), 1e-5);
  }
  for (size_t v = 0; v < d.leaf_of_vertex.size(); ++v) EXPECT_EQ(d.leaf_of_vertex[v], int(v / 4));
}

}  // namespace
}  // namespace boreas
