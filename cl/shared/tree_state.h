/* boreas: reading and writing a branch's animated state — three planes per vector
 * (cl/shared/tree_types.h). Compiles as OpenCL C (global memory) and as C/C++ (host
 * memory), so the kernels, the host's rest placement and the native twins share it. */
#ifndef BOREAS_CL_SHARED_TREE_STATE_H
#define BOREAS_CL_SHARED_TREE_STATE_H

#include "shared/tree_math.h"
#include "shared/tree_types.h"

#ifndef __OPENCL_C_VERSION__
#include <stddef.h>
#endif

/* Element i of plane `plane` (stride n). In int where the planes hold fewer than 2^31
 * floats together (PoCL vectorizes int index math ~1.6x faster: measured on the tree step),
 * in 64 bits where the host builds the kernel with BOREAS_WIDE_PLANES (a forest's planes
 * past 2^31 floats; trees/tree_batch.cpp decides). */
#ifdef BOREAS_WIDE_PLANES
#define BOREAS_TREE_AT(plane, n, i) ((size_t)(plane) * (size_t)(n) + (size_t)(i))
#else
#define BOREAS_TREE_AT(plane, n, i) ((plane) * (n) + (i))
#endif

/* The vector in planes plane, plane + 1, plane + 2 (stride n) at index i. */
BOREAS_FN BoreasV3 boreas_tree_load3(BOREAS_GLOBAL const float* planes, int n, int plane, int i) {
  return boreas_v3(planes[BOREAS_TREE_AT(plane, n, i)], planes[BOREAS_TREE_AT(plane + 1, n, i)],
                   planes[BOREAS_TREE_AT(plane + 2, n, i)]);
}

BOREAS_FN void boreas_tree_store3(BOREAS_GLOBAL float* planes, int n, int plane, int i,
                                  BoreasV3 v) {
  planes[BOREAS_TREE_AT(plane, n, i)] = v.x;
  planes[BOREAS_TREE_AT(plane + 1, n, i)] = v.y;
  planes[BOREAS_TREE_AT(plane + 2, n, i)] = v.z;
}

/* The radius functions of branch i (planes in BoreasBranchRadius's field order). */
BOREAS_FN BoreasBranchRadius boreas_tree_load_radius(BOREAS_GLOBAL const float* radius, int n,
                                                     int i) {
  BoreasBranchRadius r;
  r.radius = radius[BOREAS_TREE_AT(0, n, i)];
  r.taper_depth = radius[BOREAS_TREE_AT(1, n, i)];
  r.taper_exponent = radius[BOREAS_TREE_AT(2, n, i)];
  r.flare = radius[BOREAS_TREE_AT(3, n, i)];
  r.bulge_count = radius[BOREAS_TREE_AT(4, n, i)];
  r.bulge_depth = radius[BOREAS_TREE_AT(5, n, i)];
  r.lobe_count = radius[BOREAS_TREE_AT(6, n, i)];
  r.lobe_depth = radius[BOREAS_TREE_AT(7, n, i)];
  r.lobe_taper = radius[BOREAS_TREE_AT(8, n, i)];
  return r;
}

