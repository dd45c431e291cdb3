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
 * Scalar floats and no transcendental builtins in the field (the bend's and the texture's
 * angles go through boreas_atan2), so PoCL vectorizes the work-item loop. */
#ifndef BOREAS_CL_SHARED_BLOBTREE_FIELD_H
#define BOREAS_CL_SHARED_BLOBTREE_FIELD_H

#include "shared/blobtree_types.h"
#include "shared/tree_math.h"

#ifdef __OPENCL_C_VERSION__
#define BOREAS_BT_GLOBAL __global
#else
#define BOREAS_BT_GLOBAL
#endif
#define BOREAS_BT_FN BOREAS_TM_FN

/* Far beyond any tree: "no other member". */
#define BOREAS_BT_FAR 1e30f

BOREAS_BT_FN BoreasV3 boreas_bt_plane3(BOREAS_BT_GLOBAL const float* planes, int plane, int n, int i) {
  return boreas_v3(planes[plane * n + i], planes[(plane + 1) * n + i], planes[(plane + 2) * n + i]);
}

/* A point in a primitive's unbent frame: t along the skeleton from the base (m), and the
 * two components across it (c0 towards U_DIR, or outwards from the bend's centre for a
 * bent primitive; c1 the right-handed other), so that the distance from the axis is
 * sqrt(c0^2 + c1^2). Barr's bend is undone by the angle around the arc's centre; beyond
 * either end the frame continues rigidly along the end's tangent. */
BOREAS_BT_FN void boreas_bt_local(BoreasV3 p, BOREAS_BT_GLOBAL const float* prims, int n, int i,
                                  float* t, float* c0, float* c1) {
  BoreasV3 base = boreas_bt_plane3(prims, BOREAS_BT_BASE, n, i);
  BoreasV3 a = boreas_bt_plane3(prims, BOREAS_BT_AXIS, n, i);
  BoreasV3 q = boreas_v3_sub(p, base);
  float rho = prims[BOREAS_BT_BEND_RHO * n + i];
  if (rho == 0.0f) {
    BoreasV3 u = boreas_bt_plane3(prims, BOREAS_BT_U_DIR, n, i);
    BoreasV3 w = boreas_v3_cross(a, u);
    *t = boreas_v3_dot(q, a);
    *c0 = boreas_v3_dot(q, u);
    *c1 = boreas_v3_dot(q, w);
    return;
  }
  BoreasV3 nd = boreas_bt_plane3(prims, BOREAS_BT_BEND_DIR, n, i);
  BoreasV3 b = boreas_v3_cross(a, nd);
  float sh = prims[BOREAS_BT_BEND_SIN * n + i];
  float ch = prims[BOREAS_BT_BEND_COS * n + i];
  float length = prims[BOREAS_BT_LENGTH * n + i];
  /* Coordinates about the arc's centre, base + rho (sh a - ch n): the arc spans the
   * angles [-h, h] from n, so the two ends' half-spaces meet on the bisector behind the
   * centre (angle pi), where atan2 wraps. */
  float qa0 = boreas_v3_dot(q, a);
  float qn0 = boreas_v3_dot(q, nd);
  float xa = qa0 - rho * sh;
  float xn = qn0 + rho * ch;
  float xb = boreas_v3_dot(q, b);
  float along = rho * boreas_atan2(xa, xn) + 0.5f * length;
  /* |p - centre| - rho without the cancellation of two nearly equal lengths when rho is
   * large (a slight bend): the base lies on the circle, so |p - centre|^2 - rho^2 =
   * |q|^2 - 2 rho q.(sh a - ch n) in the arc's plane. */
  float radial = (qa0 * qa0 + qn0 * qn0 - 2.0f * rho * (sh * qa0 - ch * qn0)) / (BOREAS_TM_SQRT(xa * xa + xn * xn) + rho);
  /* Before the base: the base's tangent is (ch, sh) in (a, n), its outward (-sh, ch). */
  float before_t = qa0 * ch + qn0 * sh;
  float before_c = qn0 * ch - qa0 * sh;
  /* After the top, base + 2 rho sh a: tangent (ch, -sh), outward (sh, ch). */
  float ta = qa0 - 2.0f * rho * sh;
  float after_t = length + ta * ch - qn0 * sh;
  float after_c = ta * sh + qn0 * ch;
  int before = along < 0.0f;
  int after = along > length;
  *t = before ? before_t : (after ? after_t : along);
  *c0 = before ? before_c : (after ? after_c : radial);
  *c1 = xb;
}

