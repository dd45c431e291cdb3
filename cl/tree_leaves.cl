/* boreas: leaf instances from the animated branches — each leaf re-attached to its
 * last-level branch exactly as a child branch is (boreas_attach), its blade starting a
 * petiole's length (the template's, times the tree's scale) out along its axis. Run after
 * the step, on the state just written, so leaves never lag their branch; the leaves are
 * listed by tiles (a tree's leaves are consecutive), so one launch serves any set of
 * trees. The output is the tree's own (stride m, entry FIRST + k); the parent index and
 * placement are its template's (stride sm, entry STATIC + k), the parent counted from the
 * tree's root entry of the state. */
#include "shared/launch_tiles.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, int n, __global const int* parents,
                                 __global const float* leaves, int sm, __global float* out, int m,
                                 __global const int* tiles, int tile_first) {
  int tile = boreas_tile(tile_first);
  int k = boreas_tile_offset(tiles, tile);
  int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + k;
  int j = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + k;
  int p = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + parents[j];
  float scale = boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);
  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, p, &o);
  BoreasAttachFrame a = boreas_attach(c, o, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_V, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_THETA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_THETA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_COS_ALPHA, sm, j)],
                                      leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_SIN_ALPHA, sm, j)]);
  BoreasV3 base = boreas_v3_madd(a.origin, a.x, leaves[BOREAS_TREE_AT(BOREAS_TREE_LEAF_STEM, sm, j)] * scale);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_POSITION, i, base);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_AXIS, i, a.x);
  boreas_tree_store3(out, m, BOREAS_TREE_LEAF_OUT_NORMAL, i, a.y);
}
