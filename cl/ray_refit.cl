/* boreas: the ray structure's update after a step (host/src/rays/ray_scene.h): the
 * primitives' boxes from the current state, then every node's box as the union of the
 * boxes below it. Each launch covers a list of jobs (one per instance in reach) flattened
 * into one range of work-items: a job is BOREAS_RAY_JOB_WORDS ints, its first item and
 * count, then what its kind needs; a work-item finds its job by binary search. Scalar
 * (width 1): the work is gathers and min/max, bandwidth-bound. */
#include "shared/leaf_outline.h"
#include "shared/ray_math.h"
#include "shared/ray_types.h"
#include "shared/tree_state.h"

#define BOREAS_RAY_JOB_WORDS 8
#define BOREAS_RAY_RUN_WORDS 4

/* The job holding item k (jobs sorted by their first item), and k's index within it. */
int boreas_ray_job(__global const int* jobs, int job_count, int k, int* index) {
  int lo = 0, hi = job_count - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (jobs[mid * BOREAS_RAY_JOB_WORDS] <= k) lo = mid;
    else hi = mid - 1;
  }
  *index = k - jobs[lo * BOREAS_RAY_JOB_WORDS];
  return lo * BOREAS_RAY_JOB_WORDS;
}

void boreas_ray_store_box(__global float* boxes, int i, BoreasV3 lo, BoreasV3 hi) {
  __global float* b = boxes + (size_t)i * 6;
  b[0] = lo.x;
  b[1] = lo.y;
  b[2] = lo.z;
  b[3] = hi.x;
  b[4] = hi.y;
  b[5] = hi.z;
}

/* Primitive i's box (its instance's first box plus its index there) is stored at slots[i]:
 * its place in its hierarchy's item order (ray_scene.cpp, RayScene::build), so that a leaf node's
 * boxes lie together for the refit. */
void boreas_ray_store_slot(__global float* boxes, __global const int* slots, int i, BoreasV3 lo,
                           BoreasV3 hi) {
  boreas_ray_store_box(boxes, slots[i], lo, hi);
}

/* Trees' branches: a job's words 2.. are its branch 0's state entry, its first branch
 * record and its tree's base (3 floats' bits: the state is relative to it,
 * cl/shared/tree_origin.h; the records are world positions). Each branch's curve is copied
 * into its record: the bands' boxes and the cast
 * read one record per branch. Poses stored or derived (tree_state.h, boreas_tree_pose). */
__kernel void boreas_ray_tree_branches(__global const float* state, __global const float* motion,
                                       __global const float* shape, __global const float* settled,
                                       int n, int sn, int tn, __global const int* jobs,
                                       int job_count, int items, __global float* branches) {
  int k = (int)get_global_id(0);
  if (k >= items) return;
  int b;
  __global const int* job = jobs + boreas_ray_job(jobs, job_count, k, &b);
  BoreasV3 o;
  BoreasBezier c = boreas_tree_pose(state, motion, shape, settled, n, sn, tn, job[2] + b, &o);
  __global float* rec = branches + (size_t)(job[3] + b) * BOREAS_RAY_BRANCH_FLOATS;
  const BoreasV3 at = boreas_v3(as_float(job[4]), as_float(job[5]), as_float(job[6]));
  BoreasV3 pts[5] = {boreas_v3_add(c.p0, at), boreas_v3_add(c.p1, at), boreas_v3_add(c.p2, at),
                     boreas_v3_add(c.p3, at), o};
  for (int i = 0; i < 5; ++i) {
    rec[3 * i] = pts[i].x;
    rec[3 * i + 1] = pts[i].y;
    rec[3 * i + 2] = pts[i].z;
  }
}

/* A tree's primitive record (ray_types.h) at slot i: trees' boxes come first, so a tree
 * primitive's box slot is its record's index too (ray_scene.cpp, RayScene::build). */
