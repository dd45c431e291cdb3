/* boreas: colliders pushing a generated tree's branches out of them, and the branches
 * pushing back (tree_step.cl's contact variant, BOREAS_TREE_CONTACT, at width 1). Compiles
 * as OpenCL C and as C/C++ (the tests run this text on the host).
 *
 * The push. A branch is a bent Bezier (sec. 4.3) whose shape follows its bend factor F:
 * for a small F, P2 moves by w2 F and P3 by (1 + w2) F, so the curve's point at t moves by
 * share(t) F, share(t) = 3 t^2 (1 - t) w2 + t^3 (1 + w2). After the step's own update of
 * F (wind, damped response, hold) the branch is tested against each collider that its
 * tree's reach meets: the deepest point of its surface in the collider's swept shape
 * (boreas_collider_distance; the surface by the branch's radius functions as the deformer
 * draws them, boreas_branch_radius, around its lobes) is found along the curve
 * (boreas_contact_deepest), and if it is inside by a depth, F moves by depth / share(t) along the collider's outward normal there, less the
 * normal's part along the branch (a bend turns segments, it cannot stretch them: a branch
 * met end-on is not pushed). A branch's base, where share is below
 * BOREAS_CONTACT_SHARE_MIN (its first fifth or so), is not tested: no bend moves it; it
 * moves with its parent, whose own surface is near and meets the collider there. A trunk's
 * base is tested, with share clamped to BOREAS_CONTACT_SHARE_MIN: the ground holds it, and
 * it holds a collider off as a wall would, pushed out over several steps. The push
 * starts where the branch, moving from its last step's bend toward its updated one, first
 * met a collider, so it keeps the side it came from (boreas_contact_start), and ends with a
 * slide along the surface toward the updated bend. The colliders are visited in a fixed
 * order, each measured
 * where the pushes before it have moved the branch (linearly), and the sweep is repeated
 * on the branch bent anew (the bend is not linear in F): a Gauss-Seidel projection,
 * deterministic.
 * This is a unilateral constraint applied as a projection of F after the step, not as a
 * load on F*: a projection puts the surface outside in the step it entered (a load would
 * let the damped response carry it in for a quarter period and chatter at the surface),
 * and the rate's part into the collider is removed, so a branch let go springs back from
 * rest at its own frequency and damping, the free response of the same oscillator.
 *
 * The force. What a branch held out of a collider pushes it with is its elastic load:
 * K (F - F*) along the contact's normal, at the tip, where K is the tip's load per unit
 * bend factor (the cantilever's tip stiffness, trees/wind_load.h, times (1 + w2)^2, and the
 * tree's scale: a beam s times larger is s times stiffer at its tip) and F* is the target
 * of the wind and the children's loads; referred to the contact point by 1 / share(t) (a
 * load there moves the tip by share(t) / K per newton, Maxwell's reciprocity, so the same
 * tip displacement takes 1 / share(t) times the tip's load). Inertia and the damper are
 * neglected (the quasi-static force of the bent beam), and so is friction along the
 * surface. It is bounded by the wood's strength (boreas_contact_bearable): where holding a
 * collider off would take more, the branch yields and the push is scaled back. Torque is taken about the collider's position at the step's end, the force
 * acting at the branch's surface point facing it.
 *
 * The parent. The force on a branch (from colliders, and from its own children) is a load
 * on its parent where it attaches at v, a step later (the children's planes of the last
 * step): the parent's target moves by the load's share(v) / K_parent (the tip displacement
 * a point load at v makes). Only the force passes, not its moment about the attachment. */
#ifndef BOREAS_CL_SHARED_TREE_CONTACT_H
#define BOREAS_CL_SHARED_TREE_CONTACT_H

#include "shared/collider_math.h"
#include "shared/tree_state.h"
#include "shared/tree_types.h"

