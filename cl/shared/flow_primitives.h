/* boreas: the velocity field of one flow primitive (Wejchert-Haumann), shared by the
 * grid step (gusts, every step) and the steady forcing field (primitives, when they
 * change). OpenCL C only; the double twin is reference::flow_velocity. Written once for
 * any SIMD width (flow_primitives_width.inc, see simd_width.h): the primitive is uniform,
 * the offsets and results are per lane. */
#ifndef BOREAS_CL_SHARED_FLOW_PRIMITIVES_H
#define BOREAS_CL_SHARED_FLOW_PRIMITIVES_H

#include "shared/wind_sample.h"

#define BOREAS_INST_W 1
#include "shared/width_begin.inc"
#include "shared/flow_primitives_width.inc"
#include "shared/width_end.inc"

#if BOREAS_W > 1
#define BOREAS_INST_W BOREAS_W
#include "shared/width_begin.inc"
#include "shared/flow_primitives_width.inc"
#include "shared/width_end.inc"
#endif

#endif
