// boreas: the native twins of the tree kernels, built with -O3 -march=native -fopenmp (see
// bench/CMakeLists.txt). The per-branch math is cl/shared/tree_math.h itself (its C++ build,
// polynomials on), so the twins differ from the kernels only by rounding order. Loops are
// shaped so that GCC vectorizes each SIMD one (checked with -fopt-info-vec-missed).
#include "native_trees.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "native_wind.h"

#define BOREAS_FAST_MATH 1
#include "shared/leaf_pack.h"
#include "shared/tree_state.h"
#include "trees/tree_batch.h"
#include "trees/tree_layout.h"

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
//  - -ffinite-math-only (bench/CMakeLists.txt): GCC vectorizes fmaxf (BOREAS_FMAX in
//    the header's C++ build) only when it may ignore NaNs; without it every loop that
//    normalizes a vector stays scalar. Nothing here is NaN or infinite.

}  // namespace

NativeTrees native_tree_layout(const std::vector<NativeTreeSource>& trees) {
  impl::TreeLayout layout = impl::tree_layout(trees);
  NativeTrees t;
  t.tree_count = layout.tree_count;
  t.n = layout.n;
  t.parents = std::move(layout.parents);
  t.shape = std::move(layout.shape);
  t.radius = std::move(layout.radius);
  t.response.assign(size_t(BOREAS_TREE_RESPONSE_PLANES) * t.n, 0.0f);
  t.state[0] = layout.state;
  t.state[1] = std::move(layout.state);
  t.motion[0] = layout.motion;
  t.motion[1] = std::move(layout.motion);
  t.omega = std::move(layout.omega);
  t.zeta = std::move(layout.zeta);
  t.leaf_count = layout.leaf_count;
  t.leaf_n = layout.leaf_n;
  t.leaves = std::move(layout.leaves);
  t.tree_leaf_petiole = std::move(layout.tree_leaf_petiole);
  t.tree_first = std::move(layout.tree_first);
  // Every tree at full detail, as a batch without focus points launches them, in both
  // modes; each tree's template block sits at its own entries in this layout.
  for (size_t k = 0; k < trees.size(); ++k) {
    impl::TreeTileSource at;
    at.first = at.static_first = t.tree_first[k];
    at.scale = trees[k].params->scale;
    for (int exact = 0; exact < 2; ++exact)
      impl::add_tree_tiles(t.tiles[exact], exact ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED,
                           *trees[k].model, at, impl::TreeLod::kFull, 0.0f, 0, kTileWidth);
  }
  t.tree_leaf_first = std::move(layout.tree_leaf_first);
  t.tree_scale = std::move(layout.tree_scale);
  return t;
}

void native_tree_response(NativeTrees& t, double dt) {
  if (dt == t.response_dt) return;
  t.response = impl::tree_response_planes(t.omega, t.zeta, dt);
  t.response_dt = dt;
}

[[gnu::flatten]] void native_tree_step(const float* parent_state, float* state,
                                       const int32_t* parents, const float* shape,
                                       const float* response, const float* motion_in,
                                       float* motion_out, int n, int sn, const int32_t* tiles,
                                       int tile_count, float carry_hold, bool carry,
                                       const NativeTreeWind& wind) {
#pragma omp parallel for schedule(static)
  for (int tile = 0; tile < tile_count; ++tile) {
    const int32_t* t = tiles + size_t(tile) * BOREAS_TILE_INTS;
    const int base = t[BOREAS_TILE_FIRST];
    const int static_base = t[BOREAS_TILE_STATIC];
    const int root = t[BOREAS_TILE_ROOT];
    const int m = t[BOREAS_TILE_COUNT];
    float h = carry_hold, scale = 1.0f, scale_root = 1.0f;
    if (!carry) std::memcpy(&h, &t[BOREAS_TILE_VALUE], sizeof h);
    std::memcpy(&scale, &t[BOREAS_TILE_SCALE], sizeof scale);
    std::memcpy(&scale_root, &t[BOREAS_TILE_SCALE_ROOT], sizeof scale_root);
    // The tile's placed, unbent P1..P3 (x, y, z planes each) and the wind at P3.
    alignas(64) float placed[9][kBlock];
    alignas(64) float wind_x[kBlock], wind_y[kBlock], wind_z[kBlock];
    // 1. re-attach and place (P0 and O are final; P1 too, P2 and P3 get bent below).
#pragma GCC ivdep
    for (int jj = 0; jj < m; ++jj) {
      const int i = base + jj;
      const int j = static_base + jj;
      const int p = root + parents[j];
      BoreasV3 parent_o;
      const BoreasBezier parent = boreas_tree_load_curve(parent_state, n, p, &parent_o);
      BoreasAttachFrame a = boreas_attach(
          parent, parent_o, shape[BOREAS_TREE_SHAPE_V * sn + j],
          shape[BOREAS_TREE_SHAPE_COS_THETA * sn + j], shape[BOREAS_TREE_SHAPE_SIN_THETA * sn + j],
          shape[BOREAS_TREE_SHAPE_COS_ALPHA * sn + j], shape[BOREAS_TREE_SHAPE_SIN_ALPHA * sn + j]);
      const BoreasV3 l1 =
          boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P1, j), scale);
      const BoreasV3 l2 =
          boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P2, j), scale);
      const BoreasV3 l3 =
          boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P3, j), scale);
      const BoreasV3 p1 = boreas_attach_place(a, l1.x, l1.y, l1.z);
      const BoreasV3 p2 = boreas_attach_place(a, l2.x, l2.y, l2.z);
      const BoreasV3 p3 = boreas_attach_place(a, l3.x, l3.y, l3.z);
      // A trunk standing apart moves the frame's origin to its base (boreas_tree_place).
      (void)boreas_tree_stand(
          &a, boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P0, j), scale));
      placed[0][jj] = p1.x;
      placed[1][jj] = p1.y;
      placed[2][jj] = p1.z;
      placed[3][jj] = p2.x;
      placed[4][jj] = p2.y;
      placed[5][jj] = p2.z;
      placed[6][jj] = p3.x;
      placed[7][jj] = p3.y;
      placed[8][jj] = p3.z;
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i, a.origin);
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
    }
    // 2. the wind at the placed tips (carried branches take none).
    if (!carry)
      native_wind_block(placed[6], placed[7], placed[8], m, wind.waves, wind.wave_count, wind.grid,
                        wind.g, wind_x, wind_y, wind_z, wind.interpolated);
      // 3. response, 4. hold, 5. bend, 6. store.
