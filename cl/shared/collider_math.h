/* boreas: where a point is against a collider over a step (collider_types.h): its signed
 * distance to the swept shape and the way out. One body for every width (simd_width.h),
 * so the underbrush and tree kernels, the host and the tests run one text.
 *
 * The sweep. A point p is inside the swept shape when the shape at some s in [0, 1] of the
 * step (position c + s d) holds it. For the box grown by r, each local axis i holds p for
 * the s where |e_i - s l_i| <= h_i + r (e = p - c in local axes, l = d in local axes): an
 * interval, as in a ray's slab test against a box. The point is measured against the shape
 * at the middle s* of the three intervals' intersection, clamped to the step: inside that
 * intersection wherever it is not empty, so a point the box passed over is always found
 * inside (no tunneling, however fast the box). For a sphere or a capsule the intersection
 * is that of their bounding box's sweep: a point the rounded ends graze within a step of
 * several radii may be measured a little outside (the distance at s* instead of the
 * least over s). Where no position holds p, s* is p's closest approach to the path of the
 * shape's position. Either way the distance is at most |d| more than the least over the
 * step (positions s apart differ by s |d|), and a still collider (d = 0) is measured
 * exactly, at its position.
 *
 * The distance. Against the box of half extents h grown by r at s*, with q = e - s* l:
 * |max(|q| - h, 0)| + min(max_i(|q_i| - h_i), 0) - r, exact for all three shapes
 * (Quilez's box distance; a sphere and a capsule are boxes of zero extent in two or three
 * axes grown by r). Negative inside. The normal is the distance's gradient: outward, the
 * unit direction in which p leaves the shape fastest. */
#ifndef BOREAS_CL_SHARED_COLLIDER_MATH_H
#define BOREAS_CL_SHARED_COLLIDER_MATH_H

#include "shared/collider_types.h"
#include "shared/tree_math.h"

#define BOREAS_COLLIDER_DISTANCE BOREAS_WIDE_NAME(BoreasColliderDistance)

#define BOREAS_WIDTH_BODY "shared/collider_math_width.inc"
#include "shared/width_instantiate.inc"

#endif
