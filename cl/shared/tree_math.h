/* boreas: the geometry of a Skjermo branch — cubic Bezier, Sloan moving frames, attachment
 * to the parent, the length-preserving bend and the generalized de Casteljau sweep with
 * its radius functions and Jacobian normals (Skjermo 2007 sec. 3 and 4.2-4.3).
 *
 * Compiles as OpenCL C and as C/C++: the kernels, the native benchmark twins and (issue 5)
 * the GLSL deformer follow this one text. Everything is scalar float on small value
 * structs, which PoCL's work-item loop vectorizer handles as long as the data come from
 * planes (cl/shared/tree_types.h), not from packed triples.
 *
 * Conventions used throughout:
 *  - A branch's unpositioned control points have P0 at the origin and P1 on +x.
 *  - Sloan frame (eq. 8), handles normalized: S0 = L0 x O, T0 = S0 x L0, T1 = S0 x L1,
 *    S1 = L1 x T1, T2 = S1 x L2, S2 = L2 x T2. O is the branch's orientation vector, kept
 *    perpendicular to L0 by construction (see boreas_attach), so S0 never degenerates.
 *  - The handles between the points are blended with the quadratic Bernstein weights of
 *    the de Casteljau recursion: with eq. 9 as read in the seeds README, the surface point
 *    R^2_0 at (u, theta) is C(u) + r (sin(theta) S(u) + cos(theta) T(u)), where
 *    S(u) = (1-u)^2 S0 + 2u(1-u) S1 + u^2 S2 (T likewise): the handles enter linearly.
 */
#ifndef BOREAS_CL_SHARED_TREE_MATH_H
#define BOREAS_CL_SHARED_TREE_MATH_H

#include "shared/fast_math.h"

#ifdef __OPENCL_C_VERSION__
#define BOREAS_TM_FN inline __attribute__((always_inline))
#define BOREAS_TM_SQRT(x) sqrt(x)
#define BOREAS_TM_MAX(a, b) fmax((a), (b))
#else
#include <math.h>
#define BOREAS_TM_FN static inline
#define BOREAS_TM_SQRT(x) sqrtf(x)
#define BOREAS_TM_MAX(a, b) fmaxf((a), (b))
#endif

/* A phase in cycles brought into [-1/2, 1/2], as boreas_sin_cycle wants it. */
#define boreas_tm_wrap(u) ((u)-BOREAS_FM_RINT(u))

#define BOREAS_TM_TWO_PI 6.28318530717958648f
#define BOREAS_TM_LN_100 4.60517018598809136f

typedef struct BoreasV3 {
  float x, y, z;
} BoreasV3;

