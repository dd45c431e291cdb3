/* boreas: the geometry of a Skjermo branch — cubic Bezier, Sloan moving frames, attachment
 * to the parent, the length-preserving bend and the generalized de Casteljau sweep with
 * its radius functions and Jacobian normals (Skjermo 2007 sec. 3 and 4.2-4.3).
 *
 * Compiles as OpenCL C and as C/C++: the kernels, the native benchmark twins and (issue 5)
 * the GLSL deformer follow this one text. Everything is scalar float on small value
 * structs, which PoCL's work-item loop vectorizer handles as long as the data come from
 * planes (cl/shared/tree_types.h), not from packed triples. The bodies are written once
 * for any SIMD width (tree_math_width.inc): float structs on the host and at width 1, and
 * in kernels again at their width BOREAS_W (BoreasV3_w16 of float16, ...), as overloads.
 *
 * Conventions used throughout:
 *  - A branch's unpositioned control points have P0 at the origin and P1 on +x.
 *  - Sloan frame (eq. 8), handles normalized: S0 = L0 x O, T0 = S0 x L0, T1 = S0 x L1,
 *    S1 = L1 x T1, T2 = S1 x L2, S2 = L2 x T2. O is the branch's orientation vector, kept
 *    perpendicular to L0 by construction (see boreas_attach), so S0 never degenerates.
 *  - The handles between the points are blended with the quadratic Bernstein weights of
 *    the de Casteljau recursion: with eq. 9 as read in the seeds README, the surface point
 *    R^2_0 at (u, theta) is C(u) + r (sin(theta) S(u) + cos(theta) T(u)), where
 *    S(u) = (1-u)^2 S0 + 2u(1-u) S1 + u^2 S2 (T likewise): the handles enter linearly.
 */
#ifndef BOREAS_CL_SHARED_TREE_MATH_H
#define BOREAS_CL_SHARED_TREE_MATH_H

#include "shared/fast_math.h"

/* A phase in cycles brought into [-1/2, 1/2], as boreas_sin_cycle wants it. */
#define boreas_tm_wrap(u) ((u)-BOREAS_RINT(u))

#define BOREAS_TM_TWO_PI 6.28318530717958648f
#define BOREAS_TM_LN_100 4.60517018598809136f

/* Of a branch's `rings` mesh rings, how many go round its tip's cap where it has one
 * (boreas_ring_v): a quarter of them, at least 1 and at most 3, leaving the body 1 or more. */
#define BOREAS_CAP_RINGS(rings) \
  ((rings) < 2 ? 0 : ((rings) + 2) / 4 < 1 ? 1 : ((rings) + 2) / 4 > 3 ? 3 : ((rings) + 2) / 4)

/* The structs at the current width (simd_width.h): BoreasV3, ... at width 1,
 * BoreasV3_wN, ... of floatN at width N. */
#define BOREAS_V3 BOREAS_WIDE_NAME(BoreasV3)
#define BOREAS_BEZIER BOREAS_WIDE_NAME(BoreasBezier)
#define BOREAS_SLOAN BOREAS_WIDE_NAME(BoreasSloanFrame)
#define BOREAS_ATTACH BOREAS_WIDE_NAME(BoreasAttachFrame)
#define BOREAS_RADIUS BOREAS_WIDE_NAME(BoreasBranchRadius)

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/tree_math_width.inc"
#include "shared/width_instantiate.inc"

#endif
