/* boreas: reading and writing a branch's animated state — three planes per vector
 * (cl/shared/tree_types.h). Compiles as OpenCL C (global memory) and as C/C++ (host
 * memory), so the kernels, the host's rest placement and the native twins share it. */
#ifndef BOREAS_CL_SHARED_TREE_STATE_H
#define BOREAS_CL_SHARED_TREE_STATE_H

#include "shared/tree_math.h"
#include "shared/tree_types.h"

#ifndef __OPENCL_C_VERSION__
#include <stddef.h>
#endif

/* Element i of plane `plane` (stride n). In int where the planes hold fewer than 2^31
 * floats together (PoCL vectorizes int index math ~1.6x faster: measured on the tree step),
 * in 64 bits where the host builds the kernel with BOREAS_WIDE_PLANES (a forest's planes
 * past 2^31 floats; trees/tree_batch.cpp decides). */
#ifdef BOREAS_WIDE_PLANES
#define BOREAS_TREE_AT(plane, n, i) ((size_t)(plane) * (size_t)(n) + (size_t)(i))
#else
#define BOREAS_TREE_AT(plane, n, i) ((plane) * (n) + (i))
#endif

/* The vector in planes plane, plane + 1, plane + 2 (stride n) at index i. */
BOREAS_FN BoreasV3 boreas_tree_load3(BOREAS_GLOBAL const float* planes, int n, int plane, int i) {
  return boreas_v3(planes[BOREAS_TREE_AT(plane, n, i)], planes[BOREAS_TREE_AT(plane + 1, n, i)],
                   planes[BOREAS_TREE_AT(plane + 2, n, i)]);
}

BOREAS_FN void boreas_tree_store3(BOREAS_GLOBAL float* planes, int n, int plane, int i,
                                  BoreasV3 v) {
  planes[BOREAS_TREE_AT(plane, n, i)] = v.x;
  planes[BOREAS_TREE_AT(plane + 1, n, i)] = v.y;
  planes[BOREAS_TREE_AT(plane + 2, n, i)] = v.z;
}

/* The radius functions of branch i (planes in BoreasBranchRadius's field order). */
BOREAS_FN BoreasBranchRadius boreas_tree_load_radius(BOREAS_GLOBAL const float* radius, int n,
                                                     int i) {
  BoreasBranchRadius r;
  r.radius = radius[BOREAS_TREE_AT(0, n, i)];
  r.taper_depth = radius[BOREAS_TREE_AT(1, n, i)];
  r.taper_exponent = radius[BOREAS_TREE_AT(2, n, i)];
  r.flare = radius[BOREAS_TREE_AT(3, n, i)];
  r.bulge_count = radius[BOREAS_TREE_AT(4, n, i)];
  r.bulge_depth = radius[BOREAS_TREE_AT(5, n, i)];
  r.lobe_count = radius[BOREAS_TREE_AT(6, n, i)];
  r.lobe_depth = radius[BOREAS_TREE_AT(7, n, i)];
  r.lobe_taper = radius[BOREAS_TREE_AT(8, n, i)];
  r.tip_cap = radius[BOREAS_TREE_AT(BOREAS_TREE_RADIUS_TIP_CAP, n, i)];
  r.bulge_phase = radius[BOREAS_TREE_AT(BOREAS_TREE_RADIUS_BULGE_PHASE, n, i)];
  return r;
}

