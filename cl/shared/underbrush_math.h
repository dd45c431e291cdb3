/* boreas: the math of an underbrush component's step and shape (Endo et al. 2003 sec.
 * 3.1, 4.2-4.3), compiled as OpenCL C (underbrush_step.cl, underbrush_vertices.cl) and as
 * C/C++ (the host's rest placement, the tests' float path and the native benchmark twin).
 *
 * A component is a point mass at its center of mass X, fixed at its base. The precomputed
 * tables (host/src/underbrush/shape_table.h) give, for the load on it (gravity plus wind
 * plus colliders, per unit mass), the equilibrium X0 (forward table) and, for any X, the
 * shape whose center of mass is X (inverse table). Everything is expressed in the
 * component's bend plane: u along its unloaded axis e_u, v along the in-plane direction
 * e_v of the load (or of X), so the tables are two-dimensional.
 *
 * Scalar float arithmetic on small value structs only, for PoCL's work-item vectorizer
 * (see cl/shared/tree_math.h); no transcendental builtins: angles come from square roots
 * and a short series.
 */
#ifndef BOREAS_CL_SHARED_UNDERBRUSH_MATH_H
#define BOREAS_CL_SHARED_UNDERBRUSH_MATH_H

#include "shared/tree_state.h"
#include "shared/underbrush_types.h"

#ifdef __OPENCL_C_VERSION__
#define BOREAS_UB_IMIN(a, b) min((a), (b))
#define BOREAS_UB_IMAX(a, b) max((a), (b))
#else
#define BOREAS_UB_IMIN(a, b) ((a) < (b) ? (a) : (b))
#define BOREAS_UB_IMAX(a, b) ((a) > (b) ? (a) : (b))
#endif

#define BOREAS_UB_PI 3.14159265358979324f
/* Share of the load's size added along e_w, so the bend plane is defined when the load
 * runs along the axis (an upright blade under gravity alone). It tilts the plane by at
 * most 1e-3 rad otherwise. */
#define BOREAS_UB_SIDE_BIAS 1e-3f

/* atan(x) for 0 <= x <= tan(pi/8): Taylor to x^15 (truncation < 2e-8). */
BOREAS_TM_FN float boreas_ub_atan_small(float x) {
  float s = x * x;
  float p = -1.0f / 15.0f;
  p = p * s + 1.0f / 13.0f;
  p = p * s - 1.0f / 11.0f;
  p = p * s + 1.0f / 9.0f;
  p = p * s - 1.0f / 7.0f;
  p = p * s + 1.0f / 5.0f;
  p = p * s - 1.0f / 3.0f;
  p = p * s + 1.0f;
  return x * p;
}

/* The angle in [0, pi] of the plane vector (par, perp), perp >= 0, from +par. Halving it
 * twice with square roots brings tan of the angle into [0, 1], once more into
 * [0, tan(pi/8)], where the series converges fast: no compares, no atan builtin. */
BOREAS_TM_FN float boreas_ub_angle(float par, float perp) {
  float r = BOREAS_TM_SQRT(par * par + perp * perp);
  float h = par + r; /* (h, perp) points at half the angle */
  float rh = BOREAS_TM_SQRT(h * h + perp * perp);
  float t = perp / (rh + h + 1e-30f); /* tan of a quarter of the angle, in [0, 1] */
  float t8 = t / (1.0f + BOREAS_TM_SQRT(1.0f + t * t)); /* tan of an eighth */
  return 8.0f * boreas_ub_atan_small(t8);
}

/* The bend plane of vector a in component frame (e_u, e_w): its component along e_u, the
 * size of the rest, and the unit in-plane direction e_v (biased toward e_w; see
 * BOREAS_UB_SIDE_BIAS). */
typedef struct BoreasUbPlane {
  float par, perp;
  BoreasV3 e_v;
} BoreasUbPlane;

