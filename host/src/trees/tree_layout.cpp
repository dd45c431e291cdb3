// boreas: the tree kernels' layout and the rest placement of new trees.
#include "trees/tree_layout.h"

#include <algorithm>
#include <cmath>

// The rest placement uses the kernels' own geometry (float, C++ build of the shared
// header); its polynomial math is only reached by the deformer's radius functions.
#define BOREAS_FAST_MATH 1
#include "shared/tree_state.h"

namespace boreas::impl {

TreeLayout tree_layout(const std::vector<TreeLayoutSource>& trees) {
  TreeLayout t;
  t.tree_count = static_cast<int>(trees.size());
  t.tree_level_first.resize(trees.size());
  t.tree_leaf_first.resize(trees.size());
  int g = t.tree_count;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    t.level_first[l] = g;
    for (size_t k = 0; k < trees.size(); ++k) {
      const TreeModel& m = *trees[k].model;
      t.tree_level_first[k][l] = g;
      g += m.level_begin[l + 1] - m.level_begin[l];
    }
    t.level_count[l] = g - t.level_first[l];
  }
  for (size_t k = 0; k < trees.size(); ++k) {
    t.tree_leaf_first[k] = t.leaf_count;
    t.leaf_count += static_cast<int>(trees[k].model->leaves.size());
  }
  t.branch_count = g - t.tree_count;
  const int n = t.n = std::max(g, 1);
  const int ln = t.leaf_n = std::max(t.leaf_count, 1);

  t.parents.assign(n, 0);
  t.shape.assign(size_t(BOREAS_TREE_SHAPE_PLANES) * n, 0.0f);
  t.radius.assign(size_t(BOREAS_TREE_RADIUS_PLANES) * n, 0.0f);
  t.state.assign(size_t(BOREAS_TREE_STATE_PLANES) * n, 0.0f);
  t.motion.assign(size_t(BOREAS_TREE_MOTION_PLANES) * n, 0.0f);
  t.omega.assign(n, 0.0);
  t.zeta.assign(n, 0.0);
  t.leaf_parents.assign(ln, 0);
  t.leaf_shape.assign(size_t(BOREAS_TREE_LEAF_PLANES) * ln, 0.0f);
  float* state = t.state.data();

  for (size_t k = 0; k < trees.size(); ++k) {
    const TreeParams& params = *trees[k].params;
    const TreeModel& m = *trees[k].model;
    const int root = static_cast<int>(k);
    BoreasV3 base = boreas_v3(float(params.position[0]), float(params.position[1]), float(params.position[2]));
    t.parents[root] = root;
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, root, base);
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, root, boreas_v3_add(base, boreas_v3(0, 1.0f / 3.0f, 0)));
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, root, boreas_v3_add(base, boreas_v3(0, 2.0f / 3.0f, 0)));
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, root, boreas_v3_add(base, boreas_v3(0, 1.0f, 0)));
    boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, root, boreas_v3(1, 0, 0));

    const double w2 = std::pow(2.0 / 3.0, params.bend_exponent);
    for (int b = 0; b < static_cast<int>(m.branches.size()); ++b) {
      const BranchModel& br = m.branches[b];
      const TreeLevelParams& lp = params.levels[br.level];
      const int i = t.branch_index(k, m, b);
      const int p = br.parent < 0 ? root : t.branch_index(k, m, br.parent);
      t.parents[i] = p;
      for (int c = 1; c <= 3; ++c)
        for (int a = 0; a < 3; ++a) t.shape[size_t(3 * (c - 1) + a) * n + i] = float(br.local[c][a]);
      t.shape[size_t(BOREAS_TREE_SHAPE_V) * n + i] = float(br.v);
      t.shape[size_t(BOREAS_TREE_SHAPE_COS_THETA) * n + i] = float(std::cos(br.theta));
      t.shape[size_t(BOREAS_TREE_SHAPE_SIN_THETA) * n + i] = float(std::sin(br.theta));
      t.shape[size_t(BOREAS_TREE_SHAPE_COS_ALPHA) * n + i] = float(std::cos(br.alpha));
      t.shape[size_t(BOREAS_TREE_SHAPE_SIN_ALPHA) * n + i] = float(std::sin(br.alpha));
      t.shape[size_t(BOREAS_TREE_SHAPE_COMPLIANCE) * n + i] = float(bend_compliance(br, lp));
      t.shape[size_t(BOREAS_TREE_SHAPE_W2) * n + i] = float(w2);
      const double radius_fields[BOREAS_TREE_RADIUS_PLANES] = {
          br.radius,      br.taper_depth, std::max(br.taper_exponent, 1.0), br.flare,     br.bulge_count,
          br.bulge_depth, br.lobe_count,  br.lobe_depth,                    br.lobe_taper};
      for (int c = 0; c < BOREAS_TREE_RADIUS_PLANES; ++c) t.radius[size_t(c) * n + i] = float(radius_fields[c]);
      if (params.response == BOREAS_TREE_DAMPED) {
        t.omega[i] = natural_frequency(br, lp);
        t.zeta[i] = lp.damping_ratio;
      }
      // Placed unbent on its parent, which (levels in order) is placed already.
      BoreasV3 parent_o;
      BoreasBezier parent = boreas_tree_load_curve(state, n, p, &parent_o);
      BoreasAttachFrame a = boreas_attach(parent, parent_o, float(br.v), float(std::cos(br.theta)),
                                          float(std::sin(br.theta)), float(std::cos(br.alpha)),
                                          float(std::sin(br.alpha)));
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i, a.origin);
      for (int c = 1; c <= 3; ++c)
        boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0 + 3 * c, i,
                           boreas_attach_place(a, float(br.local[c][0]), float(br.local[c][1]), float(br.local[c][2])));
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
    }
    for (size_t j = 0; j < m.leaves.size(); ++j) {
      const LeafModel& leaf = m.leaves[j];
      const int li = t.tree_leaf_first[k] + static_cast<int>(j);
      t.leaf_parents[li] = t.branch_index(k, m, leaf.parent);
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_V) * ln + li] = float(leaf.v);
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_COS_THETA) * ln + li] = float(std::cos(leaf.theta));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_THETA) * ln + li] = float(std::sin(leaf.theta));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_COS_ALPHA) * ln + li] = float(std::cos(leaf.alpha));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_ALPHA) * ln + li] = float(std::sin(leaf.alpha));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_STEM) * ln + li] = float(leaf.stem);
    }
  }
  return t;
}

std::vector<float> tree_response_planes(const std::vector<double>& omega, const std::vector<double>& zeta,
                                        double dt) {
  const size_t n = omega.size();
  std::vector<float> response(size_t(BOREAS_TREE_RESPONSE_PLANES) * n, 0.0f);
  for (size_t i = 0; i < n; ++i) {
    if (omega[i] <= 0.0) continue;  // quasi-static: a = b = c = d = 0, F = F*
    std::array<double, 4> m = oscillator_step(omega[i], zeta[i], dt);
    for (int k = 0; k < 4; ++k) response[size_t(k) * n + i] = float(m[k]);
  }
  return response;
}

}  // namespace boreas::impl