/* Branch i's curve and orientation vector O. */
BOREAS_FN BoreasBezier boreas_tree_load_curve(BOREAS_GLOBAL const float* state, int n, int i,
                                              BoreasV3* o) {
  BoreasBezier c;
  c.p0 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_load3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_load3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

/* ---- A branch's current pose, stored or derived ------------------------------------
 * The step writes a branch's curve and O into the state planes, except for a derived
 * branch (trees/tree_batch_lod.cpp: the finest level of a tree whose finer levels are
 * carried, once their bend has settled): it sits rigidly on its parent's current frame, a
 * function of its parent's curve, its template's shape, its tree's scale and its own F and
 * broken flag (motion planes), which nothing changes while it is derived. Its state planes
 * then hold the mark below, its parent's entry, its template entry (shape planes, stride
 * sn) and its tree's scale instead of a pose (written by the host when it is marked, and
 * again when blocks move), and every reader gets its pose through boreas_tree_pose (or
 * boreas_tree_gather_pose, lane by lane): bit for bit what tree_step.cl's carry with hold 1
 * writes. Only the finest level is derived; where it has split pieces, a derived branch's
 * parent may be derived too (chains, below). The mark's layout: BOREAS_TREE_DERIVED_*
 * (tree_types.h). */

#define BOREAS_WIDTH_BODY "shared/tree_pose_width.inc"
#include "shared/width_instantiate.inc"

#ifdef __OPENCL_C_VERSION__
#define BOREAS_TREE_BITS(x) as_int(x)
#else
#define BOREAS_TREE_BITS(x) boreas_host_as_int(x)
#endif

/* Whether entry i of the state planes is a derived branch. */
BOREAS_FN int boreas_tree_derived(BOREAS_GLOBAL const float* state, int n, int i) {
  return BOREAS_TREE_BITS(state[BOREAS_TREE_AT(BOREAS_TREE_STATE_P0, n, i)]) == BOREAS_TREE_DERIVED_MARK;
}

/* Whether a reader's entry i (stride n: the trees' own planes) is in the settled space
 * (BOREAS_TREE_SETTLED_*, tree_types.h): entry i - n there. */
BOREAS_FN int boreas_tree_settled(int n, int i) { return i >= n; }

/* ---- Chains: a finest level with split pieces (tree_model.h's step tiers) holds pieces
 * that grow from pieces of the same level, so a derived branch's parent may be derived
 * too, up to BOREAS_TREE_MAX_CHAIN deep. A reader walks up to the first ancestor whose
 * pose is held (stored, or posed in the scratch) and derives back down, tier by tier: the
 * carry's order (tree_step.cl places a piece on its parent's new pose), so the same bits.
 * A settled parent in the same level is named relative to its child (a negative int: the
 * settled entry that many before it), so packing the settled space moves no parent. Every
 * derivation of a chain takes the scale of the entry read (one tree: one scale); an
 * ancestor's own SCALE may be a posed row's mark (the posed scratch, below). */

/* Settled entry j's parent as a reader's index. */
BOREAS_FN int boreas_tree_settled_parent(BOREAS_GLOBAL const float* settled, int n, int tn, int j) {
  const int p = BOREAS_TREE_BITS(settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_PARENT, tn, j)]);
  return p < 0 ? n + j + p : p;
}

/* Row k of the posed planes where settled entry j is posed, else a negative number (the
 * posed scratch, below). */
BOREAS_FN int boreas_tree_posed_row(BOREAS_GLOBAL const float* settled, int tn, int j) {
  return ~BOREAS_TREE_BITS(settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_SCALE, tn, j)]);
}

/* Whether a reader's entry e is derived (marked, or settled and not posed; posed rows are
 * looked at only where pn > 0); where it is, *parent is its parent's reader index. */
BOREAS_FN int boreas_tree_link(BOREAS_GLOBAL const float* state, BOREAS_GLOBAL const float* settled,
                               int n, int tn, int pn, int e, int* parent) {
  if (boreas_tree_settled(n, e)) {
    if (pn > 0 && boreas_tree_posed_row(settled, tn, e - n) >= 0) return 0;
    *parent = boreas_tree_settled_parent(settled, n, tn, e - n);
    return 1;
  }
  if (!boreas_tree_derived(state, n, e)) return 0;
  *parent = BOREAS_TREE_BITS(state[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_PARENT, n, e)]);
  return 1;
}

