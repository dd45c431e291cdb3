/* boreas: one tree's leaf instances from its animated branches, written as records (the
 * blade's base, axis and normal: BOREAS_LEAF_RECORD_FLOATS floats, boreas_cl.h) — each leaf
 * re-attached to its last-level branch exactly as a child branch is (boreas_attach), its
 * blade starting a petiole's length (the template's, times the tree's scale) out along its
 * axis, its blade turned about that axis by its roll (LeafBend). A leaf is a function of its branch's current state alone, so leaves are made when
 * they are read (boreas_tree_get_leaves, boreas_tree_enqueue_leaf_records), never stored
 * or stepped: a forest's hundreds of millions of leaves cost nothing until drawn.
 * The parent index and placement are the tree's template's (stride sm, from static_first),
 * the parent counted from the tree's root entry of the state. Each work-item places
 * BOREAS_W consecutive leaves (simd_width.h), their parents gathered per lane; the records
 * are written lane by lane (records interleave their floats, so lanes are not
 * contiguous). The global size may exceed ceil(count / W); lanes past the count redo the
 * last leaf and write nothing. */
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, int n, __global const int* parents,
                                 __global const float* leaves, int sm, int static_first, int count, int root,
                                 float scale, __global float* out, int out_first) {
  int k = (int)get_global_id(0) * BOREAS_W;
  BOREAS_I p = root + boreas_load_wi(parents + static_first, k, count);
  BOREAS_V3 o;
  BOREAS_BEZIER c = boreas_tree_gather_curve(state, n, p, &o);
#define BOREAS_LEAF(plane) boreas_tree_load_w(leaves, sm, (plane), static_first, k, count)
  BOREAS_ATTACH a = boreas_attach(
      c, o, BOREAS_LEAF(BOREAS_TREE_LEAF_V), BOREAS_LEAF(BOREAS_TREE_LEAF_COS_THETA),
      BOREAS_LEAF(BOREAS_TREE_LEAF_SIN_THETA), BOREAS_LEAF(BOREAS_TREE_LEAF_COS_ALPHA),
      BOREAS_LEAF(BOREAS_TREE_LEAF_SIN_ALPHA));
  BOREAS_V3 base = boreas_v3_madd(a.origin, a.x, BOREAS_LEAF(BOREAS_TREE_LEAF_STEM) * scale);
  BOREAS_V3 normal = boreas_v3_lin2(a.y, BOREAS_LEAF(BOREAS_TREE_LEAF_COS_ROLL), a.z,
                                    BOREAS_LEAF(BOREAS_TREE_LEAF_SIN_ROLL));
#undef BOREAS_LEAF
#if BOREAS_W == 1
  __global float* r = out + (size_t)(out_first + min(k, count - 1)) * BOREAS_TREE_LEAF_OUT_PLANES;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 0] = base.x;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 1] = base.y;
  r[BOREAS_TREE_LEAF_OUT_POSITION + 2] = base.z;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 0] = a.x.x;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 1] = a.x.y;
  r[BOREAS_TREE_LEAF_OUT_AXIS + 2] = a.x.z;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 0] = normal.x;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 1] = normal.y;
  r[BOREAS_TREE_LEAF_OUT_NORMAL + 2] = normal.z;
#else
  /* The 9 values of each lane, then each lane's record. */
  float v[9][BOREAS_W];
  BOREAS_CAT(vstore, BOREAS_W)(base.x, 0, v[BOREAS_TREE_LEAF_OUT_POSITION + 0]);
  BOREAS_CAT(vstore, BOREAS_W)(base.y, 0, v[BOREAS_TREE_LEAF_OUT_POSITION + 1]);
  BOREAS_CAT(vstore, BOREAS_W)(base.z, 0, v[BOREAS_TREE_LEAF_OUT_POSITION + 2]);
  BOREAS_CAT(vstore, BOREAS_W)(a.x.x, 0, v[BOREAS_TREE_LEAF_OUT_AXIS + 0]);
  BOREAS_CAT(vstore, BOREAS_W)(a.x.y, 0, v[BOREAS_TREE_LEAF_OUT_AXIS + 1]);
  BOREAS_CAT(vstore, BOREAS_W)(a.x.z, 0, v[BOREAS_TREE_LEAF_OUT_AXIS + 2]);
  BOREAS_CAT(vstore, BOREAS_W)(normal.x, 0, v[BOREAS_TREE_LEAF_OUT_NORMAL + 0]);
  BOREAS_CAT(vstore, BOREAS_W)(normal.y, 0, v[BOREAS_TREE_LEAF_OUT_NORMAL + 1]);
  BOREAS_CAT(vstore, BOREAS_W)(normal.z, 0, v[BOREAS_TREE_LEAF_OUT_NORMAL + 2]);
  __global float* r = out + (size_t)(out_first + k) * BOREAS_TREE_LEAF_OUT_PLANES;
  for (int l = 0; l < BOREAS_W && k + l < count; ++l)
    for (int f = 0; f < BOREAS_TREE_LEAF_OUT_PLANES; ++f) r[l * BOREAS_TREE_LEAF_OUT_PLANES + f] = v[f][l];
#endif
}
