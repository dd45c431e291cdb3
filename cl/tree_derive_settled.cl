/* boreas: settled branches (cl/shared/tree_state.h, the posed scratch) posed for the readers
 * that read a branch once per item: the deformer and the leaf records, which would
 * otherwise derive each settled branch lane by lane, some 18-31 times over. tree_derive.cl
 * poses own entries in place; a settled entry has no state planes, so its pose goes to a
 * row of the posed planes (15, BOREAS_TREE_STATE_* order, stride pn), and its SCALE plane
 * takes ~row until the host launches this kernel again with `restore` 1 (right after the
 * reading launch), which writes every posed tile's scales back from the tile.
 *
 * Tiles (cl/shared/launch_tiles.h), made by the host and uploaded when they change: FIRST
 * the tile's first settled entry, COUNT (up to the group size times BOREAS_W: a work-item
 * derives BOREAS_W consecutive entries at once, lane by lane), SCALE its tree's scale,
 * OBJECT its slot's row in the view table (slot + 1). With use_table, only rows the cull drew are posed. A tile's rows are taken
 * together from `counter` (an int the host zeroes first and reads back: the rows asked
 * for, drawn or not past pn); a tile whose rows pass pn is not posed, and its readers
 * derive it as before (the same bits, at their old cost). */
#include "shared/launch_tiles.h"
#include "shared/tree_records.h"
#include "shared/tree_state.h"

/* Entries j0 + k of a tile (k < count, BOREAS_W lanes a work-item, k from k0 * BOREAS_W by
 * step * BOREAS_W) posed into rows first + k, their scales marked. Lanes past the count
 * derive the tile's last entry again and store nothing. The derivation is the readers'
 * own (boreas_tree_gather_pose of an unposed settled entry: every lane derives), so the
 * posed bits are what a reader would derive. Each lane reads its own scale before it
 * writes it, and its chain's inputs, which nothing writes here. */
void boreas_tree_pose_settled_w(__global const float* state, __global const float* motion,
                                __global const float* shape,
                                __global float* settled, __global float* posed, int n, int sn,
                                int tn, int pn, int j0, int count, int first, int k0, int step) {
  __global float* scales = settled + (size_t)BOREAS_TREE_SETTLED_SCALE * (size_t)tn + j0;
  for (int k = k0 * BOREAS_W; k < count; k += step * BOREAS_W) {
    const BOREAS_I j = j0 + min(k + BOREAS_LANES, count - 1);
    BOREAS_V3 o;
    /* pn 0: no posed row is looked at. A split piece's parent may be posed by another
     * work-item meanwhile (its scale being overwritten by the mark): it is derived from
     * its inputs with this entry's scale, as every reader's chain derives (tree_state.h). */
    const BOREAS_BEZIER c = boreas_tree_gather_pose(state, motion, shape, settled, posed, n, sn, tn, 0,
                                                    (BOREAS_I)(n) + j, &o);
    __global float* rows = posed + first;
#define BOREAS_STORE_ROWS(v, plane)                                                   \
    boreas_store_w((v).x, rows + (size_t)(plane) * (size_t)pn, k, count);            \
    boreas_store_w((v).y, rows + (size_t)((plane) + 1) * (size_t)pn, k, count);      \
    boreas_store_w((v).z, rows + (size_t)((plane) + 2) * (size_t)pn, k, count)
    BOREAS_STORE_ROWS(c.p0, BOREAS_TREE_STATE_P0);
    BOREAS_STORE_ROWS(c.p1, BOREAS_TREE_STATE_P1);
    BOREAS_STORE_ROWS(c.p2, BOREAS_TREE_STATE_P2);
    BOREAS_STORE_ROWS(c.p3, BOREAS_TREE_STATE_P3);
    BOREAS_STORE_ROWS(o, BOREAS_TREE_STATE_O);
#undef BOREAS_STORE_ROWS
    boreas_store_w(BOREAS_AS_FLOAT(~((BOREAS_I)(first + k) + BOREAS_LANES)), scales, k, count);
  }
}

/* The scales of a tile's entries written back where they are marked. A tile is posed
 * whole or not at all, so a work-item's first entry says for its lanes: each reads only
 * what it writes. */
void boreas_tree_unpose_settled_w(__global float* settled, int tn, int j0, int count,
                                  float scale, int k0, int step) {
  __global float* scales = settled + (size_t)BOREAS_TREE_SETTLED_SCALE * (size_t)tn + j0;
  for (int k = k0 * BOREAS_W; k < count; k += step * BOREAS_W)
    if (boreas_tree_posed_row(settled, tn, j0 + k) >= 0) boreas_store_w((BOREAS_F)(scale), scales, k, count);
}

__kernel void boreas_tree_derive_settled(__global const float* state,
                                         __global const float* motion, int n,
                                         __global const float* shape, int sn,
                                         __global float* settled, int tn, __global float* posed,
                                         int pn, __global int* counter,
                                         __global const int* tiles, __global const int* table,
                                         int use_table, int restore) {
  const int tile = boreas_tile(0);
  const int k0 = (int)get_local_id(0), step = (int)get_local_size(0);
  const int count = boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT);
  const int j0 = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST);
  if (restore) {
    boreas_tree_unpose_settled_w(settled, tn, j0, count, boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE), k0, step);
    return;
  }
  const int row = boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT);
  __local int first;
  if (k0 == 0)
    first = use_table && table[row * BOREAS_TREE_OUT_INTS + BOREAS_TREE_OUT_KIND] != BOREAS_TREE_KIND_DRAWN
                ? -1
                : atomic_add(counter, count);
  barrier(CLK_LOCAL_MEM_FENCE);
  if (first < 0 || first + count > pn) return;
  boreas_tree_pose_settled_w(state, motion, shape, settled, posed, n, sn, tn, pn, j0, count, first, k0, step);
}