BOREAS_TM_FN BoreasUbPlane boreas_ub_plane(BoreasV3 a, BoreasV3 e_u, BoreasV3 e_w) {
  BoreasUbPlane p;
  p.par = boreas_v3_dot(a, e_u);
  float size = boreas_v3_length(a);
  BoreasV3 side = boreas_v3_lin3(a, 1.0f, e_u, -p.par, e_w, BOREAS_UB_SIDE_BIAS * size);
  p.perp = boreas_v3_length(side);
  p.e_v = boreas_v3_scale(side, 1.0f / (p.perp + 1e-30f));
  return p;
}

/* Bilinear lookup position along one table axis: the cell's first index in [0, count-2]
 * and the weight of the next, clamped to the table. */
typedef struct BoreasUbCell {
  int index;
  float weight;
} BoreasUbCell;

BOREAS_TM_FN BoreasUbCell boreas_ub_cell(float position, int count) {
  float top = (float)(count - 1);
  float p = position < 0.0f ? 0.0f : position;
  p = p > top ? top : p;
  BoreasUbCell c;
  c.index = BOREAS_UB_IMIN((int)p, count - 2);
  c.weight = p - (float)c.index;
  return c;
}

/* Bilinear (u, v) from a table of pairs laid out [row][column]. */
BOREAS_TM_FN void boreas_ub_bilinear2(BOREAS_TS_GLOBAL const float* table, int columns, BoreasUbCell row,
                                      BoreasUbCell col, float* u, float* v) {
  int a = (row.index * columns + col.index) * 2;
  int b = a + columns * 2;
  float w00 = (1.0f - row.weight) * (1.0f - col.weight);
  float w01 = (1.0f - row.weight) * col.weight;
  float w10 = row.weight * (1.0f - col.weight);
  float w11 = row.weight * col.weight;
  *u = table[a] * w00 + table[a + 2] * w01 + table[b] * w10 + table[b + 2] * w11;
  *v = table[a + 1] * w00 + table[a + 3] * w01 + table[b + 1] * w10 + table[b + 3] * w11;
}

/* Where a load of size `norm` (m/s^2) sits on a forward table's norm axis. */
BOREAS_TM_FN float boreas_ub_norm_position(float norm, float a_ref, float q_max, int norms) {
  float q = norm / (norm + a_ref);
  return q / q_max * (float)(norms - 1);
}

/* The equilibrium center of mass for a load of size `norm` (per unit mass, gravity
 * included) at angle theta (boreas_ub_angle of the plane) from e_u in bend plane `plane`:
 * the forward table at `forward` (angles x norms pairs) read there, placed in the plane. */
BOREAS_TM_FN BoreasV3 boreas_ub_equilibrium(BOREAS_TS_GLOBAL const float* forward, int angles, int norms,
                                            float a_ref, float q_max, BoreasV3 base, BoreasV3 e_u,
                                            BoreasUbPlane plane, float theta, float norm, float scale) {
  BoreasUbCell row = boreas_ub_cell(theta * ((float)(angles - 1) / BOREAS_UB_PI), angles);
  BoreasUbCell col = boreas_ub_cell(boreas_ub_norm_position(norm, a_ref, q_max, norms), norms);
  float u, v;
  boreas_ub_bilinear2(forward, norms, row, col, &u, &v);
  return boreas_v3_lin3(base, 1.0f, e_u, u * scale, plane.e_v, v * scale);
}

/* The inverse table's cell for a center of mass at (par, perp) in its bend plane. */
BOREAS_TM_FN void boreas_ub_shape_cell(float par, float perp, float reach_scaled, int psi_count, int rho_count,
                                       float rho_min, BoreasUbCell* psi, BoreasUbCell* rho) {
  float angle = boreas_ub_angle(par, perp);
  float dist = BOREAS_TM_SQRT(par * par + perp * perp) / reach_scaled;
  *psi = boreas_ub_cell(angle * ((float)(psi_count - 1) / BOREAS_UB_PI), psi_count);
  *rho = boreas_ub_cell((dist - rho_min) / (1.0f - rho_min) * (float)(rho_count - 1), rho_count);
}

/* Joint k (u, v) of the inverse table at `inverse` (psi x rho cells of BOREAS_UB_JOINTS
 * pairs), bilinear. */