/* The least share(t) a contact a branch holds off may have. A
 * branch whose base lies in a collider (one placed in a fork) cannot bend it out: held off
 * with its elastic load referred there, K / share^2 per metre of depth (tree_contact.h's
 * force), each such limb took tens of kN and passed them to its trunk, which swung metres.
 * The base moves with the parent, and the parent's own surface, within a few of the limb's
 * radii of it, holds the collider off with the parent's stiffness: the contact is the
 * parent's. 0.05 leaves out about the first fifth of a branch (share(0.19) = 0.05 at w2 0.5).
 * A trunk's base, which the ground holds, is tested, its share clamped to this. */
#define BOREAS_CONTACT_SHARE_MIN 0.05f
#define BOREAS_CONTACT_SAMPLES 8
#define BOREAS_CONTACT_SWEEPS 6
#define BOREAS_CONTACT_BISECTIONS 6
#define BOREAS_CONTACT_PATH_SAMPLES 8

/* How far the point at t of a branch moves per unit of bend factor (small F). */
BOREAS_FN float boreas_contact_share(float t, float w2) {
  return 3.0f * t * t * (1.0f - t) * w2 + t * t * t * (1.0f + w2);
}

/* A branch as the push sees it; lengths and stiffness already scaled for its tree. */
typedef struct BoreasContactBranch {
  BoreasV3 p0, p1;      /* placed on its parent (unbent: P0 and P1 do not bend) */
  BoreasV3 seg2, seg3;  /* its unbent segments P2 - P1 and P3 - P2 */
  BoreasV3 bend;        /* F after the step's update */
  BoreasV3 previous;    /* F the step began from: the last step's, after its push */
  BoreasV3 target;      /* F*: the wind's and the children's load */
  float w2;             /* P2's bend weight */
  float radius;         /* m: a bound on the radius along it (boreas_contact_reach) */
  BoreasBranchRadius shape; /* its radius functions at the tree's scale */
  float stiffness;      /* N per m of bend factor, at the tip (BOREAS_TREE_SHAPE_CONTACT_STIFFNESS) */
  float break_bend;     /* m of bend factor: the tip's bend at rupture (BOREAS_TREE_SHAPE_BREAK) */
  float parents_share;  /* contacts where share(t) is below this are its parent's:
                           BOREAS_CONTACT_SHARE_MIN on a parent, 0 for a trunk */
} BoreasContactBranch;

/* A bound on a branch's radius along it, m, for the boxes: taper, beads and the tip's cap
 * are at most 1 (a taper depth in [0, 1]), the flare at most 1 + flare; lobes are left
 * out of the contact (their mean, 1, at theta 0). */
BOREAS_FN float boreas_contact_reach(BoreasBranchRadius shape) {
  return shape.radius * (1.0f + BOREAS_FMAX(shape.flare, 0.0f));
}

/* The branch's radius at t around its lobes: theta 0, where their factor is 1. */
BOREAS_FN float boreas_contact_radius(BoreasBranchRadius shape, float t) {
  float r, dr_dv, lobes, d_lobes;
  boreas_branch_radius(shape, t, 0.0f, &r, &dr_dv, &lobes, &d_lobes);
  return r;
}

/* The branch bent by f (eq. 17, as tree_step.cl bends it). */
BOREAS_FN BoreasBezier boreas_contact_curve(BoreasContactBranch b, BoreasV3 f) {
  BoreasBezier c;
  c.p0 = b.p0;
  c.p1 = b.p1;
  c.p2 = boreas_bend_point(b.p1, b.seg2, boreas_v3_scale(f, b.w2));
  c.p3 = boreas_bend_point(c.p2, b.seg3, f);
  return c;
}

/* Where a branch's surface at t meets a collider. */
typedef struct BoreasContactPoint {
  float depth;      /* m: how far the surface is inside (negative: outside) */
  float t;          /* where along the branch */
  float share;      /* share(t), clamped from below */
  BoreasV3 normal;  /* the collider's outward normal there */
  BoreasV3 across;  /* that normal less its part along the branch */
  BoreasV3 at;      /* the branch's surface point facing the collider */
} BoreasContactPoint;

