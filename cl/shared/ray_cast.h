/* boreas: one ray through the two-level structure (ray_types.h) to its nearest hit. The
 * kernel (cl/ray_cast.cl) runs it per ray; the native twin (bench/) and the host tests run
 * it in C++. Compiles as OpenCL C and as C/C++.
 *
 * What a primitive is, per instance type:
 *  - a band of a tree's bark: one ring of a branch's (rings + 1) x (sides + 1) grid swept
 *    by the deformer (boreas_branch_surface, as cl/tree_deform.cl makes it for
 *    boreas_tree_get_mesh), two triangles a quad split as that mesh's indices split them;
 *    its box, refitted each update, is the blossomed piece of the curve widened by the
 *    radius bound over the ring;
 *  - a tree's leaf: placed at the update as cl/tree_leaves.cl places it for the renderer,
 *    the renderer's quad (render/shaders/leaf.vert) cut to its outline;
 *  - indexed triangles; a component's triangle strip; an axis-aligned box. */
#ifndef BOREAS_CL_SHARED_RAY_CAST_H
#define BOREAS_CL_SHARED_RAY_CAST_H

#include "shared/leaf_outline.h"
#include "shared/ray_math.h"
#include "shared/ray_types.h"
#include "shared/ray_wide.h"
#include "shared/tree_types.h"

/* Traversal stacks: a node popped at depth d leaves at most d nodes below it (one sibling
 * a level), and its two children make d + 2, so a hierarchy whose leaves are at most D deep
 * needs D + 1 (ray_types.h's bounds, which the builder keeps). */
#define BOREAS_RAY_TOP_STACK (BOREAS_RAY_TOP_DEPTH + 1)
#define BOREAS_RAY_STACK (BOREAS_RAY_DEPTH + 1)
/* An instance's wide nodes are its binary inner nodes at even depths, so at most
 * BOREAS_RAY_DEPTH / 2 wide levels lie above a wide node; one popped there leaves at most
 * three entries a level below it (the slots not taken) and pushes four. */
#define BOREAS_RAY_WIDE_STACK (3 * (BOREAS_RAY_DEPTH / 2) + 4)

/* Everything a ray reads, as one argument. */
typedef struct BoreasRayScene {
  BOREAS_GLOBAL const float* top;      /* the instances' hierarchy (nodes) */
  BOREAS_GLOBAL const int* top_items;  /* its leaves' instances */
  BOREAS_GLOBAL const float* wide;     /* every instance's hierarchy as wide nodes */
  BOREAS_GLOBAL const int* items;      /* their leaves' primitives */
  BOREAS_GLOBAL const int* instances;  /* BOREAS_RAY_INST_WORDS each */
  BOREAS_GLOBAL const float* branches; /* curves of this cast */
  BOREAS_GLOBAL const float* shapes;   /* template branch shapes */
  BOREAS_GLOBAL const float* records;  /* trees' primitives in item order, this cast */
  BOREAS_GLOBAL const float* positions; /* static triangles' positions, boxes */
  BOREAS_GLOBAL const float* trunks;   /* imported trees' trunks as of this cast (3 floats) */
  BOREAS_GLOBAL const float* crowns;   /* imported trees' leaves as of this cast (6 floats) */
  BOREAS_GLOBAL const float* strips;   /* meadows' strips as of this cast */
  BOREAS_GLOBAL const int* ints;       /* triangle indices, strip counts */
  int top_root;                        /* -1: nothing to hit */
} BoreasRayScene;

typedef struct BoreasRayHit {
  float t;
  BoreasV3 normal;
  int kind, instance, part;
} BoreasRayHit;

BOREAS_FN BoreasV3 boreas_ray_load3(BOREAS_GLOBAL const float* f, int i) {
  return boreas_v3(f[i], f[i + 1], f[i + 2]);
}

BOREAS_FN void boreas_ray_take(BoreasRayHit* hit, float t, BoreasV3 n, int kind, int instance,
                               int part) {
  hit->t = t;
  hit->normal = n;
  hit->kind = kind;
  hit->instance = instance;
  hit->part = part;
}

