/* boreas: a ray against the four child boxes of a wide node (ray_types.h,
 * BOREAS_RAY_WIDE_*) as one 4-lane operation: OpenCL's float4 in the kernel (PoCL makes
 * explicit vector types SIMD instructions), GCC's vector extension on the host (the native
 * twin and the tests). Each lane is boreas_ray_box's math on its box, operation for
 * operation (ray_math.h), so a lane's entry is the same bits as the scalar test's: the
 * traversal visits what the binary one visited, four boxes a load instead of two levels of
 * two (the binary nodes' loads were the cast's largest wait: bench/RESULTS.md, "Issue 37,
 * tenth round: wide"). Compiles as OpenCL C and as C/C++. */
#ifndef BOREAS_CL_SHARED_RAY_WIDE_H
#define BOREAS_CL_SHARED_RAY_WIDE_H

#include "shared/ray_math.h"
#include "shared/ray_types.h"

#ifdef __OPENCL_C_VERSION__
typedef float4 BoreasRayF4;
typedef int4 BoreasRayI4;
#define BOREAS_RAY_F4_LOAD(p) vload4(0, (p))
#define BOREAS_RAY_F4_SPLAT(x) ((float4)(x))
#define BOREAS_RAY_F4_STORE(v, p) vstore4((v), 0, (p))
#define BOREAS_RAY_F4_AS_I4(v) as_int4(v)
#define BOREAS_RAY_I4_AS_F4(v) as_float4(v)
#else
typedef float BoreasRayF4 __attribute__((vector_size(16)));
typedef int BoreasRayI4 __attribute__((vector_size(16)));
BOREAS_FN BoreasRayF4 boreas_ray_f4_load(const float* p) {
  BoreasRayF4 v;
  memcpy(&v, p, sizeof v);
  return v;
}
#define BOREAS_RAY_F4_LOAD(p) boreas_ray_f4_load(p)
BOREAS_FN BoreasRayF4 boreas_ray_f4_splat(float x) {
  BoreasRayF4 v = {x, x, x, x};
  return v;
}
#define BOREAS_RAY_F4_SPLAT(x) boreas_ray_f4_splat(x)
#define BOREAS_RAY_F4_STORE(v, p) memcpy((p), &(v), sizeof(BoreasRayF4))
#define BOREAS_RAY_F4_AS_I4(v) ((BoreasRayI4)(v))
#define BOREAS_RAY_I4_AS_F4(v) ((BoreasRayF4)(v))
#endif

/* Lane by lane: b where mask (all bits set) holds, else a, as bits (C and C++ alike). */
BOREAS_FN BoreasRayF4 boreas_ray_f4_pick(BoreasRayF4 a, BoreasRayF4 b, BoreasRayI4 mask) {
  return BOREAS_RAY_I4_AS_F4((BOREAS_RAY_F4_AS_I4(a) & ~mask) | (BOREAS_RAY_F4_AS_I4(b) & mask));
}

/* BOREAS_RAY_FMIN and BOREAS_RAY_FMAX a lane each: a NaN operand dropped (the slab test's
 * 0 * inf), as OpenCL's fmin and fmax (which the kernel calls, as its scalar test does)
 * and ray_math.h's host forms are. */
#ifdef __OPENCL_C_VERSION__
#define boreas_ray_f4_min(a, b) fmin((a), (b))
#define boreas_ray_f4_max(a, b) fmax((a), (b))
#else
BOREAS_FN BoreasRayF4 boreas_ray_f4_min(BoreasRayF4 a, BoreasRayF4 b) {
  return boreas_ray_f4_pick(b, a, (BoreasRayI4)((a < b) | (b != b)));
}
BOREAS_FN BoreasRayF4 boreas_ray_f4_max(BoreasRayF4 a, BoreasRayF4 b) {
  return boreas_ray_f4_pick(b, a, (BoreasRayI4)((a > b) | (b != b)));
}
#endif

/* boreas_ray_slab on four boxes' sides along one axis (the ray's d, o and inv the same in
 * every lane, so the parallel case is one branch for all four). */
BOREAS_FN void boreas_ray_slab4(BoreasRayF4 lo, BoreasRayF4 hi, float o, float d, float inv,
                                BoreasRayF4* t0, BoreasRayF4* t1) {
  if (d == 0.0f) {
    BoreasRayF4 vo = BOREAS_RAY_F4_SPLAT(o);
    BoreasRayI4 inside = (BoreasRayI4)((lo <= vo) & (vo <= hi));
    BoreasRayF4 in_lo = BOREAS_RAY_F4_SPLAT(-INFINITY), out = BOREAS_RAY_F4_SPLAT(INFINITY);
    *t0 = boreas_ray_f4_pick(out, in_lo, inside);
    *t1 = boreas_ray_f4_pick(in_lo, out, inside);
    return;
  }
  BoreasRayF4 vo = BOREAS_RAY_F4_SPLAT(o), vi = BOREAS_RAY_F4_SPLAT(inv);
  BoreasRayF4 a = (lo - vo) * vi, b = (hi - vo) * vi;
  *t0 = boreas_ray_f4_min(a, b);
  *t1 = boreas_ray_f4_max(a, b);
}

/* Where the ray enters each of a wide node's four boxes within [0, t_max), or -1 where it
 * misses (an empty slot's box, min > max, always): boreas_ray_box a lane. */
BOREAS_FN BoreasRayF4 boreas_ray_wide_boxes(const BoreasRay* r, BOREAS_GLOBAL const float* node,
                                            float t_max) {
  BoreasRayF4 x0, x1, y0, y1, z0, z1;
  BOREAS_GLOBAL const float* lo = node + BOREAS_RAY_WIDE_LO;
  BOREAS_GLOBAL const float* hi = node + BOREAS_RAY_WIDE_HI;
  boreas_ray_slab4(BOREAS_RAY_F4_LOAD(lo), BOREAS_RAY_F4_LOAD(hi), r->o.x, r->d.x, r->inv.x, &x0, &x1);
  boreas_ray_slab4(BOREAS_RAY_F4_LOAD(lo + 4), BOREAS_RAY_F4_LOAD(hi + 4), r->o.y, r->d.y, r->inv.y, &y0, &y1);
  boreas_ray_slab4(BOREAS_RAY_F4_LOAD(lo + 8), BOREAS_RAY_F4_LOAD(hi + 8), r->o.z, r->d.z, r->inv.z, &z0, &z1);
  BoreasRayF4 t_near = boreas_ray_f4_max(boreas_ray_f4_max(x0, y0), boreas_ray_f4_max(z0, BOREAS_RAY_F4_SPLAT(0.0f)));
  BoreasRayF4 t_far = boreas_ray_f4_min(boreas_ray_f4_min(x1, y1), boreas_ray_f4_min(z1, BOREAS_RAY_F4_SPLAT(t_max)));
  BoreasRayI4 in = (BoreasRayI4)(t_near <= t_far * BOREAS_RAY_F4_SPLAT(1.00000024f));
  return boreas_ray_f4_pick(BOREAS_RAY_F4_SPLAT(-1.0f), t_near, in);
}

#endif