/* Branch i's curve and orientation vector O. */
BOREAS_FN BoreasBezier boreas_tree_load_curve(BOREAS_GLOBAL const float* state, int n, int i,
                                              BoreasV3* o) {
  BoreasBezier c;
  c.p0 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_load3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

#ifdef __OPENCL_C_VERSION__
/* ---- At the kernel's SIMD width (simd_width.h), for kernels that process BOREAS_W items
 * per work-item: a tile's items are consecutive entries, `count` of them from `first`,
 * and a work-item's lanes are items k .. k + W - 1 of them; lanes past the count read the
 * last item and store nothing. At width 1 these are the functions above on entry
 * first + min(k, count - 1), 64-bit offsets (BOREAS_WIDE_PLANES) included; wider kernels
 * index in int, so the host builds a batch with 64-bit offsets at width 1. */
#if BOREAS_W > 1 && defined(BOREAS_WIDE_PLANES)
#error "BOREAS_WIDE_PLANES kernels are built at width 1"
#endif

/* The vector at each lane's entry i (a per-lane gather: parents are scattered). */
BOREAS_FN BOREAS_V3 boreas_tree_gather3(__global const float* planes, int n, int plane,
                                        BOREAS_I i) {
#if BOREAS_W == 1
  return boreas_tree_load3(planes, n, plane, i);
#else
  return boreas_v3(BOREAS_GATHER(planes, plane * n + i), BOREAS_GATHER(planes, (plane + 1) * n + i),
                   BOREAS_GATHER(planes, (plane + 2) * n + i));
#endif
}

/* The curve and O of each lane's entry i (boreas_tree_load_curve per lane). */
BOREAS_FN BOREAS_BEZIER boreas_tree_gather_curve(__global const float* state, int n, BOREAS_I i,
                                                 BOREAS_V3* o) {
  BOREAS_BEZIER c;
  c.p0 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

/* The radius functions of each lane's entry i (boreas_tree_load_radius per lane). */
BOREAS_FN BOREAS_RADIUS boreas_tree_gather_radius(__global const float* radius, int n, BOREAS_I i) {
#if BOREAS_W == 1
  return boreas_tree_load_radius(radius, n, i);
#else
  BOREAS_RADIUS r;
  r.radius = BOREAS_GATHER(radius, 0 * n + i);
  r.taper_depth = BOREAS_GATHER(radius, 1 * n + i);
  r.taper_exponent = BOREAS_GATHER(radius, 2 * n + i);
  r.flare = BOREAS_GATHER(radius, 3 * n + i);
  r.bulge_count = BOREAS_GATHER(radius, 4 * n + i);
  r.bulge_depth = BOREAS_GATHER(radius, 5 * n + i);
  r.lobe_count = BOREAS_GATHER(radius, 6 * n + i);
  r.lobe_depth = BOREAS_GATHER(radius, 7 * n + i);
  r.lobe_taper = BOREAS_GATHER(radius, 8 * n + i);
  return r;
#endif
}

BOREAS_FN BOREAS_F boreas_tree_load_w(__global const float* planes, int n, int plane, int first,
                                      int k, int count) {
#if BOREAS_W == 1
  return planes[BOREAS_TREE_AT(plane, n, first + min(k, count - 1))];
#else
  return boreas_load_w(planes + plane * n + first, k, count);
#endif
}

BOREAS_FN void boreas_tree_store_w(__global float* planes, int n, int plane, int first, int k,
                                   int count, BOREAS_F v) {
#if BOREAS_W == 1
  planes[BOREAS_TREE_AT(plane, n, first + min(k, count - 1))] = v;
#else
  boreas_store_w(v, planes + plane * n + first, k, count);
#endif
}

BOREAS_FN BOREAS_V3 boreas_tree_load3_w(__global const float* planes, int n, int plane, int first,
                                        int k, int count) {
  return boreas_v3(boreas_tree_load_w(planes, n, plane, first, k, count),
                   boreas_tree_load_w(planes, n, plane + 1, first, k, count),
                   boreas_tree_load_w(planes, n, plane + 2, first, k, count));
}

BOREAS_FN void boreas_tree_store3_w(__global float* planes, int n, int plane, int first, int k,
                                    int count, BOREAS_V3 v) {
#if BOREAS_W == 1
  boreas_tree_store3(planes, n, plane, first + min(k, count - 1), v);
#else
  boreas_store_w(v.x, planes + plane * n + first, k, count);
  boreas_store_w(v.y, planes + (plane + 1) * n + first, k, count);
  boreas_store_w(v.z, planes + (plane + 2) * n + first, k, count);
#endif
}
#endif

#endif