/* A derived branch's pose on its parent's pose: its template entry s (shape planes,
 * stride sn), its tree's scale, its F and broken flag. */
BOREAS_FN BoreasBezier boreas_tree_derive_on(BoreasBezier parent, BoreasV3 parent_o,
                                             BOREAS_GLOBAL const float* shape, int sn, int s,
                                             float scale, BoreasV3 f, float broken, BoreasV3* o) {
#define BOREAS_SHAPE(plane) shape[BOREAS_TREE_AT((plane), sn, s)]
  BoreasAttachFrame a;
  BoreasBezier placed = boreas_tree_place(
      parent, parent_o, BOREAS_SHAPE(BOREAS_TREE_SHAPE_V), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_THETA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_THETA), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_ALPHA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_ALPHA),
      boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P0, s),
      boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P1, s),
      boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P2, s),
      boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P3, s), scale, &a);
  return boreas_tree_bend(a, placed, boreas_tree_derived_bend(f), broken,
                          BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2), o);
#undef BOREAS_SHAPE
}

/* The derived entry e (marked or settled) posed on its parent's pose. */
BOREAS_FN BoreasBezier boreas_tree_derive_entry(BOREAS_GLOBAL const float* state,
                                                BOREAS_GLOBAL const float* motion,
                                                BOREAS_GLOBAL const float* shape,
                                                BOREAS_GLOBAL const float* settled, int n, int sn,
                                                int tn, int e, float scale, BoreasBezier parent,
                                                BoreasV3 parent_o, BoreasV3* o) {
  if (boreas_tree_settled(n, e)) {
    const int j = e - n;
    return boreas_tree_derive_on(
        parent, parent_o, shape, sn, BOREAS_TREE_BITS(settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_STATIC, tn, j)]),
        scale, boreas_tree_load3(settled, tn, BOREAS_TREE_SETTLED_F, j),
        settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_BROKEN, tn, j)], o);
  }
  return boreas_tree_derive_on(
      parent, parent_o, shape, sn, BOREAS_TREE_BITS(state[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_STATIC, n, e)]),
      scale, boreas_tree_load3(motion, n, BOREAS_TREE_MOTION_F, e),
      motion[BOREAS_TREE_AT(BOREAS_TREE_MOTION_BROKEN, n, e)], o);
}

/* boreas_tree_pose for a reader given the posed planes (posed, stride pn; any buffer and 0
 * where none): entry i's pose, stored, posed or derived along its chain. */
BOREAS_FN BoreasBezier boreas_tree_read_pose(BOREAS_GLOBAL const float* state,
                                             BOREAS_GLOBAL const float* motion,
                                             BOREAS_GLOBAL const float* shape,
                                             BOREAS_GLOBAL const float* settled,
                                             BOREAS_GLOBAL const float* posed, int n, int sn,
                                             int tn, int pn, int i, BoreasV3* o) {
  int depth = 0, e = i, p = 0;
  while (depth < BOREAS_TREE_MAX_CHAIN && boreas_tree_link(state, settled, n, tn, pn, e, &p)) {
    ++depth;
    e = p;
  }
  BoreasBezier c = boreas_tree_settled(n, e)
                       ? boreas_tree_load_curve(posed, pn, boreas_tree_posed_row(settled, tn, e - n), o)
                       : boreas_tree_load_curve(state, n, e, o);
  if (depth == 0) return c;
  const float scale = boreas_tree_settled(n, i)
                          ? settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_SCALE, tn, i - n)]
                          : state[BOREAS_TREE_AT(BOREAS_TREE_DERIVED_SCALE, n, i)];
  for (int d = depth - 1; d >= 0; --d) {
    int a = i;
    for (int t = 0; t < d; ++t) boreas_tree_link(state, settled, n, tn, pn, a, &a);
    const BoreasV3 parent_o = *o;
    c = boreas_tree_derive_entry(state, motion, shape, settled, n, sn, tn, a, scale, c, parent_o, o);
  }
  return c;
}

