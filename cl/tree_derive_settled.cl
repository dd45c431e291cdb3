/* boreas: settled branches (cl/shared/tree_state.h, the posed scratch) posed for the readers
 * that read a branch once per item: the deformer and the leaf records, which would
 * otherwise derive each settled branch lane by lane, some 18-31 times over. tree_derive.cl
 * poses own entries in place; a settled entry has no state planes, so its pose goes to a
 * row of the posed planes (15, BOREAS_TREE_STATE_* order, stride pn), and its SCALE plane
 * takes ~row until the host launches this kernel again with `restore` 1 (right after the
 * reading launch), which writes every posed entry's scale back from its tile.
 *
 * Tiles (cl/shared/launch_tiles.h), made by the host per call: FIRST the tile's first
 * settled entry, COUNT (a few times the group size: each work-item takes entries k,
 * k + group size, ...), SCALE its tree's scale, OBJECT its slot's row in the view table (slot
 * + 1). With use_table, only rows the cull drew are posed. A tile's rows are taken
 * together from `counter` (an int the host zeroes first and reads back: the rows asked
 * for, drawn or not past pn); a tile whose rows pass pn is not posed, and its readers
 * derive it as before (the same bits, at their old cost). */
#include "shared/launch_tiles.h"
#include "shared/tree_records.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_derive_settled(__global const float* state, int n,
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
    for (int j = j0 + k0; j < j0 + count; j += step)
      if (boreas_tree_posed_row(settled, tn, j) >= 0)
        settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_SCALE, tn, j)] = boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);
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
  for (int k = k0; k < count; k += step) {
    /* Its own scale (not posed: every pose is restored after its reads) and its parent's
     * own entry: no work-item reads what another writes. */
    const int j = j0 + k, r = first + k;
    BoreasV3 o;
    const BoreasBezier c = boreas_tree_derive_settled(state, shape, settled, n, sn, tn, j, &o);
    boreas_tree_store3(posed, pn, BOREAS_TREE_STATE_P0, r, c.p0);
    boreas_tree_store3(posed, pn, BOREAS_TREE_STATE_P1, r, c.p1);
    boreas_tree_store3(posed, pn, BOREAS_TREE_STATE_P2, r, c.p2);
    boreas_tree_store3(posed, pn, BOREAS_TREE_STATE_P3, r, c.p3);
    boreas_tree_store3(posed, pn, BOREAS_TREE_STATE_O, r, o);
    ((__global int*)settled)[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_SCALE, tn, j)] = ~r;
  }
}
