/* boreas: leaf instances from the animated branches — each leaf re-attached to its
 * last-level branch exactly as a child branch is (boreas_attach), its blade starting a
 * petiole's length out along its axis. Run after the step, on the state just written, so
 * leaves never lag their branch. The global size may exceed count; extra work-items redo
 * the last leaf. */
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, int n, __global const int* parents,
                                 __global const float* leaves, __global float* out, int count,
                                 int leaf_stride) {
  int i = min((int)get_global_id(0), count - 1);
  int m = leaf_stride;
  int p = parents[i];
  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, p, &o);
  BoreasAttachFrame a = boreas_attach(c, o, leaves[BOREAS_TREE_LEAF_V * m + i],
                                      leaves[BOREAS_TREE_LEAF_COS_THETA * m + i],
                                      leaves[BOREAS_TREE_LEAF_SIN_THETA * m + i],
                                      leaves[BOREAS_TREE_LEAF_COS_ALPHA * m + i],
                                      leaves[BOREAS_TREE_LEAF_SIN_ALPHA * m + i]);
  BoreasV3 base = boreas_v3_madd(a.origin, a.x, leaves[BOREAS_TREE_LEAF_STEM * m + i]);
  out[(BOREAS_TREE_LEAF_OUT_POSITION + 0) * m + i] = base.x;
  out[(BOREAS_TREE_LEAF_OUT_POSITION + 1) * m + i] = base.y;
  out[(BOREAS_TREE_LEAF_OUT_POSITION + 2) * m + i] = base.z;
  out[(BOREAS_TREE_LEAF_OUT_AXIS + 0) * m + i] = a.x.x;
  out[(BOREAS_TREE_LEAF_OUT_AXIS + 1) * m + i] = a.x.y;
  out[(BOREAS_TREE_LEAF_OUT_AXIS + 2) * m + i] = a.x.z;
  out[(BOREAS_TREE_LEAF_OUT_NORMAL + 0) * m + i] = a.y.x;
  out[(BOREAS_TREE_LEAF_OUT_NORMAL + 1) * m + i] = a.y.y;
  out[(BOREAS_TREE_LEAF_OUT_NORMAL + 2) * m + i] = a.y.z;
}