/* Branch i's current curve and O, stored, derived or settled: what every reader of a pose
 * outside the posed window calls. settled, tn: the settled space (any buffer and 0 where
 * it is empty). */
BOREAS_FN BoreasBezier boreas_tree_pose(BOREAS_GLOBAL const float* state,
                                        BOREAS_GLOBAL const float* motion,
                                        BOREAS_GLOBAL const float* shape,
                                        BOREAS_GLOBAL const float* settled, int n, int sn, int tn,
                                        int i, BoreasV3* o) {
  return boreas_tree_read_pose(state, motion, shape, settled, settled, n, sn, tn, 0, i, o);
}

/* ---- The posed scratch (cl/tree_derive_settled.cl): for readers that read a branch once
 * per item (the deformer, the leaf records), the host poses the settled branches they will
 * read just before their launch and un-poses them right after. A posed settled entry j has
 * its pose in row k of the posed planes (BOREAS_TREE_STATE_P0..O order, stride pn), and its
 * SCALE plane holds ~k (a negative int: no scale's bits) until it is un-posed (the scale
 * written back from its tile). Only those two readers and the view call's branch records
 * (export_records.cl, inside the same window) take the posed planes; every other reader
 * runs outside that window and sees the scale. */

/* Branch i's broken flag, wherever it is held. */
BOREAS_FN float boreas_tree_broken(BOREAS_GLOBAL const float* motion,
                                   BOREAS_GLOBAL const float* settled, int n, int tn, int i) {
  if (boreas_tree_settled(n, i)) return settled[BOREAS_TREE_AT(BOREAS_TREE_SETTLED_BROKEN, tn, i - n)];
  return motion[BOREAS_TREE_AT(BOREAS_TREE_MOTION_BROKEN, n, i)];
}

#ifdef __OPENCL_C_VERSION__
/* ---- At the kernel's SIMD width (simd_width.h), for kernels that process BOREAS_W items
 * per work-item: a tile's items are consecutive entries, `count` of them from `first`,
 * and a work-item's lanes are items k .. k + W - 1 of them; lanes past the count read the
 * last item and store nothing. At width 1 these are the functions above on entry
 * first + min(k, count - 1), 64-bit offsets (BOREAS_WIDE_PLANES) included; wider kernels
 * index in int, so the host builds a batch with 64-bit offsets at width 1. */
#if BOREAS_W > 1 && defined(BOREAS_WIDE_PLANES)
#error "BOREAS_WIDE_PLANES kernels are built at width 1"
#endif

/* The vector at each lane's entry i (a per-lane gather: parents are scattered). */
BOREAS_FN BOREAS_V3 boreas_tree_gather3(__global const float* planes, int n, int plane,
                                        BOREAS_I i) {
#if BOREAS_W == 1
  return boreas_tree_load3(planes, n, plane, i);
#else
  return boreas_v3(BOREAS_GATHER(planes, plane * n + i), BOREAS_GATHER(planes, (plane + 1) * n + i),
                   BOREAS_GATHER(planes, (plane + 2) * n + i));
#endif
}

/* The curve and O of each lane's entry i (boreas_tree_load_curve per lane). */
BOREAS_FN BOREAS_BEZIER boreas_tree_gather_curve(__global const float* state, int n, BOREAS_I i,
                                                 BOREAS_V3* o) {
  BOREAS_BEZIER c;
  c.p0 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P0, i);
  c.p1 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P1, i);
  c.p2 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P2, i);
  c.p3 = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_P3, i);
  *o = boreas_tree_gather3(state, n, BOREAS_TREE_STATE_O, i);
  return c;
}

