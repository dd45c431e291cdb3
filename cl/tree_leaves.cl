/* boreas: one tree's leaf instances from its animated branches, written as records (the
 * blade's base, axis and normal: BOREAS_LEAF_RECORD_FLOATS floats, boreas_cl.h) — each leaf
 * re-attached to its last-level branch exactly as a child branch is (boreas_attach), its
 * blade starting a petiole's length (the template's, times the tree's scale) out along its
 * axis, its blade turned about that axis by its roll (LeafBend). A leaf is a function of its branch's current state alone, so leaves are made when
 * they are read (boreas_tree_get_leaves, boreas_tree_enqueue_leaf_records), never stored
 * or stepped: a forest's hundreds of millions of leaves cost nothing until drawn.
 * The parent index and placement are the tree's template's (stride sm, from static_first),
 * the parent counted from the tree's root entry of the state. One work-item per leaf; the
 * global size may exceed count (extra items redo the last). */
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, int n, __global const int* parents,
                                 __global const float* leaves, int sm, int static_first, int count, int root,
                                 float scale, __global float* out, int out_first) {
  int k = min((int)get_global_id(0), count - 1);
  int j = static_first + k;
  int p = root + parents[j];
  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, p, &o);
  BoreasAttachFrame a = boreas_attach(c, o, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_V, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_THETA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_THETA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_ALPHA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_ALPHA, sm, j)]);
  BoreasV3 base = boreas_v3_madd(a.origin, a.x, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_STEM, sm, j)] * scale);
  BoreasV3 normal = boreas_v3_lin2(a.y, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_ROLL, sm, j)], a.z,
                                   leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_ROLL, sm, j)]);
  __global float* r = out + (size_t)(out_first + k) * BOREAS_TREE_LEAF_OUT_PLANES;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 0] = base.x;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 1] = base.y;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 2] = base.z;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 0] = a.x.x;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 1] = a.x.y;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 2] = a.x.z;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 0] = normal.x;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 1] = normal.y;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 2] = normal.z;
}
