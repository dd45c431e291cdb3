/* boreas: an underbrush component's static rest data in packed form (the index planes of
 * cl/shared/underbrush_types.h): how the kernels and the host's references decode it, one
 * text for both. The host's encoders (host/src/underbrush/frame_pack.h) pick the codes
 * whose decoding here is nearest the exact values, and the meadow keeps only what decodes:
 * every reader, device or host, float or double, sees the same axis, side and scale.
 *
 * LINK: the component's part (low 16 bits, meadow-local) and how many components back its
 *   parent is (high 16 bits; 0 for a root): a plant's components are consecutive and a
 *   child follows its parent, so the distance is below BOREAS_PLANT_MAX_COMPONENTS.
 * AXIS: e_u, octahedral-encoded (two 16-bit signed-normalized coordinates of the unit
 *   octahedron folded onto a square, low bits the first): the encoding of Meyer, Süßmuth,
 *   Sußner, Stamminger and Greiner, "On Floating-Point Normal Vectors" (EGSR 2010), as
 *   surveyed by Cigolle, Donow, Evangelakos, Mara, McGuire and Meyer, "A Survey of
 *   Efficient Representations for Independent Unit Vectors" (JCGT 2014). The octahedron's
 *   pole is +y (up), so upright blades sit in its densest corner.
 * TURN: e_w as an angle about e_u (low 16 bits) and the scale as an IEEE half (high 16
 *   bits). The angle is a point of the unit diamond |c| + |s| = 1 (the octahedral encoding
 *   one dimension down: no trigonometry), normalized, in the basis perpendicular to e_u of
 *   Duff, Burgess, Christensen, Hery, Kensler, Liani and Villemin, "Building an Orthonormal
 *   Basis, Revisited" (JCGT 2017). e_w is perpendicular to e_u by construction.
 * Resolution: the axis within ~5e-5 rad, the side's angle within ~1.2e-4 rad (a diamond
 * step of 2^-14 turns it by at most 2^-13 rad), the scale within a relative 2^-11 (half:
 * 11 significant bits); tests/host/underbrush/test_underbrush_pack.cpp measures them.
 */
#ifndef BOREAS_CL_SHARED_UNDERBRUSH_PACK_H
#define BOREAS_CL_SHARED_UNDERBRUSH_PACK_H

#include "shared/tree_state.h"
#include "shared/underbrush_types.h"

/* LINK's fields. */
#define BOREAS_UB_LINK_PART_BITS 16
#define BOREAS_UB_LINK_PART_MASK 0xffff
/* The octahedral coordinate q (0..2 * BOREAS_UB_OCT_HALF) stands for (q - HALF) / HALF. */
#define BOREAS_UB_OCT_HALF 32767
/* The diamond's coordinate q (0..65535) stands for q * 2^-14 - 2, in [-2, 2). */
#define BOREAS_UB_TURN_STEP (1.0f / 16384.0f)
/* The scale's half: a positive normal half h is the float of bits (h + (112 << 10)) << 13
 * (the exponent bias 127 - 15 = 112 moved in); the host refuses a scale outside halves'
 * normal range. */
#define BOREAS_UB_HALF_REBIAS (112 << 10)
#define BOREAS_UB_SCALE_MIN 6.103515625e-5 /* 2^-14: the least normal half */
#define BOREAS_UB_SCALE_MAX 65504.0        /* the largest half */

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/underbrush_pack_width.inc"
#include "shared/width_instantiate.inc"

#endif