#pragma GCC ivdep
    for (int jj = 0; jj < m; ++jj) {
      const int i = base + jj;
      const int j = static_base + jj;
      const BoreasV3 p1 = boreas_v3(placed[0][jj], placed[1][jj], placed[2][jj]);
      const BoreasV3 p2 = boreas_v3(placed[3][jj], placed[4][jj], placed[5][jj]);
      const BoreasV3 p3 = boreas_v3(placed[6][jj], placed[7][jj], placed[8][jj]);
      const BoreasV3 f_in = boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_F, i);
      const BoreasV3 u_in = boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_DF, i);
      const float broken_in = motion_in[BOREAS_TREE_MOTION_BROKEN * n + i];
      float broken = broken_in;
      BoreasV3 bend = boreas_v3(0.0f, 0.0f, 0.0f), rate = boreas_v3(0.0f, 0.0f, 0.0f);
      if (!carry) {
        const BoreasV3 wind = boreas_v3(wind_x[jj], wind_y[jj], wind_z[jj]);
        const float vogel_b = shape[BOREAS_TREE_SHAPE_VOGEL_B * sn + j];
        const float vogel_inv_speed = shape[BOREAS_TREE_SHAPE_VOGEL_SPEED * sn + j];
        const float load = shape[BOREAS_TREE_SHAPE_LOAD * sn + j];
        const float drag = boreas_tree_drag(load) * scale;
        const BoreasV3 target =
            boreas_bend_target(wind, boreas_tree_compliance(load) * scale_root,
                               drag, vogel_b, vogel_inv_speed);
#define BOREAS_RESPONSE(plane) response[(plane) * sn + j]
        const BoreasV3 x = boreas_v3_sub(f_in, target);
        BoreasV3 x_next;
        boreas_damped_step(x, u_in, BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_A),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_B), BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_C),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_D),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_ALPHA_DT),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_OMEGA_DT),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_DT),
                           BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_OMEGA2_DT), wind,
                           (1.0f + shape[BOREAS_TREE_SHAPE_W2 * sn + j]) * drag, vogel_b,
                           vogel_inv_speed, &x_next, &rate);
#undef BOREAS_RESPONSE
        bend = boreas_v3_add(target, x_next);
        broken = boreas_break_flag(broken_in, bend, shape[BOREAS_TREE_SHAPE_BREAK * sn + j] * scale);
        const BoreasV3 hang = boreas_hang_bend(wind, shape[BOREAS_TREE_SHAPE_HANG * sn + j] / scale,
                                               vogel_b, vogel_inv_speed,
                                               BOREAS_TREE_HANG_REACH * scale);
        bend = boreas_v3_toward(bend, hang, broken);
        rate = boreas_v3_scale(rate, 1.0f - broken);
      }
      const float hb = h + (carry ? broken * (1.0f - h) : 0.0f);
      bend = boreas_v3_add(bend, boreas_v3_scale(boreas_v3_sub(f_in, bend), hb));
      rate = boreas_v3_add(rate, boreas_v3_scale(boreas_v3_sub(u_in, rate), h));
      boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_F, i, bend);
      boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_DF, i, rate);
      motion_out[BOREAS_TREE_MOTION_BROKEN * n + i] = broken;
      // A broken branch's first segment and O (stored by step 1) turn with it.
      const BoreasV3 p0 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P0, i);
      const BoreasV3 y = boreas_tree_load3(state, n, BOREAS_TREE_STATE_O, i);
      const BoreasV3 bent1 = boreas_bend_point(p0, boreas_v3_sub(p1, p0), bend);
      const BoreasV3 z = boreas_v3_cross(boreas_v3_normalize(boreas_v3_sub(p1, p0)), y);
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i,
                         boreas_v3_toward(y, boreas_orientation_across(y, z, boreas_v3_normalize(
                                                                                 boreas_v3_sub(bent1, p0))),
                                          broken));
      const BoreasV3 bent2 = boreas_bend_point(
          boreas_v3_toward(p1, bent1, broken), boreas_v3_sub(p2, p1),
          boreas_v3_scale(bend, shape[BOREAS_TREE_SHAPE_W2 * sn + j]));
      const BoreasV3 bent3 = boreas_bend_point(bent2, boreas_v3_sub(p3, p2), bend);
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, i, boreas_v3_toward(p1, bent1, broken));
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, i, bent2);
      boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, i, bent3);
    }
  }
}