BOREAS_FN void boreas_ray_triangle_hit(const BoreasRay* r, BoreasV3 a, BoreasV3 b, BoreasV3 c,
                                       int kind, int instance, int part, BoreasRayHit* hit) {
  float t = boreas_ray_triangle(r, a, b, c, hit->t);
  if (t >= 0.0f)
    boreas_ray_take(hit, t, boreas_ray_facing(r, boreas_v3_cross(boreas_v3_sub(b, a), boreas_v3_sub(c, a))),
                    kind, instance, part);
}

/* The deformer's vertex (ring, side) of a branch (tree_deform.cl's math). */
BOREAS_FN BoreasV3 boreas_ray_branch_vertex(BoreasBezier c, BoreasSloanFrame f, BoreasBranchRadius p,
                                            int ring, int side, int rings, int sides) {
  float v = boreas_ring_v((float)ring, rings, p.tip_cap);
  float turns = (float)side / (float)sides;
  float sin_t = boreas_sin_cycle(boreas_tm_wrap(turns));
  float cos_t = boreas_sin_cycle(boreas_tm_wrap(turns + 0.25f));
  BoreasV3 pos, nrm;
  boreas_branch_surface(c, f, p, v, turns, sin_t, cos_t, &pos, &nrm);
  return pos;
}

/* One ring's band of a branch: its quads, split as boreas_tree_get_mesh splits them. */
BOREAS_FN void boreas_ray_band(const BoreasRay* r, BoreasBezier c, BoreasSloanFrame f,
                               BoreasBranchRadius p, int ring, int rings, int sides, int instance,
                               int branch, BoreasRayHit* hit) {
  BoreasV3 a0 = boreas_ray_branch_vertex(c, f, p, ring, 0, rings, sides);
  BoreasV3 b0 = boreas_ray_branch_vertex(c, f, p, ring + 1, 0, rings, sides);
  for (int s = 0; s < sides; ++s) {
    BoreasV3 a1 = boreas_ray_branch_vertex(c, f, p, ring, s + 1, rings, sides);
    BoreasV3 b1 = boreas_ray_branch_vertex(c, f, p, ring + 1, s + 1, rings, sides);
    boreas_ray_triangle_hit(r, a0, a1, b0, BOREAS_RAY_HIT_BRANCH, instance, branch, hit);
    boreas_ray_triangle_hit(r, a1, b1, b0, BOREAS_RAY_HIT_BRANCH, instance, branch, hit);
    a0 = a1;
    b0 = b1;
  }
}

/* Leaf `index` of a tree, its record `rec` (ray_types.h: placed at this cast as
 * cl/tree_leaves.cl places it for the renderer, its axis and normal made units, its blade at
 * the tree's scale): the renderer's quad (render/shaders/leaf.vert), cut to the outline. */
BOREAS_FN void boreas_ray_leaf(const BoreasRay* r, BOREAS_GLOBAL const float* rec, int outline,
                               int instance, int index, BoreasRayHit* hit) {
  BoreasV3 base = boreas_ray_load3(rec, BOREAS_RAY_PRIM_BASE);
  BoreasV3 axis = boreas_ray_load3(rec, BOREAS_RAY_PRIM_AXIS);
  BoreasV3 n = boreas_ray_load3(rec, BOREAS_RAY_PRIM_NORMAL);
  float denom = boreas_v3_dot(r->d, n);
  if (denom == 0.0f) return;
  float t = boreas_v3_dot(boreas_v3_sub(base, r->o), n) / denom;
  if (!(t >= 0.0f && t < hit->t)) return;
  BoreasV3 rel = boreas_v3_sub(boreas_v3_madd(r->o, r->d, t), base);
  float length = rec[BOREAS_RAY_PRIM_LENGTH], width = rec[BOREAS_RAY_PRIM_WIDTH];
  float u, v;
  boreas_leaf_uv(boreas_v3_dot(rel, axis), boreas_v3_dot(rel, boreas_v3_cross(axis, n)), length,
                 width, &u, &v);
  if (u < 0.0f || u > 1.0f || v < 0.0f || v > 1.0f || !boreas_leaf_outline_inside(outline, u, v))
    return;
  boreas_ray_take(hit, t, boreas_ray_facing(r, n), BOREAS_RAY_HIT_LEAF, instance, index);
}