/* The radius functions of each lane's entry i (boreas_tree_load_radius per lane). */
BOREAS_FN BOREAS_RADIUS boreas_tree_gather_radius(__global const float* radius, int n, BOREAS_I i) {
#if BOREAS_W == 1
  return boreas_tree_load_radius(radius, n, i);
#else
  BOREAS_RADIUS r;
  r.radius = BOREAS_GATHER(radius, 0 * n + i);
  r.taper_depth = BOREAS_GATHER(radius, 1 * n + i);
  r.taper_exponent = BOREAS_GATHER(radius, 2 * n + i);
  r.flare = BOREAS_GATHER(radius, 3 * n + i);
  r.bulge_count = BOREAS_GATHER(radius, 4 * n + i);
  r.bulge_depth = BOREAS_GATHER(radius, 5 * n + i);
  r.lobe_count = BOREAS_GATHER(radius, 6 * n + i);
  r.lobe_depth = BOREAS_GATHER(radius, 7 * n + i);
  r.lobe_taper = BOREAS_GATHER(radius, 8 * n + i);
  r.tip_cap = BOREAS_GATHER(radius, BOREAS_TREE_RADIUS_TIP_CAP * n + i);
  r.bulge_phase = BOREAS_GATHER(radius, BOREAS_TREE_RADIUS_BULGE_PHASE * n + i);
  return r;
#endif
}

/* Lanes `lane` of the curve c and its O take those of q and qo (width > 1 only). */
#if BOREAS_W > 1
BOREAS_FN void boreas_tree_select_pose(BOREAS_BEZIER* c, BOREAS_V3* o, BOREAS_BEZIER q,
                                       BOREAS_V3 qo, BOREAS_I lane) {
#define BOREAS_PICK(v, w)                         \
  v.x = BOREAS_SELECT(v.x, w.x, lane);            \
  v.y = BOREAS_SELECT(v.y, w.y, lane);            \
  v.z = BOREAS_SELECT(v.z, w.z, lane)
  BOREAS_PICK(c->p0, q.p0);
  BOREAS_PICK(c->p1, q.p1);
  BOREAS_PICK(c->p2, q.p2);
  BOREAS_PICK(c->p3, q.p3);
  BOREAS_PICK((*o), qo);
#undef BOREAS_PICK
}
#endif

#if BOREAS_W > 1
/* Each lane's boreas_tree_link: whether its entry e is derived, and where it is, *parent
 * its parent's reader index (0, the sink, where it is not). */
BOREAS_FN BOREAS_I boreas_tree_gather_link(__global const float* state,
                                           __global const float* settled, int n, int tn, int pn,
                                           BOREAS_I e, BOREAS_I* parent) {
  const BOREAS_I zero = (BOREAS_I)(0);
  const BOREAS_I apart = e >= (BOREAS_I)(n);
  const BOREAS_I own = BOREAS_SELECT(e, zero, apart), j = BOREAS_SELECT(zero, e - (BOREAS_I)(n), apart);
  const BOREAS_I marked =
      (BOREAS_AS_INT(BOREAS_GATHER(state, BOREAS_TREE_STATE_P0 * n + own)) == (BOREAS_I)(BOREAS_TREE_DERIVED_MARK)) & ~apart;
  const BOREAS_I posed = apart & (BOREAS_I)(pn > 0 ? -1 : 0) &
                         (~BOREAS_AS_INT(BOREAS_GATHER(settled, BOREAS_TREE_SETTLED_SCALE * tn + j)) >= zero);
  const BOREAS_I link = marked | (apart & ~posed);
  BOREAS_I ps = BOREAS_AS_INT(BOREAS_GATHER(settled, BOREAS_TREE_SETTLED_PARENT * tn + j));
  ps = BOREAS_SELECT(ps, (BOREAS_I)(n) + j + ps, ps < zero);
  const BOREAS_I pm = BOREAS_AS_INT(BOREAS_GATHER(state, BOREAS_TREE_DERIVED_PARENT * n + own));
  *parent = BOREAS_SELECT(zero, BOREAS_SELECT(pm, ps, apart), link);
  return link;
}