BOREAS_TM_FN BoreasV3 boreas_v3(float x, float y, float z) {
  BoreasV3 r;
  r.x = x;
  r.y = y;
  r.z = z;
  return r;
}
BOREAS_TM_FN BoreasV3 boreas_v3_add(BoreasV3 a, BoreasV3 b) { return boreas_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
BOREAS_TM_FN BoreasV3 boreas_v3_sub(BoreasV3 a, BoreasV3 b) { return boreas_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
BOREAS_TM_FN BoreasV3 boreas_v3_scale(BoreasV3 a, float s) { return boreas_v3(a.x * s, a.y * s, a.z * s); }
/* a + s b */
BOREAS_TM_FN BoreasV3 boreas_v3_madd(BoreasV3 a, BoreasV3 b, float s) {
  return boreas_v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
/* Linear combinations as single expressions, so each component contracts to fmas. Built
 * from add(scale(), scale()) instead, the separate products of matching x/y/z chains are
 * what LLVM's SLP vectorizer packs into <2 x float> before PoCL forms its work-item loops,
 * and any vector value there stops those loops from vectorizing. */
BOREAS_TM_FN BoreasV3 boreas_v3_lin2(BoreasV3 a, float sa, BoreasV3 b, float sb) {
  return boreas_v3(a.x * sa + b.x * sb, a.y * sa + b.y * sb, a.z * sa + b.z * sb);
}
BOREAS_TM_FN BoreasV3 boreas_v3_lin3(BoreasV3 a, float sa, BoreasV3 b, float sb, BoreasV3 c, float sc) {
  return boreas_v3(a.x * sa + b.x * sb + c.x * sc, a.y * sa + b.y * sb + c.y * sc, a.z * sa + b.z * sb + c.z * sc);
}
BOREAS_TM_FN float boreas_v3_dot(BoreasV3 a, BoreasV3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
BOREAS_TM_FN BoreasV3 boreas_v3_cross(BoreasV3 a, BoreasV3 b) {
  return boreas_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
BOREAS_TM_FN float boreas_v3_length(BoreasV3 a) { return BOREAS_TM_SQRT(boreas_v3_dot(a, a)); }
/* The 1e-30 keeps a zero vector zero instead of NaN and changes nothing for lengths above
 * ~1e-11. (fmax would do the same but is a compare-and-select that the SLP vectorizer
 * packs, which stops PoCL's work-item vectorization; see boreas_v3_lin2.) */
BOREAS_TM_FN BoreasV3 boreas_v3_normalize(BoreasV3 a) {
  return boreas_v3_scale(a, 1.0f / BOREAS_TM_SQRT(boreas_v3_dot(a, a) + 1e-30f));
}

/* ---- Cubic Bezier ------------------------------------------------------------------- */

typedef struct BoreasBezier {
  BoreasV3 p0, p1, p2, p3;
} BoreasBezier;

BOREAS_TM_FN BoreasV3 boreas_bezier_point(BoreasBezier c, float u) {
  float w = 1.0f - u;
  float b0 = w * w * w, b1 = 3.0f * u * w * w, b2 = 3.0f * u * u * w, b3 = u * u * u;
  return boreas_v3(b0 * c.p0.x + b1 * c.p1.x + b2 * c.p2.x + b3 * c.p3.x,
                   b0 * c.p0.y + b1 * c.p1.y + b2 * c.p2.y + b3 * c.p3.y,
                   b0 * c.p0.z + b1 * c.p1.z + b2 * c.p2.z + b3 * c.p3.z);
}

/* dC/du */
BOREAS_TM_FN BoreasV3 boreas_bezier_derivative(BoreasBezier c, float u) {
  float w = 1.0f - u;
  float d0 = 3.0f * w * w, d1 = 6.0f * u * w, d2 = 3.0f * u * u;
  BoreasV3 a = boreas_v3_sub(c.p1, c.p0), b = boreas_v3_sub(c.p2, c.p1), e = boreas_v3_sub(c.p3, c.p2);
  return boreas_v3(d0 * a.x + d1 * b.x + d2 * e.x, d0 * a.y + d1 * b.y + d2 * e.y,
                   d0 * a.z + d1 * b.z + d2 * e.z);
}

/* ---- Sloan moving frame (eq. 8) ------------------------------------------------------ */

typedef struct BoreasSloanFrame {
  BoreasV3 s0, t0, s1, t1, s2, t2;
} BoreasSloanFrame;

BOREAS_TM_FN BoreasSloanFrame boreas_sloan_frame(BoreasBezier c, BoreasV3 o) {
  BoreasV3 l0 = boreas_v3_normalize(boreas_v3_sub(c.p1, c.p0));
  BoreasV3 l1 = boreas_v3_normalize(boreas_v3_sub(c.p2, c.p1));
  BoreasV3 l2 = boreas_v3_normalize(boreas_v3_sub(c.p3, c.p2));
  BoreasSloanFrame f;
  f.s0 = boreas_v3_normalize(boreas_v3_cross(l0, o));
  f.t0 = boreas_v3_cross(f.s0, l0);
  f.t1 = boreas_v3_normalize(boreas_v3_cross(f.s0, l1));
  f.s1 = boreas_v3_cross(l1, f.t1);
  f.t2 = boreas_v3_normalize(boreas_v3_cross(f.s1, l2));
  f.s2 = boreas_v3_cross(l2, f.t2);
  return f;
}

/* The blended handles S(u), T(u) of the de Casteljau recursion, and their u-derivatives. */
BOREAS_TM_FN void boreas_frame_handles(BoreasSloanFrame f, float u, BoreasV3* s, BoreasV3* t,
                                       BoreasV3* ds, BoreasV3* dt) {
  float w = 1.0f - u;
  float q0 = w * w, q1 = 2.0f * u * w, q2 = u * u;
  *s = boreas_v3_lin3(f.s0, q0, f.s1, q1, f.s2, q2);
  *t = boreas_v3_lin3(f.t0, q0, f.t1, q1, f.t2, q2);
  /* d/du: 2 [(1-u)(X1 - X0) + u (X2 - X1)] */
  *ds = boreas_v3_lin2(boreas_v3_sub(f.s1, f.s0), 2.0f * w, boreas_v3_sub(f.s2, f.s1), 2.0f * u);
  *dt = boreas_v3_lin2(boreas_v3_sub(f.t1, f.t0), 2.0f * w, boreas_v3_sub(f.t2, f.t1), 2.0f * u);
}

/* ---- Attachment (sec. 4.2) ---------------------------------------------------------- */

/* Where and how a child sits on its parent: origin on the parent's curve, and the child's
 * frame (x along its unbent first segment, y in the plane of the parent's tangent and
 * the child, z = x cross y). */
typedef struct BoreasAttachFrame {
  BoreasV3 origin, x, y, z;
} BoreasAttachFrame;

/* The child at parameter v on the parent, angle theta around it (cos_t, sin_t), rotated
 * down by alpha (cos_a, sin_a) from the parent's tangent U: V points from the curve to
 * the parent's sweep surface at (v, theta), made perpendicular to U; the frame (U, V,
 * U x V) turned by alpha about U x V gives the child's axes. With alpha = 0 the child
 * continues along the parent. */
BOREAS_TM_FN BoreasAttachFrame boreas_attach(BoreasBezier parent, BoreasV3 parent_o, float v,
                                             float cos_t, float sin_t, float cos_a, float sin_a) {
  BoreasSloanFrame f = boreas_sloan_frame(parent, parent_o);
  BoreasV3 s, t, ds, dt;
  boreas_frame_handles(f, v, &s, &t, &ds, &dt);
  BoreasV3 u = boreas_v3_normalize(boreas_bezier_derivative(parent, v));
  BoreasV3 radial = boreas_v3_lin2(s, sin_t, t, cos_t);
  BoreasV3 e2 = boreas_v3_normalize(boreas_v3_madd(radial, u, -boreas_v3_dot(radial, u)));
  BoreasAttachFrame a;
  a.origin = boreas_bezier_point(parent, v);
  a.x = boreas_v3_lin2(u, cos_a, e2, sin_a);
  a.y = boreas_v3_lin2(e2, cos_a, u, -sin_a);
  a.z = boreas_v3_cross(u, e2);
  return a;
}

/* A point given in the child's unpositioned coordinates, placed by the frame. */
BOREAS_TM_FN BoreasV3 boreas_attach_place(BoreasAttachFrame a, float lx, float ly, float lz) {
  return boreas_v3(a.origin.x + a.x.x * lx + a.y.x * ly + a.z.x * lz, a.origin.y + a.x.y * lx + a.y.y * ly + a.z.y * lz,
                   a.origin.z + a.x.z * lx + a.y.z * ly + a.z.z * lz);
}

/* ---- Bending (sec. 4.3, eq. 17 as read in the seeds README) ------------------------- */

/* The bent point P'_i = P'_{i-1} + |seg| normalize(seg + b_i), seg = P_i - P_{i-1} unbent:
 * the segment turns toward the bend vector and keeps its length. */
BOREAS_TM_FN BoreasV3 boreas_bend_point(BoreasV3 bent_prev, BoreasV3 seg, BoreasV3 bend) {
  return boreas_v3_madd(bent_prev, boreas_v3_normalize(boreas_v3_add(seg, bend)), boreas_v3_length(seg));
}

/* ---- The wind's load (trees/wind_load.h on the host) ------------------------------ */

/* The bend's target: the paper's linear load F* = linear u, or the drag load F* =
 * drag |w| w with w the wind relative to the branch's tip: u less the tip's own velocity,
 * (1 + w2) dF/dt for a small bend (P2 moves by w2 F, P3 by (1 + w2) F). That term is the
 * branch's aerodynamic damping; it is taken from the last step's rate, so it is clamped
 * to the wind's speed, which bounds the target (|F*| <= 4 drag |u|^2) however long the
 * step. A quasi-static branch has no rate: w = u, bit for bit. `linear` and `drag` are
 * the compliances of the two loads, already scaled for the tree; one of them is 0. The
 * linear load keeps the paper's absolute wind (no aerodynamic damping), so that its
 * damped response stays the linear oscillator's. */
BOREAS_TM_FN BoreasV3 boreas_bend_target(BoreasV3 wind, BoreasV3 rate, float w2, float linear, float drag) {
  BoreasV3 tip = boreas_v3_scale(rate, drag > 0.0f ? 1.0f + w2 : 0.0f);
  float wind2 = boreas_v3_dot(wind, wind);
  float tip2 = boreas_v3_dot(tip, tip);
  float keep = BOREAS_TM_SQRT(wind2 / BOREAS_TM_MAX(BOREAS_TM_MAX(tip2, wind2), 1e-30f));
  BoreasV3 w = boreas_v3_madd(wind, tip, -keep);
  return boreas_v3_scale(w, linear + drag * boreas_v3_length(w));
}

/* ---- Radius functions (eq. 2-5) ----------------------------------------------------- */

typedef struct BoreasBranchRadius {
  float radius;          /* m, at the base before flare */
  float taper_depth;     /* eq. 2 generalized: 1 - depth v^exponent (the paper: depth 1) */
  float taper_exponent;  /* >= 1 */
  float flare;           /* eq. 3 as in the data README: 1 + f (100^max(0, 1-8v) - 1) / 100 */
  float bulge_count, bulge_depth;           /* eq. 4 */
  float lobe_count, lobe_depth, lobe_taper; /* eq. 5 */
} BoreasBranchRadius;

/* r(v, theta) and dr/dv, and the lobe factor with its theta-derivative (per radian; the
 * only theta dependence: dr/dtheta = r / lobes * d_lobes). theta in cycles (theta_rad /
 * 2 pi) so the lobes' sine needs no range reduction beyond lobe_count. */
BOREAS_TM_FN void boreas_branch_radius(BoreasBranchRadius p, float v, float theta_cycles,
                                       float* r, float* dr_dv, float* lobes_out,
                                       float* d_lobes_out) {
  /* taper: 1 - k v^t, d/dv = -k t v^(t-1) (t >= 1 keeps it finite at v = 0) */
  float vt1 = boreas_pow(v, p.taper_exponent - 1.0f);
  float taper = 1.0f - p.taper_depth * vt1 * v;
  float d_taper = -p.taper_depth * p.taper_exponent * vt1;
  /* flare: 100^e with e = max(0, 1 - 8v); zero slope where e is clamped */
  float e = BOREAS_TM_MAX(1.0f - 8.0f * v, 0.0f);
  float p100 = boreas_exp2(e * 6.64385618977472470f); /* log2(100) */
  float flare = 1.0f + p.flare * (p100 - 1.0f) * 0.01f;
  float d_flare = (e > 0.0f ? 1.0f : 0.0f) * p.flare * 0.01f * p100 * BOREAS_TM_LN_100 * -8.0f;
  /* bulges: 1 + b_d sin(2 pi b_n v) */
  float bulge_phase = p.bulge_count * v;
  float bulges = 1.0f + p.bulge_depth * boreas_sin_cycle(boreas_tm_wrap(bulge_phase));
  float bulge_cos_phase = bulge_phase + 0.25f;
  float d_bulges = p.bulge_depth * BOREAS_TM_TWO_PI * p.bulge_count *
                   boreas_sin_cycle(boreas_tm_wrap(bulge_cos_phase));
  /* lobes: 1 + l_d sin(l_n theta) (1 - v l_t) */
  float lobe_phase = p.lobe_count * theta_cycles;
  float lobe_sin = boreas_sin_cycle(boreas_tm_wrap(lobe_phase));
  float lobe_cos_phase = lobe_phase + 0.25f;
  float lobe_cos = boreas_sin_cycle(boreas_tm_wrap(lobe_cos_phase));
  float lobe_fade = 1.0f - v * p.lobe_taper;
  float lobes = 1.0f + p.lobe_depth * lobe_sin * lobe_fade;
  float d_lobes_dv = -p.lobe_depth * lobe_sin * p.lobe_taper;
  float radial = taper * flare * bulges;
  *r = p.radius * radial * lobes;
  *dr_dv = p.radius * ((d_taper * flare * bulges + taper * d_flare * bulges + taper * flare * d_bulges) * lobes +
                       radial * d_lobes_dv);
  *lobes_out = lobes;
  *d_lobes_out = p.lobe_depth * p.lobe_count * lobe_cos * lobe_fade;
}

/* ---- The deformed surface (eq. 6-9) and its normal (sec. 3.4) ---------------------- */

/* Surface point and unit outward normal of the bent branch at (v, theta). The normal is
 * the cross product of the Jacobian's images of the two parameter directions, X_theta x
 * X_v (that order is outward for Sloan frames as built above: (L, S, T) is left-handed). */
BOREAS_TM_FN void boreas_branch_surface(BoreasBezier c, BoreasSloanFrame f, BoreasBranchRadius p,
                                        float v, float theta_cycles, float sin_t, float cos_t,
                                        BoreasV3* position, BoreasV3* normal) {
  BoreasV3 s, t, ds, dt;
  boreas_frame_handles(f, v, &s, &t, &ds, &dt);
  float r, dr_dv, lobes, d_lobes;
  boreas_branch_radius(p, v, theta_cycles, &r, &dr_dv, &lobes, &d_lobes);
  BoreasV3 dir = boreas_v3_lin2(s, sin_t, t, cos_t);
  BoreasV3 ddir_dv = boreas_v3_lin2(ds, sin_t, dt, cos_t);
  BoreasV3 ddir_dtheta = boreas_v3_lin2(s, cos_t, t, -sin_t);
  *position = boreas_v3_madd(boreas_bezier_point(c, v), dir, r);
  BoreasV3 x_v = boreas_v3_add(boreas_bezier_derivative(c, v),
                               boreas_v3_lin2(dir, dr_dv, ddir_dv, r));
  /* X_theta divided by radius taper flare bulges (> 0 or 0): the same direction, and still
   * defined where the radius reaches 0 at a fully tapered tip (the cone's limit). */
  BoreasV3 x_theta = boreas_v3_lin2(dir, d_lobes, ddir_dtheta, lobes);
  *normal = boreas_v3_normalize(boreas_v3_cross(x_theta, x_v));
}

#endif
