/* boreas: a leaf's placement in 8 bytes — its parent branch's entry, where along the
 * branch, and the three turns of its attachment (around the branch, down from it, the
 * blade's roll), quantized into two ints (the template's leaf planes, tree_types.h). What
 * every leaf of a tree shares (blade length and width, the petiole) is kept once per
 * template and scaled per tree (the leaf tiles' BOREAS_TILE_VALUE: the petiole times the
 * tree's scale), so an aspen's 22,000 leaves take 176 KB, not 792 KB.
 *
 * Every reader decodes through boreas_leaf_unpack (the leaf records of cl/tree_leaves.cl,
 * and through them the rays, the getters, export and crown light; the native twin); the
 * host packs with boreas_leaf_pack. Compiles as OpenCL C and as C/C++.
 *
 * Layout (bits, from the lowest):
 *   word PLACE: the parent's local entry (BOREAS_LEAF_ENTRY_BITS), then v (V_BITS)
 *   word TURN:  theta (THETA_BITS), alpha (ALPHA_BITS), roll (ROLL_BITS)
 * v, the Bezier parameter on the parent, is fixed point over [0, 1] with both ends exact.
 * A turn is a unit 2-vector (cos, sin) on the "diamond" |x| + |y| = 1, t in [0, 4) turning
 * counter-clockwise from (1, 0) through (0, 1), (-1, 0) and (0, -1), t quantized to
 * 2^bits steps; decoding normalizes the diamond's point, with no trigonometry (PoCL
 * vectorizes it). The four axis directions are exact.
 *
 * Error bounds of a decoded leaf against the double placement it was packed from:
 *   |v - v'| <= 1/2 / (2^V_BITS - 1)   (1.2e-4 at 12 bits: 0.12 mm along a 1 m twig)
 *   each turn within 4 / 2^bits rad     (rounding t by half a step, 2 / 2^bits, turns the
 *     direction by at most twice that: |d angle / dt| <= 2 on the diamond, at its edges'
 *     midpoints): theta and alpha 1.95e-3 rad (0.112 deg), roll 3.9e-3 rad (0.224 deg)
 *   so the blade's axis within the theta and alpha bounds' sum, its normal within all
 *   three's, its base within the petiole times the axis bound plus the parent's speed
 *   along its curve (|dB/dv| <= 3 times its longest leg) times the v bound.
 * Entries are exact: a tree of at most 2^ENTRY_BITS entries (root + branches; the
 * generator's limit, GrowthLimits, keeps below it) fits. */
#ifndef BOREAS_CL_SHARED_LEAF_PACK_H
#define BOREAS_CL_SHARED_LEAF_PACK_H

#include "shared/simd_width.h"
#include "shared/tree_types.h"

#define BOREAS_LEAF_ENTRY_BITS 20
#define BOREAS_LEAF_V_BITS 12
#define BOREAS_LEAF_THETA_BITS 11
#define BOREAS_LEAF_ALPHA_BITS 11
#define BOREAS_LEAF_ROLL_BITS 10
#define BOREAS_LEAF_V_SHIFT BOREAS_LEAF_ENTRY_BITS
#define BOREAS_LEAF_ALPHA_SHIFT BOREAS_LEAF_THETA_BITS
#define BOREAS_LEAF_ROLL_SHIFT (BOREAS_LEAF_THETA_BITS + BOREAS_LEAF_ALPHA_BITS)

/* A leaf decoded, at the current width (simd_width.h). */
#define BOREAS_LEAF_PLACE BOREAS_WIDE_NAME(BoreasLeafPlace)

#define BOREAS_WIDTH_BODY "shared/leaf_pack_width.inc"
#include "shared/width_instantiate.inc"

#ifdef __OPENCL_C_VERSION__
/* The leaves of a work-item (its W from k on, of a tile of count leaves from the template
 * leaf `first`) from the leaf planes (stride sm), decoded. */
BOREAS_FN BOREAS_LEAF_PLACE boreas_leaf_load_w(__global const int* leaves, int sm, int first,
                                               int k, int count) {
#if BOREAS_W == 1
#ifdef BOREAS_WIDE_PLANES
  const size_t at = (size_t)first + (size_t)min(k, count - 1);
#else
  const int at = first + min(k, count - 1);
#endif
  return boreas_leaf_unpack(leaves[(size_t)BOREAS_TREE_LEAF_PLACE * (size_t)sm + at],
                            leaves[(size_t)BOREAS_TREE_LEAF_TURN * (size_t)sm + at]);
#else
  return boreas_leaf_unpack(boreas_load_wi(leaves + BOREAS_TREE_LEAF_PLACE * sm + first, k, count),
                            boreas_load_wi(leaves + BOREAS_TREE_LEAF_TURN * sm + first, k, count));
#endif
}
#else
/* The diamond parameter of (c, s) (not both 0) quantized to `bits`. */
static inline unsigned boreas_leaf_pack_turn(double c, double s, int bits) {
  const double x = c / (fabs(c) + fabs(s));
  const double t = s >= 0.0 ? 1.0 - x : 3.0 + x;
  const double steps = (double)(1u << bits);
  return (unsigned)(long long)floor(t * steps / 4.0 + 0.5) & ((1u << bits) - 1u);
}

/* The two words of a leaf on local entry `entry` (0 <= entry < 2^ENTRY_BITS) at v
 * (clamped to [0, 1]), turned by theta, alpha and roll (cosine and sine each, unit up to
 * rounding). */
static inline void boreas_leaf_pack(int entry, double v, double cos_theta, double sin_theta,
                                    double cos_alpha, double sin_alpha, double cos_roll,
                                    double sin_roll, int words[2]) {
  const double top = (double)((1u << BOREAS_LEAF_V_BITS) - 1u);
  const double at = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
  const unsigned vq = (unsigned)(long long)floor(at * top + 0.5);
  const unsigned place = ((unsigned)entry & ((1u << BOREAS_LEAF_ENTRY_BITS) - 1u)) |
                         (vq << BOREAS_LEAF_V_SHIFT);
  const unsigned turn =
      boreas_leaf_pack_turn(cos_theta, sin_theta, BOREAS_LEAF_THETA_BITS) |
      (boreas_leaf_pack_turn(cos_alpha, sin_alpha, BOREAS_LEAF_ALPHA_BITS) << BOREAS_LEAF_ALPHA_SHIFT) |
      (boreas_leaf_pack_turn(cos_roll, sin_roll, BOREAS_LEAF_ROLL_BITS) << BOREAS_LEAF_ROLL_SHIFT);
  memcpy(&words[0], &place, sizeof place);
  memcpy(&words[1], &turn, sizeof turn);
}
#endif

#endif