/* Whether the ray can meet the band of curve c over v in [v0, v1] whose surface lies
 * within e of the curve (the band box's own bound), asked before the band's triangles are
 * made (each of its 2 (sides + 1) vertices is the deformer's whole surface math, and a
 * slanted branch's box is mostly empty). The piece of the curve lies in the hull of its
 * blossomed control points q0 .. q3 (as the box holds), and that hull in the capsule about
 * the chord q0 q3 whose radius is the farther of q1 and q2 from the chord: a convex set
 * holding all four. Widened by e it holds the surface and its flat triangles. The ray is
 * tested against two shapes that hold the capsule, the cylinder about the chord's line and
 * the sphere about its middle, each by a margin well past the float error of these sums
 * and of the vertices (1e-5 of the coordinates' sizes): a band turned away here has no hit,
 * so the hits are the same bits as without the test (tests/host/rays/test_ray_host_copy.cpp
 * checks it on a windy forest). The one way past the margin is the triangle test's own
 * rounding for a ray within some 0.3 degrees of a triangle's plane, whose rounded
 * barycentrics can pass the edge slack at a point off the triangle: such a grazing "hit"
 * is not made here. */
BOREAS_FN int boreas_ray_band_near(const BoreasRay* r, BoreasBezier c, float v0, float v1, float e) {
  BoreasV3 q0 = boreas_ray_blossom(c, v0, v0, v0), q1 = boreas_ray_blossom(c, v0, v0, v1);
  BoreasV3 q2 = boreas_ray_blossom(c, v0, v1, v1), q3 = boreas_ray_blossom(c, v1, v1, v1);
  BoreasV3 u = boreas_v3_sub(q3, q0);
  float uu = boreas_v3_dot(u, u);
  float inv_uu = uu > 0.0f ? 1.0f / uu : 0.0f;
  BoreasV3 a1 = boreas_v3_sub(q1, q0), a2 = boreas_v3_sub(q2, q0);
  float k1 = BOREAS_RAY_FMIN(BOREAS_RAY_FMAX(boreas_v3_dot(a1, u) * inv_uu, 0.0f), 1.0f);
  float k2 = BOREAS_RAY_FMIN(BOREAS_RAY_FMAX(boreas_v3_dot(a2, u) * inv_uu, 0.0f), 1.0f);
  BoreasV3 off1 = boreas_v3_madd(a1, u, -k1), off2 = boreas_v3_madd(a2, u, -k2);
  float bulge = BOREAS_SQRT(BOREAS_RAY_FMAX(boreas_v3_dot(off1, off1), boreas_v3_dot(off2, off2)));
  float half_chord = 0.5f * BOREAS_SQRT(uu);
  BoreasV3 w = boreas_v3_sub(q0, r->o);
  float size = BOREAS_RAY_FABS(w.x) + BOREAS_RAY_FABS(w.y) + BOREAS_RAY_FABS(w.z) +
               BOREAS_RAY_FABS(q0.x) + BOREAS_RAY_FABS(q0.y) + BOREAS_RAY_FABS(q0.z) + half_chord;
  float reach = (e + bulge) * 1.0001f + 1e-5f * size;
  /* The cylinder: the distance between the ray's line and the chord's, |w . n| / |n|. */
  BoreasV3 n = boreas_v3_cross(r->d, u);
  float wn = boreas_v3_dot(w, n);
  if (wn * wn > reach * reach * boreas_v3_dot(n, n)) return 0;
  /* The sphere: the distance of the chord's middle from the ray's line (d is a unit). */
  BoreasV3 x = boreas_v3_cross(boreas_v3_madd(w, u, 0.5f), r->d);
  float rs = reach + half_chord;
  return boreas_v3_dot(x, x) <= rs * rs;
}

