/* boreas: the sway of imported trees (Kusternig sec. 5.2-5.3), per branch and per vertex,
 * for their kernels (mesh_tree_branches.cl, mesh_tree_vertices.cl) and the native
 * benchmark twins. Compiles as OpenCL C and as C/C++, at width 1 only: the kernels take
 * one item per work-item, which PoCL vectorizes across work-items. The double-precision
 * reference, written apart from this, is host/src/reference/mesh_tree_reference.cpp.
 * Scalar floats and no transcendental builtins, so that PoCL vectorizes the work-item loop
 * (shared/notes: pocl-performance).
 *
 * A vertex with weights w_k (already raised to the bend exponent) moves by
 *   sum_k w_k * L(W_k) * ( bend_k * W_k,perp / |W_k| + sway_k * (n0 * right_k + n1 * up_k) )
 * where branch k is the one animating level k, W_k the wind it feels, W_k,perp its part
 * normal to the branch, (n0, n1) the two noise channels at the branch's phase moved along
 * by its level's clock, and L the load: the tree's drag 1/2 rho C_d A |W|^2 R(|W|), Vogel's
 * reconfiguration R of its leafy share, normalized to 0.8 at 10 m/s
 * (mesh_trees/mesh_tree_drag.h). Displacing vertices (rather than rotating branches)
 * stretches limbs as the load grows: a storm's 40 m/s moves them about 7 times as far as
 * 10 m/s. */
#ifndef BOREAS_CL_SHARED_MESH_TREE_MATH_H
#define BOREAS_CL_SHARED_MESH_TREE_MATH_H

#include "shared/fast_math.h"
#include "shared/mesh_tree_types.h"
#include "shared/simd_width.h"

#ifndef __OPENCL_C_VERSION__
#include <stddef.h>
#endif

/* The vector in planes plane, plane + 1, plane + 2 (stride n) at index i. */
BOREAS_FN void boreas_mesh_tree_load3(BOREAS_GLOBAL const float* planes, int plane, int n, int i,
                                      float* x, float* y, float* z) {
  *x = planes[(plane + 0) * n + i];
  *y = planes[(plane + 1) * n + i];
  *z = planes[(plane + 2) * n + i];
}

/* ---- Branches (mesh_tree_branches.cl) -------------------------------------------------- */

/* Tree t's leaf noise moved by its stem's wind (sx, sz) m/s over dt s (frozen turbulence
 * carried downwind), kept in one tile so the float keeps its precision. */
BOREAS_FN void boreas_mesh_tree_roll(BOREAS_GLOBAL const float* trees, int nt, int t,
                                     BOREAS_GLOBAL const float* roll_in,
                                     BOREAS_GLOBAL float* roll_out, float sx, float sz, float dt) {
  float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + t];
  float u = roll_in[(BOREAS_MESH_TREE_ROLL + 0) * nt + t] + sx * dt * inv_tile;
  float v = roll_in[(BOREAS_MESH_TREE_ROLL + 1) * nt + t] + sz * dt * inv_tile;
  roll_out[(BOREAS_MESH_TREE_ROLL + 0) * nt + t] = u - BOREAS_FLOOR(u);
  roll_out[(BOREAS_MESH_TREE_ROLL + 1) * nt + t] = v - BOREAS_FLOOR(v);
}

/* ---- The sway of a vertex ------------------------------------------------------------- */

/* Tree t's load at squared speed s2, 0 in calm: DRAG s2 times Vogel's factor (fast_math.h's
 * polynomial exp2 and log2 on every device, so the host's twins, which include this header
 * without the device prelude, compute the same; exponent 0 gives 1 exactly). */
BOREAS_FN float boreas_mesh_tree_load(float s2, BOREAS_GLOBAL const float* trees, int nt, int t) {
  float speed = s2 * BOREAS_RSQRT(s2 + 1e-30f);
  float above = BOREAS_FMAX(speed * trees[BOREAS_MESH_TREE_TREE_VOGEL_SPEED * nt + t], 1.0f);
  float r = boreas_poly_exp2(trees[BOREAS_MESH_TREE_TREE_VOGEL_B * nt + t] * boreas_poly_log2(above));
  return trees[BOREAS_MESH_TREE_TREE_DRAG * nt + t] * s2 * r;
}