BOREAS_FN BoreasContactPoint boreas_contact_point(BoreasContactBranch b, BoreasBezier curve,
                                                  float t,
                                                  BOREAS_GLOBAL const BoreasGpuCollider* col) {
  BoreasV3 axis = boreas_bezier_point(curve, t);
  float r = boreas_contact_radius(b.shape, t);
  BoreasColliderDistance d = boreas_collider_distance(axis, col);
  BoreasV3 along = boreas_v3_normalize(boreas_bezier_derivative(curve, t));
  BoreasContactPoint p;
  float share = boreas_contact_share(t, b.w2);
  /* The base, which no bend moves: its parent's contact (BOREAS_CONTACT_SHARE_MIN). */
  p.depth = share < b.parents_share ? -1.0f : r - d.distance;
  p.t = t;
  p.share = BOREAS_FMAX(share, BOREAS_CONTACT_SHARE_MIN);
  p.normal = d.normal;
  p.across = boreas_v3_madd(d.normal, along, -boreas_v3_dot(d.normal, along));
  p.at = boreas_v3_madd(axis, d.normal, -r);
  return p;
}

/* The deepest point of the branch's surface in collider col: its depth at t = 1/8 .. 1,
 * then half a step either side of the deepest of those, then the vertex of the parabola
 * through those three (the depth along a nearly straight branch in a convex shape has one
 * maximum: this finds it to a small fraction of the spacing). */
BOREAS_FN BoreasContactPoint boreas_contact_deepest(BoreasContactBranch b, BoreasBezier curve,
                                                    BOREAS_GLOBAL const BoreasGpuCollider* col) {
  const float h = 1.0f / (float)BOREAS_CONTACT_SAMPLES;
  BoreasContactPoint best = boreas_contact_point(b, curve, h, col);
  float best_t = h;
  for (int s = 2; s <= BOREAS_CONTACT_SAMPLES; ++s) {
    BoreasContactPoint p = boreas_contact_point(b, curve, (float)s * h, col);
    best_t = p.depth > best.depth ? (float)s * h : best_t;
    best = p.depth > best.depth ? p : best;
  }
  float t_lo = BOREAS_MAX(best_t - 0.5f * h, 0.5f * h), t_hi = BOREAS_MIN(best_t + 0.5f * h, 1.0f);
  BoreasContactPoint lo = boreas_contact_point(b, curve, t_lo, col);
  BoreasContactPoint hi = boreas_contact_point(b, curve, t_hi, col);
  /* The vertex of the parabola through (t_lo, t, t_hi), kept within them. */
  float a = best_t - t_lo, c = t_hi - best_t;
  float dl = (lo.depth - best.depth) / (a + 1e-30f), dh = (hi.depth - best.depth) / (c + 1e-30f);
  float curvature = (dl + dh) / (a + c + 1e-30f);
  float vertex = curvature < 0.0f ? 0.5f * (t_lo + best_t) + 0.5f * dl / curvature : best_t;
  vertex = BOREAS_CLAMP(vertex, t_lo, t_hi);
  BoreasContactPoint v = boreas_contact_point(b, curve, vertex, col);
  best = lo.depth > best.depth ? lo : best;
  best = hi.depth > best.depth ? hi : best;
  return v.depth > best.depth ? v : best;
}

/* Whether collider col can reach the branch whose curve lies in the box lo..hi (a Bezier
 * lies in its control points' hull; the box is grown by the branch's radius): the box
 * against the sphere round the collider's whole sweep. Most branches of a touched tree are
 * far from its colliders and pay this test alone. */
