/* boreas: derived branches (cl/shared/tree_state.h) written out for the readers that read
 * many items of one branch. A derived branch's state holds marks, and every reader derives
 * its pose from them (boreas_tree_pose), so a reader is right without this kernel; but the
 * deformer and the leaf records read a branch once per vertex or leaf, at a width where
 * deriving costs about what the item's own work does. Before they run, the host launches
 * this kernel with `marks` 0 over the derived branches they will read: each one's pose
 * (boreas_tree_pose, bit for bit) written over its marks in the current half, its row's
 * flag in `posed` set; they then read stored poses. A posed half must not outlive the
 * state it was derived from: before the next step commits, the host launches it with
 * `marks` 1, which writes every posed row's marks back (from its tile: its tree's root,
 * template entry and scale) and clears nothing (the host clears the flags).
 *
 * Tiles (cl/shared/launch_tiles.h): the batch's derived ranges, one tree's finest level
 * each: FIRST its first entry, COUNT, STATIC its first template entry, ROOT the tree's root
 * entry (the parents count from it), SCALE its scale, OBJECT its row in the view table and
 * out table (slot + 1; 0: a dead tile, skipped). With `table` (all 0 or 1 rows' out rows,
 * cl/shared/tree_records.h), only drawn rows are posed; one work-item per branch, none for
 * the items past a tile's count (one writes what another reads). */
#include "shared/launch_tiles.h"
#include "shared/tree_records.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_derive(__global float* state, __global const float* motion, int n,
                                 __global const int* parents, __global const float* shape, int sn,
                                 __global const int* tiles, int tile_first,
                                 __global const int* table, int use_table, __global int* posed,
                                 int marks) {
  const int tile = boreas_tile(tile_first);
  const int k = (int)get_local_id(0);
  const int row = boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT);
  if (k >= boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT) || row == 0) return;
  const int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + k;
  if (marks) {
    if (!posed[row]) return;
    const int s = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + k;
    __global int* bits = (__global int*)state; /* the mark and entries as ints, bit for bit */
    bits[BOREAS_TREE_AT(BOREAS_TREE_STATE_P0, n, i)] = BOREAS_TREE_DERIVED_MARK;
    bits[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_PARENT, n, i)] = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + parents[s];
    bits[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_STATIC, n, i)] = s;
    state[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_SCALE, n, i)] = boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);
    return;
  }
  if (use_table && table[row * BOREAS_TREE_OUT_INTS + BOREAS_TREE_OUT_KIND] != BOREAS_TREE_KIND_DRAWN) return;
  BoreasV3 o;
  /* Its tiles are entries of the trees' own planes (marked, or posed already): no settled
   * space is read (shape binds it, stride 0). */
  BoreasBezier c = boreas_tree_pose(state, motion, shape, shape, n, sn, 0, i, &o);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i, c.p0);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, i, c.p1);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, i, c.p2);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, i, c.p3);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, o);
  posed[row] = 1;
}