/* Branch b's own level's bend amplitude (m at weight 1, TREE_BEND + k of its tree t): the
 * lowest k with ANIMATED_BY + k b itself (a branch animates its own level and, for its
 * own vertices, the levels past it); 0 past level 3, whose branches animate no vertex. */
BOREAS_FN float boreas_mesh_tree_own_bend(BOREAS_GLOBAL const int* links, int nb, int b,
                                          BOREAS_GLOBAL const float* trees, int nt, int t) {
  float bend = 0.0f;
  for (int k = 3; k >= 0; --k)
    bend = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + k) * nb + b] == b
               ? trees[(BOREAS_MESH_TREE_TREE_BEND + k) * nt + t]
               : bend;
  return bend;
}

/* Branch b's wind after a step of dt s toward the wind (wx, wy, wz) m/s it feels now,
 * relative to the branch's own motion. The branch's tip moves by D = bend L(|W|) W_perp /
 * |W| (boreas_mesh_tree_level at weight 1), so as W changes it moves at dD/dt = J dW/dt:
 * across W, J = j = bend L / |W| (s); along W, (2 + b') j (L ~ |W|^(2 + b'), b' Vogel's
 * exponent above the reference speed, 0 below). The wind it feels is the wind less that
 * velocity, so tau dW/dt = wind - J dW/dt - W, i.e. (tau + J) dW/dt = wind - W: the air
 * lengthens its level's response time (aerodynamic damping: a branch moving through the
 * air is held back by it, most in strong wind, as L / |W| grows with |W|). Its parents'
 * motion, slower, is left out. Backward Euler with J at the step's start, along and across
 * W: W += dt / (tau + J + dt) (wind - W), stable for any dt and never overshooting, without
 * exp; a steady wind's rest is the wind itself. A tree's first step starts at the wind, so
 * a tree placed in a steady wind does not swing. Read from state_in, written to state_out
 * and to (sx, sy, sz). */
BOREAS_FN void boreas_mesh_tree_follow(BOREAS_GLOBAL const float* branches,
                                       BOREAS_GLOBAL const int* links, int nb, int b,
                                       BOREAS_GLOBAL const float* trees, int nt, int t,
                                       BOREAS_GLOBAL const float* state_in,
                                       BOREAS_GLOBAL float* state_out, float dt, float wx, float wy,
                                       float wz, float* sx, float* sy, float* sz) {
  float x, y, z;
  boreas_mesh_tree_load3(state_in, BOREAS_MESH_TREE_STATE_WIND, nb, b, &x, &y, &z);
  float s2 = x * x + y * y + z * z;
  float inv_s = BOREAS_RSQRT(s2 + 1e-12f);
  float j = boreas_mesh_tree_own_bend(links, nb, b, trees, nt, t) *
            boreas_mesh_tree_load(s2, trees, nt, t) * inv_s;
  float above = s2 * inv_s * trees[BOREAS_MESH_TREE_TREE_VOGEL_SPEED * nt + t] > 1.0f
                    ? trees[BOREAS_MESH_TREE_TREE_VOGEL_B * nt + t]
                    : 0.0f;
  float tau = branches[BOREAS_MESH_TREE_BRANCH_TAU * nb + b];
  int fresh = trees[BOREAS_MESH_TREE_TREE_FRESH * nt + t] != 0.0f;
  float k_across = fresh ? 1.0f : dt / (tau + j + dt);
  float k_along = fresh ? 1.0f : dt / (tau + (2.0f + above) * j + dt);
  /* the change toward the wind, split along W (e) and across it */
  float dx = wx - x, dy = wy - y, dz = wz - z;
  float ex = x * inv_s, ey = y * inv_s, ez = z * inv_s;
  float along = (dx * ex + dy * ey + dz * ez) * (k_along - k_across);
  x = BOREAS_FMA(k_across, dx, BOREAS_FMA(along, ex, x));
  y = BOREAS_FMA(k_across, dy, BOREAS_FMA(along, ey, y));
  z = BOREAS_FMA(k_across, dz, BOREAS_FMA(along, ez, z));
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b] = x;
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b] = y;
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b] = z;
  *sx = x;
  *sy = y;
  *sz = z;
}

