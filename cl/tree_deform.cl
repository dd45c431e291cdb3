/* boreas: the branch deformer (Skjermo 2007 sec. 3) — a (v, theta) grid per branch swept
 * along the branch's animated Bezier: radius functions (eq. 2-5), generalized de Casteljau
 * with Sloan handles (eq. 7-9), Jacobian normals (sec. 3.4). One work-item per vertex of
 * `count` branches starting at `first`, each a grid of (rings + 1) x (sides + 1) vertices
 * (the seam duplicated for its uv), v = ring / rings, theta = side / sides turns.
 * The state is the tree's (stride n, from `first`), the radius functions its template's
 * (stride sn, from `static_first`; the radius times the tree's scale).
 * Output planes (stride out_n) from vertex out_first: position, normal, uv (u = theta in
 * turns, v). Each work-item makes BOREAS_W consecutive vertices (simd_width.h); the
 * global size may exceed ceil(vertices / W); lanes past the last vertex redo it and store
 * nothing. */
#include "shared/tree_state.h"

__kernel void boreas_tree_deform(__global const float* state, int n, __global const float* radius, int sn,
                                 int first, int static_first, int count, float scale, int rings, int sides,
                                 __global float* out, int out_n, int out_first) {
  int per_branch = (rings + 1) * (sides + 1);
  int total = count * per_branch;
  int k0 = (int)get_global_id(0) * BOREAS_W;
  BOREAS_I k = min(k0 + BOREAS_LANES, total - 1);
  BOREAS_I b = boreas_div_w(k, per_branch);
  BOREAS_I r = k - b * per_branch;
  BOREAS_I ring = boreas_div_w(r, sides + 1);
  BOREAS_I side = r - ring * (sides + 1);
  BOREAS_I i = first + b;

  BOREAS_V3 o;
  BOREAS_BEZIER c = boreas_tree_gather_curve(state, n, i, &o);
  BOREAS_RADIUS rp = boreas_tree_gather_radius(radius, sn, static_first + b);
  rp.radius *= scale;

  BOREAS_F v = BOREAS_TO_FLOAT(ring) / (float)rings;
  BOREAS_F turns = BOREAS_TO_FLOAT(side) / (float)sides;
  BOREAS_F sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
  BOREAS_F cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
  BOREAS_SLOAN f = boreas_sloan_frame(c, o);
  BOREAS_V3 pos, nrm;
  boreas_branch_surface(c, f, rp, v, turns, sin_t, cos_t, &pos, &nrm);
  __global float* w = out + out_first;
  boreas_store_w(pos.x, w + (BOREAS_TREE_VERTEX_POSITION + 0) * out_n, k0, total);
  boreas_store_w(pos.y, w + (BOREAS_TREE_VERTEX_POSITION + 1) * out_n, k0, total);
  boreas_store_w(pos.z, w + (BOREAS_TREE_VERTEX_POSITION + 2) * out_n, k0, total);
  boreas_store_w(nrm.x, w + (BOREAS_TREE_VERTEX_NORMAL + 0) * out_n, k0, total);
  boreas_store_w(nrm.y, w + (BOREAS_TREE_VERTEX_NORMAL + 1) * out_n, k0, total);
  boreas_store_w(nrm.z, w + (BOREAS_TREE_VERTEX_NORMAL + 2) * out_n, k0, total);
  boreas_store_w(turns, w + (BOREAS_TREE_VERTEX_UV + 0) * out_n, k0, total);
  boreas_store_w(v, w + (BOREAS_TREE_VERTEX_UV + 1) * out_n, k0, total);
}