__global float* boreas_ray_record(__global float* records, __global const int* slots, int i) {
  return records + (size_t)slots[i] * BOREAS_RAY_PRIM_FLOATS;
}

/* A band's box from its branch's curve c: the hull of the blossomed control points of its
 * ring's piece of the curve (which holds that piece), widened by the template's bound on
 * the surface's distance from the curve over the ring (`bound`, scale 1), times the scale. */
void boreas_ray_band_box(BoreasBezier c, int ring, int rings, float cap, float bound, float scale,
                         BoreasV3* lo, BoreasV3* hi) {
  float v0 = boreas_ring_v((float)ring, rings, cap);
  float v1 = boreas_ring_v((float)(ring + 1), rings, cap);
  BoreasV3 q0 = boreas_ray_blossom(c, v0, v0, v0), q1 = boreas_ray_blossom(c, v0, v0, v1);
  BoreasV3 q2 = boreas_ray_blossom(c, v0, v1, v1), q3 = boreas_ray_blossom(c, v1, v1, v1);
  float e = bound * scale;
  BoreasV3 pad = boreas_v3(e, e, e);
  *lo = boreas_v3_sub(boreas_v3_min(boreas_v3_min(q0, q1), boreas_v3_min(q2, q3)), pad);
  *hi = boreas_v3_add(boreas_v3_max(boreas_v3_max(q0, q1), boreas_v3_max(q2, q3)), pad);
}

#define BOREAS_RAY_BRANCH_WORDS 8
#define BOREAS_RAY_BOX_FULL 1    /* box the bands from the curve */
#define BOREAS_RAY_BOX_EMPTY 2   /* empty boxes, which no ray enters (no ray reaches the branch) */
#define BOREAS_RAY_BOX_RECORDS 4 /* and write the bands' records (a tree's first update) */

/* The bands of the reached trees' listed branches, a branch a work-item (the curve loaded
 * once for its rings; host/src/rays/ray_scene.cpp, list_branches): an item's
 * BOREAS_RAY_BRANCH_WORDS ints are its branch record, its shape, its template's first band
 * of it, its rings, its first box, the tree's scale (float bits) and the flags above. A
 * band's record, the template band's words, never changes. */
__kernel void boreas_ray_branch_bands(__global const float* branches, __global const float* bands,
                                      __global const float* shapes, __global const int* items,
                                      int count, __global const int* slots, __global float* boxes,
                                      __global float* records) {
  int k = (int)get_global_id(0);
  if (k >= count) return;
  __global const int* it = items + (size_t)k * BOREAS_RAY_BRANCH_WORDS;
  int flags = it[6], rings = it[3];
  if (flags & BOREAS_RAY_BOX_RECORDS) {
    for (int p = 0; p < rings; ++p) {
      __global const float* band = bands + (size_t)(it[2] + p) * BOREAS_RAY_BAND_FLOATS;
      __global float* r = boreas_ray_record(records, slots, it[4] + p);
      for (int w = 0; w < BOREAS_RAY_BAND_FLOATS; ++w) r[w] = band[w];
      r[BOREAS_RAY_PRIM_INDEX] = as_float(-1);
    }
  }
  if (flags & BOREAS_RAY_BOX_EMPTY) {
    BoreasV3 lo = boreas_v3(INFINITY, INFINITY, INFINITY), hi = boreas_v3(-INFINITY, -INFINITY, -INFINITY);
    for (int p = 0; p < rings; ++p) boreas_ray_store_slot(boxes, slots, it[4] + p, lo, hi);
    return;
  }
  __global const float* rec = branches + (size_t)it[0] * BOREAS_RAY_BRANCH_FLOATS;
  BoreasBezier c;
  c.p0 = boreas_v3(rec[0], rec[1], rec[2]);
  c.p1 = boreas_v3(rec[3], rec[4], rec[5]);
  c.p2 = boreas_v3(rec[6], rec[7], rec[8]);
  c.p3 = boreas_v3(rec[9], rec[10], rec[11]);
  __global const float* shape = shapes + (size_t)it[1] * BOREAS_RAY_SHAPE_FLOATS;
  int shape_rings = (int)shape[BOREAS_RAY_SHAPE_RINGS];
  float cap = shape[BOREAS_RAY_SHAPE_TIP_CAP]; /* the rings round a tip cap (boreas_ring_v) */
  float scale = as_float(it[5]);
  for (int p = 0; p < rings; ++p) {
    __global const float* band = bands + (size_t)(it[2] + p) * BOREAS_RAY_BAND_FLOATS;
    BoreasV3 lo, hi;
    boreas_ray_band_box(c, (int)band[BOREAS_RAY_BAND_RING], shape_rings, cap, band[BOREAS_RAY_BAND_BOUND],
                        scale, &lo, &hi);
    boreas_ray_store_slot(boxes, slots, it[4] + p, lo, hi);
  }
}