/* Bilinear lookup with wrap-around in one tree's noise (both channels), u and v in tiles;
 * texel i covers [i, i+1) / size and holds the value at its center (noise_texture.h). */
BOREAS_FN void boreas_mesh_tree_noise(BOREAS_GLOBAL const float* noise, float u, float v, float* n0,
                                      float* n1) {
  const int size = BOREAS_MESH_TREE_NOISE_SIZE;
  float x = (u - BOREAS_FLOOR(u)) * (float)size - 0.5f;
  float y = (v - BOREAS_FLOOR(v)) * (float)size - 0.5f;
  float x0 = BOREAS_FLOOR(x);
  float y0 = BOREAS_FLOOR(y);
  float fx = x - x0;
  float fy = y - y0;
  int i0 = ((int)x0) & (size - 1);
  int j0 = ((int)y0) & (size - 1);
  int i1 = (i0 + 1) & (size - 1);
  int j1 = (j0 + 1) & (size - 1);
  int a = j0 * size + i0, b = j0 * size + i1, c = j1 * size + i0, d = j1 * size + i1;
  float w00 = (1.0f - fx) * (1.0f - fy), w10 = fx * (1.0f - fy), w01 = (1.0f - fx) * fy,
        w11 = fx * fy;
  BOREAS_GLOBAL const float* second = noise + size * size;
  *n0 = w00 * noise[a] + w10 * noise[b] + w01 * noise[c] + w11 * noise[d];
  *n1 = w00 * second[a] + w10 * second[b] + w01 * second[c] + w11 * second[d];
}

/* One level's term for a vertex of weight w animated by branch a of tree t. */
BOREAS_FN void boreas_mesh_tree_level(int k, float w, int a, int t,
                                      BOREAS_GLOBAL const float* branches, int nb,
                                      BOREAS_GLOBAL const float* state,
                                      BOREAS_GLOBAL const float* trees, int nt,
                                      BOREAS_GLOBAL const float* noise, float* dx, float* dy,
                                      float* dz) {
  float wx, wy, wz;
  boreas_mesh_tree_load3(state, BOREAS_MESH_TREE_STATE_WIND, nb, a, &wx, &wy, &wz);
  float ax, ay, az;
  boreas_mesh_tree_load3(branches, BOREAS_MESH_TREE_BRANCH_AXIS, nb, a, &ax, &ay, &az);
  float s2 = wx * wx + wy * wy + wz * wz;
  float load = w * boreas_mesh_tree_load(s2, trees, nt, t);
  float along = wx * ax + wy * ay + wz * az;
  float bend = load * trees[(BOREAS_MESH_TREE_TREE_BEND + k) * nt + t] * BOREAS_RSQRT(s2 + 1e-12f);
  float sway = load * trees[(BOREAS_MESH_TREE_TREE_SWAY + k) * nt + t];
  float n0, n1;
  boreas_mesh_tree_noise(
      noise + (size_t)t * 2 * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE,
      branches[BOREAS_MESH_TREE_BRANCH_PHASE * nb + a] +
          trees[(BOREAS_MESH_TREE_TREE_CLOCK + k) * nt + t],
      branches[(BOREAS_MESH_TREE_BRANCH_PHASE + 1) * nb + a], &n0, &n1);
  float r = sway * n0, u = sway * n1;
  *dx += bend * (wx - along * ax) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 0) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 0) * nb + a];
  *dy += bend * (wy - along * ay) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 1) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 1) * nb + a];
  *dz += bend * (wz - along * az) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 2) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 2) * nb + a];
}

/* The displacement of a point with weights w[0..3] on branch b (all four levels, summed in
 * that order from 0; written out, not looped: GCC vectorizes no vertex loop of the native
 * twins with a loop left inside). */
