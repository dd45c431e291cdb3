/* boreas: reading and writing a branch's animated state in the kernels — three planes
 * per vector (cl/shared/tree_types.h). OpenCL C only: the host has its own copies. */
#ifndef BOREAS_CL_SHARED_TREE_STATE_H
#define BOREAS_CL_SHARED_TREE_STATE_H

#include "shared/tree_math.h"
#include "shared/tree_types.h"

/* The vector in planes plane, plane + 1, plane + 2 (stride n) at index i. */
BOREAS_TM_FN BoreasV3 boreas_tree_load3(__global const float* planes, int n, int plane, int i) {
  return boreas_v3(planes[plane * n + i], planes[(plane + 1) * n + i], planes[(plane + 2) * n + i]);
}

BOREAS_TM_FN void boreas_tree_store3(__global float* planes, int n, int plane, int i, BoreasV3 v) {
  planes[plane * n + i] = v.x;
  planes[(plane + 1) * n + i] = v.y;
  planes[(plane + 2) * n + i] = v.z;
}

/* Branch i's curve and orientation vector O. */
BOREAS_TM_FN BoreasBezier boreas_tree_load_curve(__global const float* state, int n, int i, BoreasV3* o) {
  BoreasBezier c;
  c.p0 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_load3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

#endif