/* Runs of the reached trees' leaves placed at this cast (cl/tree_leaves.cl's records): a
 * job's words 2.. are its first placed record, its first blade, the tree's scale (float
 * bits), its first box, its first leaf's index in the tree and the mode
 * (BOREAS_RAY_BOX_FULL or _EMPTY). Each leaf's box is its quad's (the renderer's: u, v in
 * [0, 1] about the blade's base), and its record (ray_types.h) for the cast; an emptied
 * leaf's box is empty and its record's normal zero, which the cast's plane test turns away
 * (the leaf may share a hierarchy's leaf node with a reached one). */
__kernel void boreas_ray_leaf_runs(__global const float* placed, __global const float* blades,
                                   __global const int* jobs, int job_count, int items,
                                   __global const int* slots, __global float* boxes,
                                   __global float* records) {
  int k = (int)get_global_id(0);
  if (k >= items) return;
  int l;
  __global const int* job = jobs + boreas_ray_job(jobs, job_count, k, &l);
  int box = job[5] + l;
  __global float* r = boreas_ray_record(records, slots, box);
  r[BOREAS_RAY_PRIM_INDEX] = as_float(job[6] + l);
  if (job[7] == BOREAS_RAY_BOX_EMPTY) {
    boreas_ray_store_slot(boxes, slots, box, boreas_v3(INFINITY, INFINITY, INFINITY),
                          boreas_v3(-INFINITY, -INFINITY, -INFINITY));
    vstore3((float3)(0.0f, 0.0f, 0.0f), 0, r + BOREAS_RAY_PRIM_NORMAL);
    return;
  }
  __global const float* rec = placed + (size_t)(job[2] + l) * BOREAS_RAY_PLACED_FLOATS;
  __global const float* blade = blades + (size_t)(job[3] + l) * BOREAS_RAY_LEAF_FLOATS;
  float scale = as_float(job[4]);
  BoreasV3 base = boreas_v3(rec[BOREAS_TREE_LEAF_OUT_POSITION], rec[BOREAS_TREE_LEAF_OUT_POSITION + 1],
                            rec[BOREAS_TREE_LEAF_OUT_POSITION + 2]);
  BoreasV3 axis = boreas_v3(rec[BOREAS_TREE_LEAF_OUT_AXIS], rec[BOREAS_TREE_LEAF_OUT_AXIS + 1],
                            rec[BOREAS_TREE_LEAF_OUT_AXIS + 2]);
  BoreasV3 n = boreas_v3(rec[BOREAS_TREE_LEAF_OUT_NORMAL], rec[BOREAS_TREE_LEAF_OUT_NORMAL + 1],
                         rec[BOREAS_TREE_LEAF_OUT_NORMAL + 2]);
  BoreasV3 lo, hi;
  float length = blade[BOREAS_RAY_LEAF_LENGTH] * scale, width = blade[BOREAS_RAY_LEAF_WIDTH] * scale;
  boreas_ray_leaf_box(base, axis, n, length, width, &lo, &hi);
  /* A hair for the cast's rounding of the same point (it normalizes the same vectors). */
  BoreasV3 pad = boreas_v3(1e-6f, 1e-6f, 1e-6f);
  BoreasV3 unit_axis = boreas_v3_normalize(axis), unit_n = boreas_v3_normalize(n);
  boreas_ray_store_slot(boxes, slots, box, boreas_v3_sub(lo, pad), boreas_v3_add(hi, pad));
  vstore3((float3)(base.x, base.y, base.z), 0, r + BOREAS_RAY_PRIM_BASE);
  vstore3((float3)(unit_axis.x, unit_axis.y, unit_axis.z), 0, r + BOREAS_RAY_PRIM_AXIS);
  vstore3((float3)(unit_n.x, unit_n.y, unit_n.z), 0, r + BOREAS_RAY_PRIM_NORMAL);
  r[BOREAS_RAY_PRIM_LENGTH] = length;
  r[BOREAS_RAY_PRIM_WIDTH] = width;
}