BOREAS_FN void boreas_mesh_tree_displacement(float w0, float w1, float w2, float w3, int b,
                                             BOREAS_GLOBAL const float* branches,
                                             BOREAS_GLOBAL const int* links, int nb,
                                             BOREAS_GLOBAL const float* state,
                                             BOREAS_GLOBAL const float* trees, int nt,
                                             BOREAS_GLOBAL const float* noise, float* dx, float* dy,
                                             float* dz) {
  int t = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  *dx = 0.0f;
  *dy = 0.0f;
  *dz = 0.0f;
  boreas_mesh_tree_level(0, w0, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 0) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(1, w1, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 1) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(2, w2, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 2) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(3, w3, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 3) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
}

/* ---- Trunk vertices (boreas_mesh_tree_trunk) ------------------------------------------ */

/* Trunk vertex i's record: its rest position moved by (dx, dy, dz), 3 floats (the normals
 * stay the rest normals: the sway is smooth along a branch, and re-deriving normals would
 * need the neighbours). Value k of the record goes to out[record * size + k * stride]:
 * records side by side (size 3, stride 1: the kernel's output) or in planes (size 1). */
BOREAS_FN void boreas_mesh_tree_trunk_vertex(BOREAS_GLOBAL const float* vertices, int nv, int i,
                                             float dx, float dy, float dz, BOREAS_GLOBAL float* out,
                                             int record, int size, int stride) {
  out[record * size + 0 * stride] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 0) * nv + i] + dx;
  out[record * size + 1 * stride] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 1) * nv + i] + dy;
  out[record * size + 2 * stride] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 2) * nv + i] + dz;
}

/* ---- Leaves (boreas_mesh_tree_leaves) ------------------------------------------------- */

/* A leaf turns rigidly about its petiole by the rotation taking its axis a to
 * a' = normalize((1 - f) a + f W/|W|), with f = turn * L / (1 + L) (a fraction of the way
 * into the wind that grows with the load and never reaches it);
 * R v = c v + k x v + k (k.v) / (1 + c), k = a x a', c = a.a' (Rodrigues without the
 * angle: no trigonometry). In calm f is 0 and the rotation exactly the identity (a' = a
 * up to rounding). */
typedef struct BoreasMeshTreeTurn {
  float ux, uy, uz; /* W / |W|, the wind's direction */
  float load;       /* L(W) */
  float kx, ky, kz; /* k = a x a' (0 in calm) */
  float c;          /* c = a . a' (1 in calm) */
  float h;          /* 1 / (1 + c), kept finite */
} BoreasMeshTreeTurn;

/* The turn of leaf l on branch b (whose wind is in state) of tree t, into *r. (Written
 * through a pointer, not returned: an inlined struct return leaves alias scopes behind
 * that change PoCL's code for the kernel.) */
BOREAS_FN void boreas_mesh_tree_leaf_turn(BOREAS_GLOBAL const float* state, int nb, int b,
                                          BOREAS_GLOBAL const float* leaves, int nl, int l,
                                          BOREAS_GLOBAL const float* trees, int nt, int t,
                                          BoreasMeshTreeTurn* r) {
  float wx, wy, wz;
  boreas_mesh_tree_load3(state, BOREAS_MESH_TREE_STATE_WIND, nb, b, &wx, &wy, &wz);
  float s2 = wx * wx + wy * wy + wz * wz;
  r->load = boreas_mesh_tree_load(s2, trees, nt, t);
  float inv_s = BOREAS_RSQRT(s2 + 1e-12f);
  r->ux = wx * inv_s;
  r->uy = wy * inv_s;
  r->uz = wz * inv_s;

  float ax, ay, az;

  boreas_mesh_tree_load3(leaves, BOREAS_MESH_TREE_LEAF_AXIS, nl, l, &ax, &ay, &az);
  float f = trees[BOREAS_MESH_TREE_TREE_TURN * nt + t] * r->load / (1.0f + r->load);
  float px = BOREAS_FMA(f, r->ux - ax, ax), py = BOREAS_FMA(f, r->uy - ay, ay),
        pz = BOREAS_FMA(f, r->uz - az, az);
  float inv_p = BOREAS_RSQRT(px * px + py * py + pz * pz + 1e-12f);
  px *= inv_p;
  py *= inv_p;
  pz *= inv_p;
  float kx = ay * pz - az * py, ky = az * px - ax * pz, kz = ax * py - ay * px;
  float c = ax * px + ay * py + az * pz;
  int still = f == 0.0f;
  r->kx = still ? 0.0f : kx;
  r->ky = still ? 0.0f : ky;
  r->kz = still ? 0.0f : kz;
  r->c = still ? 1.0f : c;
  r->h = 1.0f / BOREAS_FMAX(1.0f + r->c, 1e-4f);
}

