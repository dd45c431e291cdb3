/* boreas: the velocity field of one flow primitive (Wejchert-Haumann), shared by the
 * grid step (gusts, every step) and the steady forcing field (primitives, when they
 * change). OpenCL C only; the double twin is reference::flow_velocity. */
#ifndef BOREAS_CL_SHARED_FLOW_PRIMITIVES_H
#define BOREAS_CL_SHARED_FLOW_PRIMITIVES_H

#include "shared/wind_sample.h"

/* Smooth compact falloff, 1 at the primitive's position and 0 at its radius. */
BOREAS_INLINE float boreas_flow_coverage(float d2, float radius) {
  float q = max(1.0f - d2 / (radius * radius), 0.0f);
  return radius > 0.0f ? q * q : 1.0f;
}

/* Adds one primitive's velocity at offset r from its position to v, and returns its
 * coverage. Source, sink and vortex rise linearly over the inner quarter of the radius
 * so that they have no singular core. All three shapes are computed and weighted: a
 * branch on the kind would stop the work-item loop from vectorizing. */
BOREAS_INLINE float boreas_flow_add(__global const BoreasGpuForcing* f, float rx, float ry,
                                    float rz, float* vx, float* vy, float* vz) {
  float ax = f->dir_x;
  float ay = f->dir_y;
  float az = f->dir_z;
  float strength = f->strength;
  float radius = f->radius;
  float d2 = rx * rx + ry * ry + rz * rz;
  float coverage = boreas_flow_coverage(d2, radius);
  float d = sqrt(d2);
  float core = max(0.25f * radius, 1e-6f);
  float ramp = min(d / core, 1.0f) * coverage * strength;
  /* radial: r / |r| (source, sink) */
  float radial = f->radial_weight * ramp * (d > 1e-6f ? 1.0f / d : 0.0f);
  /* swirl: axis x r, normalized (vortex). Equal to axis x (the part of r across the
   * axis), and written without that part on purpose: the longer form got packed by LLVM's
   * SLP vectorizer, which stopped PoCL from vectorizing the work-item loop. */
  float sx = ay * rz - az * ry;
  float sy = az * rx - ax * rz;
  float sz = ax * ry - ay * rx;
  float slen2 = sx * sx + sy * sy + sz * sz;
  float swirl = f->swirl_weight * ramp * (slen2 > 1e-12f ? rsqrt(slen2) : 0.0f);
  float uniform = f->uniform_weight * strength * coverage;
  *vx += ax * uniform + rx * radial + sx * swirl;
  *vy += ay * uniform + ry * radial + sy * swirl;
  *vz += az * uniform + rz * radial + sz * swirl;
  return coverage;
}

#endif