/* Indexed triangles whose positions moved: words 2.. are the first position (floats), the
 * stride (floats), the first index and the first box. */
__kernel void boreas_ray_triangle_boxes(__global const float* positions, __global const int* ints,
                                        __global const int* jobs, int job_count, int items,
                                        __global const int* slots, __global float* boxes) {
  int k = (int)get_global_id(0);
  if (k >= items) return;
  int t;
  __global const int* job = jobs + boreas_ray_job(jobs, job_count, k, &t);
  __global const float* pos = positions + job[2];
  __global const int* idx = ints + job[4] + 3 * (size_t)t;
  BoreasV3 a = boreas_v3(pos[idx[0] * job[3]], pos[idx[0] * job[3] + 1], pos[idx[0] * job[3] + 2]);
  BoreasV3 b = boreas_v3(pos[idx[1] * job[3]], pos[idx[1] * job[3] + 1], pos[idx[1] * job[3] + 2]);
  BoreasV3 c = boreas_v3(pos[idx[2] * job[3]], pos[idx[2] * job[3] + 1], pos[idx[2] * job[3] + 2]);
  boreas_ray_store_slot(boxes, slots, job[5] + t, boreas_v3_min(boreas_v3_min(a, b), c),
                       boreas_v3_max(boreas_v3_max(a, b), c));
}

/* Components' strips: words 2.. are the first strip float, the first count and the first
 * box. A component drawn with no vertices gets an empty box (lo > hi), which no ray enters. */
__kernel void boreas_ray_strip_boxes(__global const float* strips, __global const int* ints,
                                     __global const int* jobs, int job_count, int items,
                                     __global const int* slots, __global float* boxes) {
  int k = (int)get_global_id(0);
  if (k >= items) return;
  int c;
  __global const int* job = jobs + boreas_ray_job(jobs, job_count, k, &c);
  __global const float* v = strips + job[2] + (size_t)c * BOREAS_RAY_STRIP_STRIDE * BOREAS_RAY_STRIP_VERTEX_FLOATS;
  int count = ints[job[3] + c];
  BoreasV3 lo = boreas_v3(INFINITY, INFINITY, INFINITY), hi = boreas_v3(-INFINITY, -INFINITY, -INFINITY);
  for (int i = 0; i < count; ++i) {
    BoreasV3 p = boreas_v3(v[i * BOREAS_RAY_STRIP_VERTEX_FLOATS], v[i * BOREAS_RAY_STRIP_VERTEX_FLOATS + 1],
                           v[i * BOREAS_RAY_STRIP_VERTEX_FLOATS + 2]);
    lo = boreas_v3_min(lo, p);
    hi = boreas_v3_max(hi, p);
  }
  boreas_ray_store_slot(boxes, slots, job[4] + c, lo, hi);
}

