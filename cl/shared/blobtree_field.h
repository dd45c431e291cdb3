/* boreas: the field of a BlobTree tree at a point (Galbraith, MacMurchy and Wyvill 2004
 * sec. 3.1-3.4), for the polygonizer's kernels and the host's float twin. The double
 * precision reference, written apart from this, is host/src/reference/blobtree_reference.
 *
 *   F(p) = min( sum over groups G(p), 1 - max over cuts C_k(p) )
 *
 * A group of one primitive contributes weight * g(d). A group combined by Precise Contact
 * Modeling (the branches leaving one branching point, eq. 4) contributes the union of its
 * deformed members, max_i (f_i + s_i) with Gascuel's deformation term s_i:
 *   - inside another member (r_i < 0): s_i = 1/2 - o_i, compression to the contact
 *     surface f_i = o_i;
 *   - within w_i of the others (0 <= r_i < w_i): s_i = h(r_i) min(1, 4 f_i), expansion
 *     (the bark ridge), faded out with the member's own field well beyond its surface so
 *     that it swells this member only;
 *   - elsewhere 0;
 * and where two members overlap, at least the second largest member field (so the wood
 * between the contact surfaces stays inside). o_i is the largest field among the other members and r_i the distance from p to
 * the nearest other member's surface (d_j - iso_j: exact for distance fields, where
 * Gascuel follows the gradient to the interpenetration boundary). h rises with slope k (the
 * nearest other's |grad g| on its surface, so s_i is C1 across r = 0) to its peak M at
 * w/2 and falls to 0 with zero slope at w. Summing the groups blends each branching point
 * with its basal internode (eq. 5) and successive internodes with each other.
 *
 * No transcendental builtins in the field (the bend's and the texture's angles go through
 * boreas_atan2). The bodies are written once for any SIMD width
 * (blobtree_field_width.inc): in floats on the host and at width 1, and in kernels again
 * at their width BOREAS_W, several points per work-item (simd_width.h). */
#ifndef BOREAS_CL_SHARED_BLOBTREE_FIELD_H
#define BOREAS_CL_SHARED_BLOBTREE_FIELD_H

#include "shared/blobtree_types.h"
#include "shared/tree_math.h"

/* Far beyond any tree: "no other member". */
#define BOREAS_BT_FAR 1e30f

BOREAS_FN BoreasV3 boreas_bt_plane3(BOREAS_GLOBAL const float* planes, int plane, int n, int i) {
  return boreas_v3(planes[plane * n + i], planes[(plane + 1) * n + i], planes[(plane + 2) * n + i]);
}

/* Past the end of a list (above every primitive's index). */
#define BOREAS_BT_NONE 0x7fffffff

/* Whether primitive m (or BOREAS_BT_NONE) continues the PCM group `group`. */
BOREAS_FN int boreas_bt_in_group(BOREAS_GLOBAL const int* ints, int n, int m, int group) {
  return m != BOREAS_BT_NONE && ints[BOREAS_BT_GROUP * n + m] == group && ints[BOREAS_BT_PCM * n + m] != 0;
}

/* A walk over one list of primitives, items[k, end), the same for every lane. */
typedef struct BoreasBtList {
  int k, end;
} BoreasBtList;

BOREAS_FN BoreasBtList boreas_bt_list(int begin, int end) {
  BoreasBtList c;
  c.k = begin;
  c.end = end;
  return c;
}

/* The walk's next primitive, BOREAS_BT_NONE at the end. */
BOREAS_FN int boreas_bt_next(BOREAS_GLOBAL const int* items, BoreasBtList c) {
  return c.k < c.end ? items[c.k] : BOREAS_BT_NONE;
}

/* Past primitive i, the list's next. */
BOREAS_FN void boreas_bt_advance(BOREAS_GLOBAL const int* items, BoreasBtList* c, int i) {
  (void)items; /* the lanes' walk needs them */
  (void)i;
  ++c->k;
}

/* A primitive's vector, the same in every lane of the width being instantiated. */
#define BOREAS_BT_LANES3(v) boreas_v3((BOREAS_F)((v).x), (BOREAS_F)((v).y), (BOREAS_F)((v).z))

/* The walk of each lane's own list, at the current width (blobtree_field_width.inc). */
#define BOREAS_BT_CURSOR BOREAS_WIDE_NAME(BoreasBtCursor)

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/blobtree_field_width.inc"
#include "shared/width_instantiate.inc"

#endif
