/* boreas: device records for renderers that draw straight from OpenCL buffers (CL-GL
 * interop, boreas_cl.h). The state lives in planes (structure of arrays) because that is
 * what PoCL vectorizes; a renderer wants one record per instance (array of structures),
 * which a vertex shader reads with one index. This kernel gathers branches (their pose,
 * stored or derived through boreas_tree_read_pose, their template's radius functions at their
 * tree's scale) into such records: nothing can differ from boreas_tree_get_branches, which
 * reads its derived branches through this kernel. Leaf records are made by
 * cl/tree_leaves.cl itself (leaves are made when read).
 *
 * Branch record (BOREAS_BRANCH_RECORD_FLOATS = 28): P0..P3 (x y z each), O (x y z), then
 * the first 9 radius-function values in BoreasBranchRadius's order, the broken flag (0 or 1),
 * the tip's cap (BOREAS_TREE_RECORD_TIP_CAP), the beads' phase (BOREAS_TREE_RECORD_BULGE_PHASE)
 * and a zero (a record of seven vec4s).
 *
 * One launch covers any set of trees: one work-group per tile of the batch's branch tiles
 * (cl/shared/launch_tiles.h), a tile a run of one tree's branches: FIRST the first one's
 * state entry (stride n), COUNT, STATIC its template entry (stride sn), ROOT the tree's
 * root entry (a branch's record within its tree is its entry - ROOT - 1), SCALE its scale,
 * OBJECT its slot's row (the out table's; the offsets', shared/tree_origin.h: positions are
 * its base's plus that row's offset). One branch per work-item; items past the tile's count redo its last.
 * Settled branches are read from the posed scratch where the view call posed them
 * (posed, stride pn: tree_batch_posed.cpp, for its leaves; the derivation otherwise).
 * Where a tree's records go: with one_tree, from out_first (the per-tree call, launched
 * over that tree's tiles alone); otherwise from out_first plus its row's branch first in
 * the out table (cl/shared/tree_records.h), and nowhere where that is -1. */
#include "shared/launch_tiles.h"
#include "shared/tree_origin.h"
#include "shared/tree_records.h"
#include "shared/tree_state.h"

__kernel void boreas_export_branch_records(__global const float* state, __global const float* motion, int n,
                                           __global const float* shape, __global const float* radius, int sn,
                                           __global const float* settled, int tn,
                                           __global const float* posed, int pn, __global const int* tiles,
                                           int tile_first, __global const int* table, int one_tree,
                                           __global float* out, int out_first,
                                           __global const float* offsets) {
  const int tile = boreas_tile(tile_first);
  const int k = boreas_tile_offset(tiles, tile);
  int base = out_first;
  if (!one_tree) {
    const int object = boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT);
    const int first = table[object * BOREAS_TREE_OUT_INTS + BOREAS_TREE_OUT_BRANCH_FIRST];
    if (first < 0) return;
    base += first;
  }
  const int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + k;
  const int j = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + k;
  const int record = i - boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) - 1;
  __global float* o = out + (size_t)(base + record) * BOREAS_TREE_RECORD_FLOATS;
  /* Its pose, stored, posed or derived (tree_state.h). */
  BoreasV3 orientation;
  BoreasBezier c = boreas_tree_read_pose(state, motion, shape, settled, posed, n, sn, tn, pn, i, &orientation);
  /* Positions from the tree's base to the caller's frame (shared/tree_origin.h). */
  const BoreasV3 offset = boreas_tree_offset(offsets, boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT));
  BoreasV3 v[5] = {boreas_v3_add(c.p0, offset), boreas_v3_add(c.p1, offset),
                   boreas_v3_add(c.p2, offset), boreas_v3_add(c.p3, offset), orientation};
  for (int p = 0; p < 5; ++p) {
    o[3 * p] = v[p].x;
    o[3 * p + 1] = v[p].y;
    o[3 * p + 2] = v[p].z;
  }
  /* The template's radius functions; only the radius itself is a length. */
  for (int p = 0; p < BOREAS_TREE_RADIUS_TIP_CAP; ++p) o[BOREAS_TREE_STATE_PLANES + p] = radius[BOREAS_TREE_AT(p, sn, j)];
  o[BOREAS_TREE_STATE_PLANES] *= boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);
  o[BOREAS_TREE_RECORD_BROKEN] = boreas_tree_broken(motion, settled, n, tn, i);
  /* The cap is a ratio (tip radius over length): the tree's scale leaves it. */
  o[BOREAS_TREE_RECORD_TIP_CAP] = radius[BOREAS_TREE_AT(BOREAS_TREE_RADIUS_TIP_CAP, sn, j)];
  /* The beads' phase is counted in beads: a ratio too. */
  o[BOREAS_TREE_RECORD_BULGE_PHASE] = radius[BOREAS_TREE_AT(BOREAS_TREE_RADIUS_BULGE_PHASE, sn, j)];
  for (int p = BOREAS_TREE_RECORD_BULGE_PHASE + 1; p < BOREAS_TREE_RECORD_FLOATS; ++p) o[p] = 0.0f;
}