/* Node `node` of a hierarchy made again from what lies below it: a leaf's box is the union
 * of its primitives' boxes (item i's at box i + box_shift: the boxes lie in item order,
 * boreas_ray_store_slot), an inner node's that of its two children. A node with nothing
 * below it (every primitive's box emptied: ray_scene.cpp, select_branches; a meadow's
 * component drawn with no vertices) is stored as the point BOREAS_RAY_NOWHERE on every
 * axis, which no ray enters, not as the inverted union: the slab test
 * (cl/shared/ray_math.h) orders each axis's two planes, so it takes an inverted box for all
 * of space. Its parent leaves it out of its union. */
void boreas_ray_refit_node(__global float* nodes, __global const float* boxes, int node, int box_shift) {
  __global float* w = nodes + (size_t)node * BOREAS_RAY_NODE_WORDS;
  int a = as_int(w[3]), n = as_int(w[7]);
  BoreasV3 lo = boreas_v3(INFINITY, INFINITY, INFINITY), hi = boreas_v3(-INFINITY, -INFINITY, -INFINITY);
  if (n > 0) {
    for (int i = a; i < a + n; ++i) {
      __global const float* b = boxes + (size_t)(box_shift + i) * 6;
      lo = boreas_v3_min(lo, boreas_v3(b[0], b[1], b[2]));
      hi = boreas_v3_max(hi, boreas_v3(b[3], b[4], b[5]));
    }
  } else {
    for (int c = a; c < a + 2; ++c) {
      __global const float* b = nodes + (size_t)c * BOREAS_RAY_NODE_WORDS;
      if (b[0] == BOREAS_RAY_NOWHERE) continue;
      lo = boreas_v3_min(lo, boreas_v3(b[0], b[1], b[2]));
      hi = boreas_v3_max(hi, boreas_v3(b[4], b[5], b[6]));
    }
  }
  if (!(lo.x <= hi.x)) {
    lo = boreas_v3(BOREAS_RAY_NOWHERE, BOREAS_RAY_NOWHERE, BOREAS_RAY_NOWHERE);
    hi = lo;
  }
  w[0] = lo.x;
  w[1] = lo.y;
  w[2] = lo.z;
  w[4] = hi.x;
  w[5] = hi.y;
  w[6] = hi.z;
}

/* Runs of the refitted hierarchies' nodes, a work-item a run (host/src/rays/refit_runs.h):
 * jobs of BOREAS_RAY_RUN_WORDS ints, the run's first entry in `order`, its length and its
 * instance's first box. A run lists nodes by falling index, and a node's children have
 * larger indices than it, so each node is made after its children: a run holds a whole
 * subtree (one launch for all of them), or an instance's nodes above its subtrees (a second
 * launch). Each node is made once, from the same boxes in the same order, so the result is
 * the same bits however the runs are scheduled. */
__kernel void boreas_ray_refit_runs(__global float* nodes,
                                    __global const float* boxes, __global const int* order,
                                    __global const int* jobs, int job_count) {
  int k = (int)get_global_id(0);
  if (k >= job_count) return;
  __global const int* job = jobs + (size_t)k * BOREAS_RAY_RUN_WORDS;
  for (int e = job[0]; e < job[0] + job[1]; ++e)
    boreas_ray_refit_node(nodes, boxes, order[e], job[2]);
}

/* Branches' hulls: a job (BOREAS_RAY_RUN_WORDS) is a tree's first branch record, its branch
 * count, its template's first shape and its scale (float bits), a work-item a tree; each
 * branch's box, that of its control points widened by its largest band bound at the scale,
 * is written at out_first[k] (the tree's first place in `out`: the candidates' hulls packed)
 * plus its index in the tree. A Bezier curve lies in the hull of its control points and a
 * band's piece of it in the hull of its blossoms (ring v in [0, 1]), so this box holds
 * every band's box: the update decides from these which trees and branches the rays reach
 * before it boxes any band (ray_scene.cpp, select_branches). */
