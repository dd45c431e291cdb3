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
  boreas_i k = min(k0 + BOREAS_LANES, total - 1);
  boreas_i b = boreas_div_w(k, per_branch);
  boreas_i r = k - b * per_branch;
  boreas_i ring = boreas_div_w(r, sides + 1);
  boreas_i side = r - ring * (sides + 1);
  boreas_i i = first + b;

  boreas_v3w o;
  boreas_bezier_w c = boreas_tree_gather_curve(state, n, i, &o);
  boreas_radius_w rp = boreas_tree_gather_radius(radius, sn, static_first + b);
  rp.radius *= scale;

  boreas_f v = boreas_to_f(ring) / (float)rings;
  boreas_f turns = boreas_to_f(side) / (float)sides;
  boreas_f sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
  boreas_f cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
  boreas_sloan_w f = boreas_sloan_frame(c, o);
  boreas_v3w pos, nrm;
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
