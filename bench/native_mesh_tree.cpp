// boreas: the native twins of the imported-tree kernels, built with -O3 -march=native
// -fopenmp (see bench/CMakeLists.txt). They call the kernels' own math, the C++ build of
// cl/shared/mesh_tree_math.h, around loops shaped so that GCC vectorizes each SIMD one
// (checked with -fopt-info-vec); the twins differ from the kernels only by rounding order
// (GCC contracts to fma across statements, clang within expressions).
#include "native_mesh_tree.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "errors.h"
#include "native_wind.h"
#include "shared/mesh_tree_math.h"

namespace boreas::bench {

namespace {

// Work per OpenMP chunk: branches (a block goes through native_wind_block together) and
// vertices.
constexpr int kBranchBlock = kNativeWindBlock;
constexpr int kVertexBlock = 1024;

// How the SIMD loops are written, as in native_trees.cpp: `#pragma GCC ivdep` (not
// `omp simd`, which turns the helpers' out-parameters and return slots into per-lane arrays
// in memory), [[gnu::flatten]] on each twin so that the helpers are inlined, and
// -ffinite-math-only for fmaxf (bench/CMakeLists.txt). Besides those: the leaf pass writes
// its six outputs to block-local planes first: GCC 12 vectorizes no loop that stores
// interleaved groups of 6 floats (3, as the trunk's, it does). The gathers (a vertex's leaf
// and branch, its four animating branches' rows, four noise texels of two channels per
// level) are AVX-512 gathers.

}  // namespace

NativeMeshTrees native_mesh_layout(const std::vector<const impl::MeshTreeInstance*>& trees) {
  impl::MeshTreeTables m = impl::mesh_tree_tables(trees);
  NativeMeshTrees t;
  t.nt = int(trees.size());
  t.nb = int(m.branches);
  t.nv = int(m.trunk_vertices);
  t.nl = int(m.leaves_count);
  t.nlv = int(m.leaf_vertices_count);
  t.instances = trees;
  t.fresh.assign(trees.size(), true);
  t.branches = std::move(m.branch_table);
  t.links = std::move(m.links);
  t.state[0].assign(BOREAS_MESH_TREE_STATE_FLOATS * m.branches, 0.0f);
  t.state[1] = t.state[0];
  t.roll[0].assign(BOREAS_MESH_TREE_ROLL_FLOATS * trees.size(), 0.0f);
  t.roll[1] = t.roll[0];
  t.trees.assign(BOREAS_MESH_TREE_TREE_FLOATS * trees.size(), 0.0f);
  t.noise = std::move(m.noise);
  t.trunk = std::move(m.trunk);
  t.trunk_branch = std::move(m.trunk_branch);
  t.trunk_out = std::move(m.trunk_rest);
  t.leaves = std::move(m.leaves);
  t.leaf_branch = std::move(m.leaf_branch);
  t.leaf_vertices = std::move(m.leaf_vertices);
  t.vertex_leaf = std::move(m.vertex_leaf);
  t.leaf_out = std::move(m.leaf_rest);
  return t;
}

void native_mesh_tree_params(NativeMeshTrees& t, double time) {
  t.trees = impl::mesh_tree_planes(t.instances, t.fresh, time);
}

[[gnu::flatten]] void native_mesh_branches(const NativeMeshTrees& t, const float* state_in,
                                           float* state_out, const float* roll_in, float* roll_out,
                                           float dt, const NativeTreeWind& wind) {
  const int nb = t.nb, nt = t.nt;
  const float* branches = t.branches.data();
  const int32_t* links = t.links.data();
  const float* trees = t.trees.data();
#pragma omp parallel for schedule(static)
  for (int start = 0; start < nb; start += kBranchBlock) {
    const int m = std::min(kBranchBlock, nb - start);
    alignas(64) float wx[kBranchBlock], wy[kBranchBlock], wz[kBranchBlock];
    native_wind_block(&branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 0) * nb + start],
                      &branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 1) * nb + start],
                      &branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 2) * nb + start], m, wind.waves,
                      wind.wave_count, wind.grid, wind.g, wx, wy, wz, wind.interpolated);
#pragma GCC ivdep
    for (int j = 0; j < m; ++j) {
      const int b = start + j;
      float sx, sy, sz;
      boreas_mesh_tree_follow(branches, links, nb, b, trees, nt,
                              links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b], state_in, state_out, dt,
                              wx[j], wy[j], wz[j], &sx, &sy, &sz);
    }
    // The stems (one per tree) roll their tree's leaf noise; scalar, they are few.
    for (int j = 0; j < m; ++j) {
      const int b = start + j;
      if (links[BOREAS_MESH_TREE_BRANCH_IS_STEM * nb + b] == 0) continue;
      boreas_mesh_tree_roll(trees, nt, links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b], roll_in,
                            roll_out, state_out[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b],
                            state_out[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b], dt);
    }
  }
}

