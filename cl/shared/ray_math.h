/* boreas: the geometric tests of ray casting — a ray against a box, a triangle, a plane —
 * and the bounds of a bent branch's piece. Compiles as OpenCL C and as C/C++ (the native
 * twin and the host's tests run the same math). Scalar: a ray's traversal branches on
 * what it meets, which no SIMD lane layout helps (pocl-performance.md). */
#ifndef BOREAS_CL_SHARED_RAY_MATH_H
#define BOREAS_CL_SHARED_RAY_MATH_H

#include "shared/leaf_outline.h"
#include "shared/ray_types.h"
#include "shared/tree_math.h"

#ifndef __OPENCL_C_VERSION__
#include <math.h>
/* fminf and fmaxf as OpenCL's fmin and fmax are (a NaN operand dropped), written out: GCC
 * calls libm's for them unless told no NaN occurs (-ffinite-math-only), and the slab test
 * makes NaNs on purpose (0 * inf); the calls showed in the native twin's profile. */
BOREAS_FN float boreas_ray_fminf(float a, float b) { return a < b || b != b ? a : b; }
BOREAS_FN float boreas_ray_fmaxf(float a, float b) { return a > b || b != b ? a : b; }
#define BOREAS_RAY_FMIN boreas_ray_fminf
#define BOREAS_RAY_FMAX boreas_ray_fmaxf
#define BOREAS_RAY_FABS fabsf
#else
#define BOREAS_RAY_FMIN fmin
#define BOREAS_RAY_FMAX fmax
#define BOREAS_RAY_FABS fabs
#endif

/* A float's bits as an int and back, at width 1 whatever the kernel's width (records mix
 * both in one buffer): OpenCL's casts, or simd_width.h's host ones. */
#ifdef __OPENCL_C_VERSION__
#define boreas_as_float(i) as_float(i)
#define boreas_as_int(f) as_int(f)
#else
#define boreas_as_float(i) boreas_host_as_float(i)
#define boreas_as_int(f) boreas_host_as_int(f)
#endif

/* A ray ready for tests: origin, unit direction, its reciprocal per axis (+-inf where the
 * direction's component is 0: the slab test then keeps or drops the box whole). */
typedef struct BoreasRay {
  BoreasV3 o, d, inv;
} BoreasRay;

