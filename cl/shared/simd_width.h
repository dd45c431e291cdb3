/* boreas: the SIMD width a kernel works at, and the one vocabulary the math is written in.
 * Compiles as OpenCL C and as C/C++ (the host has width 1 only).
 *
 * The scheme in twenty lines:
 *  - BOREAS_W is the kernel's width: the neighbouring items one work-item processes, in
 *    OpenCL vector types. PoCL vectorizes its loop over work-items 8 lanes wide at most
 *    and gives up on a kernel with a vector value or a data-dependent loop; a kernel
 *    written in floatW is compiled straight to that width (bench/RESULTS.md, "CPU SIMD
 *    width"). The device prelude sets BOREAS_DEVICE_W (a CPU's native float width; 1 on
 *    GPUs, where the source is a plain scalar kernel); a kernel's defines may set BOREAS_W.
 *  - Code names only "the current width": BOREAS_F, BOREAS_I (float, int or floatW,
 *    intW), BOREAS_TO_FLOAT, BOREAS_GATHER, BOREAS_LANES, BOREAS_WIDE_NAME(Struct), ...
 *    (width_names.inc). In a kernel the current width is BOREAS_W; boreas_load_w,
 *    boreas_store_w and boreas_div_w below work at it.
 *  - A math header writes its body once in that vocabulary (x_width.inc) and has it
 *    instantiated at width 1 and, where BOREAS_W is wider, again at BOREAS_W, as overloads
 *    of the same names (structs get a _wN suffix): it defines BOREAS_WIDTH_BODY as the
 *    body's quoted file name and includes width_instantiate.inc (see fast_math.h). So the
 *    host, the native twins, a scalar kernel and a wide one run one text.
 *  - Every function is BOREAS_FN, and the builtins the bodies call are BOREAS_FMA,
 *    BOREAS_SELECT, ... (below: OpenCL's, or <math.h> and ternaries on the host).
 *    Comparisons give 1 (scalar) or -1 (vector lanes) for true; BOREAS_SELECT and & take
 *    either, so bodies compare with the operators and choose with BOREAS_SELECT. */
#ifndef BOREAS_CL_SHARED_SIMD_WIDTH_H
#define BOREAS_CL_SHARED_SIMD_WIDTH_H

#ifdef __OPENCL_C_VERSION__
#ifndef BOREAS_DEVICE_W
#define BOREAS_DEVICE_W 1
#endif
#ifndef BOREAS_W
#define BOREAS_W BOREAS_DEVICE_W
#endif
#else
#define BOREAS_W 1
#endif

#if BOREAS_W != 1 && BOREAS_W != 2 && BOREAS_W != 4 && BOREAS_W != 8 && BOREAS_W != 16
#error "BOREAS_W must be 1, 2, 4, 8 or 16"
#endif

#define BOREAS_CAT_(a, b) a##b
#define BOREAS_CAT(a, b) BOREAS_CAT_(a, b)

/* Every function: always inlined (a call left in PoCL's work-item loop stops its
 * vectorization) and overloadable (each width's instantiation shares the names) in
 * OpenCL; static inline on the host. */
#ifdef __OPENCL_C_VERSION__
#define BOREAS_FN inline __attribute__((always_inline, overloadable))
#else
#define BOREAS_FN static inline
#endif

/* The builtins the bodies call, at any width. On the host min and max are OpenCL's (and
 * std::min's and std::max's) b < a ? b : a and a < b ? b : a. */
#ifdef __OPENCL_C_VERSION__
#define BOREAS_GLOBAL __global
#define BOREAS_SELECT(a, b, c) select((a), (b), (c))
#define BOREAS_FMA(a, b, c) fma((a), (b), (c))
#define BOREAS_RINT(x) rint(x)
#define BOREAS_FLOOR(x) floor(x)
#define BOREAS_FABS(x) fabs(x)
#define BOREAS_COPYSIGN(x, y) copysign((x), (y))
#define BOREAS_SQRT(x) sqrt(x)
#define BOREAS_RSQRT(x) rsqrt(x)
#define BOREAS_FMAX(a, b) fmax((a), (b))
#define BOREAS_MIN(a, b) min((a), (b))
#define BOREAS_MAX(a, b) max((a), (b))
#define BOREAS_CLAMP(x, lo, hi) clamp((x), (lo), (hi))
#define BOREAS_MIX(a, b, t) mix((a), (b), (t))
#define BOREAS_UNROLL _Pragma("unroll")
#else
#include <math.h>
#include <string.h>
#define BOREAS_GLOBAL
#define BOREAS_SELECT(a, b, c) ((c) ? (b) : (a))
#define BOREAS_FMA(a, b, c) fmaf((a), (b), (c))
#define BOREAS_RINT(x) rintf(x)
#define BOREAS_FLOOR(x) floorf(x)
#define BOREAS_FABS(x) fabsf(x)
#define BOREAS_COPYSIGN(x, y) copysignf((x), (y))
#define BOREAS_SQRT(x) sqrtf(x)
#define BOREAS_RSQRT(x) (1.0f / sqrtf(x))
#define BOREAS_FMAX(a, b) fmaxf((a), (b))
#define BOREAS_MIN(a, b) ((b) < (a) ? (b) : (a))
#define BOREAS_MAX(a, b) ((a) < (b) ? (b) : (a))
#define BOREAS_CLAMP(x, lo, hi) BOREAS_MIN(BOREAS_MAX((x), (lo)), (hi))
#define BOREAS_MIX(a, b, t) ((a) + ((b) - (a)) * (t))
#if defined(__clang__)
#define BOREAS_UNROLL _Pragma("unroll")
#elif defined(__GNUC__)
#define BOREAS_UNROLL _Pragma("GCC unroll 16")
#else
#define BOREAS_UNROLL
#endif
/* Bit casts (BOREAS_AS_INT, BOREAS_AS_FLOAT on the host). */
BOREAS_FN int boreas_host_as_int(float x) {
  int i;
  memcpy(&i, &x, sizeof i);
  return i;
}
BOREAS_FN float boreas_host_as_float(int i) {
  float x;
  memcpy(&x, &i, sizeof x);
  return x;
}
#endif

