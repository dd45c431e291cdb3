/* boreas: polynomial sin, cos, exp2, log2 and pow that vectorize on CPU OpenCL devices.
 * Compiles as OpenCL C and as C/C++, so kernels, host tests and the native benchmark
 * reference run the very same math.
 *
 * Why: on PoCL, calls to libm-style builtins (sin, pow, native_*, half_*) stop the
 * work-item loop from vectorizing and cost 10-80x (shared/notes/pocl-performance.md).
 * These use only +, *, fma, rint, int conversions and bit casts, which vectorize.
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

#ifdef __OPENCL_C_VERSION__
/* Always inlined: on PoCL a call left in the work-item loop stops its vectorization. */
#define BOREAS_FM_FN inline __attribute__((always_inline))
#define BOREAS_FM_AS_INT(x) as_int(x)
#define BOREAS_FM_AS_FLOAT(i) as_float(i)
#define BOREAS_FM_RINT(x) rint(x)
#define BOREAS_FM_FMA(a, b, c) fma((a), (b), (c))
#define BOREAS_FM_FABS(x) fabs(x)
#define BOREAS_FM_COPYSIGN(x, y) copysign((x), (y))
#else
#include <math.h>
#include <string.h>
#define BOREAS_FM_FN static inline
static inline int boreas_fm_as_int(float x) { int i; memcpy(&i, &x, sizeof i); return i; }
static inline float boreas_fm_as_float(int i) { float x; memcpy(&x, &i, sizeof x); return x; }
#define BOREAS_FM_AS_INT(x) boreas_fm_as_int(x)
#define BOREAS_FM_AS_FLOAT(i) boreas_fm_as_float(i)
#define BOREAS_FM_RINT(x) rintf(x)
#define BOREAS_FM_FMA(a, b, c) fmaf((a), (b), (c))
#define BOREAS_FM_FABS(x) fabsf(x)
#define BOREAS_FM_COPYSIGN(x, y) copysignf((x), (y))
#endif

/* pi split in three floats for Cody-Waite reduction: each product m*part is exact enough
 * under fma that the reduced argument keeps ~1e-7 absolute accuracy up to |x| = 1e5. */
#define BOREAS_FM_PI_HI 3.1415927410125732f
#define BOREAS_FM_PI_MID -8.742277657347586e-8f
#define BOREAS_FM_PI_LO -3.4302490200117637e-15f
#define BOREAS_FM_INV_PI 0.31830987334251404f

/* sin(r) for r in [-pi/2, pi/2]: Taylor to r^11 (truncation < 6e-8). One polynomial over
 * half a turn costs less than the usual sin and cos pair over quarter turns plus a select. */
BOREAS_FM_FN float boreas_fm_sin_half_turn(float r) {
  float s = r * r;
  float p = -2.50521083854417188e-8f;                /* -1/11! */
  p = BOREAS_FM_FMA(p, s, 2.75573192239858907e-6f);   /* 1/9! */
  p = BOREAS_FM_FMA(p, s, -1.98412698412698413e-4f);  /* -1/7! */
  p = BOREAS_FM_FMA(p, s, 8.33333333333333333e-3f);   /* 1/5! */
  p = BOREAS_FM_FMA(p, s, -1.66666666666666667e-1f);  /* -1/3! */
  return BOREAS_FM_FMA(r * s, p, r);
}

/* sin(x + offset * pi) for offset 0 (sin) or 1/2 (cos): x = m pi + r with m + offset an
 * integer n and |r| <= pi/2, so the result is (-1)^n sin(r). */
BOREAS_FM_FN float boreas_fm_sin_shifted(float x, float offset) {
  float n = BOREAS_FM_RINT(BOREAS_FM_FMA(x, BOREAS_FM_INV_PI, offset));
  float m = n - offset; /* exact: |n| < 2^22 over the domain */
  float r = BOREAS_FM_FMA(-m, BOREAS_FM_PI_HI, x);
  r = BOREAS_FM_FMA(-m, BOREAS_FM_PI_MID, r);
  r = BOREAS_FM_FMA(-m, BOREAS_FM_PI_LO, r);
  float v = boreas_fm_sin_half_turn(r);
  return ((int)n & 1) ? -v : v;
}

BOREAS_FM_FN float boreas_poly_sin(float x) { return boreas_fm_sin_shifted(x, 0.0f); }
BOREAS_FM_FN float boreas_poly_cos(float x) { return boreas_fm_sin_shifted(x, 0.5f); }

/* sin(2 pi u) for a phase u in [-1/2, 1/2] cycles (already reduced by the caller): folded
 * into a quarter turn by sin(-x) = -sin(x) and sin(pi - x) = sin(x), written with fabs and
 * copysign. No rounding step (on PoCL it costs more than the polynomial) and no compares:
 * compare-and-select folds let LLVM's SLP vectorizer pack neighbouring sines into short
 * vectors, which stops PoCL's work-item vectorization. */
BOREAS_FM_FN float boreas_poly_sin_cycle(float u) {
  float a = BOREAS_FM_FABS(u);
  float b = 0.25f - BOREAS_FM_FABS(0.25f - a);
  return BOREAS_FM_COPYSIGN(boreas_fm_sin_half_turn(b * 6.28318530717958648f), u);
}