BOREAS_TM_FN void boreas_ub_shape_joint(BOREAS_TS_GLOBAL const float* inverse, int rho_count, BoreasUbCell psi,
                                        BoreasUbCell rho, int k, float* u, float* v) {
  int stride = 2 * BOREAS_UB_JOINTS;
  int a = (psi.index * rho_count + rho.index) * stride + 2 * k;
  int b = a + rho_count * stride;
  float w00 = (1.0f - psi.weight) * (1.0f - rho.weight);
  float w01 = (1.0f - psi.weight) * rho.weight;
  float w10 = psi.weight * (1.0f - rho.weight);
  float w11 = psi.weight * rho.weight;
  *u = inverse[a] * w00 + inverse[a + stride] * w01 + inverse[b] * w10 + inverse[b + stride] * w11;
  *v = inverse[a + 1] * w00 + inverse[a + 1 + stride] * w01 + inverse[b + 1] * w10 + inverse[b + 1 + stride] * w11;
}

/* The break table's verdict: the new broken state of a component (0 intact, else 1 + the
 * joint) under a load of size norm at angle theta. Intact components break at the nearest
 * tabulated angle's threshold; broken ones stay as they are. */
BOREAS_TM_FN float boreas_ub_broken(BOREAS_TS_GLOBAL const float* breaking, int angles, float theta, float norm,
                                   float broken) {
  int i = (int)(theta * ((float)(angles - 1) / BOREAS_UB_PI) + 0.5f);
  i = BOREAS_UB_IMIN(i, angles - 1);
  float breaks = (broken == 0.0f && norm > breaking[2 * i]) ? 1.0f : 0.0f;
  return broken + breaks * (1.0f + breaking[2 * i + 1]);
}

/* The critically damped constraint of Barzel and Barr for a point mass (seeds README:
 * F_c = -F_E - (2/tau) m v - (1/tau^2) m (X - X0)): the external force cancels, and
 * y = X - X0 obeys y'' = -(2/tau) y' - y/tau^2. Its exact solution over a step with X0
 * held, y(t) = (y0 + (v0 + y0/tau) t) e^(-t/tau), v(t) = (v0 - (v0 + y0/tau) t/tau)
 * e^(-t/tau), is stable for every dt and never overshoots from rest. decay = e^(-dt/tau)
 * comes from the host (one per part and step), so no exp runs here. */
BOREAS_TM_FN void boreas_ub_constraint_step(BoreasV3* x, BoreasV3* v, BoreasV3 x0, float tau, float decay,
                                            float dt) {
  float inv_tau = 1.0f / tau;
  BoreasV3 y = boreas_v3_sub(*x, x0);
  BoreasV3 c = boreas_v3_lin2(*v, 1.0f, y, inv_tau);
  BoreasV3 ny = boreas_v3_lin2(y, decay, c, dt * decay);
  *v = boreas_v3_lin2(*v, decay, c, -dt * inv_tau * decay);
  *x = boreas_v3_add(x0, ny);
}

/* max(x, 0) and min(max(x, 0), 1) of a float that is not NaN, exactly, by integer max and
 * min on its bits (non-negative floats order like their bit patterns read as ints; negative
 * ones read as negative ints; -0 becomes +0). Float compares and selects in their place
 * are what LLVM's SLP vectorizer packs across the unrolled collider and impulse loops of
 * underbrush_step.cl, and one packed value stops PoCL's work-item vectorizer (see
 * boreas_v3_lin2). */
BOREAS_TM_FN float boreas_ub_max0(float x) { return BOREAS_FM_AS_FLOAT(BOREAS_UB_IMAX(BOREAS_FM_AS_INT(x), 0)); }
BOREAS_TM_FN float boreas_ub_clamp01(float x) {
  return BOREAS_FM_AS_FLOAT(BOREAS_UB_IMIN(BOREAS_UB_IMAX(BOREAS_FM_AS_INT(x), 0), 0x3f800000 /* 1.0f */));
}

/* Adds to the load (m/s^2) the push of a sphere collider on a component with center of
 * mass x: along the line from the sphere's center, growing linearly from 0 where X is
 * `reach` outside the sphere to `push` where X is on its surface or inside (a component is
 * touched when its blade, not just its center of mass, reaches the ball; reach is its
 * length scale). Added in place, each component one multiply-add: a BoreasV3 sum would
 * be a reduction, which SLP also packs across colliders. */