/* A bark band of a tree instance (`band`: its template band's words, BOREAS_RAY_BAND_*): a
 * ring of one of its branches, made by the deformer's math from the branch's curve as of
 * this cast (the band's box, refitted from the same curve, let the ray here), where
 * boreas_ray_band_near lets the ray on. */
BOREAS_FN void boreas_ray_tree_band(const BoreasRay* r, const BoreasRayScene* s,
                                    BOREAS_GLOBAL const int* inst, int instance,
                                    BOREAS_GLOBAL const float* band, BoreasRayHit* hit) {
  int b = (int)band[BOREAS_RAY_BAND_BRANCH], ring = (int)band[BOREAS_RAY_BAND_RING];
  BOREAS_GLOBAL const float* rec = s->branches + (size_t)(inst[BOREAS_RAY_INST_BRANCHES] + b) * BOREAS_RAY_BRANCH_FLOATS;
  BOREAS_GLOBAL const float* shape = s->shapes + (size_t)(inst[BOREAS_RAY_INST_SHAPES] + b) * BOREAS_RAY_SHAPE_FLOATS;
  BoreasBezier c;
  c.p0 = boreas_ray_load3(rec, 0);
  c.p1 = boreas_ray_load3(rec, 3);
  c.p2 = boreas_ray_load3(rec, 6);
  c.p3 = boreas_ray_load3(rec, 9);
  float scale = boreas_as_float(inst[BOREAS_RAY_INST_SCALE]);
  int rings = (int)shape[BOREAS_RAY_SHAPE_RINGS];
  /* v0 and v1 as the band's box has them (cl/ray_refit.cl) */
  float cap = shape[BOREAS_RAY_SHAPE_TIP_CAP];
  if (!boreas_ray_band_near(r, c, boreas_ring_v((float)ring, rings, cap),
                            boreas_ring_v((float)(ring + 1), rings, cap),
                            band[BOREAS_RAY_BAND_BOUND] * scale))
    return;
  BoreasV3 o = boreas_ray_load3(rec, 12);
  BoreasBranchRadius radius = boreas_ray_shape_radius(shape, scale);
  boreas_ray_band(r, c, boreas_sloan_frame(c, o), radius, ring, rings,
                  (int)shape[BOREAS_RAY_SHAPE_SIDES], instance, b, hit);
}

/* Item k of a tree instance's hierarchy: its record (ray_types.h) a leaf or a bark band. */
BOREAS_FN void boreas_ray_tree_item(const BoreasRay* r, const BoreasRayScene* s,
                                    BOREAS_GLOBAL const int* inst, int instance, int k,
                                    BoreasRayHit* hit) {
  BOREAS_GLOBAL const float* rec =
      s->records + (size_t)(k + inst[BOREAS_RAY_INST_RECORDS]) * BOREAS_RAY_PRIM_FLOATS;
  int leaf = boreas_as_int(rec[BOREAS_RAY_PRIM_INDEX]);
  if (leaf < 0) boreas_ray_tree_band(r, s, inst, instance, rec, hit);
  else boreas_ray_leaf(r, rec, inst[BOREAS_RAY_INST_OUTLINE], instance, leaf, hit);
}

BOREAS_FN void boreas_ray_indexed(const BoreasRay* r, const BoreasRayScene* s,
                                  BOREAS_GLOBAL const int* inst, int instance, int tri,
                                  BoreasRayHit* hit) {
  int buffer = inst[BOREAS_RAY_INST_BUFFER], stride = inst[BOREAS_RAY_INST_STRIDE];
  BOREAS_GLOBAL const float* pos = buffer == 0 ? s->positions : buffer == 1 ? s->trunks : s->crowns;
  pos += inst[BOREAS_RAY_INST_VERTICES];
  BOREAS_GLOBAL const int* idx = s->ints + inst[BOREAS_RAY_INST_INDICES] + 3 * (size_t)tri;
  boreas_ray_triangle_hit(r, boreas_ray_load3(pos, idx[0] * stride), boreas_ray_load3(pos, idx[1] * stride),
                          boreas_ray_load3(pos, idx[2] * stride), inst[BOREAS_RAY_INST_HIT_KIND], instance,
                          tri, hit);
}