/* Squared distance from (t, r) (r >= 0 from the axis) to the skeleton cone of length L and
 * base radius r0: the triangle (0, 0), (0, r0), (L, 0) of the (t, r) half-plane. Behind
 * the base the nearest point is on the base disc; otherwise on the slanted side. */
BOREAS_BT_FN float boreas_bt_cone_distance2(float t, float r, float length, float r0) {
  float e = r - r0;
  e = e > 0.0f ? e : 0.0f;
  float behind = t * t + e * e;
  /* The floor keeps a degenerate skeleton (no length, no radius: a point) from 0/0. */
  float s = (t * length - (r - r0) * r0) / (length * length + r0 * r0 + 1e-30f);
  s = s < 0.0f ? 0.0f : (s > 1.0f ? 1.0f : s);
  float dt = t - s * length;
  float dr = r - r0 * (1.0f - s);
  float slant = dt * dt + dr * dr;
  int inside = t >= 0.0f && t <= length && r * length <= r0 * (length - t);
  return inside ? 0.0f : (t < 0.0f ? behind : slant);
}

/* Wyvill's fall-off of a squared distance: (1 - d^2/R^2)^3 inside R, else 0. */
BOREAS_BT_FN float boreas_bt_falloff(float d2, float inv_r2) {
  float x = 1.0f - d2 * inv_r2;
  x = x > 0.0f ? x : 0.0f;
  return x * x * x;
}

/* One primitive at p: its fall-off and its squared distance to the skeleton. */
BOREAS_BT_FN float boreas_bt_primitive(BoreasV3 p, BOREAS_BT_GLOBAL const float* prims, int n, int i,
                                       float* d2) {
  float t, c0, c1;
  boreas_bt_local(p, prims, n, i, &t, &c0, &c1);
  float r = BOREAS_TM_SQRT(c0 * c0 + c1 * c1);
  *d2 = boreas_bt_cone_distance2(t, r, prims[BOREAS_BT_LENGTH * n + i], prims[BOREAS_BT_CONE * n + i]);
  return boreas_bt_falloff(*d2, prims[BOREAS_BT_INV_R2 * n + i]);
}

/* Gascuel's expansion h(r) over the propagation region [0, w], r >= 0: a cubic from slope
 * k at 0 to the peak m at w/2 (zero slope), then (4m/w^3)(r - w)^2(4r - w) down to 0 at w
 * with zero slope. */
BOREAS_BT_FN float boreas_bt_pcm_expansion(float r, float w, float m, float k) {
  float inv_w = 1.0f / w;
  float inv_w2 = inv_w * inv_w;
  float c = 4.0f * (w * k - 4.0f * m) * inv_w2 * inv_w;
  float d = 4.0f * (3.0f * m - w * k) * inv_w2;
  float rising = ((c * r + d) * r + k) * r;
  float rw = r - w;
  float falling = 4.0f * m * inv_w2 * inv_w * rw * rw * (4.0f * r - w);
  return r < 0.5f * w ? rising : (r < w ? falling : 0.0f);
}

/* A cut's cutter field at p (see BOREAS_BT_CUT_*). */
BOREAS_BT_FN float boreas_bt_cutter(BoreasV3 p, BOREAS_BT_GLOBAL const float* cuts, int nc, int k) {
  BoreasV3 q = boreas_v3_sub(p, boreas_bt_plane3(cuts, BOREAS_BT_CUT_POINT, nc, k));
  float inv_ramp = 1.0f / cuts[BOREAS_BT_CUT_RAMP * nc + k];
  float side = 0.5f + 0.5f * boreas_v3_dot(q, boreas_bt_plane3(cuts, BOREAS_BT_CUT_NORMAL, nc, k)) * inv_ramp;
  float ball = 0.5f + 0.5f * (cuts[BOREAS_BT_CUT_RADIUS * nc + k] - boreas_v3_length(q)) * inv_ramp;
  float f = side < ball ? side : ball;
  return f < 0.0f ? 0.0f : (f > 1.0f ? 1.0f : f);
}

