/* boreas: the velocity field of one flow primitive (Wejchert-Haumann), shared by the
 * grid step (gusts, every step) and the steady forcing field (primitives, when they
 * change). Compiles as OpenCL C and as C/C++ (width 1, the native twins); the double
 * reference is reference::flow_velocity. Written once for any SIMD width
 * (flow_primitives_width.inc, see simd_width.h): the primitive is uniform, the offsets and
 * results are per lane. */
#ifndef BOREAS_CL_SHARED_FLOW_PRIMITIVES_H
#define BOREAS_CL_SHARED_FLOW_PRIMITIVES_H

#include "shared/wind_sample.h"

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/flow_primitives_width.inc"
#include "shared/width_instantiate.inc"

#endif
