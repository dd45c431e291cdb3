/* boreas: the branch deformer (Skjermo 2007 sec. 3) — a (v, theta) grid per branch swept
 * along the branch's animated Bezier: radius functions (eq. 2-5), generalized de Casteljau
 * with Sloan handles (eq. 7-9), Jacobian normals (sec. 3.4). One work-item per vertex of
 * `count` branches starting at `first`, each a grid of (rings + 1) x (sides + 1) vertices
 * (the seam duplicated for its uv), v = ring / rings, theta = side / sides turns.
 * The state is the tree's (stride n, from `first`), the radius functions its template's
 * (stride sn, from `static_first`; the radius times the tree's scale).
 * Output planes (stride out_n) from vertex out_first: position, normal, uv (u = theta in
 * turns, v). The global size may exceed the vertex count; extra work-items redo the last. */
#include "shared/tree_state.h"

__kernel void boreas_tree_deform(__global const float* state, int n, __global const float* radius, int sn,
                                 int first, int static_first, int count, float scale, int rings, int sides,
                                 __global float* out, int out_n, int out_first) {
  int per_branch = (rings + 1) * (sides + 1);
  int k = min((int)get_global_id(0), count * per_branch - 1);
  int b = k / per_branch;
  int r = k - b * per_branch;
  int ring = r / (sides + 1);
  int side = r - ring * (sides + 1);
  int i = first + b;

  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, i, &o);
  BoreasBranchRadius rp = boreas_tree_load_radius(radius, sn, static_first + b);
  rp.radius *= scale;

  float v = (float)ring / (float)rings;
  float turns = (float)side / (float)sides;
  float sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
  float cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
  BoreasSloanFrame f = boreas_sloan_frame(c, o);
  BoreasV3 pos, nrm;
  boreas_branch_surface(c, f, rp, v, turns, sin_t, cos_t, &pos, &nrm);
  int w = out_first + k;
  out[(BOREAS_TREE_VERTEX_POSITION + 0) * out_n + w] = pos.x;
  out[(BOREAS_TREE_VERTEX_POSITION + 1) * out_n + w] = pos.y;
  out[(BOREAS_TREE_VERTEX_POSITION + 2) * out_n + w] = pos.z;
  out[(BOREAS_TREE_VERTEX_NORMAL + 0) * out_n + w] = nrm.x;
  out[(BOREAS_TREE_VERTEX_NORMAL + 1) * out_n + w] = nrm.y;
  out[(BOREAS_TREE_VERTEX_NORMAL + 2) * out_n + w] = nrm.z;
  out[(BOREAS_TREE_VERTEX_UV + 0) * out_n + w] = turns;
  out[(BOREAS_TREE_VERTEX_UV + 1) * out_n + w] = v;
}