BOREAS_FN void boreas_ray_strip(const BoreasRay* r, const BoreasRayScene* s,
                                BOREAS_GLOBAL const int* inst, int instance, int comp,
                                BoreasRayHit* hit) {
  BOREAS_GLOBAL const float* v = s->strips + inst[BOREAS_RAY_INST_VERTICES] +
                                 (size_t)comp * BOREAS_RAY_STRIP_STRIDE * BOREAS_RAY_STRIP_VERTEX_FLOATS;
  int count = s->ints[inst[BOREAS_RAY_INST_INDICES] + comp];
  for (int k = 0; k + 2 < count; ++k)
    boreas_ray_triangle_hit(r, boreas_ray_load3(v, k * BOREAS_RAY_STRIP_VERTEX_FLOATS),
                            boreas_ray_load3(v, (k + 1) * BOREAS_RAY_STRIP_VERTEX_FLOATS),
                            boreas_ray_load3(v, (k + 2) * BOREAS_RAY_STRIP_VERTEX_FLOATS),
                            BOREAS_RAY_HIT_UNDERBRUSH, instance, comp + inst[BOREAS_RAY_INST_PART_FIRST],
                            hit);
}

/* A solid box: where the ray enters it (an origin inside sees nothing of it: a sensor
 * inside a wall has no range to it), and the face's normal. */
BOREAS_FN void boreas_ray_solid(const BoreasRay* r, const BoreasRayScene* s,
                                BOREAS_GLOBAL const int* inst, int instance, int box,
                                BoreasRayHit* hit) {
  BOREAS_GLOBAL const float* b = s->positions + inst[BOREAS_RAY_INST_VERTICES] + 6 * (size_t)box;
  BoreasV3 lo = boreas_ray_load3(b, 0), hi = boreas_ray_load3(b, 3);
  float t = boreas_ray_box(r, lo, hi, hit->t);
  if (!(t > 0.0f)) return;
  BoreasV3 p = boreas_v3_madd(r->o, r->d, t);
  /* The face the entry point lies on: the axis where it is nearest a side, relative to
   * the box's size. */
  BoreasV3 size = boreas_v3_sub(hi, lo);
  float dx = BOREAS_RAY_FMIN(BOREAS_RAY_FABS(p.x - lo.x), BOREAS_RAY_FABS(hi.x - p.x)) / size.x;
  float dy = BOREAS_RAY_FMIN(BOREAS_RAY_FABS(p.y - lo.y), BOREAS_RAY_FABS(hi.y - p.y)) / size.y;
  float dz = BOREAS_RAY_FMIN(BOREAS_RAY_FABS(p.z - lo.z), BOREAS_RAY_FABS(hi.z - p.z)) / size.z;
  BoreasV3 n = dx <= dy && dx <= dz ? boreas_v3(1.0f, 0.0f, 0.0f)
               : dy <= dz          ? boreas_v3(0.0f, 1.0f, 0.0f)
                                   : boreas_v3(0.0f, 0.0f, 1.0f);
  boreas_ray_take(hit, t, boreas_ray_facing(r, n), BOREAS_RAY_HIT_SOLID_BOX, instance, box);
}

BOREAS_FN void boreas_ray_primitive(const BoreasRay* r, const BoreasRayScene* s, int instance,
                                    int prim, BoreasRayHit* hit) {
  BOREAS_GLOBAL const int* inst = s->instances + (size_t)instance * BOREAS_RAY_INST_WORDS;
  int type = inst[BOREAS_RAY_INST_TYPE];
  if (type == BOREAS_RAY_TYPE_TRIANGLES) boreas_ray_indexed(r, s, inst, instance, prim, hit);
  else if (type == BOREAS_RAY_TYPE_STRIPS) boreas_ray_strip(r, s, inst, instance, prim, hit);
  else boreas_ray_solid(r, s, inst, instance, prim, hit);
}

