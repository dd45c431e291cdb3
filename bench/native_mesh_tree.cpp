// boreas: the native twins of the imported-tree kernels, built with -O3 -march=native
// -fopenmp (see bench/CMakeLists.txt). cl/shared/mesh_tree_math.h is OpenCL C only, so its
// formulas are written out again here, operation for operation (fma where the kernels call
// fma; rsqrt as 1 / std::sqrt); the twins differ from the kernels only by rounding order.
// Loops are shaped so that GCC vectorizes each SIMD one (checked with -fopt-info-vec).
#include "native_mesh_tree.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "errors.h"
#include "native_wind.h"
#include "shared/mesh_tree_types.h"

namespace boreas::bench {

namespace {

// Work per OpenMP chunk: branches (a block goes through native_wind_block together) and
// vertices.
constexpr int kBranchBlock = kNativeWindBlock;
constexpr int kVertexBlock = 1024;
constexpr int kNoiseSize = BOREAS_MESH_TREE_NOISE_SIZE;
constexpr size_t kNoiseTexels = size_t(kNoiseSize) * kNoiseSize;

// How the SIMD loops are written, as in native_trees.cpp: `#pragma GCC ivdep` (not
// `omp simd`, which turns the helpers' return slots into per-lane arrays in memory), the
// helpers returning small structs by value, [[gnu::flatten]] on each twin so that they are
// inlined, and -ffinite-math-only for std::fmax (bench/CMakeLists.txt). Besides those:
//  - the four levels are written out, not looped over (a vertex loop with an inner loop
//    is not vectorized);
//  - the leaf pass writes its six outputs to block-local planes first: GCC 12 vectorizes
//    no loop that stores interleaved groups of 6 floats (3, as the trunk's, it does).
// The gathers (a vertex's leaf and branch, its four animating branches' rows, four noise
// texels of two channels per level) are AVX-512 gathers.

struct Displacement {
  float x, y, z;
};

struct NoisePair {
  float n0, n1;
};

// boreas_mesh_tree_load
inline float mesh_tree_load(float s2) {
  float q = s2 * (1.0f / (BOREAS_MESH_TREE_REFERENCE_SPEED * BOREAS_MESH_TREE_REFERENCE_SPEED));
  return q / (1.0f + q * (1.0f / BOREAS_MESH_TREE_LOAD_CEILING));
}

// boreas_mesh_tree_noise: bilinear, wrapping, both channels of one tree's texture.
inline NoisePair mesh_tree_noise(const float* noise, float u, float v) {
  const int size = kNoiseSize;
  float x = (u - std::floor(u)) * float(size) - 0.5f;
  float y = (v - std::floor(v)) * float(size) - 0.5f;
  float x0 = std::floor(x);
  float y0 = std::floor(y);
  float fx = x - x0;
  float fy = y - y0;
  int i0 = int(x0) & (size - 1);
  int j0 = int(y0) & (size - 1);
  int i1 = (i0 + 1) & (size - 1);
  int j1 = (j0 + 1) & (size - 1);
  int a = j0 * size + i0, b = j0 * size + i1, c = j1 * size + i0, d = j1 * size + i1;
  float w00 = (1.0f - fx) * (1.0f - fy), w10 = fx * (1.0f - fy), w01 = (1.0f - fx) * fy,
        w11 = fx * fy;
  const float* second = noise + size * size;
  return {w00 * noise[a] + w10 * noise[b] + w01 * noise[c] + w11 * noise[d],
          w00 * second[a] + w10 * second[b] + w01 * second[c] + w11 * second[d]};
}

// The tables a vertex pass reads.
struct Tables {
  const float* branches;
  const int32_t* links;
  int nb;
  const float* state;
  const float* trees;
  int nt;
  const float* noise;
};

// boreas_mesh_tree_level: one level's term for weight w, animated by branch a of tree t.
inline Displacement mesh_tree_level(int k, float w, int a, int t, const Tables& s) {
  const int nb = s.nb, nt = s.nt;
  const float* branches = s.branches;
  float wx = s.state[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + a];
  float wy = s.state[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + a];
  float wz = s.state[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + a];
  float ax = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 0) * nb + a];
  float ay = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 1) * nb + a];
  float az = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 2) * nb + a];
  float s2 = wx * wx + wy * wy + wz * wz;
  float load = w * mesh_tree_load(s2);
  float along = wx * ax + wy * ay + wz * az;
  float bend =
      load * s.trees[(BOREAS_MESH_TREE_TREE_BEND + k) * nt + t] * (1.0f / std::sqrt(s2 + 1e-12f));
  float sway = load * s.trees[(BOREAS_MESH_TREE_TREE_SWAY + k) * nt + t];
  NoisePair n = mesh_tree_noise(s.noise + size_t(t) * 2 * kNoiseTexels,
                                branches[BOREAS_MESH_TREE_BRANCH_PHASE * nb + a] +
                                    s.trees[(BOREAS_MESH_TREE_TREE_CLOCK + k) * nt + t],
                                branches[(BOREAS_MESH_TREE_BRANCH_PHASE + 1) * nb + a]);
  float r = sway * n.n0, u = sway * n.n1;
  return {bend * (wx - along * ax) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 0) * nb + a] +
              u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 0) * nb + a],
          bend * (wy - along * ay) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 1) * nb + a] +
              u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 1) * nb + a],
          bend * (wz - along * az) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 2) * nb + a] +
              u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 2) * nb + a]};
}