BOREAS_FN int boreas_contact_near(BoreasV3 lo, BoreasV3 hi,
                                  BOREAS_GLOBAL const BoreasGpuCollider* col) {
  BoreasV3 m = boreas_v3(col->cx + 0.5f * col->dx, col->cy + 0.5f * col->dy,
                         col->cz + 0.5f * col->dz);
  float reach = BOREAS_SQRT(col->hx * col->hx + col->hy * col->hy + col->hz * col->hz) +
                col->radius +
                0.5f * BOREAS_SQRT(col->dx * col->dx + col->dy * col->dy + col->dz * col->dz);
  BoreasV3 out = boreas_v3(BOREAS_MAX(BOREAS_MAX(lo.x - m.x, m.x - hi.x), 0.0f),
                           BOREAS_MAX(BOREAS_MAX(lo.y - m.y, m.y - hi.y), 0.0f),
                           BOREAS_MAX(BOREAS_MAX(lo.z - m.z, m.z - hi.z), 0.0f));
  return boreas_v3_dot(out, out) <= reach * reach;
}

/* One sweep over the colliders on the branch bent by bend + push: each collider's deepest
 * point moves out by its depth / share along the normal across the branch, measured where
 * the pushes before it in the sweep have moved it (linearly). Returns the push grown so.
 * With `first` set, writes each collider's deepest contact into its record for the force
 * to come: normal (FORCE), surface point (TORQUE), TOUCHING and t (slot 7). */
BOREAS_FN BoreasV3 boreas_contact_sweep(BoreasContactBranch b, BoreasV3 push,
                                        BOREAS_GLOBAL const BoreasGpuCollider* colliders,
                                        int count, BOREAS_GLOBAL float* records, int first,
                                        BoreasV3 lo, BoreasV3 hi) {
  BoreasBezier curve = boreas_contact_curve(b, boreas_v3_add(b.bend, push));
  BoreasV3 moved = boreas_v3(0.0f, 0.0f, 0.0f); /* this sweep's push so far */
  for (int j = 0; j < count; ++j) {
    BOREAS_GLOBAL const BoreasGpuCollider* col = colliders + j;
    BoreasContactPoint p;
    if (boreas_contact_near(lo, hi, col)) {
      p = boreas_contact_deepest(b, curve, col);
    } else {
      p.depth = -1.0f;
      p.t = 1.0f;
      p.share = 1.0f;
      p.normal = boreas_v3(0.0f, 0.0f, 0.0f);
      p.across = p.normal;
      p.at = p.normal;
    }
    /* The pushes before it in this sweep moved it by about share times theirs. */
    float depth = p.depth - boreas_v3_dot(moved, p.normal) * p.share;
    moved = boreas_v3_madd(moved, p.across, depth > 0.0f ? depth / p.share : 0.0f);
    if (first) {
      BOREAS_GLOBAL float* rec = records + j * BOREAS_TREE_CONTACT_RECORD_FLOATS;
      rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 0] = p.normal.x;
      rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 1] = p.normal.y;
      rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 2] = p.normal.z;
      rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 0] = p.at.x;
      rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 1] = p.at.y;
      rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 2] = p.at.z;
      rec[BOREAS_TREE_CONTACT_RECORD_TOUCHING] = p.depth > 0.0f ? 1.0f : 0.0f;
      rec[BOREAS_TREE_CONTACT_RECORD_TOUCHING + 1] = p.t;
    }
  }
  return boreas_v3_add(push, moved);
}

/* The deepest the branch bent by f goes into any collider near the box lo..hi (negative or
 * -1: clear of them all). */
BOREAS_FN float boreas_contact_depth(BoreasContactBranch b, BoreasV3 f,
                                     BOREAS_GLOBAL const BoreasGpuCollider* colliders, int count,
                                     BoreasV3 lo, BoreasV3 hi) {
  BoreasBezier curve = boreas_contact_curve(b, f);
  float deepest = -1.0f;
  for (int j = 0; j < count; ++j)
    if (boreas_contact_near(lo, hi, colliders + j))
      deepest = BOREAS_FMAX(deepest, boreas_contact_deepest(b, curve, colliders + j).depth);
  return deepest;
}

