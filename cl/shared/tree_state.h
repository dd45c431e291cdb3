/* boreas: reading and writing a branch's animated state — three planes per vector
 * (cl/shared/tree_types.h). Compiles as OpenCL C (global memory) and as C/C++ (host
 * memory), so the kernels, the host's rest placement and the native twins share it. */
#ifndef BOREAS_CL_SHARED_TREE_STATE_H
#define BOREAS_CL_SHARED_TREE_STATE_H

#include "shared/tree_math.h"
#include "shared/tree_types.h"

#ifdef __OPENCL_C_VERSION__
#define BOREAS_TS_GLOBAL __global
#else
#include <stddef.h>
#define BOREAS_TS_GLOBAL
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
BOREAS_TM_FN BoreasV3 boreas_tree_load3(BOREAS_TS_GLOBAL const float* planes, int n, int plane, int i) {
  return boreas_v3(planes[BOREAS_TREE_AT(plane, n, i)], planes[BOREAS_TREE_AT(plane + 1, n, i)],
                   planes[BOREAS_TREE_AT(plane + 2, n, i)]);
}

BOREAS_TM_FN void boreas_tree_store3(BOREAS_TS_GLOBAL float* planes, int n, int plane, int i, BoreasV3 v) {
  planes[BOREAS_TREE_AT(plane, n, i)] = v.x;
  planes[BOREAS_TREE_AT(plane + 1, n, i)] = v.y;
  planes[BOREAS_TREE_AT(plane + 2, n, i)] = v.z;
}

/* The radius functions of branch i (planes in BoreasBranchRadius's field order). */
BOREAS_TM_FN BoreasBranchRadius boreas_tree_load_radius(BOREAS_TS_GLOBAL const float* radius, int n, int i) {
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
BOREAS_TM_FN BoreasBezier boreas_tree_load_curve(BOREAS_TS_GLOBAL const float* state, int n, int i, BoreasV3* o) {
  BoreasBezier c;
  c.p0 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_load3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

#endif
