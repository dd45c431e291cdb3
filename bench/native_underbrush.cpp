// boreas: the native twins of the underbrush kernels, built with -O3 -march=native -fopenmp
// (see bench/CMakeLists.txt). The per-component math is cl/shared/underbrush_math.h itself
// (its C++ build, polynomials on), so the twins differ from the kernels only by rounding
// order. Loops are shaped so that GCC vectorizes each SIMD one (checked with
// -fopt-info-vec-missed), the way native_trees.cpp's are: `#pragma GCC ivdep` rather than
// `omp simd` (the header's out-parameters and struct returns become per-lane "simd arrays"
// under omp simd), [[gnu::flatten]] so that no header function stays a call, and the
// kernels' loops over colliders, impulses and joints turned inside out: each runs outside
// a SIMD loop over a block of components, whose partial results wait in block arrays.
#include "native_underbrush.h"

#include <algorithm>

#include "native_wind.h"

#define BOREAS_FAST_MATH 1
#include "shared/underbrush_math.h"

namespace boreas::bench {

namespace {

// Components per block: a block's centers of mass go through native_wind_block together.
constexpr int kBlock = kNativeWindBlock;
constexpr int kJoints = BOREAS_UB_JOINTS;
constexpr int kStrip = 2 * BOREAS_UB_JOINTS;  // vertices per component

}  // namespace

[[gnu::flatten]] void native_underbrush_step(const NativeMeadowPlanes& m, const float* state_in,
                                             float* state_out, float dt, float gravity,
                                             const NativeTreeWind& wind,
                                             const BoreasGpuCollider* colliders, int collider_count,
                                             const BoreasGpuImpulse* impulses, int impulse_count) {
  const int n = m.n;
  const float* frame = m.frame;
  const int32_t* index = m.index;
  const BoreasGpuPart* parts = m.parts;
  const float* tables = m.tables;
#pragma omp parallel for schedule(static)
  for (int start = 0; start < n; start += kBlock) {
    const int count = std::min(kBlock, n - start);
    // 1. the base, and X carried along by its move since the last step.
    alignas(64) float base_x[kBlock], base_y[kBlock], base_z[kBlock];
    alignas(64) float x_x[kBlock], x_y[kBlock], x_z[kBlock];
#pragma GCC ivdep
    for (int j = 0; j < count; ++j) {
      const int i = start + j;
      const BoreasV3 base =
          boreas_ub_base(frame, state_in, n, i,
                         i - boreas_ub_link_back(index[BOREAS_UB_INDEX_LINK * n + i]));
      const BoreasV3 moved =
          boreas_v3_sub(base, boreas_tree_load3(state_in, n, BOREAS_UB_STATE_BASE, i));
      const BoreasV3 x = boreas_v3_add(boreas_tree_load3(state_in, n, BOREAS_UB_STATE_X, i), moved);
      base_x[j] = base.x, base_y[j] = base.y, base_z[j] = base.z;
      x_x[j] = x.x, x_y[j] = x.y, x_z[j] = x.z;
    }
    // 2. the wind at the block's centers of mass.
    alignas(64) float wind_x[kBlock], wind_y[kBlock], wind_z[kBlock];
    native_wind_block(x_x, x_y, x_z, count, wind.waves, wind.wave_count, wind.grid, wind.g, wind_x,
                      wind_y, wind_z, wind.interpolated);
    // The load per unit mass (gravity and drag, then each collider's push in turn) and the
    // velocity (then each impulse's kick in turn).
    alignas(64) float load_x[kBlock], load_y[kBlock], load_z[kBlock];
    alignas(64) float vel_x[kBlock], vel_y[kBlock], vel_z[kBlock];
    alignas(64) float reach[kBlock], push[kBlock], inv_mass[kBlock], crushed[kBlock],
        wind_load[kBlock];
#pragma GCC ivdep
    for (int j = 0; j < count; ++j) {
      const int i = start + j;
      const int p = boreas_ub_link_part(index[BOREAS_UB_INDEX_LINK * n + i]);
      const float im = parts[p].inv_mass;
      const BoreasV3 w = boreas_v3(wind_x[j], wind_y[j], wind_z[j]);
      const float drag = parts[p].drag_area * im * boreas_v3_length(w);
      load_x[j] = w.x * drag;
      load_y[j] = w.y * drag - gravity;
      load_z[j] = w.z * drag;
      wind_load[j] = drag * boreas_v3_length(w);
      crushed[j] = 0.0f;
      const float scale = boreas_ub_unpack_scale(index[BOREAS_UB_INDEX_TURN * n + i]);
      reach[j] = parts[p].reach * scale;
      push[j] = parts[p].collider_push;
      inv_mass[j] = boreas_ub_inv_mass(im, scale);
      vel_x[j] = state_in[BOREAS_UB_STATE_V * n + i];
      vel_y[j] = state_in[(BOREAS_UB_STATE_V + 1) * n + i];
      vel_z[j] = state_in[(BOREAS_UB_STATE_V + 2) * n + i];
    }
    for (int c = 0; c < collider_count; ++c) {
      const BoreasGpuCollider* body = colliders + c;
#pragma GCC ivdep
      for (int j = 0; j < count; ++j) {
        const BoreasV3 x = boreas_v3(x_x[j], x_y[j], x_z[j]);
        const BoreasV3 base = boreas_v3(base_x[j], base_y[j], base_z[j]);
        boreas_ub_add_collider_push(x, base, body, reach[j], push[j], &load_x[j], &load_y[j],
                                    &load_z[j], &crushed[j]);
      }
    }
    for (int k = 0; k < impulse_count; ++k) {
      const BoreasGpuImpulse kick = impulses[k];
      const BoreasV3 jolt = boreas_v3(kick.jx, kick.jy, kick.jz);
#pragma GCC ivdep
      for (int j = 0; j < count; ++j) {
        const BoreasV3 x = boreas_v3(x_x[j], x_y[j], x_z[j]);
        boreas_ub_add_impulse(x, kick.x, kick.y, kick.z, kick.radius, jolt, inv_mass[j], &vel_x[j],
                              &vel_y[j], &vel_z[j]);
      }
    }
    // 3. breaking, 4. the equilibrium, 6. the constraint, 7. within reach; store.
#pragma GCC ivdep
    for (int j = 0; j < count; ++j) {
      const int i = start + j;
      const int p = boreas_ub_link_part(index[BOREAS_UB_INDEX_LINK * n + i]);
      const BoreasGpuPart& part = parts[p];
      const BoreasV3 base = boreas_v3(base_x[j], base_y[j], base_z[j]);
      const int turn = index[BOREAS_UB_INDEX_TURN * n + i];
      const BoreasV3 e_u = boreas_ub_unpack_axis(index[BOREAS_UB_INDEX_AXIS * n + i]);
      const BoreasV3 e_w = boreas_ub_unpack_side(e_u, turn);
      const float scale = boreas_ub_unpack_scale(turn);
      BoreasV3 x = boreas_v3(x_x[j], x_y[j], x_z[j]);
      BoreasV3 v = boreas_v3(vel_x[j], vel_y[j], vel_z[j]);
      const BoreasV3 load = boreas_v3(load_x[j], load_y[j], load_z[j]);
      const BoreasUbPlane plane = boreas_ub_plane(load, e_u, e_w);
      const float norm = boreas_v3_length(load);
      const float theta = boreas_ub_angle(plane.par, plane.perp);
      float joint;
      const float break_load = boreas_ub_break_load(tables, part.breaking, part.angles, theta,
                                                    &joint);
      const float broken_before = state_in[BOREAS_UB_STATE_BROKEN * n + i];
      const float broken =
          boreas_ub_broken_at(break_load, joint, boreas_ub_break_norm(norm, scale), broken_before);
      const int state = int(broken);
      BoreasV3 x0 = boreas_ub_equilibrium(tables, part.forward + state * part.forward_size,
                                          part.angles, part.norms, part.a_ref, part.q_max, base,
                                          e_u, plane, theta, norm, scale);
      const float flat = state_in[BOREAS_UB_STATE_FLAT * n + i];
      x0 = boreas_ub_flatten(x0, x, base, e_w, reach[j], flat);
      const BoreasV3 wind = boreas_v3(wind_x[j], wind_y[j], wind_z[j]);
      const BoreasV3 v_base = boreas_v3_scale(
          boreas_v3_sub(base, boreas_tree_load3(state_in, n, BOREAS_UB_STATE_BASE, i)), 1.0f / dt);
      boreas_ub_air_step(&x, &v, x0, wind, v_base, part.drag_area * part.inv_mass * part.air_coupling,
                         boreas_ub_tau(part.tau, scale), dt);
      boreas_ub_keep_within_reach(&x, &v, base, reach[j]);
      boreas_tree_store3(state_out, n, BOREAS_UB_STATE_X, i, x);
      boreas_tree_store3(state_out, n, BOREAS_UB_STATE_V, i, v);
      state_out[BOREAS_UB_STATE_BROKEN * n + i] = broken;
      boreas_tree_store3(state_out, n, BOREAS_UB_STATE_BASE, i, base);
      state_out[BOREAS_UB_STATE_FLAT * n + i] =
          boreas_ub_flat_next(flat, part.recovery_loss, crushed[j], broken_before, broken,
                              wind_load[j], break_load);
    }
  }
}

[[gnu::flatten]] void native_underbrush_vertices(const NativeMeadowPlanes& m, const float* state,
                                                 const float camera[3], const float lod[3],
                                                 float* out, int32_t* counts) {
  const int n = m.n;
  const int32_t* index = m.index;
  const BoreasGpuPart* parts = m.parts;
  const float* tables = m.tables;
  const BoreasV3 cam = boreas_v3(camera[0], camera[1], camera[2]);
  const float lod0 = lod[0], lod1 = lod[1], lod2 = lod[2];
#pragma omp parallel for schedule(static)
  for (int start = 0; start < n; start += kBlock) {
    const int count = std::min(kBlock, n - start);
    // Per component: its base, bend plane (e_u, e_v), the axis across the blade, the
    // inverse table's cell and where its tables start, its LOD's joint step.
    alignas(64) float base_x[kBlock], base_y[kBlock], base_z[kBlock];
    alignas(64) float eu_x[kBlock], eu_y[kBlock], eu_z[kBlock];
    alignas(64) float ev_x[kBlock], ev_y[kBlock], ev_z[kBlock];
    alignas(64) float across_x[kBlock], across_y[kBlock], across_z[kBlock];
    alignas(64) float scales[kBlock], psi_w[kBlock], rho_w[kBlock];
    alignas(64) int psi_i[kBlock], rho_i[kBlock], rho_counts[kBlock];
    alignas(64) int inverse_at[kBlock], widths_at[kBlock], steps[kBlock], sections[kBlock];
#pragma GCC ivdep
    for (int j = 0; j < count; ++j) {
      const int i = start + j;
      const int p = boreas_ub_link_part(index[BOREAS_UB_INDEX_LINK * n + i]);
      const BoreasGpuPart& part = parts[p];
      const BoreasV3 base = boreas_tree_load3(state, n, BOREAS_UB_STATE_BASE, i);
      const int turn = index[BOREAS_UB_INDEX_TURN * n + i];
      const BoreasV3 e_u = boreas_ub_unpack_axis(index[BOREAS_UB_INDEX_AXIS * n + i]);
      const BoreasV3 e_w = boreas_ub_unpack_side(e_u, turn);
      const float scale = boreas_ub_unpack_scale(turn);
      const BoreasV3 x = boreas_tree_load3(state, n, BOREAS_UB_STATE_X, i);
      const int broken = int(state[BOREAS_UB_STATE_BROKEN * n + i]);
      const int s = part.sections;
      const BoreasUbPlane plane = boreas_ub_plane(boreas_v3_sub(x, base), e_u, e_w);
      BoreasUbCell psi, rho;
      boreas_ub_shape_cell(plane.par, plane.perp, part.reach * scale, part.psi_count,
                           part.rho_count, part.rho_min, &psi, &rho);
      const BoreasV3 across = boreas_v3_cross(e_u, plane.e_v);
      const float dist = boreas_v3_length(boreas_v3_sub(base, cam));
      const int level = (dist > lod0 ? 1 : 0) + (dist > lod1 ? 1 : 0) + (dist > lod2 ? 1 : 0);
      // The kernel's level == 0, 1, 2 chain, written so that GCC does not turn it into a
      // switch (control flow: the loop would stay scalar); levels 2 and 3 draw 2 and 0.
      const int used = level < 2 ? (level == 0 ? s + 1 : (s + 1) / 2 + 1) : 2 * (3 - level);
      counts[i] = 2 * used;
      steps[j] = level == 0 ? 1 : (level == 1 ? 2 : s);
      sections[j] = s;
      base_x[j] = base.x, base_y[j] = base.y, base_z[j] = base.z;
      eu_x[j] = e_u.x, eu_y[j] = e_u.y, eu_z[j] = e_u.z;
      ev_x[j] = plane.e_v.x, ev_y[j] = plane.e_v.y, ev_z[j] = plane.e_v.z;
      across_x[j] = across.x, across_y[j] = across.y, across_z[j] = across.z;
      scales[j] = scale;
      psi_i[j] = psi.index, psi_w[j] = psi.weight;
      rho_i[j] = rho.index, rho_w[j] = rho.weight;
      rho_counts[j] = part.rho_count;
      inverse_at[j] = part.inverse + broken * part.inverse_size;
      widths_at[j] = part.widths;
    }
    // The joints, one joint of every component at a time.
    alignas(64) float joint_x[kJoints][kBlock], joint_y[kJoints][kBlock], joint_z[kJoints][kBlock];
    alignas(64) float half_width[kJoints][kBlock], along[kJoints][kBlock];
    for (int k = 0; k < kJoints; ++k) {
#pragma GCC ivdep
      for (int j = 0; j < count; ++j) {
        const int at = std::min(k * steps[j], sections[j]);
        BoreasUbCell psi, rho;
        psi.index = psi_i[j], psi.weight = psi_w[j];
        rho.index = rho_i[j], rho.weight = rho_w[j];
        float u, v;
        boreas_ub_shape_joint(tables, inverse_at[j], rho_counts[j], psi, rho, at, &u, &v);
        const BoreasV3 joint = boreas_v3_lin3(boreas_v3(base_x[j], base_y[j], base_z[j]), 1.0f,
                                              boreas_v3(eu_x[j], eu_y[j], eu_z[j]), u * scales[j],
                                              boreas_v3(ev_x[j], ev_y[j], ev_z[j]), v * scales[j]);
        joint_x[k][j] = joint.x, joint_y[k][j] = joint.y, joint_z[k][j] = joint.z;
        half_width[k][j] = tables[widths_at[j] + at] * scales[j];
        along[k][j] = float(at) / float(sections[j]);
      }
    }
    // The strip: two vertices per joint.
    for (int k = 0; k < kJoints; ++k) {
      const int next_k = k < kJoints - 1 ? k + 1 : k;
      const int prev_k = k > 0 ? k - 1 : k;
#pragma GCC ivdep
      for (int j = 0; j < count; ++j) {
        const BoreasV3 joint = boreas_v3(joint_x[k][j], joint_y[k][j], joint_z[k][j]);
        const BoreasV3 next = boreas_v3(joint_x[next_k][j], joint_y[next_k][j], joint_z[next_k][j]);
        const BoreasV3 prev = boreas_v3(joint_x[prev_k][j], joint_y[prev_k][j], joint_z[prev_k][j]);
        const BoreasV3 across = boreas_v3(across_x[j], across_y[j], across_z[j]);
        BoreasV3 t = boreas_v3_sub(next, prev);
        t = boreas_v3_dot(t, t) > 0.0f ? t : boreas_v3_sub(joint, prev);
        const BoreasV3 nrm = boreas_v3_normalize(boreas_v3_cross(t, across));
        const BoreasV3 left = boreas_v3_madd(joint, across, -half_width[k][j]);
        const BoreasV3 right = boreas_v3_madd(joint, across, half_width[k][j]);
        float* o = out + (size_t(start + j) * kStrip + 2 * k) * 8;
        o[0] = left.x, o[1] = left.y, o[2] = left.z;
        o[3] = nrm.x, o[4] = nrm.y, o[5] = nrm.z;
        o[6] = 0.0f, o[7] = along[k][j];
        o[8] = right.x, o[9] = right.y, o[10] = right.z;
        o[11] = nrm.x, o[12] = nrm.y, o[13] = nrm.z;
        o[14] = 1.0f, o[15] = along[k][j];
      }
    }
  }
}

}  // namespace boreas::bench