/* Where the push starts from: the side a branch is pushed to is the side it met the
 * collider from. The nearest way out of a collider is not that side once the collider's
 * middle has passed the branch's axis, and a quasi-static branch, whose updated bend is its
 * target, remembers nothing else: it would be thrown to the far side in one step, or spring
 * back through a collider that has passed its rest pose. So the branch moves from where it
 * was (`previous`, outside last step) toward its updated bend and stops where it first
 * enters a collider (conservative advancement): the path is sampled at
 * BOREAS_CONTACT_PATH_SAMPLES points, and the entry bisected between the last clear one and
 * the first inside, just inside, where the nearest way out is back the way it came. (A
 * collider thinner than the path's spacing, 1/8 of a step's change of bend, can be missed:
 * a branch that springs back 40 cm in one step passes a 5 cm bar.) A clear path ends at the
 * updated bend, with no contact; if the previous bend is already inside (the collider moved
 * into it) the push starts there, shallow, on its side. */
BOREAS_FN BoreasV3 boreas_contact_start(BoreasContactBranch b,
                                        BOREAS_GLOBAL const BoreasGpuCollider* colliders,
                                        int count, BoreasV3 lo, BoreasV3 hi) {
  BoreasV3 path = boreas_v3_sub(b.bend, b.previous);
  float clear = 0.0f, inside = -1.0f;
  for (int i = 0; i <= BOREAS_CONTACT_PATH_SAMPLES && inside < 0.0f; ++i) {
    float s = (float)i / (float)BOREAS_CONTACT_PATH_SAMPLES;
    /* the end exactly: a clear path leaves the bend as the step made it, bit for bit */
    BoreasV3 f = i == BOREAS_CONTACT_PATH_SAMPLES ? b.bend : boreas_v3_madd(b.previous, path, s);
    if (boreas_contact_depth(b, f, colliders, count, lo, hi) > 0.0f) inside = s;
    else clear = s;
  }
  if (inside < 0.0f) return b.bend;
  if (inside == 0.0f) return b.previous;
  for (int i = 0; i < BOREAS_CONTACT_BISECTIONS; ++i) {
    float mid = 0.5f * (clear + inside);
    int in = boreas_contact_depth(b, boreas_v3_madd(b.previous, path, mid), colliders, count,
                                  lo, hi) > 0.0f;
    inside = in ? mid : inside;
    clear = in ? clear : mid;
  }
  return inside == 1.0f ? b.bend : boreas_v3_madd(b.previous, path, inside);
}

/* The push grown by BOREAS_CONTACT_SWEEPS sweeps, each on the branch bent by the push so
 * far (the bend is not linear in F, so a sweep's prediction falls short where the branch is
 * bent far); the first writes the records when `write` is set. */
BOREAS_FN BoreasV3 boreas_contact_project(BoreasContactBranch b, BoreasV3 push,
                                          BOREAS_GLOBAL const BoreasGpuCollider* colliders,
                                          int count, BOREAS_GLOBAL float* records, int write,
                                          BoreasV3 lo, BoreasV3 hi) {
  for (int sweep = 0; sweep < BOREAS_CONTACT_SWEEPS; ++sweep) {
    BoreasV3 before = push;
    push = boreas_contact_sweep(b, push, colliders, count, records, write && sweep == 0, lo, hi);
    /* Nothing moved: every later sweep would find the same (the first always runs, for the
     * records). */
    if (push.x == before.x && push.y == before.y && push.z == before.z) break;
  }
  return push;
}

/* The box of a curve's control points (which hold it), grown by g. */
BOREAS_FN void boreas_curve_box(BoreasBezier c, float g, BoreasV3* lo, BoreasV3* hi) {
  *lo = boreas_v3(BOREAS_MIN(BOREAS_MIN(c.p0.x, c.p1.x), BOREAS_MIN(c.p2.x, c.p3.x)) - g,
                  BOREAS_MIN(BOREAS_MIN(c.p0.y, c.p1.y), BOREAS_MIN(c.p2.y, c.p3.y)) - g,
                  BOREAS_MIN(BOREAS_MIN(c.p0.z, c.p1.z), BOREAS_MIN(c.p2.z, c.p3.z)) - g);
  *hi = boreas_v3(BOREAS_MAX(BOREAS_MAX(c.p0.x, c.p1.x), BOREAS_MAX(c.p2.x, c.p3.x)) + g,
                  BOREAS_MAX(BOREAS_MAX(c.p0.y, c.p1.y), BOREAS_MAX(c.p2.y, c.p3.y)) + g,
                  BOREAS_MAX(BOREAS_MAX(c.p0.z, c.p1.z), BOREAS_MAX(c.p2.z, c.p3.z)) + g);
}