/* 2^x = 2^n * 2^f with n = rint(x), f in [-1/2, 1/2]; 2^f = e^(f ln2) by Taylor to
 * degree 7 (truncation < 6e-9 relative). 2^n is built in the exponent bits. */
BOREAS_FM_FN float boreas_poly_exp2(float x) {
  x = x < -127.0f ? -127.0f : x;
  x = x > 127.4f ? 127.4f : x;
  float n = BOREAS_FM_RINT(x);
  float g = (x - n) * 0.693147180559945309f;
  float p = 1.98412698412698413e-4f;                /* 1/7! */
  p = BOREAS_FM_FMA(p, g, 1.38888888888888889e-3f);  /* 1/6! */
  p = BOREAS_FM_FMA(p, g, 8.33333333333333333e-3f);  /* 1/5! */
  p = BOREAS_FM_FMA(p, g, 4.16666666666666667e-2f);  /* 1/4! */
  p = BOREAS_FM_FMA(p, g, 1.66666666666666667e-1f);  /* 1/3! */
  p = BOREAS_FM_FMA(p, g, 0.5f);
  p = BOREAS_FM_FMA(p, g, 1.0f);
  p = BOREAS_FM_FMA(p, g, 1.0f);
  /* n = -127 gives a zero scale: results below the normal range flush to zero. */
  float scale = BOREAS_FM_AS_FLOAT(((int)n + 127) << 23);
  return p * scale;
}

/* log2(x) = e + log2(m) with m in [sqrt(1/2), sqrt(2)); ln(m) = 2 atanh(t),
 * t = (m-1)/(m+1), |t| < 0.172, by its series to t^9 (truncation < 1e-9). */
BOREAS_FM_FN float boreas_poly_log2(float x) {
  int bits = BOREAS_FM_AS_INT(x);
  int e = ((bits >> 23) & 255) - 127;
  float m = BOREAS_FM_AS_FLOAT((bits & 0x007fffff) | 0x3f800000);
  int big = m > 1.41421356237309505f;
  m = big ? m * 0.5f : m;
  e = big ? e + 1 : e;
  float t = (m - 1.0f) / (m + 1.0f);
  float t2 = t * t;
  float p = 1.0f / 9.0f;
  p = BOREAS_FM_FMA(p, t2, 1.0f / 7.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f / 5.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f / 3.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f);
  /* 2/ln2 folds the atanh factor 2 and the change of base. */
  return BOREAS_FM_FMA(t * p, 2.88539008177792681f, (float)e);
}

/* x^y for x >= 0. */
BOREAS_FM_FN float boreas_poly_pow(float x, float y) {
  float v = boreas_poly_exp2(y * boreas_poly_log2(x));
  float at_zero = (y == 0.0f) ? 1.0f : 0.0f;
  return x > 0.0f ? v : at_zero;
}

/* atan2(y, x) in (-pi, pi]: a = min/max of |x|, |y| in [0, 1]; above tan(pi/8) it is moved
 * to t = (a - 1)/(a + 1) with atan(a) = pi/4 + atan(t), so |t| <= tan(pi/8) and the
 * Taylor series of atan to t^17 truncates below 3e-9. Folded back by octant with selects.
 * atan2(0, 0) is 0. */
BOREAS_FM_FN float boreas_poly_atan2(float y, float x) {
  float ax = BOREAS_FM_FABS(x);
  float ay = BOREAS_FM_FABS(y);
  float hi = ax > ay ? ax : ay;
  float lo = ax > ay ? ay : ax;
  float a = lo / (hi + 1e-37f);
  int far = a > 0.41421356237309505f;
  float t = far ? (a - 1.0f) / (a + 1.0f) : a;
  float t2 = t * t;
  float p = 1.0f / 17.0f;
  p = BOREAS_FM_FMA(p, t2, -1.0f / 15.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f / 13.0f);
  p = BOREAS_FM_FMA(p, t2, -1.0f / 11.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f / 9.0f);
  p = BOREAS_FM_FMA(p, t2, -1.0f / 7.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f / 5.0f);
  p = BOREAS_FM_FMA(p, t2, -1.0f / 3.0f);
  p = BOREAS_FM_FMA(p, t2, 1.0f);
  float r = t * p + (far ? 0.785398163397448310f : 0.0f);
  r = ay > ax ? 1.57079632679489662f - r : r;
  r = x < 0.0f ? 3.14159265358979324f - r : r;
  return BOREAS_FM_COPYSIGN(r, y);
}

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
#define boreas_sin(x) sin(x)
#define boreas_cos(x) cos(x)
#define boreas_sin_cycle(u) sinpi(2.0f * (u))
#define boreas_exp2(x) exp2(x)
#define boreas_log2(x) log2(x)
#define boreas_pow(x, y) ((x) > 0.0f ? powr((x), (y)) : ((y) == 0.0f ? 1.0f : 0.0f))
#define boreas_atan2(y, x) atan2((y), (x))
#endif

#endif