/* Each lane's entry a (derived where `live`; lanes that are not read the sink's inputs
 * and keep nothing) posed on its parent's pose: boreas_tree_derive_entry per lane. */
BOREAS_FN BOREAS_BEZIER boreas_tree_gather_derive(__global const float* state,
                                                  __global const float* motion,
                                                  __global const float* shape,
                                                  __global const float* settled, int n, int sn,
                                                  int tn, BOREAS_I a, BOREAS_I live, BOREAS_F scale,
                                                  BOREAS_BEZIER parent, BOREAS_V3 parent_o,
                                                  BOREAS_V3* o) {
  const BOREAS_I zero = (BOREAS_I)(0);
  const BOREAS_I apart = (a >= (BOREAS_I)(n)) & live;
  const BOREAS_I own = BOREAS_SELECT(zero, a, live & ~apart), j = BOREAS_SELECT(zero, a - (BOREAS_I)(n), apart);
#define BOREAS_SETTLED(plane) BOREAS_GATHER(settled, (plane) * tn + j)
  const BOREAS_I s = BOREAS_SELECT(
      BOREAS_SELECT(zero, BOREAS_AS_INT(BOREAS_GATHER(state, BOREAS_TREE_DERIVED_STATIC * n + own)), live),
      BOREAS_AS_INT(BOREAS_SETTLED(BOREAS_TREE_SETTLED_STATIC)), apart);
  BOREAS_V3 f = boreas_tree_gather3(motion, n, BOREAS_TREE_MOTION_F, own);
  f.x = BOREAS_SELECT(f.x, BOREAS_SETTLED(BOREAS_TREE_SETTLED_F), apart);
  f.y = BOREAS_SELECT(f.y, BOREAS_SETTLED(BOREAS_TREE_SETTLED_F + 1), apart);
  f.z = BOREAS_SELECT(f.z, BOREAS_SETTLED(BOREAS_TREE_SETTLED_F + 2), apart);
  const BOREAS_F broken = BOREAS_SELECT(BOREAS_GATHER(motion, BOREAS_TREE_MOTION_BROKEN * n + own),
                                        BOREAS_SETTLED(BOREAS_TREE_SETTLED_BROKEN), apart);
#undef BOREAS_SETTLED
#define BOREAS_SHAPE(plane) BOREAS_GATHER(shape, (plane) * sn + s)
  BOREAS_ATTACH at;
  BOREAS_BEZIER placed = boreas_tree_place(
      parent, parent_o, BOREAS_SHAPE(BOREAS_TREE_SHAPE_V), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_THETA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_THETA), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_ALPHA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_ALPHA),
      boreas_tree_gather3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P0, s),
      boreas_tree_gather3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P1, s),
      boreas_tree_gather3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P2, s),
      boreas_tree_gather3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P3, s), scale, &at);
  BOREAS_BEZIER d = boreas_tree_bend(at, placed, boreas_tree_derived_bend(f), broken,
                                     BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2), o);
#undef BOREAS_SHAPE
  return d;
}

/* Each lane's pose of entry e along its chain (boreas_tree_read_pose per lane), where
 * every derivation takes `scale`: the held ancestor's curve (stored, or posed where
 * pn > 0), then the derived ones down to e, deepest first. */