/* The most a contact at t can press a branch with, as its bend factor's excess over the
 * target along the contact's normal. A branch holds a collider off with its elastic load,
 * K (F - F*) . n / share(t) at the contact point; the wood bears at most the load whose
 * moment about the base is the break load's at the tip (K F_break, trees/wind_load.h), a
 * load of K F_break / t at t. A collider that needs more, pressed deep near a branch's base
 * where share is small and the elastic load, K depth / share^2, large, is not held off: the
 * branch yields there, as wood that has reached its strength does, and neither swings its
 * tip nor loads its parent with tens of kN (in the fork test, without this bound: 26-32 kN,
 * more than breaks the aspen's trunk). Its break stays the wind's (tree_step.cl): this load
 * is at most the one that breaks it. */
BOREAS_FN float boreas_contact_bearable(BoreasContactBranch b, float t) {
  float share = BOREAS_FMAX(boreas_contact_share(t, b.w2), BOREAS_CONTACT_SHARE_MIN);
  return b.break_bend * share / BOREAS_FMAX(t, 1e-6f);
}

/* The push scaled back (by one factor, 0..1, the same direction) until no contact's
 * pressing passes what the branch bears there (boreas_contact_bearable); the records hold
 * each contact's normal and t (the first sweep's). */
BOREAS_FN BoreasV3 boreas_contact_yield(BoreasContactBranch b, BoreasV3 push,
                                        BOREAS_GLOBAL const float* records, int count) {
  BoreasV3 unpushed = boreas_v3_sub(b.bend, b.target);
  float scale = 1.0f;
  for (int j = 0; j < count; ++j) {
    BOREAS_GLOBAL const float* rec = records + j * BOREAS_TREE_CONTACT_RECORD_FLOATS;
    BoreasV3 normal = boreas_v3(rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 0],
                                rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 1],
                                rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 2]);
    float bearable = boreas_contact_bearable(b, rec[BOREAS_TREE_CONTACT_RECORD_TOUCHING + 1]);
    float before = boreas_v3_dot(unpushed, normal), added = boreas_v3_dot(push, normal);
    if (added > 0.0f && before + added > bearable)
      scale = BOREAS_MIN(scale, BOREAS_FMAX((bearable - before) / added, 0.0f));
  }
  return boreas_v3_scale(push, scale);
}

/* Pushes branch b out of `count` colliders (tree_contact.h): from where it met them
 * (boreas_contact_start) out along their normals, then a slide toward its updated bend
 * across those normals (the surface holds the branch only along its normal: a quasi-static
 * branch settles where its target is nearest, frictionless, and a damped one keeps the
 * motion along the surface) pushed out again. Returns the change of its bend factor;
 * writes one record per collider from `records` (tree_types.h: force and torque on the
 * collider, touching: as the first sweep found the contact), and adds the forces on the
 * branch to *load. */
