/* boreas: a ray against the four child boxes of a wide node (ray_types.h,
 * BOREAS_RAY_WIDE_*: one cache line, the boxes stored as 8-bit steps from the node's
 * corner, rounded outward) as one 4-lane operation: OpenCL's float4 in the kernel (PoCL makes
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
#define BOREAS_RAY_F4_FROM_Q(p) convert_float4(vload4(0, (p)))
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
typedef unsigned char BoreasRayQ4 __attribute__((vector_size(4)));
BOREAS_FN BoreasRayF4 boreas_ray_f4_from_q(const unsigned char* p) {
  BoreasRayQ4 v;
  memcpy(&v, p, sizeof v);
  return __builtin_convertvector(v, BoreasRayF4);
}
#define BOREAS_RAY_F4_FROM_Q(p) boreas_ray_f4_from_q(p)
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

/* Slot k's a and count (ray_types.h, BOREAS_RAY_WIDE_*). */
BOREAS_FN int boreas_ray_wide_a(BOREAS_GLOBAL const float* node, int k) {
  return boreas_as_int(node[BOREAS_RAY_WIDE_A + k]);
}
BOREAS_FN int boreas_ray_wide_count(BOREAS_GLOBAL const float* node, int k) {
  return ((BOREAS_GLOBAL const signed char*)(node + BOREAS_RAY_WIDE_COUNT))[k];
}

/* An axis's step: a power of two, so that q * step is exact and origin + q * step one
 * rounding whether or not a compiler fuses it (the pack and the cast get the same bits). */
BOREAS_FN float boreas_ray_wide_step(BOREAS_GLOBAL const float* node, int axis) {
  int e = ((BOREAS_GLOBAL const unsigned char*)(node + BOREAS_RAY_WIDE_SCALE))[axis];
  return boreas_as_float(e << 23);
}

/* The four slots' sides `side` (0..5: min x, y, z, max x, y, z) as the cast sees them. */
BOREAS_FN BoreasRayF4 boreas_ray_wide_side(BOREAS_GLOBAL const float* node, int side) {
  int axis = side % 3;
  BOREAS_GLOBAL const unsigned char* q = (BOREAS_GLOBAL const unsigned char*)(node + BOREAS_RAY_WIDE_Q) + 4 * side;
  return BOREAS_RAY_F4_SPLAT(node[BOREAS_RAY_WIDE_ORIGIN + axis]) +
         BOREAS_RAY_F4_FROM_Q(q) * BOREAS_RAY_F4_SPLAT(boreas_ray_wide_step(node, axis));
}

/* Where the ray enters each of a wide node's four boxes within [0, t_max), or -1 where it
 * misses (an empty slot's lane means nothing: the caller skips it by its count). Each
 * lane is boreas_ray_box's math on the slot's stored box, which holds the slot's own box
 * (boreas_ray_wide_pack): every operation is monotone in the box's sides, so a ray that
 * enters the slot's box enters the stored one, at the same t or before. */
BOREAS_FN BoreasRayF4 boreas_ray_wide_boxes(const BoreasRay* r, BOREAS_GLOBAL const float* node,
                                            float t_max) {
  BoreasRayF4 x0, x1, y0, y1, z0, z1;
  boreas_ray_slab4(boreas_ray_wide_side(node, 0), boreas_ray_wide_side(node, 3), r->o.x, r->d.x, r->inv.x, &x0, &x1);
  boreas_ray_slab4(boreas_ray_wide_side(node, 1), boreas_ray_wide_side(node, 4), r->o.y, r->d.y, r->inv.y, &y0, &y1);
  boreas_ray_slab4(boreas_ray_wide_side(node, 2), boreas_ray_wide_side(node, 5), r->o.z, r->d.z, r->inv.z, &z0, &z1);
  BoreasRayF4 t_near = boreas_ray_f4_max(boreas_ray_f4_max(x0, y0), boreas_ray_f4_max(z0, BOREAS_RAY_F4_SPLAT(0.0f)));
  BoreasRayF4 t_far = boreas_ray_f4_min(boreas_ray_f4_min(x1, y1), boreas_ray_f4_min(z1, BOREAS_RAY_F4_SPLAT(t_max)));
  BoreasRayI4 in = (BoreasRayI4)(t_near <= t_far * BOREAS_RAY_F4_SPLAT(1.00000024f));
  return boreas_ray_f4_pick(BOREAS_RAY_F4_SPLAT(-1.0f), t_near, in);
}