void native_trees_step(NativeTrees& t, bool exact, double dt, const NativeTreeWind& wind) {
  native_tree_response(t, dt);
  const int next = 1 - t.current;
  float* state = t.state[next].data();
  const float* motion_in = t.motion[t.current].data();
  float* motion_out = t.motion[next].data();
  const float carry_hold = float(std::exp(-dt / impl::kCarryTimeConstant));
  auto pass = [&](const float* parent_state, int list, bool carry) {
    const std::vector<int32_t>& tiles = t.tiles[exact ? 1 : 0].list(list);
    native_tree_step(parent_state, state, t.parents.data(), t.shape.data(), t.response.data(),
                     motion_in, motion_out, t.n, t.n, tiles.data(),
                     int(tiles.size() / BOREAS_TILE_INTS), carry_hold, carry, wind);
  };
  // Every tree at full detail carries nothing; the carry lists are walked as the batch
  // does (tier by tier, parents from the state being written) all the same.
  if (!exact) pass(t.state[t.current].data(), impl::tree_step_list(0), false);
  for (int k = 0; k < impl::kMaxTreeTiers; ++k) {
    if (exact) pass(state, impl::tree_step_list(k), false);
    pass(state, impl::tree_carry_list(k, 1, 0), true);
  }
  t.current = next;
}

[[gnu::flatten]] void native_tree_deform(const float* state, int n, const float* radius, int sn,
                                         int first, int static_first, int count, float scale,
                                         int rings, int sides, float* out, int out_n,
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
      BoreasV3 o;
      const BoreasBezier c = boreas_tree_load_curve(state, n, i, &o);
      BoreasBranchRadius rp = boreas_tree_load_radius(radius, sn, static_first + b);
      rp.radius *= scale;
      // As the kernel: divisions, not products with the reciprocals (same rounding).
      const float grid_v = float(ring) / float(rings);
      const float v = boreas_ring_v(float(ring), rings, rp.tip_cap);  // round a tip cap
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
      out[(BOREAS_TREE_VERTEX_UV + 1) * out_n + w] = grid_v;
    }
  }
}

[[gnu::flatten]] void native_tree_leaves(const float* state, int n, const int32_t* leaves, int sm,
                                         int static_first, int count, int root, float petiole,
                                         float* out, int out_first) {
#pragma omp parallel for schedule(static)
  for (int start = 0; start < count; start += kBlock) {
    const int end = std::min(start + kBlock, count);
#pragma GCC ivdep
    for (int k = start; k < end; ++k) {
      const int j = static_first + k;
      const BoreasLeafPlace leaf = boreas_leaf_unpack(leaves[BOREAS_TREE_LEAF_PLACE * sm + j],
                                                      leaves[BOREAS_TREE_LEAF_TURN * sm + j]);
      BoreasV3 o;
      const BoreasBezier c = boreas_tree_load_curve(state, n, root + leaf.entry, &o);
      const BoreasAttachFrame a = boreas_attach(c, o, leaf.v, leaf.cos_theta, leaf.sin_theta,
                                                leaf.cos_alpha, leaf.sin_alpha);
      const BoreasV3 base = boreas_v3_madd(a.origin, a.x, petiole);
      const BoreasV3 normal = boreas_v3_lin2(a.y, leaf.cos_roll, a.z, leaf.sin_roll);
      float* r = out + size_t(out_first + k) * BOREAS_TREE_LEAF_OUT_PLANES;
      r[BOREAS_TREE_LEAF_OUT_POSITION + 0] = base.x;
      r[BOREAS_TREE_LEAF_OUT_POSITION + 1] = base.y;
      r[BOREAS_TREE_LEAF_OUT_POSITION + 2] = base.z;
      r[BOREAS_TREE_LEAF_OUT_AXIS + 0] = a.x.x;
      r[BOREAS_TREE_LEAF_OUT_AXIS + 1] = a.x.y;
      r[BOREAS_TREE_LEAF_OUT_AXIS + 2] = a.x.z;
      r[BOREAS_TREE_LEAF_OUT_NORMAL + 0] = normal.x;
      r[BOREAS_TREE_LEAF_OUT_NORMAL + 1] = normal.y;
      r[BOREAS_TREE_LEAF_OUT_NORMAL + 2] = normal.z;
    }
  }
}

}  // namespace boreas::bench
