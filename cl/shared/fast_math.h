/* boreas: polynomial sin, cos, exp2, log2 and pow that vectorize on CPU OpenCL devices.
 * Compiles as OpenCL C and as C/C++, so kernels, host tests and the native benchmark
 * reference run the very same math.
 *
 * Why: on PoCL, calls to libm-style builtins (sin, pow, native_*, half_*) stop the
 * work-item loop from vectorizing and cost 10-80x (shared/notes/pocl-performance.md).
 * These use only +, *, fma, rint, int conversions and bit casts, which vectorize.
 * Written once for any width (fast_math_width.inc): float on the host, and in kernels float
 * plus the kernel's SIMD width (simd_width.h), as overloads.
 * GPUs have fast builtins, so BOREAS_FAST_MATH (set per device by the runtime's
 * prelude) picks between the two: boreas_sin() and friends are what kernels call.
 *
 * Coefficients are Taylor coefficients (1/n! and 1/n, rounded to float), taken far enough that
 * the truncation error is below float rounding on the reduced interval; the tests bound
 * the total error against double precision over each function's domain:
 *   boreas_poly_sin/cos(x)  |x| <= 1e5 rad        absolute error, see tests/cl
 *   boreas_poly_sin_cycle(u) = sin(2 pi u), |u| <= 1/2 cycle
 *   boreas_poly_exp2(x)     -126 <= x <= 127      relative error (x < -127 gives 0)
 *   boreas_poly_log2(x)     FLT_MIN <= x <= FLT_MAX absolute error
 *   boreas_poly_pow(x, y)   x >= 0, |y log2 x| <= 126; pow(0, y>0) = 0, pow(x, 0) = 1
 */
#ifndef BOREAS_CL_SHARED_FAST_MATH_H
#define BOREAS_CL_SHARED_FAST_MATH_H

#include "shared/simd_width.h"

/* pi split in three floats for Cody-Waite reduction: each product m*part is exact enough
 * under fma that the reduced argument keeps ~1e-7 absolute accuracy up to |x| = 1e5. */
#define BOREAS_FM_PI_HI 3.1415927410125732f
#define BOREAS_FM_PI_MID -8.742277657347586e-8f
#define BOREAS_FM_PI_LO -3.4302490200117637e-15f
#define BOREAS_FM_INV_PI 0.31830987334251404f

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/fast_math_width.inc"
#include "shared/width_instantiate.inc"

/* The builtins lane by lane above width 1. Every width must give width 1's bits (README,
 * "Determinism"), and a device's vector builtins need not give its scalar ones': PoCL 3.1's
 * exp2 and atan2 at float4 and wider differ from float by an ulp for about 1 % and 0.3 % of
 * arguments, powr for a few in a million (with BOREAS_FAST_MATH=0 the meadow's width test
 * failed at 8 and 16).
 * The runtime runs builtins at width 1 unless BOREAS_SIMD_WIDTH asks otherwise (tests,
 * benchmarks), so the lanes cost nothing where it picks them. By halves, as
 * boreas_lanes_sum in simd_width.h. */
#if !(defined(BOREAS_FAST_MATH) && BOREAS_FAST_MATH) && defined(__OPENCL_C_VERSION__)
#define BOREAS_FM_LANES(name, builtin)                                                  \
  BOREAS_FN float name(float x) { return builtin(x); }                                  \
  BOREAS_FN float2 name(float2 x) { return (float2)(name(x.lo), name(x.hi)); }          \
  BOREAS_FN float4 name(float4 x) { return (float4)(name(x.lo), name(x.hi)); }          \
  BOREAS_FN float8 name(float8 x) { return (float8)(name(x.lo), name(x.hi)); }          \
  BOREAS_FN float16 name(float16 x) { return (float16)(name(x.lo), name(x.hi)); }
#define BOREAS_FM_LANES2(name, builtin)                                                 \
  BOREAS_FN float name(float x, float y) { return builtin(x, y); }                      \
  BOREAS_FN float2 name(float2 x, float2 y) {                                           \
    return (float2)(name(x.lo, y.lo), name(x.hi, y.hi));                                \
  }                                                                                     \
  BOREAS_FN float4 name(float4 x, float4 y) {                                           \
    return (float4)(name(x.lo, y.lo), name(x.hi, y.hi));                                \
  }                                                                                     \
  BOREAS_FN float8 name(float8 x, float8 y) {                                           \
    return (float8)(name(x.lo, y.lo), name(x.hi, y.hi));                                \
  }                                                                                     \
  BOREAS_FN float16 name(float16 x, float16 y) {                                        \
    return (float16)(name(x.lo, y.lo), name(x.hi, y.hi));                               \
  }
BOREAS_FM_LANES(boreas_lanes_sin, sin)
BOREAS_FM_LANES(boreas_lanes_cos, cos)
BOREAS_FM_LANES(boreas_lanes_sinpi, sinpi)
BOREAS_FM_LANES(boreas_lanes_exp2, exp2)
BOREAS_FM_LANES(boreas_lanes_log2, log2)
BOREAS_FM_LANES2(boreas_lanes_powr, powr)
BOREAS_FM_LANES2(boreas_lanes_atan2, atan2)
#undef BOREAS_FM_LANES
#undef BOREAS_FM_LANES2
#endif

/* What kernels call: polynomials on CPU devices, builtins on GPUs. */
#if defined(BOREAS_FAST_MATH) && BOREAS_FAST_MATH
#define boreas_sin(x) boreas_poly_sin(x)
#define boreas_cos(x) boreas_poly_cos(x)
#define boreas_sin_cycle(u) boreas_poly_sin_cycle(u)
#define boreas_exp2(x) boreas_poly_exp2(x)
#define boreas_log2(x) boreas_poly_log2(x)
#define boreas_pow(x, y) boreas_poly_pow((x), (y))
#define boreas_atan2(y, x) boreas_poly_atan2((y), (x))
#elif defined(__OPENCL_C_VERSION__)
#define boreas_sin(x) boreas_lanes_sin(x)
#define boreas_cos(x) boreas_lanes_cos(x)
#define boreas_sin_cycle(u) boreas_lanes_sinpi(2.0f * (u))
#define boreas_exp2(x) boreas_lanes_exp2(x)
#define boreas_log2(x) boreas_lanes_log2(x)
#define boreas_pow(x, y) ((x) > 0.0f ? boreas_lanes_powr((x), (y)) : ((y) == 0.0f ? 1.0f : 0.0f))
#define boreas_atan2(y, x) boreas_lanes_atan2((y), (x))
#endif

#endif