/* Whether a slot's box (min xyz, max xyz) holds anything a ray could hit: not empty
 * (min > max, or the binary builder's empty box) and not the refit's point for nothing
 * (BOREAS_RAY_NOWHERE), which would stretch the node's steps over the whole float range. */
BOREAS_FN int boreas_ray_wide_in_use(const float* box) {
  return box[0] <= box[3] && box[1] <= box[4] && box[2] <= box[5] && box[0] != BOREAS_RAY_NOWHERE;
}

/* The step of one axis whose slots span [lo, hi]: the smallest power of two (at least the
 * smallest normal float's) with lo + 255 step >= hi as the cast computes it. */
BOREAS_FN float boreas_ray_wide_pick_step(float lo, float hi) {
  float step = 1.17549435e-38f, need = (hi - lo) / 255.0f;
  if (need > step) {
    step = boreas_as_float(boreas_as_int(need) & 0x7f800000);
    if (step < need) step *= 2.0f;
  }
  while (!(lo + 255.0f * step >= hi) && step < 8.50705917e+37f) step *= 2.0f;
  return step;
}

/* Value v in steps from origin, rounded down (up: rounded up): the largest q (smallest)
 * in 0..255 whose origin + q step, as the cast computes it, lies at or below v (at or
 * above; far out a step can be finer than the floats' spacing, so the sums decide). */
BOREAS_FN int boreas_ray_wide_down(float origin, float step, float v) {
  int q = (int)BOREAS_RAY_FMIN((v - origin) / step, 255.0f);
  q = q < 0 ? 0 : q;
  while (q > 0 && !(origin + (float)q * step <= v)) --q;
  while (q < 255 && origin + (float)(q + 1) * step <= v) ++q;
  return q;
}
BOREAS_FN int boreas_ray_wide_up(float origin, float step, float v) {
  int q = (int)BOREAS_RAY_FMIN((v - origin) / step, 255.0f);
  q = q < 0 ? 0 : q;
  while (q < 255 && !(origin + (float)q * step >= v)) ++q;
  while (q > 0 && origin + (float)(q - 1) * step >= v) --q;
  return q;
}

/* A wide node's origin, steps and stored boxes from its slots' boxes (box: 6 floats a
 * slot, min xyz then max xyz; a slot not in use, boreas_ray_wide_in_use, stored as the
 * point at the far corner): each stored box holds the slot's own, within a step more on
 * each side. Its a and counts are left as they are. The host's collapse and the gather
 * after each refit both pack through here, so they store the same bytes. */
BOREAS_FN void boreas_ray_wide_pack(BOREAS_GLOBAL float* node, const float* box) {
  BOREAS_GLOBAL unsigned char* scale = (BOREAS_GLOBAL unsigned char*)(node + BOREAS_RAY_WIDE_SCALE);
  BOREAS_GLOBAL unsigned char* q = (BOREAS_GLOBAL unsigned char*)(node + BOREAS_RAY_WIDE_Q);
  for (int axis = 0; axis < 3; ++axis) {
    float lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 4; ++k) {
      if (!boreas_ray_wide_in_use(box + 6 * k)) continue;
      lo = BOREAS_RAY_FMIN(lo, box[6 * k + axis]);
      hi = BOREAS_RAY_FMAX(hi, box[6 * k + 3 + axis]);
    }
    if (!(lo <= hi)) lo = hi = 0.0f; /* no slot in use */
    float step = boreas_ray_wide_pick_step(lo, hi);
    node[BOREAS_RAY_WIDE_ORIGIN + axis] = lo;
    scale[axis] = (unsigned char)(boreas_as_int(step) >> 23);
    for (int k = 0; k < 4; ++k) {
      int use = boreas_ray_wide_in_use(box + 6 * k);
      q[4 * axis + k] = (unsigned char)(use ? boreas_ray_wide_down(lo, step, box[6 * k + axis]) : 255);
      q[4 * (axis + 3) + k] = (unsigned char)(use ? boreas_ray_wide_up(lo, step, box[6 * k + 3 + axis]) : 255);
    }
  }
  scale[3] = 0;
}

#endif