BOREAS_FN BOREAS_BEZIER boreas_tree_gather_chain(__global const float* state,
                                                 __global const float* motion,
                                                 __global const float* shape,
                                                 __global const float* settled,
                                                 __global const float* posed, int n, int sn,
                                                 int tn, int pn, BOREAS_I e, BOREAS_F scale,
                                                 BOREAS_V3* o) {
  const BOREAS_I zero = (BOREAS_I)(0);
  BOREAS_I depth = zero, top = e, p;
  int most = 0;
  for (; most < BOREAS_TREE_MAX_CHAIN; ++most) {
    const BOREAS_I link = boreas_tree_gather_link(state, settled, n, tn, pn, top, &p);
    if (!BOREAS_ANY(link)) break;
    depth -= link; /* a true lane is -1 */
    top = BOREAS_SELECT(top, p, link);
  }
  const BOREAS_I apart = top >= (BOREAS_I)(n);
  const BOREAS_I row = BOREAS_SELECT(zero, ~BOREAS_AS_INT(BOREAS_GATHER(settled, BOREAS_TREE_SETTLED_SCALE * tn + BOREAS_SELECT(zero, top - (BOREAS_I)(n), apart))), apart);
  BOREAS_BEZIER c = boreas_tree_gather_curve(state, n, BOREAS_SELECT(top, zero, apart), o);
  if (BOREAS_ANY(apart)) {
    BOREAS_V3 posed_o;
    const BOREAS_BEZIER q = boreas_tree_gather_curve(posed, pn, row, &posed_o);
    boreas_tree_select_pose(&c, o, q, posed_o, apart);
  }
  for (int d = most - 1; d >= 0; --d) {
    const BOREAS_I live = depth > (BOREAS_I)(d);
    BOREAS_I a = e;
    for (int t = 0; t < d; ++t) {
      const BOREAS_I link = boreas_tree_gather_link(state, settled, n, tn, pn, a, &p);
      a = BOREAS_SELECT(a, p, link);
    }
    BOREAS_V3 next_o;
    const BOREAS_BEZIER next =
        boreas_tree_gather_derive(state, motion, shape, settled, n, sn, tn, a, live, scale, c, *o, &next_o);
    boreas_tree_select_pose(&c, o, next, next_o, live);
  }
  return c;
}
#endif

/* Each lane's boreas_tree_read_pose at entry i: the stored curves; posed settled lanes'
 * poses gathered from the posed planes (posed, stride pn; looked at only where pn > 0);
 * and where some lane's entry is derived (marked, or settled and not posed), the
 * derivation for every lane, on its parent's pose along its chain (a settled lane's
 * stored reads and the other lanes' derivation inputs go to the sink, entry 0; lanes
 * that are neither keep what they read). */
