// boreas: the native twins of the tree kernels, built with -O3 -march=native -fopenmp (see
// bench/CMakeLists.txt). The per-branch math is cl/shared/tree_math.h itself (its C++ build,
// polynomials on), so the twins differ from the kernels only by rounding order. Loops are
// shaped so that GCC vectorizes each SIMD one (checked with -fopt-info-vec-missed).
#include "native_trees.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "native_wind.h"

#define BOREAS_FAST_MATH 1
#include "shared/tree_math.h"
#include "shared/tree_types.h"

namespace boreas::bench {

namespace {

// Branches per block: a block's unbent tips go through native_wind_block together.
constexpr int kBlock = kNativeWindBlock;

// How the SIMD loops are written, and why (each checked with -fopt-info-vec-missed):
//  - `#pragma GCC ivdep`, not `omp simd`: inside an omp simd loop GCC turns every local
//    struct whose address is taken (tree_math.h's out-parameters, struct return slots)
//    into a per-lane "simd array" in memory and then gives up ("no vectype for stmt");
//    ivdep only drops the assumed dependences (the planes never overlap within a loop:
//    exact mode writes a level while reading the levels before it).
//  - [[gnu::flatten]] on each twin: tree_math.h's C++ build declares its functions plain
//    `static inline`, and GCC leaves boreas_attach as a call, which stops the loop.
//  - -ffinite-math-only (bench/CMakeLists.txt): GCC vectorizes fmaxf (BOREAS_TM_MAX in
//    the header's C++ build) only when it may ignore NaNs; without it every loop that
//    normalizes a vector stays scalar. Nothing here is NaN or infinite.

[[gnu::always_inline]] inline BoreasV3 load3(const float* planes, int n, int plane, int i) {
  return boreas_v3(planes[plane * n + i], planes[(plane + 1) * n + i], planes[(plane + 2) * n + i]);
}

[[gnu::always_inline]] inline void store3(float* planes, int n, int plane, int i, BoreasV3 v) {
  planes[plane * n + i] = v.x;
  planes[(plane + 1) * n + i] = v.y;
  planes[(plane + 2) * n + i] = v.z;
}

[[gnu::always_inline]] inline BoreasBezier load_curve(const float* state, int n, int i) {
  BoreasBezier c;
  c.p0 = load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = load3(state, n, BOREAS_TREE_STATE_P3, i);
  return c;
}

}  // namespace

NativeTrees native_tree_layout(const std::vector<NativeTreeSource>& trees) {
  using impl::kMaxTreeLevels;
  NativeTrees t;
  t.tree_count = int(trees.size());
  t.tree_level_first.resize(trees.size());
  int g = t.tree_count;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    t.level_first[l] = g;
    for (size_t k = 0; k < trees.size(); ++k) {
      const impl::TreeModel& m = *trees[k].model;
      t.tree_level_first[k][l] = g;
      g += m.level_begin[l + 1] - m.level_begin[l];
    }
    t.level_count[l] = g - t.level_first[l];
  }
  std::vector<int> leaf_first(trees.size());
  int leaves = 0;
  for (size_t k = 0; k < trees.size(); ++k) {
    leaf_first[k] = leaves;
    leaves += int(trees[k].model->leaves.size());
  }
  const int n = std::max(g, 1);
  const int ln = std::max(leaves, 1);
  t.n = n;
  t.leaf_count = leaves;
  t.leaf_n = ln;
  t.parents.assign(n, 0);
  t.shape.assign(size_t(BOREAS_TREE_SHAPE_PLANES) * n, 0.0f);
  t.radius.assign(size_t(BOREAS_TREE_RADIUS_PLANES) * n, 0.0f);
  t.response.assign(size_t(BOREAS_TREE_RESPONSE_PLANES) * n, 0.0f);
  std::vector<float> state(size_t(BOREAS_TREE_STATE_PLANES) * n, 0.0f);
  t.omega.assign(n, 0.0);
  t.zeta.assign(n, 0.0);
  t.leaf_parents.assign(ln, 0);
  t.leaf_shape.assign(size_t(BOREAS_TREE_LEAF_PLANES) * ln, 0.0f);