/* Leaf vertex i's record, of leaf l on a branch of tree t: its rest position moved by the
 * displacement (dx, dy, dz) of the leaf's petiole and by the turn r about the petiole,
 * then by the rolling noise in the wind direction and up, scaled by its distance from the
 * petiole (so gusts run through the crown as the noise moves downwind); and its normal
 * turned. 6 floats, position then normal, at out[record * size + k * stride] as for
 * boreas_mesh_tree_trunk_vertex. */
BOREAS_FN void boreas_mesh_tree_leaf_vertex(
    const BoreasMeshTreeTurn* r, float dx, float dy, float dz, BOREAS_GLOBAL const float* vertices,
    int nv, int i, BOREAS_GLOBAL const float* leaves, int nl, int l,
    BOREAS_GLOBAL const float* trees, int nt, int t, BOREAS_GLOBAL const float* roll,
    BOREAS_GLOBAL const float* noise, BOREAS_GLOBAL float* out, int record, int size, int stride) {
  float petx, pety, petz;
  boreas_mesh_tree_load3(leaves, BOREAS_MESH_TREE_LEAF_PETIOLE, nl, l, &petx, &pety, &petz);
  float rx, ry, rz;
  boreas_mesh_tree_load3(vertices, BOREAS_MESH_TREE_LEAF_VERTEX_REST, nv, i, &rx, &ry, &rz);
  float ox = rx - petx, oy = ry - pety, oz = rz - petz;
  /* R o - o, added to the rest position (not R o to the petiole): in calm it is exactly
   * 0, so a leaf at rest stays bit for bit where it was. */
  float kx = r->kx, ky = r->ky, kz = r->kz, c = r->c, h = r->h;
  float ko = kx * ox + ky * oy + kz * oz;
  float cm1 = c - 1.0f;
  float qx = cm1 * ox + (ky * oz - kz * oy) + kx * ko * h;
  float qy = cm1 * oy + (kz * ox - kx * oz) + ky * ko * h;
  float qz = cm1 * oz + (kx * oy - ky * ox) + kz * ko * h;
  float nx, ny, nz;
  boreas_mesh_tree_load3(vertices, BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL, nv, i, &nx, &ny, &nz);
  float kn = kx * nx + ky * ny + kz * nz;
  float mx = c * nx + (ky * nz - kz * ny) + kx * kn * h;
  float my = c * ny + (kz * nx - kx * nz) + ky * kn * h;
  float mz = c * nz + (kx * ny - ky * nx) + kz * kn * h;

  float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + t];
  float n0, n1;
  boreas_mesh_tree_noise(
      noise + (size_t)t * 2 * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE,
      rx * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 0) * nt + t],
      rz * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 1) * nt + t], &n0, &n1);
  float flutter = trees[BOREAS_MESH_TREE_TREE_FLUTTER * nt + t] * r->load *
                  vertices[BOREAS_MESH_TREE_LEAF_VERTEX_TIP * nv + i];
  out[record * size + 0 * stride] = rx + (dx + qx + flutter * n0 * r->ux);
  out[record * size + 1 * stride] = ry + (dy + qy + flutter * (n0 * r->uy + n1));
  out[record * size + 2 * stride] = rz + (dz + qz + flutter * n0 * r->uz);
  out[record * size + 3 * stride] = mx;
  out[record * size + 4 * stride] = my;
  out[record * size + 5 * stride] = mz;
}

#endif