// boreas_mesh_tree_displacement: the four levels summed in the kernel's order (0 + l0 + l1 ...).
inline Displacement mesh_tree_displacement(float w0, float w1, float w2, float w3, int b,
                                           const Tables& s) {
  const int nb = s.nb;
  const int t = s.links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  // Written out (no loop over k): GCC vectorizes no vertex loop with an inner loop left.
  const Displacement l0 =
      mesh_tree_level(0, w0, s.links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 0) * nb + b], t, s);
  const Displacement l1 =
      mesh_tree_level(1, w1, s.links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 1) * nb + b], t, s);
  const Displacement l2 =
      mesh_tree_level(2, w2, s.links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 2) * nb + b], t, s);
  const Displacement l3 =
      mesh_tree_level(3, w3, s.links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 3) * nb + b], t, s);
  return {((0.0f + l0.x) + l1.x + l2.x) + l3.x, ((0.0f + l0.y) + l1.y + l2.y) + l3.y,
          ((0.0f + l0.z) + l1.z + l2.z) + l3.z};
}

Tables tables(const NativeMeshTrees& t, const float* state) {
  return {t.branches.data(), t.links.data(), t.nb, state, t.trees.data(), t.nt, t.noise.data()};
}

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
      const int tr = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
      float k = dt / (branches[BOREAS_MESH_TREE_BRANCH_TAU * nb + b] + dt);
      k = trees[BOREAS_MESH_TREE_TREE_FRESH * nt + tr] != 0.0f ? 1.0f : k;
      float sx = state_in[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b];
      float sy = state_in[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b];
      float sz = state_in[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b];
      state_out[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b] = std::fma(k, wx[j] - sx, sx);
      state_out[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b] = std::fma(k, wy[j] - sy, sy);
      state_out[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b] = std::fma(k, wz[j] - sz, sz);
    }
    // The stems (one per tree) roll their tree's leaf noise; scalar, they are few.
    for (int j = 0; j < m; ++j) {
      const int b = start + j;
      if (links[BOREAS_MESH_TREE_BRANCH_IS_STEM * nb + b] == 0) continue;
      const int tr = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
      const float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + tr];
      float u = roll_in[(BOREAS_MESH_TREE_ROLL + 0) * nt + tr] +
                state_out[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b] * dt * inv_tile;
      float v = roll_in[(BOREAS_MESH_TREE_ROLL + 1) * nt + tr] +
                state_out[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b] * dt * inv_tile;
      roll_out[(BOREAS_MESH_TREE_ROLL + 0) * nt + tr] = u - std::floor(u);
      roll_out[(BOREAS_MESH_TREE_ROLL + 1) * nt + tr] = v - std::floor(v);
    }
  }
}

[[gnu::flatten]] void native_mesh_trunk(NativeMeshTrees& t, const float* state) {
  const int nv = t.nv;
  const Tables s = tables(t, state);
  const float* vertices = t.trunk.data();
  const int32_t* vertex_branch = t.trunk_branch.data();
  float* out = t.trunk_out.data();
#pragma omp parallel for schedule(static)
  for (int start = 0; start < nv; start += kVertexBlock) {
    const int end = std::min(start + kVertexBlock, nv);
#pragma GCC ivdep
    for (int i = start; i < end; ++i) {
      const Displacement d = mesh_tree_displacement(
          vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
          vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
          vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
          vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i], vertex_branch[i], s);
      out[3 * i + 0] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 0) * nv + i] + d.x;
      out[3 * i + 1] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 1) * nv + i] + d.y;
      out[3 * i + 2] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 2) * nv + i] + d.z;
    }
  }
}