  auto global_of = [&](size_t k, int b) {
    const impl::TreeModel& m = *trees[k].model;
    const int level = m.branches[b].level;
    return t.tree_level_first[k][level] + (b - m.level_begin[level]);
  };
  for (size_t k = 0; k < trees.size(); ++k) {
    const impl::TreeParams& params = *trees[k].params;
    const impl::TreeModel& m = *trees[k].model;
    const int root = int(k);
    const BoreasV3 base =
        boreas_v3(float(params.position[0]), float(params.position[1]), float(params.position[2]));
    t.parents[root] = root;
    store3(state.data(), n, BOREAS_TREE_STATE_P0, root, base);
    store3(state.data(), n, BOREAS_TREE_STATE_P1, root,
           boreas_v3_add(base, boreas_v3(0, 1.0f / 3.0f, 0)));
    store3(state.data(), n, BOREAS_TREE_STATE_P2, root,
           boreas_v3_add(base, boreas_v3(0, 2.0f / 3.0f, 0)));
    store3(state.data(), n, BOREAS_TREE_STATE_P3, root, boreas_v3_add(base, boreas_v3(0, 1.0f, 0)));
    store3(state.data(), n, BOREAS_TREE_STATE_O, root, boreas_v3(1, 0, 0));
    const double w2 = std::pow(2.0 / 3.0, params.bend_exponent);
    for (int b = 0; b < int(m.branches.size()); ++b) {
      const impl::BranchModel& br = m.branches[b];
      const impl::TreeLevelParams& lp = params.levels[br.level];
      const int i = global_of(k, b);
      const int p = br.parent < 0 ? root : global_of(k, br.parent);
      t.parents[i] = p;
      for (int c = 1; c <= 3; ++c)
        for (int a = 0; a < 3; ++a)
          t.shape[size_t(3 * (c - 1) + a) * n + i] = float(br.local[c][a]);
      t.shape[size_t(BOREAS_TREE_SHAPE_V) * n + i] = float(br.v);
      t.shape[size_t(BOREAS_TREE_SHAPE_COS_THETA) * n + i] = float(std::cos(br.theta));
      t.shape[size_t(BOREAS_TREE_SHAPE_SIN_THETA) * n + i] = float(std::sin(br.theta));
      t.shape[size_t(BOREAS_TREE_SHAPE_COS_ALPHA) * n + i] = float(std::cos(br.alpha));
      t.shape[size_t(BOREAS_TREE_SHAPE_SIN_ALPHA) * n + i] = float(std::sin(br.alpha));
      t.shape[size_t(BOREAS_TREE_SHAPE_COMPLIANCE) * n + i] = float(impl::bend_compliance(br, lp));
      t.shape[size_t(BOREAS_TREE_SHAPE_W2) * n + i] = float(w2);
      const double radius_fields[BOREAS_TREE_RADIUS_PLANES] = {
          br.radius,     br.taper_depth, std::max(br.taper_exponent, 1.0),
          br.flare,      br.bulge_count, br.bulge_depth,
          br.lobe_count, br.lobe_depth,  br.lobe_taper};
      for (int c = 0; c < BOREAS_TREE_RADIUS_PLANES; ++c)
        t.radius[size_t(c) * n + i] = float(radius_fields[c]);
      if (params.response == BOREAS_TREE_DAMPED) {
        t.omega[i] = impl::natural_frequency(br, lp);
        t.zeta[i] = lp.damping_ratio;
      }
      // Placed unbent on its parent, which (levels in order) is placed already.
      const BoreasAttachFrame a = boreas_attach(
          load_curve(state.data(), n, p), load3(state.data(), n, BOREAS_TREE_STATE_O, p),
          float(br.v), float(std::cos(br.theta)), float(std::sin(br.theta)),
          float(std::cos(br.alpha)), float(std::sin(br.alpha)));
      store3(state.data(), n, BOREAS_TREE_STATE_P0, i, a.origin);
      for (int c = 1; c <= 3; ++c)
        store3(state.data(), n, BOREAS_TREE_STATE_P0 + 3 * c, i,
               boreas_attach_place(a, float(br.local[c][0]), float(br.local[c][1]),
                                   float(br.local[c][2])));
      store3(state.data(), n, BOREAS_TREE_STATE_O, i, a.y);
    }
    for (size_t j = 0; j < m.leaves.size(); ++j) {
      const impl::LeafModel& leaf = m.leaves[j];
      const int li = leaf_first[k] + int(j);
      t.leaf_parents[li] = global_of(k, leaf.parent);
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_V) * ln + li] = float(leaf.v);
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_COS_THETA) * ln + li] = float(std::cos(leaf.theta));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_THETA) * ln + li] = float(std::sin(leaf.theta));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_COS_ALPHA) * ln + li] = float(std::cos(leaf.alpha));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_SIN_ALPHA) * ln + li] = float(std::sin(leaf.alpha));
      t.leaf_shape[size_t(BOREAS_TREE_LEAF_STEM) * ln + li] = float(leaf.stem);
    }
  }
  t.state[0] = state;
  t.state[1] = std::move(state);
  t.motion[0].assign(size_t(BOREAS_TREE_MOTION_PLANES) * n, 0.0f);
  t.motion[1] = t.motion[0];
  return t;
}

