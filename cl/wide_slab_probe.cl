/* boreas probe (issue 22): the sine slab of wind_sine_slab.cl with explicit vector width,
 * each work-item computing BOREAS_PROBE_W (8 or 16) neighbouring columns in OpenCL vector
 * types, to measure whether PoCL turns float16 into 512-bit code where its own work-item
 * vectorizer stops at 8 lanes. Same math as cl/shared/fast_math.h's polynomials (sin of a
 * phase in cycles, pow by exp2 and log2), written for vectors with select. The global size
 * is (nx / W, nz); nx must be a multiple of W. Not part of the library. */
#include "shared/wind_types.h"

#ifndef BOREAS_PROBE_W
#define BOREAS_PROBE_W 16
#endif
#if BOREAS_PROBE_W == 16
typedef float16 vf;
typedef int16 vi;
#define VLOAD vload16
#define VSTORE vstore16
#define AS_VF as_float16
#define AS_VI as_int16
#define CONVERT_VI convert_int16
#define CONVERT_VF convert_float16
#define LANES (vf)(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f, 14.0f, 15.0f)
#else
typedef float8 vf;
typedef int8 vi;
#define VSTORE vstore8
#define AS_VF as_float8
#define AS_VI as_int8
#define CONVERT_VI convert_int8
#define CONVERT_VF convert_float8
#define LANES (vf)(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f)
#endif

#define BOREAS_VINLINE inline __attribute__((always_inline))

BOREAS_VINLINE vf v_sin_half_turn(vf r) {
  vf s = r * r;
  vf p = (vf)(-2.50521083854417188e-8f);
  p = fma(p, s, (vf)(2.75573192239858907e-6f));
  p = fma(p, s, (vf)(-1.98412698412698413e-4f));
  p = fma(p, s, (vf)(8.33333333333333333e-3f));
  p = fma(p, s, (vf)(-1.66666666666666667e-1f));
  return fma(r * s, p, r);
}

BOREAS_VINLINE vf v_sin_cycle(vf u) {
  vf a = fabs(u);
  vf b = 0.25f - fabs(0.25f - a);
  return copysign(v_sin_half_turn(b * 6.28318530717958648f), u);
}

BOREAS_VINLINE vf v_exp2(vf x) {
  x = clamp(x, -127.0f, 127.4f);
  vf n = rint(x);
  vf g = (x - n) * 0.693147180559945309f;
  vf p = (vf)(1.98412698412698413e-4f);
  p = fma(p, g, (vf)(1.38888888888888889e-3f));
  p = fma(p, g, (vf)(8.33333333333333333e-3f));
  p = fma(p, g, (vf)(4.16666666666666667e-2f));
  p = fma(p, g, (vf)(1.66666666666666667e-1f));
  p = fma(p, g, (vf)(0.5f));
  p = fma(p, g, (vf)(1.0f));
  p = fma(p, g, (vf)(1.0f));
  return p * AS_VF((CONVERT_VI(n) + 127) << 23);
}

BOREAS_VINLINE vf v_log2(vf x) {
  vi bits = AS_VI(x);
  vi e = ((bits >> 23) & 255) - 127;
  vf m = AS_VF((bits & 0x007fffff) | 0x3f800000);
  vi big = isgreater(m, (vf)(1.41421356237309505f)); /* -1 where true */
  m = select(m, m * 0.5f, big);
  e = e - big;
  vf t = (m - 1.0f) / (m + 1.0f);
  vf t2 = t * t;
  vf p = (vf)(1.0f / 9.0f);
  p = fma(p, t2, (vf)(1.0f / 7.0f));
  p = fma(p, t2, (vf)(1.0f / 5.0f));
  p = fma(p, t2, (vf)(1.0f / 3.0f));
  p = fma(p, t2, (vf)(1.0f));
  return fma(t * p, (vf)(2.88539008177792681f), CONVERT_VF(e));
}

BOREAS_VINLINE vf v_pow(vf x, float y) {
  vf v = v_exp2(y * v_log2(x));
  vf at_zero = (vf)(y == 0.0f ? 1.0f : 0.0f);
  return select(at_zero, v, isgreater(x, (vf)(0.0f)));
}

__kernel void boreas_wide_sine_slab_probe(__global float* slab, __global const BoreasGpuWave* waves,
                                          int wave_count, BoreasGpuGrid g) {
  const int i0 = (int)get_global_id(0) * BOREAS_PROBE_W;
  const int k = get_global_id(1);
  const vf x = g.origin_x + ((float)i0 + LANES + 0.5f) * g.cell_size;
  const float z = g.origin_z + ((float)k + 0.5f) * g.cell_size;
  vf fx = (vf)(0.0f), fz = (vf)(0.0f);
#pragma unroll
  for (int w = 0; w < BOREAS_WAVE_SLOTS; ++w) {
    const float dx = waves[w].dir_x, dz = waves[w].dir_z;
    vf u = fma(fma((vf)(dx), x, (vf)(dz * z)), (vf)(waves[w].cycles_per_meter), (vf)(waves[w].phase_cycles));
    u -= floor(u + 0.5f);
    vf base = fma(v_sin_cycle(u), (vf)(0.5f), (vf)(0.5f));
    vf s = waves[w].amplitude * v_pow(base, waves[w].sharpness);
    fx = fma((vf)(dx), s, fx);
    fz = fma((vf)(dz), s, fz);
  }
  VSTORE(fx, 0, slab + k * g.nx + i0);
  VSTORE(fz, 0, slab + g.nx * g.nz + k * g.nx + i0);
}