[[gnu::flatten]] void native_mesh_leaves(NativeMeshTrees& t, const float* state,
                                         const float* roll) {
  const Tables s = tables(t, state);
  const int nv = t.nlv, nl = t.nl, nb = s.nb, nt = s.nt;
  const float* vertices = t.leaf_vertices.data();
  const int32_t* vertex_leaf = t.vertex_leaf.data();
  const float* leaves = t.leaves.data();
  const int32_t* leaf_branch = t.leaf_branch.data();
  const int32_t* links = s.links;
  const float* trees = s.trees;
  const float* noise = s.noise;
  float* out = t.leaf_out.data();
#pragma omp parallel for schedule(static)
  for (int start = 0; start < nv; start += kVertexBlock) {
    const int end = std::min(start + kVertexBlock, nv);
    alignas(64) float result[6][kVertexBlock];  // position xyz, normal xyz, per vertex
#pragma GCC ivdep
    for (int i = start; i < end; ++i) {
      const int l = vertex_leaf[i];
      const int b = leaf_branch[l];
      const int tr = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
      const Displacement d =
          mesh_tree_displacement(leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 0) * nl + l],
                                 leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 1) * nl + l],
                                 leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 2) * nl + l],
                                 leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 3) * nl + l], b, s);

      float wx = state[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b];
      float wy = state[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b];
      float wz = state[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b];
      float s2 = wx * wx + wy * wy + wz * wz;
      float load = mesh_tree_load(s2);
      float inv_s = 1.0f / std::sqrt(s2 + 1e-12f);
      float ux = wx * inv_s, uy = wy * inv_s, uz = wz * inv_s;

      float ax = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 0) * nl + l];
      float ay = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 1) * nl + l];
      float az = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 2) * nl + l];
      float f = trees[BOREAS_MESH_TREE_TREE_TURN * nt + tr] * load / (1.0f + load);
      float px = std::fma(f, ux - ax, ax), py = std::fma(f, uy - ay, ay),
            pz = std::fma(f, uz - az, az);
      float inv_p = 1.0f / std::sqrt(px * px + py * py + pz * pz + 1e-12f);
      px *= inv_p;
      py *= inv_p;
      pz *= inv_p;
      float kx = ay * pz - az * py, ky = az * px - ax * pz, kz = ax * py - ay * px;
      float c = ax * px + ay * py + az * pz;
      const bool still = f == 0.0f;
      kx = still ? 0.0f : kx;
      ky = still ? 0.0f : ky;
      kz = still ? 0.0f : kz;
      c = still ? 1.0f : c;
      float h = 1.0f / std::fmax(1.0f + c, 1e-4f);

      float petx = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 0) * nl + l];
      float pety = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 1) * nl + l];
      float petz = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 2) * nl + l];
      float rx = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 0) * nv + i];
      float ry = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 1) * nv + i];
      float rz = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 2) * nv + i];
      float ox = rx - petx, oy = ry - pety, oz = rz - petz;
      float ko = kx * ox + ky * oy + kz * oz;
      float cm1 = c - 1.0f;
      float qx = cm1 * ox + (ky * oz - kz * oy) + kx * ko * h;
      float qy = cm1 * oy + (kz * ox - kx * oz) + ky * ko * h;
      float qz = cm1 * oz + (kx * oy - ky * ox) + kz * ko * h;
      float nx = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 0) * nv + i];
      float ny = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 1) * nv + i];
      float nz = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 2) * nv + i];
      float kn = kx * nx + ky * ny + kz * nz;
      float mx = c * nx + (ky * nz - kz * ny) + kx * kn * h;
      float my = c * ny + (kz * nx - kx * nz) + ky * kn * h;
      float mz = c * nz + (kx * ny - ky * nx) + kz * kn * h;

      float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + tr];
      NoisePair n = mesh_tree_noise(noise + size_t(tr) * 2 * kNoiseTexels,
                                    rx * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 0) * nt + tr],
                                    rz * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 1) * nt + tr]);
      float flutter = trees[BOREAS_MESH_TREE_TREE_FLUTTER * nt + tr] * load *
                      vertices[BOREAS_MESH_TREE_LEAF_VERTEX_TIP * nv + i];
      const int j = i - start;
      result[0][j] = rx + (d.x + qx + flutter * n.n0 * ux);
      result[1][j] = ry + (d.y + qy + flutter * (n.n0 * uy + n.n1));
      result[2][j] = rz + (d.z + qz + flutter * n.n0 * uz);
      result[3][j] = mx;
      result[4][j] = my;
      result[5][j] = mz;
    }
    // Interleaved into out (see the top of this file); a copy, cheap next to the math.
    for (int i = start; i < end; ++i)
      for (int c = 0; c < 6; ++c) out[6 * i + c] = result[c][i - start];
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