BOREAS_TM_FN void boreas_ub_add_collider_push(BoreasV3 x, float cx, float cy, float cz, float radius, float reach,
                                              float push, float* load_x, float* load_y, float* load_z) {
  float dx = x.x - cx, dy = x.y - cy, dz = x.z - cz;
  float dist = BOREAS_TM_SQRT(dx * dx + dy * dy + dz * dz + 1e-30f);
  float overlap = boreas_ub_clamp01((radius + reach - dist) / reach);
  float k = push * overlap / dist;
  *load_x = dx * k + *load_x;
  *load_y = dy * k + *load_y;
  *load_z = dz * k + *load_z;
}

/* Adds to the velocity (m/s) of a component of inverse mass inv_mass at x the kick of an
 * impulse of momentum j (N s) at c, fading linearly to 0 at distance radius; in place, as
 * boreas_ub_add_collider_push. */
BOREAS_TM_FN void boreas_ub_add_impulse(BoreasV3 x, float cx, float cy, float cz, float radius, BoreasV3 j,
                                        float inv_mass, float* v_x, float* v_y, float* v_z) {
  float dx = x.x - cx, dy = x.y - cy, dz = x.z - cz;
  float dist = BOREAS_TM_SQRT(dx * dx + dy * dy + dz * dz);
  float k = boreas_ub_max0(1.0f - dist / radius) * inv_mass;
  *v_x = j.x * k + *v_x;
  *v_y = j.y * k + *v_y;
  *v_z = j.z * k + *v_z;
}

/* A part is no longer than it is: its center of mass stays within `reach` (the straight
 * part's base-to-X distance, times its scale) of its base. The constraint pulls X toward an
 * equilibrium that is always within reach, but an impulse can carry it past: a rain drop of
 * the default 2e-4 N s gives a daisy's petal of 15 mg some 13 m/s, which threw its center of
 * mass over a metre from its base, through the ground (tests/soak). Beyond reach, X goes
 * back to reach along the same direction and the outward part of V is spent (an inelastic
 * stop: the part's length takes the pull); within reach X and V stay as they are.
 * Branch-free (boreas_ub_max0, boreas_ub_clamp01), as the rest of the step. */
BOREAS_TM_FN void boreas_ub_keep_within_reach(BoreasV3* x, BoreasV3* v, BoreasV3 base, float reach) {
  BoreasV3 r = boreas_v3_sub(*x, base);
  float d2 = boreas_v3_dot(r, r);
  float reach2 = reach * reach;
  float beyond = boreas_ub_clamp01((d2 - reach2) * 1e30f); /* 1 past reach, else 0 */
  float d = BOREAS_TM_SQRT(d2 + 1e-30f);
  float pull = beyond * (1.0f - reach / d); /* the share of r to take back */
  float out = beyond * boreas_ub_max0(boreas_v3_dot(*v, r)) / (d * d);
  *x = boreas_v3_lin2(*x, 1.0f, r, -pull);
  *v = boreas_v3_lin2(*v, 1.0f, r, -out);
}

/* Where the base of component i is now: its rest base moved by `follow` times its parent's
 * displacement from rest in `state` (roots: follow 0, parent i). For a part fixed on a
 * parent at distance s from the parent's base, follow = s / |X_rest - base| of the parent:
 * points along a bent component move about in proportion to their distance from its base.
 * Planes of cl/shared/underbrush_types.h, stride n. */
BOREAS_TM_FN BoreasV3 boreas_ub_base(BOREAS_TS_GLOBAL const float* frame, BOREAS_TS_GLOBAL const float* state, int n,
                                    int i, int parent) {
  float follow = frame[BOREAS_UB_FRAME_FOLLOW * n + i];
  return boreas_v3_lin3(boreas_tree_load3(frame, n, BOREAS_UB_FRAME_BASE, i), 1.0f,
                        boreas_tree_load3(state, n, BOREAS_UB_STATE_X, parent), follow,
                        boreas_tree_load3(frame, n, BOREAS_UB_FRAME_REST, parent), -follow);
}

#endif