BOREAS_FN float boreas_ray_node_box(const BoreasRay* r, BOREAS_GLOBAL const float* node, float t_max) {
  return boreas_ray_box(r, boreas_ray_load3(node, 0), boreas_ray_load3(node, 4), t_max);
}

BOREAS_FN int boreas_ray_node_int(BOREAS_GLOBAL const float* node, int word) {
  return boreas_as_int(node[word]);
}

/* Pushes the children of inner node `a`'s pair (nodes a and a + 1 of `nodes`) that the ray
 * enters before t_max, the farther below the nearer so that the nearer is visited first,
 * each with where the ray enters its box. */
BOREAS_FN void boreas_ray_push_children(const BoreasRay* r, BOREAS_GLOBAL const float* nodes, int a,
                                        float t_max, int* stack, float* enter, int* top) {
  float t0 = boreas_ray_node_box(r, nodes + (size_t)a * BOREAS_RAY_NODE_WORDS, t_max);
  float t1 = boreas_ray_node_box(r, nodes + (size_t)(a + 1) * BOREAS_RAY_NODE_WORDS, t_max);
  int first = t0 <= t1 ? a : a + 1;
  float t_near = t0 <= t1 ? t0 : t1;
  if (t0 >= 0.0f && t1 >= 0.0f) {
    stack[*top] = first == a ? a + 1 : a;
    enter[(*top)++] = first == a ? t1 : t0;
    stack[*top] = first;
    enter[(*top)++] = t_near;
  } else if (t0 >= 0.0f || t1 >= 0.0f) {
    stack[*top] = t0 >= 0.0f ? a : a + 1;
    enter[(*top)++] = t0 >= 0.0f ? t0 : t1;
  }
}

/* Whether a box the ray enters at `enter` (as boreas_ray_box found it when it was pushed)
 * still lies within the nearest hit: the box test's own condition against the smaller
 * t_max, without testing the box again (the same bits as testing it again). */
BOREAS_FN int boreas_ray_still_open(float enter, float t_max) { return enter <= t_max * 1.00000024f; }

/* The primitives of a leaf slot (its first item a, count of them) of an instance. */
BOREAS_FN void boreas_ray_leaf_items(const BoreasRay* r, const BoreasRayScene* s,
                                     BOREAS_GLOBAL const int* inst, int instance, int tree, int a,
                                     int count, BoreasRayHit* hit) {
  for (int k = a; k < a + count; ++k) {
    if (tree) boreas_ray_tree_item(r, s, inst, instance, k, hit);
    else boreas_ray_primitive(r, s, instance, s->items[k], hit);
  }
}

/* A hint to fetch the cache line at p now (clang's builtin, which PoCL compiles OpenCL C
 * with, and GCC's): the traversal knows which nodes and records it will read next a whole
 * box test before it reads them. No effect on what is computed. OpenCL takes the address
 * through an integer (the builtin's pointer is private; a CPU device's spaces are one). */
#if defined(__OPENCL_C_VERSION__) && defined(__clang__)
#define BOREAS_RAY_PREFETCH(p) __builtin_prefetch((const void*)(size_t)(p))
#elif defined(__clang__) || defined(__GNUC__)
#define BOREAS_RAY_PREFETCH(p) __builtin_prefetch((const void*)(p))
#else
#define BOREAS_RAY_PREFETCH(p) ((void)(p))
#endif

/* Pushes the slots of wide node `w` that the ray enters before t_max, the farthest lowest
 * so that the nearest is visited first, each with where the ray enters its box: a wide
 * node as its index, a leaf slot as ~(4 w + slot). An empty slot is never pushed. */