/* F at p from the primitives items[begin, end) (ascending; a bin's list, or all of them)
 * and every cut. Primitives missing from the list must not reach p: then F is the same,
 * bit for bit, as from the full list (their terms are exact zeros, see blobtree_bins.h). */
BOREAS_BT_FN float boreas_bt_field(BoreasV3 p, BOREAS_BT_GLOBAL const float* prims,
                                   BOREAS_BT_GLOBAL const int* ints, int n,
                                   BOREAS_BT_GLOBAL const int* items, int begin, int end,
                                   BOREAS_BT_GLOBAL const float* cuts, int nc) {
  float total = 0.0f;
  int k = begin;
  while (k < end) {
    int i = items[k];
    if (ints[BOREAS_BT_PCM * n + i] == 0) {
      float d2;
      total += prims[BOREAS_BT_WEIGHT * n + i] * boreas_bt_primitive(p, prims, n, i, &d2);
      ++k;
      continue;
    }
    int group = ints[BOREAS_BT_GROUP * n + i];
    int e = k + 1;
    while (e < end && ints[BOREAS_BT_GROUP * n + items[e]] == group && ints[BOREAS_BT_PCM * n + items[e]] != 0) ++e;
    /* The two largest fields and the two nearest surfaces, with whose they are, so that
     * each member's "others" are one select away. */
    float f1 = 0.0f, f2 = 0.0f, r1 = BOREAS_BT_FAR, r2 = BOREAS_BT_FAR, k1 = 0.0f, k2 = 0.0f;
    int f_at = -1, r_at = -1;
    for (int j = k; j < e; ++j) {
      int m = items[j];
      float d2;
      float f = boreas_bt_primitive(p, prims, n, m, &d2);
      float r = BOREAS_TM_SQRT(d2) - prims[BOREAS_BT_ISO_DIST * n + m];
      float slope = prims[BOREAS_BT_SLOPE * n + m];
      int top_f = f > f1;
      f2 = top_f ? f1 : (f > f2 ? f : f2);
      f1 = top_f ? f : f1;
      f_at = top_f ? j : f_at;
      int top_r = r < r1;
      int second_r = !top_r && r < r2;
      r2 = top_r ? r1 : (second_r ? r : r2);
      k2 = top_r ? k1 : (second_r ? slope : k2);
      r1 = top_r ? r : r1;
      k1 = top_r ? slope : k1;
      r_at = top_r ? j : r_at;
    }
    float best = 0.0f;
    for (int j = k; j < e; ++j) {
      int m = items[j];
      float d2;
      float f = boreas_bt_primitive(p, prims, n, m, &d2);
      float other_f = j == f_at ? f2 : f1;
      float other_r = j == r_at ? r2 : r1;
      float other_k = j == r_at ? k2 : k1;
      float expansion = boreas_bt_pcm_expansion(other_r < 0.0f ? 0.0f : other_r, prims[BOREAS_BT_PCM_WIDTH * n + m],
                                                prims[BOREAS_BT_PCM_PEAK * n + m], other_k);
      /* The expansion fades out with the member's own field where that is below half
       * the iso-value (well beyond the ridge), so it swells only this member; a member
       * with no field there adds nothing, which lets a bin leave out members that do not
       * reach it. */
      float support = f * (2.0f / BOREAS_BT_ISO);
      support = support < 1.0f ? support : 1.0f;
      float s = other_r < 0.0f ? BOREAS_BT_ISO - other_f : expansion * support;
      float deformed = f + s;
      best = deformed > best ? deformed : best;
    }
    /* Where two members overlap the solid stays solid: the second largest field exceeds
     * the iso-value exactly there, while the deformed fields alone equal it on the whole
     * contact surface, a sheet of iso-value inside the wood. */
    best = f2 > best ? f2 : best;
    total += best;
    k = e;
  }
  if (nc > 0 && total > 0.0f) {
    float cutter = 0.0f;
    for (int c = 0; c < nc; ++c) {
      float f = boreas_bt_cutter(p, cuts, nc, c);
      cutter = f > cutter ? f : cutter;
    }
    float keep = 1.0f - cutter;
    total = total < keep ? total : keep;
  }
  return total;
}

#endif
