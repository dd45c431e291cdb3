/* boreas: the branch deformer (Skjermo 2007 sec. 3) — a (v, theta) grid per branch swept
 * along the branch's animated Bezier: radius functions (eq. 2-5), generalized de Casteljau
 * with Sloan handles (eq. 7-9), Jacobian normals (sec. 3.4). Each branch is a grid of
 * (rings + 1) x (sides + 1) vertices (the seam duplicated for its uv), v = ring / rings,
 * theta = side / sides turns.
 *
 * One launch covers any set of (tree, level) ranges: one work-group per tile
 * (cl/shared/launch_tiles.h; trees/tree_record_tiles.h builds them), a tile a run of the
 * vertices of one range of branches of one level of one tree, its fields read as: FIRST
 * the run's first vertex counted from the range's first, COUNT, STATIC the range's first
 * branch's template entry (radius functions, stride sn; the radius times the tree's scale
 * SCALE), ROOT the range's first branch's state entry (stride n), VALUE the level's rings,
 * SCALE_ROOT its sides (ints), OBJECT where the range's vertices start in the output.
 * Output planes (stride out_n) from vertex out_first: position, normal, uv (u = theta in
 * turns, v). Each work-item makes BOREAS_W consecutive vertices of its tile (simd_width.h);
 * lanes past the tile's count redo its last vertex and store nothing. A branch's curve is
 * read through boreas_tree_gather_pose (tree_state.h: stored, posed (posed, stride pn: the
 * settled branches the host posed for this launch) or derived; motion and shape, the latter
 * stride sn like the radius functions, for the derived ones). */
#include "shared/launch_tiles.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_deform(__global const float* state, __global const float* motion, int n,
                                 __global const float* shape, __global const float* radius, int sn,
                                 __global const float* settled, int tn, __global const float* posed, int pn,
                                 __global const int* tiles, int tile_first, __global float* out, int out_n,
                                 int out_first) {
  const int tile = boreas_tile(tile_first);
  const int run = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST);
  const int end = run + boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT);
  const int rings = boreas_tile_int(tiles, tile, BOREAS_TILE_VALUE);
  const int sides = boreas_tile_int(tiles, tile, BOREAS_TILE_SCALE_ROOT);
  const int per_branch = (rings + 1) * (sides + 1);
  int k0 = run + (int)get_local_id(0) * BOREAS_W;
  BOREAS_I k = min(k0 + BOREAS_LANES, end - 1);
  BOREAS_I b = boreas_div_w(k, per_branch);
  BOREAS_I r = k - b * per_branch;
  BOREAS_I ring = boreas_div_w(r, sides + 1);
  BOREAS_I side = r - ring * (sides + 1);
  BOREAS_I i = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + b;

  BOREAS_V3 o;
  BOREAS_BEZIER c = boreas_tree_gather_pose(state, motion, shape, settled, posed, n, sn, tn, pn, i, &o);
  BOREAS_RADIUS rp = boreas_tree_gather_radius(radius, sn, boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + b);
  rp.radius *= boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);

  BOREAS_F grid_v = BOREAS_TO_FLOAT(ring) / (float)rings;
  BOREAS_F v = boreas_ring_v(BOREAS_TO_FLOAT(ring), rings, rp.tip_cap);
  BOREAS_F turns = BOREAS_TO_FLOAT(side) / (float)sides;
  BOREAS_F sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
  BOREAS_F cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
  BOREAS_SLOAN f = boreas_sloan_frame(c, o);
  BOREAS_V3 pos, nrm;
  boreas_branch_surface(c, f, rp, v, turns, sin_t, cos_t, &pos, &nrm);
  __global float* w = out + out_first + boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT);
  boreas_store_w(pos.x, w + (BOREAS_TREE_VERTEX_POSITION + 0) * out_n, k0, end);
  boreas_store_w(pos.y, w + (BOREAS_TREE_VERTEX_POSITION + 1) * out_n, k0, end);
  boreas_store_w(pos.z, w + (BOREAS_TREE_VERTEX_POSITION + 2) * out_n, k0, end);
  boreas_store_w(nrm.x, w + (BOREAS_TREE_VERTEX_NORMAL + 0) * out_n, k0, end);
  boreas_store_w(nrm.y, w + (BOREAS_TREE_VERTEX_NORMAL + 1) * out_n, k0, end);
  boreas_store_w(nrm.z, w + (BOREAS_TREE_VERTEX_NORMAL + 2) * out_n, k0, end);
  boreas_store_w(turns, w + (BOREAS_TREE_VERTEX_UV + 0) * out_n, k0, end);
  boreas_store_w(grid_v, w + (BOREAS_TREE_VERTEX_UV + 1) * out_n, k0, end);
}