BOREAS_FN BoreasV3 boreas_tree_contact(BoreasContactBranch b,
                                       BOREAS_GLOBAL const BoreasGpuCollider* colliders, int count,
                                       BOREAS_GLOBAL float* records, BoreasV3* load) {
  /* The boxes of the branch where it was and as the step left it, grown by its radius (a
   * push that moves it into a collider it was not near is met the next step). */
  BoreasV3 lo, hi, lo_p, hi_p;
  boreas_curve_box(boreas_contact_curve(b, b.bend), b.radius, &lo, &hi);
  boreas_curve_box(boreas_contact_curve(b, b.previous), b.radius, &lo_p, &hi_p);
  lo = boreas_v3(BOREAS_MIN(lo.x, lo_p.x), BOREAS_MIN(lo.y, lo_p.y), BOREAS_MIN(lo.z, lo_p.z));
  hi = boreas_v3(BOREAS_MAX(hi.x, hi_p.x), BOREAS_MAX(hi.y, hi_p.y), BOREAS_MAX(hi.z, hi_p.z));
  BoreasV3 entry = boreas_v3_sub(boreas_contact_start(b, colliders, count, lo, hi), b.bend);
  BoreasV3 push = boreas_contact_project(b, entry, colliders, count, records, 1, lo, hi);
  /* The slide: the rest of the way to the updated bend, less its part into the colliders
   * (along the push they made); a convex surface falls away under a slide along it, so the
   * branch then moves on toward its updated bend until it meets the surface again (as it
   * met it first), and is pushed out of any it entered. Where the branch settles is so a
   * fixed point of the step: the next step, starting there, slides back to it. */
  BoreasV3 met = boreas_v3_sub(push, entry);
  if (met.x != 0.0f || met.y != 0.0f || met.z != 0.0f) {
    BoreasV3 n = boreas_v3_normalize(met);
    BoreasV3 rest = boreas_v3_scale(push, -1.0f);
    rest = boreas_v3_madd(rest, n, -BOREAS_MIN(boreas_v3_dot(rest, n), 0.0f));
    BoreasContactBranch slid = b;
    slid.previous = boreas_v3_add(b.bend, boreas_v3_add(push, rest));
    BoreasV3 again = boreas_v3_sub(boreas_contact_start(slid, colliders, count, lo, hi), b.bend);
    push = boreas_contact_project(b, again, colliders, count, records, 0, lo, hi);
  }
  push = boreas_contact_yield(b, push, records, count);
  /* The elastic load that holds the branch out, along each contact's normal, referred to
   * its contact point; on the collider it pushes the other way. */
  BoreasV3 held = boreas_v3_sub(boreas_v3_add(b.bend, push), b.target);
  for (int j = 0; j < count; ++j) {
    BOREAS_GLOBAL const BoreasGpuCollider* col = colliders + j;
    BOREAS_GLOBAL float* rec = records + j * BOREAS_TREE_CONTACT_RECORD_FLOATS;
    BoreasV3 normal = boreas_v3(rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 0], rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 1],
                                rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 2]);
    BoreasV3 at = boreas_v3(rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 0], rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 1],
                            rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 2]);
    float t = rec[BOREAS_TREE_CONTACT_RECORD_TOUCHING + 1];
    float share = BOREAS_FMAX(boreas_contact_share(t, b.w2), BOREAS_CONTACT_SHARE_MIN);
    float pressed =
        BOREAS_MIN(BOREAS_FMAX(boreas_v3_dot(held, normal), 0.0f), boreas_contact_bearable(b, t));
    BoreasV3 on_branch = boreas_v3_scale(normal, b.stiffness * pressed / share);
    *load = boreas_v3_add(*load, on_branch);
    BoreasV3 end = boreas_v3(col->cx + col->dx, col->cy + col->dy, col->cz + col->dz);
    BoreasV3 on_collider = boreas_v3_scale(on_branch, -1.0f);
    BoreasV3 torque = boreas_v3_cross(boreas_v3_sub(at, end), on_collider);
    rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 0] = on_collider.x;
    rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 1] = on_collider.y;
    rec[BOREAS_TREE_CONTACT_RECORD_FORCE + 2] = on_collider.z;
    rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 0] = torque.x;
    rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 1] = torque.y;
    rec[BOREAS_TREE_CONTACT_RECORD_TORQUE + 2] = torque.z;
    rec[BOREAS_TREE_CONTACT_RECORD_TOUCHING + 1] = 0.0f;
  }
  return push;
}

/* The rate after a push: its part into the collider (against the push) removed. */
BOREAS_FN BoreasV3 boreas_contact_rate(BoreasV3 rate, BoreasV3 push) {
  BoreasV3 n = boreas_v3_normalize(push); /* zero where nothing pushed: the rate stays */
  return boreas_v3_madd(rate, n, -BOREAS_MIN(boreas_v3_dot(rate, n), 0.0f));
}