void native_tree_response(NativeTrees& t, double dt) {
  if (dt == t.response_dt) return;
  const int n = t.n;
  std::fill(t.response.begin(), t.response.end(), 0.0f);
  for (int i = 0; i < n; ++i) {
    if (t.omega[i] <= 0.0) continue;
    const std::array<double, 4> m = impl::oscillator_step(t.omega[i], t.zeta[i], dt);
    for (int k = 0; k < 4; ++k) t.response[size_t(k) * n + i] = float(m[k]);
  }
  t.response_dt = dt;
}

[[gnu::flatten]] void native_tree_step(const float* parent_state, float* state,
                                       const int32_t* parents, const float* shape,
                                       const float* response, const float* motion_in,
                                       float* motion_out, int first, int count, int n,
                                       const NativeTreeWind& wind) {
#pragma omp parallel for schedule(static)
  for (int start = 0; start < count; start += kBlock) {
    const int m = std::min(kBlock, count - start);
    const int base = first + start;
    // The block's placed, unbent P1..P3 (x, y, z planes each) and the wind at P3.
    alignas(64) float placed[9][kBlock];
    alignas(64) float wind_x[kBlock], wind_y[kBlock], wind_z[kBlock];
    // 1. re-attach and place (P0 and O are final; P1 too, P2 and P3 get bent below).
#pragma GCC ivdep
    for (int j = 0; j < m; ++j) {
      const int i = base + j;
      const int p = parents[i];
      const BoreasBezier parent = load_curve(parent_state, n, p);
      const BoreasV3 parent_o = load3(parent_state, n, BOREAS_TREE_STATE_O, p);
      const BoreasAttachFrame a = boreas_attach(
          parent, parent_o, shape[BOREAS_TREE_SHAPE_V * n + i],
          shape[BOREAS_TREE_SHAPE_COS_THETA * n + i], shape[BOREAS_TREE_SHAPE_SIN_THETA * n + i],
          shape[BOREAS_TREE_SHAPE_COS_ALPHA * n + i], shape[BOREAS_TREE_SHAPE_SIN_ALPHA * n + i]);
      const BoreasV3 l1 = load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P1, i);
      const BoreasV3 l2 = load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P2, i);
      const BoreasV3 l3 = load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P3, i);
      const BoreasV3 p1 = boreas_attach_place(a, l1.x, l1.y, l1.z);
      const BoreasV3 p2 = boreas_attach_place(a, l2.x, l2.y, l2.z);
      const BoreasV3 p3 = boreas_attach_place(a, l3.x, l3.y, l3.z);
      placed[0][j] = p1.x;
      placed[1][j] = p1.y;
      placed[2][j] = p1.z;
      placed[3][j] = p2.x;
      placed[4][j] = p2.y;
      placed[5][j] = p2.z;
      placed[6][j] = p3.x;
      placed[7][j] = p3.y;
      placed[8][j] = p3.z;
      store3(state, n, BOREAS_TREE_STATE_P0, i, a.origin);
      store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
    }
    // 2. the wind at the placed tips.
    native_wind_block(placed[6], placed[7], placed[8], m, wind.waves, wind.wave_count, wind.grid,
                      wind.g, wind_x, wind_y, wind_z);
    // 3. response, 4. bend, 5. store.