BOREAS_FN BoreasRay boreas_ray_make(BoreasV3 o, BoreasV3 d) {
  BoreasRay r;
  r.o = o;
  r.d = d;
  r.inv = boreas_v3(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
  return r;
}

/* Where the ray enters the box [lo, hi] within [0, t_max), or a negative value when it
 * misses (Kay and Kajiya's slabs). One axis's entry and exit along the ray: */
BOREAS_FN void boreas_ray_slab(float lo, float hi, float o, float d, float inv, float* t0, float* t1) {
  if (d == 0.0f) {
    /* Parallel to the slab: inside it for every t, or never (0 * inf would be NaN). */
    int inside = lo <= o && o <= hi;
    *t0 = inside ? -INFINITY : INFINITY;
    *t1 = inside ? INFINITY : -INFINITY;
    return;
  }
  float a = (lo - o) * inv, b = (hi - o) * inv;
  *t0 = BOREAS_RAY_FMIN(a, b);
  *t1 = BOREAS_RAY_FMAX(a, b);
}

BOREAS_FN float boreas_ray_box(const BoreasRay* r, BoreasV3 lo, BoreasV3 hi, float t_max) {
  float x0, x1, y0, y1, z0, z1;
  boreas_ray_slab(lo.x, hi.x, r->o.x, r->d.x, r->inv.x, &x0, &x1);
  boreas_ray_slab(lo.y, hi.y, r->o.y, r->d.y, r->inv.y, &y0, &y1);
  boreas_ray_slab(lo.z, hi.z, r->o.z, r->d.z, r->inv.z, &z0, &z1);
  float t_near = BOREAS_RAY_FMAX(BOREAS_RAY_FMAX(x0, y0), BOREAS_RAY_FMAX(z0, 0.0f));
  float t_far = BOREAS_RAY_FMIN(BOREAS_RAY_FMIN(x1, y1), BOREAS_RAY_FMIN(z1, t_max));
  /* A box's far side may round below its near side by an ulp for a grazing ray: the
   * factor keeps such boxes (conservative, as a traversal must be). */
  return t_near <= t_far * 1.00000024f ? t_near : -1.0f;
}

/* The ray against triangle (a, b, c) (Moller and Trumbore, "Fast, minimum storage
 * ray-triangle intersection"): the distance in [0, t_max), or a negative value. The
 * barycentric tests take BOREAS_RAY_EDGE_SLACK more on every side: a ray through a shared
 * edge or vertex is caught by one of its triangles whatever the rounding of u and v (a
 * camera looking straight down at a grid of ground cells hits a vertex in many pixels),
 * at the cost of triangles a millionth larger. */
#define BOREAS_RAY_EDGE_SLACK 1e-6f
BOREAS_FN float boreas_ray_triangle(const BoreasRay* r, BoreasV3 a, BoreasV3 b, BoreasV3 c,
                                    float t_max) {
  BoreasV3 e1 = boreas_v3_sub(b, a), e2 = boreas_v3_sub(c, a);
  BoreasV3 p = boreas_v3_cross(r->d, e2);
  float det = boreas_v3_dot(e1, p);
  if (det == 0.0f) return -1.0f; /* parallel to the plane */
  float inv = 1.0f / det;
  BoreasV3 s = boreas_v3_sub(r->o, a);
  float u = boreas_v3_dot(s, p) * inv;
  if (u < -BOREAS_RAY_EDGE_SLACK || u > 1.0f + BOREAS_RAY_EDGE_SLACK) return -1.0f;
  BoreasV3 q = boreas_v3_cross(s, e1);
  float v = boreas_v3_dot(r->d, q) * inv;
  if (v < -BOREAS_RAY_EDGE_SLACK || u + v > 1.0f + BOREAS_RAY_EDGE_SLACK) return -1.0f;
  float t = boreas_v3_dot(e2, q) * inv;
  return t >= 0.0f && t < t_max ? t : -1.0f;
}

/* The unit normal n (or -n) that faces the ray: every surface is seen from both sides. */
BOREAS_FN BoreasV3 boreas_ray_facing(const BoreasRay* r, BoreasV3 n) {
  n = boreas_v3_normalize(n);
  return boreas_v3_dot(n, r->d) > 0.0f ? boreas_v3_scale(n, -1.0f) : n;
}

BOREAS_FN BoreasV3 boreas_v3_min(BoreasV3 a, BoreasV3 b) {
  return boreas_v3(BOREAS_RAY_FMIN(a.x, b.x), BOREAS_RAY_FMIN(a.y, b.y), BOREAS_RAY_FMIN(a.z, b.z));
}
BOREAS_FN BoreasV3 boreas_v3_max(BoreasV3 a, BoreasV3 b) {
  return boreas_v3(BOREAS_RAY_FMAX(a.x, b.x), BOREAS_RAY_FMAX(a.y, b.y), BOREAS_RAY_FMAX(a.z, b.z));
}

/* The blossom B(a, b, c) of a cubic Bezier (de Casteljau with a different parameter at
 * each level): B(v0, v0, v0), B(v0, v0, v1), B(v0, v1, v1), B(v1, v1, v1) are the control
 * points of the piece over [v0, v1], whose hull holds that piece. */
BOREAS_FN BoreasV3 boreas_ray_blossom(BoreasBezier c, float a, float b, float t) {
  BoreasV3 q0 = boreas_v3_lin2(c.p0, 1.0f - a, c.p1, a);
  BoreasV3 q1 = boreas_v3_lin2(c.p1, 1.0f - a, c.p2, a);
  BoreasV3 q2 = boreas_v3_lin2(c.p2, 1.0f - a, c.p3, a);
  BoreasV3 r0 = boreas_v3_lin2(q0, 1.0f - b, q1, b);
  BoreasV3 r1 = boreas_v3_lin2(q1, 1.0f - b, q2, b);
  return boreas_v3_lin2(r0, 1.0f - t, r1, t);
}

/* A bound on how far the swept surface lies from the curve over v in [v0, v1]: the
 * radius functions' factors bounded apart (taper and flare are monotone in v, so their
 * ends bound them; bulges and lobes by their depths (beads are at most 1, so 1 + depth is
 * loose); the tip's cap is at most 1), times
 * sqrt(2): the frame's handles S(v), T(v) blend unit vectors with weights summing to 1, so
 * |S sin + T cos| <= sqrt 2. */
BOREAS_FN float boreas_ray_radius_bound(BoreasBranchRadius p, float v0, float v1) {
  float taper0 = 1.0f - p.taper_depth * boreas_pow(v0, p.taper_exponent);
  float taper1 = 1.0f - p.taper_depth * boreas_pow(v1, p.taper_exponent);
  float e0 = BOREAS_RAY_FMAX(1.0f - 8.0f * v0, 0.0f), e1 = BOREAS_RAY_FMAX(1.0f - 8.0f * v1, 0.0f);
  float flare0 = 1.0f + p.flare * (boreas_exp2(e0 * 6.64385618977472470f) - 1.0f) * 0.01f;
  float flare1 = 1.0f + p.flare * (boreas_exp2(e1 * 6.64385618977472470f) - 1.0f) * 0.01f;
  float fade = BOREAS_RAY_FMAX(BOREAS_RAY_FABS(1.0f - v0 * p.lobe_taper),
                               BOREAS_RAY_FABS(1.0f - v1 * p.lobe_taper));
  float bound = BOREAS_RAY_FABS(p.radius) *
                BOREAS_RAY_FMAX(BOREAS_RAY_FABS(taper0), BOREAS_RAY_FABS(taper1)) *
                BOREAS_RAY_FMAX(BOREAS_RAY_FABS(flare0), BOREAS_RAY_FABS(flare1)) *
                (1.0f + BOREAS_RAY_FABS(p.bulge_depth)) * (1.0f + BOREAS_RAY_FABS(p.lobe_depth) * fade);
  return bound * 1.41421356f * 1.0001f; /* and a hair for the float error of the vertices */
}

/* A template branch's radius functions (ray_types.h's shape record) at the tree's scale. */
BOREAS_FN BoreasBranchRadius boreas_ray_shape_radius(BOREAS_GLOBAL const float* shape, float scale) {
  BoreasBranchRadius p;
  p.radius = shape[BOREAS_RAY_SHAPE_RADIUS] * scale;
  p.taper_depth = shape[BOREAS_RAY_SHAPE_RADIUS + 1];
  p.taper_exponent = shape[BOREAS_RAY_SHAPE_RADIUS + 2];
  p.flare = shape[BOREAS_RAY_SHAPE_RADIUS + 3];
  p.bulge_count = shape[BOREAS_RAY_SHAPE_RADIUS + 4];
  p.bulge_depth = shape[BOREAS_RAY_SHAPE_RADIUS + 5];
  p.lobe_count = shape[BOREAS_RAY_SHAPE_RADIUS + 6];
  p.lobe_depth = shape[BOREAS_RAY_SHAPE_RADIUS + 7];
  p.lobe_taper = shape[BOREAS_RAY_SHAPE_RADIUS + 8];
  p.tip_cap = shape[BOREAS_RAY_SHAPE_TIP_CAP];
  p.bulge_phase = shape[BOREAS_RAY_SHAPE_BULGE_PHASE];
  return p;
}

/* The box of a leaf's quad as the renderer draws it (render/shaders/leaf.vert: u, v in [0, 1]
 * about the blade's base), from its placed record's base, axis and normal (normalized
 * here, as the cast normalizes them) and its blade's length and width at the tree's scale.
 * Written out corner by corner: no loop, so a kernel's lanes run it straight. */
BOREAS_FN void boreas_ray_leaf_box(BoreasV3 base, BoreasV3 axis, BoreasV3 normal, float length,
                                   float width, BoreasV3* lo, BoreasV3* hi) {
  axis = boreas_v3_normalize(axis);
  BoreasV3 across = boreas_v3_cross(axis, boreas_v3_normalize(normal));
  float a0, a1, s0, s1;
  boreas_leaf_offsets(0.0f, 0.0f, length, width, &a0, &s0);
  boreas_leaf_offsets(1.0f, 1.0f, length, width, &a1, &s1);
  BoreasV3 p00 = boreas_v3_madd(boreas_v3_madd(base, axis, a0), across, s0);
  BoreasV3 p01 = boreas_v3_madd(boreas_v3_madd(base, axis, a0), across, s1);
  BoreasV3 p10 = boreas_v3_madd(boreas_v3_madd(base, axis, a1), across, s0);
  BoreasV3 p11 = boreas_v3_madd(boreas_v3_madd(base, axis, a1), across, s1);
  *lo = boreas_v3_min(boreas_v3_min(p00, p01), boreas_v3_min(p10, p11));
  *hi = boreas_v3_max(boreas_v3_max(p00, p01), boreas_v3_max(p10, p11));
}

#endif