BOREAS_FN void boreas_ray_push_slots(const BoreasRay* r, const BoreasRayScene* s, int tree,
                                     int records, BOREAS_GLOBAL const float* node, int w, float t_max, int* stack,
                                     float* enter, int* top) {
  float t[4];
  BoreasRayF4 t4 = boreas_ray_wide_boxes(r, node, t_max);
  BOREAS_RAY_F4_STORE(t4, t);
  /* What each entered slot will read first, fetched together (the loads were the cast's
   * largest wait): a wide node's two lines, or a tree leaf's first records. */
  for (int k = 0; k < 4; ++k) {
    int count = boreas_ray_node_int(node, BOREAS_RAY_WIDE_COUNT + k);
    /* An empty slot's box (inf, -inf) passes the slab test (its sides' order is not
     * asked), and its a is -1: never pushed. */
    if (!(t[k] >= 0.0f) || count < 0) {
      t[k] = -1.0f;
      continue;
    }
    int a = boreas_ray_node_int(node, BOREAS_RAY_WIDE_A + k);
    if (count == 0) {
      BOREAS_RAY_PREFETCH(s->wide + (size_t)a * BOREAS_RAY_WIDE_WORDS);
      BOREAS_RAY_PREFETCH(s->wide + (size_t)a * BOREAS_RAY_WIDE_WORDS + 16);
    } else if (tree) {
      BOREAS_RAY_PREFETCH(s->records + (size_t)(a + records) * BOREAS_RAY_PRIM_FLOATS);
      BOREAS_RAY_PREFETCH(s->records + (size_t)(a + records) * BOREAS_RAY_PRIM_FLOATS + 16);
    }
  }
  int slot[4], n = 0;
  float e[4];
  for (int k = 0; k < 4; ++k) {
    if (!(t[k] >= 0.0f)) continue;
    int j = n++;
    for (; j > 0 && e[j - 1] < t[k]; --j) {
      e[j] = e[j - 1];
      slot[j] = slot[j - 1];
    }
    e[j] = t[k];
    slot[j] = k;
  }
  for (int j = 0; j < n; ++j) {
    int k = slot[j];
    int leaf = boreas_ray_node_int(node, BOREAS_RAY_WIDE_COUNT + k) > 0;
    stack[*top] = leaf ? ~(4 * w + k) : boreas_ray_node_int(node, BOREAS_RAY_WIDE_A + k);
    enter[(*top)++] = e[j];
  }
}

/* Visits instance `instance`'s hierarchy through its wide nodes, nearer slot first; its
 * leaves' entries go to boreas_ray_tree_item (trees) or boreas_ray_primitive (the rest). A
 * popped entry whose box the ray enters past the nearest hit found since it was pushed is
 * dropped. The same boxes are tested as through the binary nodes, so the same primitives
 * are met and the nearest hit is the same. */
BOREAS_FN void boreas_ray_instance(const BoreasRay* r, const BoreasRayScene* s, int instance,
                                   BoreasRayHit* hit) {
  int stack[BOREAS_RAY_WIDE_STACK];
  float enter[BOREAS_RAY_WIDE_STACK];
  int top = 0;
  BOREAS_GLOBAL const int* inst = s->instances + (size_t)instance * BOREAS_RAY_INST_WORDS;
  int tree = inst[BOREAS_RAY_INST_TYPE] == BOREAS_RAY_TYPE_TREE;
  /* The root's own box lies within the top level's leaf the ray entered; its slots decide. */
  stack[top] = inst[BOREAS_RAY_INST_WIDE_ROOT];
  enter[top++] = 0.0f;
  while (top > 0) {
    --top;
    if (!boreas_ray_still_open(enter[top], hit->t)) continue;
    int ref = stack[top];
    if (ref < 0) {
      BOREAS_GLOBAL const float* node = s->wide + (size_t)(~ref >> 2) * BOREAS_RAY_WIDE_WORDS;
      int k = ~ref & 3;
      boreas_ray_leaf_items(r, s, inst, instance, tree, boreas_ray_node_int(node, BOREAS_RAY_WIDE_A + k),
                            boreas_ray_node_int(node, BOREAS_RAY_WIDE_COUNT + k), hit);
      continue;
    }
    boreas_ray_push_slots(r, s, tree, inst[BOREAS_RAY_INST_RECORDS], s->wide + (size_t)ref * BOREAS_RAY_WIDE_WORDS, ref, hit->t,
                          stack, enter, &top);
  }
}

