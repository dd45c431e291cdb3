/* boreas: the math of an underbrush component's step and shape (Endo et al. 2003 sec.
 * 3.1, 4.2-4.3), compiled as OpenCL C (underbrush_step.cl, underbrush_vertices.cl) and as
 * C/C++ (the host's rest placement, the tests' float path and the native benchmark twin).
 *
 * A component is a point mass at its center of mass X, fixed at its base. The precomputed
 * tables (host/src/underbrush/shape_table.h) give, for the load on it (gravity plus wind
 * plus colliders, per unit mass), the equilibrium X0 (forward table) and, for any X, the
 * shape whose center of mass is X (inverse table). Everything is expressed in the
 * component's bend plane: u along its unloaded axis e_u, v along the in-plane direction
 * e_v of the load (or of X), so the tables are two-dimensional.
 *
 * Scalar float arithmetic on small value structs only, for PoCL's work-item vectorizer
 * (see cl/shared/tree_math.h); no transcendental builtins: angles come from square roots
 * and a short series. Written once for any SIMD width (underbrush_math_width.inc), as
 * tree_math.h: width 1 on the host and in kernels, and the kernel's width BOREAS_W.
 */
#ifndef BOREAS_CL_SHARED_UNDERBRUSH_MATH_H
#define BOREAS_CL_SHARED_UNDERBRUSH_MATH_H

#include "shared/tree_state.h"
#include "shared/collider_math.h"
#include "shared/underbrush_types.h"
#include "shared/underbrush_pack.h"

#define BOREAS_UB_PI 3.14159265358979324f
/* Share of the load's size added along e_w, so the bend plane is defined when the load
 * runs along the axis (an upright blade under gravity alone). It tilts the plane by at
 * most 1e-3 rad otherwise. */
#define BOREAS_UB_SIDE_BIAS 1e-3f

/* The structs at the current width (simd_width.h). */
#define BOREAS_UB_PLANE BOREAS_WIDE_NAME(BoreasUbPlane)
#define BOREAS_UB_CELL BOREAS_WIDE_NAME(BoreasUbCell)

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/underbrush_math_width.inc"
#include "shared/width_instantiate.inc"

#endif