#pragma GCC ivdep
    for (int j = 0; j < m; ++j) {
      const int i = base + j;
      const BoreasV3 p1 = boreas_v3(placed[0][j], placed[1][j], placed[2][j]);
      const BoreasV3 p2 = boreas_v3(placed[3][j], placed[4][j], placed[5][j]);
      const BoreasV3 p3 = boreas_v3(placed[6][j], placed[7][j], placed[8][j]);
      const BoreasV3 target = boreas_v3_scale(boreas_v3(wind_x[j], wind_y[j], wind_z[j]),
                                              shape[BOREAS_TREE_SHAPE_COMPLIANCE * n + i]);
      const float ra = response[BOREAS_TREE_RESPONSE_A * n + i];
      const float rb = response[BOREAS_TREE_RESPONSE_B * n + i];
      const float rc = response[BOREAS_TREE_RESPONSE_C * n + i];
      const float rd = response[BOREAS_TREE_RESPONSE_D * n + i];
      const BoreasV3 x = boreas_v3_sub(load3(motion_in, n, BOREAS_TREE_MOTION_F, i), target);
      const BoreasV3 u = load3(motion_in, n, BOREAS_TREE_MOTION_DF, i);
      const BoreasV3 bend =
          boreas_v3_add(target, boreas_v3_add(boreas_v3_scale(x, ra), boreas_v3_scale(u, rb)));
      const BoreasV3 rate = boreas_v3_add(boreas_v3_scale(x, rc), boreas_v3_scale(u, rd));
      store3(motion_out, n, BOREAS_TREE_MOTION_F, i, bend);
      store3(motion_out, n, BOREAS_TREE_MOTION_DF, i, rate);
      const BoreasV3 bent2 = boreas_bend_point(
          p1, boreas_v3_sub(p2, p1), boreas_v3_scale(bend, shape[BOREAS_TREE_SHAPE_W2 * n + i]));
      const BoreasV3 bent3 = boreas_bend_point(bent2, boreas_v3_sub(p3, p2), bend);
      store3(state, n, BOREAS_TREE_STATE_P1, i, p1);
      store3(state, n, BOREAS_TREE_STATE_P2, i, bent2);
      store3(state, n, BOREAS_TREE_STATE_P3, i, bent3);
    }
  }
}

void native_trees_step(NativeTrees& t, bool exact, double dt, const NativeTreeWind& wind) {
  native_tree_response(t, dt);
  const int next = 1 - t.current;
  float* state = t.state[next].data();
  const float* motion_in = t.motion[t.current].data();
  float* motion_out = t.motion[next].data();
  if (!exact) {
    native_tree_step(t.state[t.current].data(), state, t.parents.data(), t.shape.data(),
                     t.response.data(), motion_in, motion_out, t.level_first[0], t.branch_count(),
                     t.n, wind);
  } else {
    for (int l = 0; l < impl::kMaxTreeLevels; ++l) {
      if (t.level_count[l] <= 0) continue;
      native_tree_step(state, state, t.parents.data(), t.shape.data(), t.response.data(), motion_in,
                       motion_out, t.level_first[l], t.level_count[l], t.n, wind);
    }
  }
  t.current = next;
}