BOREAS_FN BOREAS_BEZIER boreas_tree_gather_pose(__global const float* state,
                                                __global const float* motion,
                                                __global const float* shape,
                                                __global const float* settled,
                                                __global const float* posed, int n, int sn,
                                                int tn, int pn, BOREAS_I i, BOREAS_V3* o) {
#if BOREAS_W == 1
  return boreas_tree_read_pose(state, motion, shape, settled, posed, n, sn, tn, pn, i, o);
#else
  const BOREAS_I zero = (BOREAS_I)(0);
  const BOREAS_I apart = i >= (BOREAS_I)(n);
  /* Every lane settled and posed (a drawn far tree's leaves or vertices): the posed planes
   * alone, what the selects below would give, without the own planes' reads. */
  if (pn > 0 && !BOREAS_ANY(~apart)) {
    const BOREAS_I row = ~BOREAS_AS_INT(BOREAS_GATHER(settled, BOREAS_TREE_SETTLED_SCALE * tn + (i - (BOREAS_I)(n))));
    if (!BOREAS_ANY(row < zero)) return boreas_tree_gather_curve(posed, pn, row, o);
  }
  const BOREAS_I own = BOREAS_SELECT(i, zero, apart);
  BOREAS_BEZIER c = boreas_tree_gather_curve(state, n, own, o);
  const BOREAS_I marked = (BOREAS_AS_INT(c.p0.x) == (BOREAS_I)(BOREAS_TREE_DERIVED_MARK)) & ~apart;
  if (!BOREAS_ANY(marked | apart)) return c;
  const BOREAS_I j = BOREAS_SELECT(zero, i - (BOREAS_I)(n), apart);
#define BOREAS_SETTLED(plane) BOREAS_GATHER(settled, (plane) * tn + j)
  const BOREAS_I row = ~BOREAS_AS_INT(BOREAS_SETTLED(BOREAS_TREE_SETTLED_SCALE));
  const BOREAS_I posed_lane = apart & (BOREAS_I)(pn > 0 ? -1 : 0) & (row >= zero);
  if (BOREAS_ANY(posed_lane)) {
    BOREAS_V3 posed_o;
    const BOREAS_BEZIER q = boreas_tree_gather_curve(posed, pn, BOREAS_SELECT(zero, row, posed_lane), &posed_o);
    boreas_tree_select_pose(&c, o, q, posed_o, posed_lane);
  }
  const BOREAS_I derived = marked | (apart & ~posed_lane);
  if (!BOREAS_ANY(derived)) return c;
  BOREAS_I ps = BOREAS_AS_INT(BOREAS_SETTLED(BOREAS_TREE_SETTLED_PARENT));
  ps = BOREAS_SELECT(ps, (BOREAS_I)(n) + j + ps, ps < zero);
  const BOREAS_I p = BOREAS_SELECT(BOREAS_SELECT(zero, BOREAS_AS_INT(c.p0.y), marked), ps, derived & apart);
  const BOREAS_F scale = BOREAS_SELECT(c.p1.x, BOREAS_SETTLED(BOREAS_TREE_SETTLED_SCALE), apart);
#undef BOREAS_SETTLED
  /* The parents: stored (a level without split pieces: the gather alone), or posed or
   * derived along their chains. */
  BOREAS_I up;
  BOREAS_V3 parent_o;
  const BOREAS_BEZIER parent =
      BOREAS_ANY(boreas_tree_gather_link(state, settled, n, tn, pn, p, &up) | (p >= (BOREAS_I)(n)))
          ? boreas_tree_gather_chain(state, motion, shape, settled, posed, n, sn, tn, pn, p, scale, &parent_o)
          : boreas_tree_gather_curve(state, n, p, &parent_o);
  BOREAS_V3 derived_o;
  const BOREAS_BEZIER d = boreas_tree_gather_derive(state, motion, shape, settled, n, sn, tn, i, derived,
                                                    scale, parent, parent_o, &derived_o);
  boreas_tree_select_pose(&c, o, d, derived_o, derived);
  return c;
#endif
}

BOREAS_FN BOREAS_F boreas_tree_load_w(__global const float* planes, int n, int plane, int first,
                                      int k, int count) {
#if BOREAS_W == 1
  return planes[BOREAS_TREE_AT(plane, n, first + min(k, count - 1))];
#else
  return boreas_load_w(planes + plane * n + first, k, count);
#endif
}

BOREAS_FN void boreas_tree_store_w(__global float* planes, int n, int plane, int first, int k,
                                   int count, BOREAS_F v) {
#if BOREAS_W == 1
  planes[BOREAS_TREE_AT(plane, n, first + min(k, count - 1))] = v;
#else
  boreas_store_w(v, planes + plane * n + first, k, count);
#endif
}

BOREAS_FN BOREAS_V3 boreas_tree_load3_w(__global const float* planes, int n, int plane, int first,
                                        int k, int count) {
  return boreas_v3(boreas_tree_load_w(planes, n, plane, first, k, count),
                   boreas_tree_load_w(planes, n, plane + 1, first, k, count),
                   boreas_tree_load_w(planes, n, plane + 2, first, k, count));
}

BOREAS_FN void boreas_tree_store3_w(__global float* planes, int n, int plane, int first, int k,
                                    int count, BOREAS_V3 v) {
#if BOREAS_W == 1
  boreas_tree_store3(planes, n, plane, first + min(k, count - 1), v);
#else
  boreas_store_w(v.x, planes + plane * n + first, k, count);
  boreas_store_w(v.y, planes + (plane + 1) * n + first, k, count);
  boreas_store_w(v.z, planes + (plane + 2) * n + first, k, count);
#endif
}
#endif

#endif
