/* boreas: leaf instances from the animated branches — each leaf re-attached to its
 * last-level branch exactly as a child branch is (boreas_attach), its blade starting a
 * petiole's length out along its axis. Run after the step, on the state just written, so
 * leaves never lag their branch; the leaves are listed by tiles (a tree's leaves are
 * consecutive), so one launch serves any set of trees. */
#include "shared/launch_tiles.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, int n, __global const int* parents,
                                 __global const float* leaves, __global float* out, int leaf_stride,
                                 __global const int* tiles, int tile_first) {
  int i = boreas_tile_item(tiles, boreas_tile(tile_first));
  int m = leaf_stride;
  int p = parents[i];
  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, p, &o);
  BoreasAttachFrame a = boreas_attach(c, o, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_V, m, i)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_THETA, m, i)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_THETA, m, i)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_ALPHA, m, i)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_ALPHA, m, i)]);
  BoreasV3 base = boreas_v3_madd(a.origin, a.x, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_STEM, m, i)]);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_POSITION, i, base);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_AXIS, i, a.x);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_NORMAL, i, a.y);
}