/* From here on the vocabulary names the kernel's width. */
#define BOREAS_INST_W BOREAS_W
#include "shared/width_names.inc"

#ifdef __OPENCL_C_VERSION__
/* Each lane loads its own element (BOREAS_GATHER above width 1): the grid's trilinear
 * corners, per-item records. */
#if BOREAS_W == 2
#define BOREAS_LANES_GATHER(T, p, i) (T)((p)[(i).s0], (p)[(i).s1])
#elif BOREAS_W == 4
#define BOREAS_LANES_GATHER(T, p, i) (T)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3])
#elif BOREAS_W == 8
#define BOREAS_LANES_GATHER(T, p, i)                                                          \
  (T)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3], (p)[(i).s4], (p)[(i).s5],     \
           (p)[(i).s6], (p)[(i).s7])
#elif BOREAS_W == 16
#define BOREAS_LANES_GATHER(T, p, i)                                                          \
  (T)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3], (p)[(i).s4], (p)[(i).s5],    \
            (p)[(i).s6], (p)[(i).s7], (p)[(i).s8], (p)[(i).s9], (p)[(i).sa], (p)[(i).sb],    \
            (p)[(i).sc], (p)[(i).sd], (p)[(i).se], (p)[(i).sf])
#endif
#if BOREAS_W > 1
BOREAS_FN BOREAS_F BOREAS_CAT(boreas_gather, BOREAS_W)(__global const float* p, BOREAS_I i) {
  return BOREAS_LANES_GATHER(BOREAS_F, p, i);
}
BOREAS_FN BOREAS_I BOREAS_CAT(boreas_gather_int, BOREAS_W)(__global const int* p, BOREAS_I i) {
  return BOREAS_LANES_GATHER(BOREAS_I, p, i);
}
#endif

/* The least and the sum of an int vector's lanes, by halves (BOREAS_HMIN, BOREAS_HSUM). */
BOREAS_FN int boreas_lanes_min(int2 v) { return min(v.x, v.y); }
BOREAS_FN int boreas_lanes_min(int4 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_FN int boreas_lanes_min(int8 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_FN int boreas_lanes_min(int16 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_FN int boreas_lanes_sum(int2 v) { return v.x + v.y; }
BOREAS_FN int boreas_lanes_sum(int4 v) { return boreas_lanes_sum(v.lo + v.hi); }
BOREAS_FN int boreas_lanes_sum(int8 v) { return boreas_lanes_sum(v.lo + v.hi); }
BOREAS_FN int boreas_lanes_sum(int16 v) { return boreas_lanes_sum(v.lo + v.hi); }

/* ---- Planes at the kernel's width: a work-item's W items from index first on. ---- */

/* W floats of p from index first on, of a plane of count floats. A work-item whose W
 * items run past the plane's end (the last one, when count is not a multiple of W) reads
 * the last item again in the lanes beyond it, so nothing is read past the buffer; full
 * ones load with one vload. At width 1 this is p[min(first, count - 1)], today's form. */
BOREAS_FN BOREAS_F boreas_load_w(__global const float* p, int first, int count) {
#if BOREAS_W == 1
  return p[min(first, count - 1)];
#else
  if (first + BOREAS_W <= count) return BOREAS_CAT(vload, BOREAS_W)(0, p + first);
  return BOREAS_GATHER(p, min(first + BOREAS_LANES, count - 1));
#endif
}

/* The same for a plane of ints (their bits moved as floats: no arithmetic touches them). */
BOREAS_FN BOREAS_I boreas_load_wi(__global const int* p, int first, int count) {
  return BOREAS_AS_INT(boreas_load_w((__global const float*)p, first, count));
}

/* k / d per lane for 0 <= k < 2^31 and d > 0, exactly (a vertex's branch and ring from
 * its index). AVX-512 has no integer division, so above width 1 the quotient comes from a
 * float division, corrected by the remainder twice: the first estimate is within k 2^-23
 * of the quotient, the second within one, the selects make it exact. */
BOREAS_FN BOREAS_I boreas_div_w(BOREAS_I k, int d) {
#if BOREAS_W == 1
  return k / d;
#else
  const float inv = 1.0f / (float)d;
  BOREAS_I q = BOREAS_TO_INT(BOREAS_TO_FLOAT(k) * inv);
  q += BOREAS_TO_INT(floor(BOREAS_TO_FLOAT(k - q * d) * inv));
  BOREAS_I r = k - q * d;
  q = select(q, q + 1, r >= d);
  return select(q, q - 1, r < 0);
#endif
}

/* Stores the lanes of v whose items are below count (the rest were copies, see
 * boreas_load_w). At width 1 the clamped item is written, with the value every copy of
 * it computed, which keeps the store free of a branch. */
BOREAS_FN void boreas_store_w(BOREAS_F v, __global float* p, int first, int count) {
#if BOREAS_W == 1
  p[min(first, count - 1)] = v;
#else
  if (first + BOREAS_W <= count) {
    BOREAS_CAT(vstore, BOREAS_W)(v, 0, p + first);
    return;
  }
  float lanes[BOREAS_W];
  BOREAS_CAT(vstore, BOREAS_W)(v, 0, lanes);
  for (int l = 0; first + l < count && l < BOREAS_W; ++l) p[first + l] = lanes[l];
#endif
}
#endif

#endif