/* The load a branch takes from its children's contact loads of the last step, as the
 * displacement of its target: each child's force at its attachment v, times share(v) / K
 * (K: the branch's `stiffness`, scaled). *passed is their sum, which the branch hands on.
 * Entries: the branch's own planes from `root` (its tree's root entry), its template's
 * from `static_root`; the branch is entry `offset` of its tree. */
BOREAS_FN BoreasV3 boreas_tree_child_load(BOREAS_GLOBAL const float* contact_in, int n, int root,
                                          BOREAS_GLOBAL const int* children,
                                          BOREAS_GLOBAL const float* shape, int sn,
                                          int static_root, int offset, float w2, float stiffness,
                                          BoreasV3* passed) {
  BoreasV3 sum = boreas_v3(0.0f, 0.0f, 0.0f), moved = sum;
  for (int run = 0; run < 2; ++run) {
    int first = children[BOREAS_TREE_AT(BOREAS_TREE_CHILD_FIRST_A + 2 * run, sn, static_root + offset)];
    int count = children[BOREAS_TREE_AT(BOREAS_TREE_CHILD_COUNT_A + 2 * run, sn, static_root + offset)];
    for (int c = first; c < first + count; ++c) {
      float v = shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_V, sn, static_root + c)];
      BoreasV3 force = boreas_tree_load3(contact_in, n, 0, root + c);
      sum = boreas_v3_add(sum, force);
      moved = boreas_v3_madd(moved, force, boreas_contact_share(v, w2));
    }
  }
  *passed = sum;
  return boreas_v3_scale(moved, 1.0f / (stiffness + 1e-30f));
}

/* Whether a branch of a touched tree is left as the plain launch stepped it: it and its
 * children took no load last step and its new curve (`state`, which the plain launch wrote
 * before this one runs, from the same inputs) is near none of its tree's colliders; then
 * the contact variant would give the same bits, so it only writes what that launch does
 * not: no load for its parent and empty records. Most branches of a touched tree are so. */
BOREAS_FN int boreas_tree_contact_idle(BOREAS_GLOBAL const float* contact_in,
                                       BOREAS_GLOBAL const float* state, int n, int root,
                                       BOREAS_GLOBAL const int* children,
                                       BOREAS_GLOBAL const float* shape, int sn, int static_root,
                                       int offset, float radius,
                                       BOREAS_GLOBAL const BoreasGpuCollider* colliders, int count,
                                       BOREAS_GLOBAL float* records, BOREAS_GLOBAL float* contact_out) {
  BoreasV3 passed;
  boreas_tree_child_load(contact_in, n, root, children, shape, sn, static_root, offset, 0.0f, 1.0f,
                         &passed);
  /* Its own load of the last step: a branch held out of a collider then is not idle now,
   * though its new curve (a quasi-static branch's rest) be far from it: the way back may
   * cross the collider (boreas_contact_start). */
  BoreasV3 own = boreas_tree_load3(contact_in, n, 0, root + offset);
  int idle = passed.x == 0.0f && passed.y == 0.0f && passed.z == 0.0f && own.x == 0.0f &&
             own.y == 0.0f && own.z == 0.0f;
  BoreasV3 o;
  BoreasBezier c = boreas_tree_load_curve(state, n, root + offset, &o);
  BoreasV3 lo, hi;
  boreas_curve_box(c, radius, &lo, &hi);
  for (int j = 0; j < count; ++j) idle = idle && !boreas_contact_near(lo, hi, colliders + j);
  if (!idle) return 0;
  for (int j = 0; j < count * BOREAS_TREE_CONTACT_RECORD_FLOATS; ++j) records[j] = 0.0f;
  boreas_tree_store3(contact_out, n, 0, root + offset, boreas_v3(0.0f, 0.0f, 0.0f));
  return 1;
}

#endif