BOREAS_FN BoreasRayHit boreas_ray_cast(const BoreasRayScene* s, const BoreasRay* r, float t_max) {
  BoreasRayHit hit;
  hit.t = t_max;
  hit.normal = boreas_v3(0.0f, 0.0f, 0.0f);
  hit.kind = BOREAS_RAY_HIT_NONE;
  hit.instance = -1;
  hit.part = -1;
  if (s->top_root < 0) return hit;
  /* The instances' hierarchy nearer child first too: a ray through a stand meets the
   * nearer crowns first, and the hit there closes the farther ones' boxes. */
  int stack[BOREAS_RAY_TOP_STACK];
  float enter[BOREAS_RAY_TOP_STACK];
  int top = 0;
  float t_root = boreas_ray_node_box(r, s->top + (size_t)s->top_root * BOREAS_RAY_NODE_WORDS, hit.t);
  if (t_root < 0.0f) return hit;
  stack[top] = s->top_root;
  enter[top++] = t_root;
  while (top > 0) {
    --top;
    if (!boreas_ray_still_open(enter[top], hit.t)) continue;
    BOREAS_GLOBAL const float* node = s->top + (size_t)stack[top] * BOREAS_RAY_NODE_WORDS;
    int a = boreas_ray_node_int(node, 3), count = boreas_ray_node_int(node, 7);
    if (count > 0) {
      for (int k = a; k < a + count; ++k) boreas_ray_instance(r, s, s->top_items[k], &hit);
      continue;
    }
    boreas_ray_push_children(r, s->top, a, hit.t, stack, enter, &top);
  }
  return hit;
}

/* One boreas_ray record (in: origin, direction, max distance; BOREAS_RAY_RAY_FLOATS) cast,
 * its boreas_hit record written (out, and out_int: the same words as ints): the distance,
 * point, normal, kind, object id and part, or a miss (INFINITY, zeros, part -1). The
 * direction is normalized here. The kernel's work-item and the native twin's loop body. */
BOREAS_FN void boreas_ray_cast_record(const BoreasRayScene* s, BOREAS_GLOBAL const float* in,
                                      BOREAS_GLOBAL float* out, BOREAS_GLOBAL int* out_int) {
  BoreasV3 o = boreas_v3(in[0], in[1], in[2]);
  BoreasV3 d = boreas_v3_normalize(boreas_v3(in[3], in[4], in[5]));
  BoreasRay r = boreas_ray_make(o, d);
  BoreasRayHit h = boreas_ray_cast(s, &r, in[6]);
  if (h.kind == BOREAS_RAY_HIT_NONE) {
    out[0] = INFINITY;
    for (int w = 1; w < 7; ++w) out[w] = 0.0f;
    for (int w = 7; w < 11; ++w) out_int[w] = 0;
    out_int[11] = -1;
    return;
  }
  BoreasV3 p = boreas_v3_madd(o, d, h.t);
  BOREAS_GLOBAL const int* inst = s->instances + (size_t)h.instance * BOREAS_RAY_INST_WORDS;
  out[0] = h.t;
  out[1] = p.x;
  out[2] = p.y;
  out[3] = p.z;
  out[4] = h.normal.x;
  out[5] = h.normal.y;
  out[6] = h.normal.z;
  out_int[7] = h.kind;
  out_int[8] = inst[BOREAS_RAY_INST_ID];
  out_int[9] = inst[BOREAS_RAY_INST_ID + 1];
  out_int[10] = inst[BOREAS_RAY_INST_ID + 2];
  out_int[11] = h.part;
}

#endif