[[gnu::flatten]] void native_mesh_trunk(NativeMeshTrees& t, const float* state) {
  const int nv = t.nv, nb = t.nb, nt = t.nt;
  const float* vertices = t.trunk.data();
  const int32_t* vertex_branch = t.trunk_branch.data();
  const float* branches = t.branches.data();
  const int32_t* links = t.links.data();
  const float* trees = t.trees.data();
  const float* noise = t.noise.data();
  float* out = t.trunk_out.data();
#pragma omp parallel for schedule(static)
  for (int start = 0; start < nv; start += kVertexBlock) {
    const int end = std::min(start + kVertexBlock, nv);
#pragma GCC ivdep
    for (int i = start; i < end; ++i) {
      float dx, dy, dz;
      boreas_mesh_tree_displacement(vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
                                    vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
                                    vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
                                    vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i],
                                    vertex_branch[i], branches, links, nb, state, trees, nt, noise,
                                    &dx, &dy, &dz);
      boreas_mesh_tree_trunk_vertex(vertices, nv, i, dx, dy, dz, out, i, 3, 1);
    }
  }
}

[[gnu::flatten]] void native_mesh_leaves(NativeMeshTrees& t, const float* state,
                                         const float* roll) {
  const int nv = t.nlv, nl = t.nl, nb = t.nb, nt = t.nt;
  const float* vertices = t.leaf_vertices.data();
  const int32_t* vertex_leaf = t.vertex_leaf.data();
  const float* leaves = t.leaves.data();
  const int32_t* leaf_branch = t.leaf_branch.data();
  const float* branches = t.branches.data();
  const int32_t* links = t.links.data();
  const float* trees = t.trees.data();
  const float* noise = t.noise.data();
  float* out = t.leaf_out.data();
#pragma omp parallel for schedule(static)
  for (int start = 0; start < nv; start += kVertexBlock) {
    const int end = std::min(start + kVertexBlock, nv);
    // Position xyz, normal xyz: plane c holds value c of the block's vertices.
    alignas(64) float result[6 * kVertexBlock];
#pragma GCC ivdep
    for (int i = start; i < end; ++i) {
      const int l = vertex_leaf[i];
      const int b = leaf_branch[l];
      const int tr = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
      float dx, dy, dz;
      boreas_mesh_tree_displacement(leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 0) * nl + l],
                                    leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 1) * nl + l],
                                    leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 2) * nl + l],
                                    leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 3) * nl + l], b,
                                    branches, links, nb, state, trees, nt, noise, &dx, &dy, &dz);
      BoreasMeshTreeTurn turn;
      boreas_mesh_tree_leaf_turn(state, nb, b, leaves, nl, l, trees, nt, tr, &turn);
      boreas_mesh_tree_leaf_vertex(&turn, dx, dy, dz, vertices, nv, i, leaves, nl, l, trees, nt, tr,
                                   roll, noise, result, i - start, 1, kVertexBlock);
    }
    // Interleaved into out (see the top of this file); a copy, cheap next to the math.
    for (int i = start; i < end; ++i)
      for (int c = 0; c < 6; ++c) out[6 * i + c] = result[c * kVertexBlock + i - start];
  }
}

void native_mesh_step(NativeMeshTrees& t, double dt, double time, const NativeTreeWind& wind,
                      double pass_seconds[3]) {
  if (t.nt == 0) return;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  native_mesh_tree_params(t, time);
  const int next = 1 - t.current;
  native_mesh_branches(t, t.state[t.current].data(), t.state[next].data(), t.roll[t.current].data(),
                       t.roll[next].data(), float(dt), wind);
  const Clock::time_point branches = Clock::now();
  native_mesh_trunk(t, t.state[next].data());
  const Clock::time_point trunk = Clock::now();
  native_mesh_leaves(t, t.state[next].data(), t.roll[next].data());
  if (pass_seconds) {
    pass_seconds[0] += std::chrono::duration<double>(branches - start).count();
    pass_seconds[1] += std::chrono::duration<double>(trunk - branches).count();
    pass_seconds[2] += std::chrono::duration<double>(Clock::now() - trunk).count();
  }
  t.current = next;
  t.fresh.assign(t.fresh.size(), false);
}

}  // namespace boreas::bench