[[gnu::flatten]] void native_tree_deform(const float* state, int n, const float* radius, int first,
                                         int count, int rings, int sides, float* out, int out_n,
                                         int out_first) {
  const int row = sides + 1;
  const int per_branch = (rings + 1) * row;
  const int vertices = count * per_branch;
  // Integer division does not vectorize: a block's first branch is found by division, its
  // other vertices by float quotients of small block-relative indices. (j + 1/2) / d is at
  // least 1/(2d) from an integer, far more than its rounding error (~1e-7 (j/d + 1)) for
  // any rings and sides the API allows (d <= 257^2, j < 1024 + d).
  const float inv_per_branch = 1.0f / float(per_branch);
  const float inv_row = 1.0f / float(row);
  constexpr int kVertexBlock = 1024;
#pragma omp parallel for schedule(static)
  for (int start = 0; start < vertices; start += kVertexBlock) {
    const int end = std::min(start + kVertexBlock, vertices);
    const int b0 = start / per_branch;
    const int r0 = start - b0 * per_branch;
#pragma GCC ivdep
    for (int k = start; k < end; ++k) {
      const int j = k - start + r0;  // vertex index from branch b0's first vertex
      const int db = int((float(j) + 0.5f) * inv_per_branch);
      const int b = b0 + db;
      const int r = j - db * per_branch;
      const int ring = int((float(r) + 0.5f) * inv_row);
      const int side = r - ring * row;
      const int i = first + b;
      const BoreasBezier c = load_curve(state, n, i);
      const BoreasV3 o = load3(state, n, BOREAS_TREE_STATE_O, i);
      BoreasBranchRadius rp;
      rp.radius = radius[0 * n + i];
      rp.taper_depth = radius[1 * n + i];
      rp.taper_exponent = radius[2 * n + i];
      rp.flare = radius[3 * n + i];
      rp.bulge_count = radius[4 * n + i];
      rp.bulge_depth = radius[5 * n + i];
      rp.lobe_count = radius[6 * n + i];
      rp.lobe_depth = radius[7 * n + i];
      rp.lobe_taper = radius[8 * n + i];
      // As the kernel: divisions, not products with the reciprocals (same rounding).
      const float v = float(ring) / float(rings);
      const float turns = float(side) / float(sides);
      const float sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
      const float cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
      const BoreasSloanFrame f = boreas_sloan_frame(c, o);
      BoreasV3 pos, nrm;
      boreas_branch_surface(c, f, rp, v, turns, sin_t, cos_t, &pos, &nrm);
      const int w = out_first + k;
      out[(BOREAS_TREE_VERTEX_POSITION + 0) * out_n + w] = pos.x;
      out[(BOREAS_TREE_VERTEX_POSITION + 1) * out_n + w] = pos.y;
      out[(BOREAS_TREE_VERTEX_POSITION + 2) * out_n + w] = pos.z;
      out[(BOREAS_TREE_VERTEX_NORMAL + 0) * out_n + w] = nrm.x;
      out[(BOREAS_TREE_VERTEX_NORMAL + 1) * out_n + w] = nrm.y;
      out[(BOREAS_TREE_VERTEX_NORMAL + 2) * out_n + w] = nrm.z;
      out[(BOREAS_TREE_VERTEX_UV + 0) * out_n + w] = turns;
      out[(BOREAS_TREE_VERTEX_UV + 1) * out_n + w] = v;
    }
  }
}

[[gnu::flatten]] void native_tree_leaves(const float* state, int n, const int32_t* parents,
                                         const float* leaves, float* out, int count,
                                         int leaf_stride) {
  const int m = leaf_stride;
#pragma omp parallel for schedule(static)
  for (int start = 0; start < count; start += kBlock) {
    const int end = std::min(start + kBlock, count);
#pragma GCC ivdep
    for (int i = start; i < end; ++i) {
      const int p = parents[i];
      const BoreasBezier c = load_curve(state, n, p);
      const BoreasV3 o = load3(state, n, BOREAS_TREE_STATE_O, p);
      const BoreasAttachFrame a = boreas_attach(
          c, o, leaves[BOREAS_TREE_LEAF_V * m + i], leaves[BOREAS_TREE_LEAF_COS_THETA * m + i],
          leaves[BOREAS_TREE_LEAF_SIN_THETA * m + i], leaves[BOREAS_TREE_LEAF_COS_ALPHA * m + i],
          leaves[BOREAS_TREE_LEAF_SIN_ALPHA * m + i]);
      const BoreasV3 base = boreas_v3_madd(a.origin, a.x, leaves[BOREAS_TREE_LEAF_STEM * m + i]);
      store3(out, m, BOREAS_TREE_LEAF_OUT_POSITION, i, base);
      store3(out, m, BOREAS_TREE_LEAF_OUT_AXIS, i, a.x);
      store3(out, m, BOREAS_TREE_LEAF_OUT_NORMAL, i, a.y);
    }
  }
}

}  // namespace boreas::bench