__kernel void boreas_ray_branch_hulls(__global const float* branches, __global const float* shapes,
                                      __global const int* jobs, int count,
                                      __global const int* out_first, __global float* out) {
  int k = (int)get_global_id(0);
  if (k >= count) return;
  __global const int* job = jobs + (size_t)k * BOREAS_RAY_RUN_WORDS;
  for (int b = job[0]; b < job[0] + job[1]; ++b) {
    __global const float* rec = branches + (size_t)b * BOREAS_RAY_BRANCH_FLOATS;
    float e = shapes[(size_t)(job[2] + b - job[0]) * BOREAS_RAY_SHAPE_FLOATS + BOREAS_RAY_SHAPE_BOUND] *
              as_float(job[3]);
    BoreasV3 pad = boreas_v3(e, e, e);
    BoreasV3 lo = boreas_v3(INFINITY, INFINITY, INFINITY), hi = boreas_v3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < 4; ++i) {
      BoreasV3 p = boreas_v3(rec[3 * i], rec[3 * i + 1], rec[3 * i + 2]);
      lo = boreas_v3_min(lo, boreas_v3_sub(p, pad));
      hi = boreas_v3_max(hi, boreas_v3_add(p, pad));
    }
    boreas_ray_store_box(out, out_first[k] + b - job[0], lo, hi);
  }
}

/* The root boxes of the instances just refitted (roots: their root nodes), 6 floats
 * each, for the host's hierarchy over the instances. */
__kernel void boreas_ray_roots(__global const float* nodes, __global const int* roots, int count,
                               __global float* out) {
  int k = (int)get_global_id(0);
  if (k >= count) return;
  __global const float* n = nodes + (size_t)roots[k] * BOREAS_RAY_NODE_WORDS;
  __global float* o = out + (size_t)k * 6;
  o[0] = n[0];
  o[1] = n[1];
  o[2] = n[2];
  o[3] = n[4];
  o[4] = n[5];
  o[5] = n[6];
}

/* The check of rays in a caller's buffer (boreas_world_enqueue_cast_rays): `parts`
 * work-items each take every parts-th ray and write 8 words: the first bad ray's index
 * (count when none), 0, then the box the good rays reach (min xyz, max xyz; an unbounded
 * ray reaches infinity along its direction). The host reads the parts and names the bad
 * ray's fault from its own copy of that one ray. */
__kernel void boreas_ray_check(__global const float* rays, int first, int count, int parts,
                               __global float* out) {
  int k = (int)get_global_id(0);
  if (k >= parts) return;
  int bad = count;
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = k; i < count; i += parts) {
    __global const float* r = rays + (size_t)(first + i) * BOREAS_RAY_RAY_FLOATS;
    float len2 = r[3] * r[3] + r[4] * r[4] + r[5] * r[5];
    int ok = isfinite(r[0]) && isfinite(r[1]) && isfinite(r[2]) && isfinite(r[3]) && isfinite(r[4]) &&
             isfinite(r[5]) && len2 > 1e-30f && !isnan(r[6]) && r[6] >= 0.0f;
    if (!ok) {
      bad = min(bad, i);
      continue;
    }
    float inv = 1.0f / sqrt(len2);
    for (int a = 0; a < 3; ++a) {
      float step = r[3 + a] * inv * r[6];
      float end = r[a] + (isnan(step) ? 0.0f : step);
      lo[a] = fmin(lo[a], fmin(r[a], end));
      hi[a] = fmax(hi[a], fmax(r[a], end));
    }
  }
  __global float* o = out + (size_t)k * 8;
  ((__global int*)o)[0] = bad;
  ((__global int*)o)[1] = 0;
  for (int a = 0; a < 3; ++a) {
    o[2 + a] = lo[a];
    o[5 + a] = hi[a];
  }
}
