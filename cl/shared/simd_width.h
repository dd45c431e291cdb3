/* boreas: the SIMD width a kernel works at, and the types and helpers written for it.
 * OpenCL C only.
 *
 * Why: PoCL vectorizes the loop over work-items 8 lanes wide at most, and gives up on a
 * kernel with any vector-typed value or data-dependent loop, where a native CPU build runs
 * 16 lanes on AVX-512 (bench/RESULTS.md, "CPU SIMD width"). A kernel that processes
 * BOREAS_W neighbouring items per work-item in OpenCL vector types is compiled by PoCL
 * straight to that width. GPUs want one item per work-item: there BOREAS_W is 1, the types
 * are plain float and int, and the same source is today's scalar kernel.
 *
 * BOREAS_W comes from the device prelude (BOREAS_DEVICE_W: the device's native float
 * vector width on CPUs, 1 on GPUs) unless a kernel's defines set it first.
 *
 * The math headers (fast_math.h, wind_sample.h) are instantiated at width 1 and, where
 * BOREAS_W > 1, again at BOREAS_W, as overloads of the same names, so a scalar kernel and
 * a wide one call the very same source and cannot drift. Inside those bodies BOREAS_F and
 * BOREAS_I name the width being instantiated (width_begin.inc). */
#ifndef BOREAS_CL_SHARED_SIMD_WIDTH_H
#define BOREAS_CL_SHARED_SIMD_WIDTH_H

#ifndef BOREAS_DEVICE_W
#define BOREAS_DEVICE_W 1
#endif
#ifndef BOREAS_W
#define BOREAS_W BOREAS_DEVICE_W
#endif

#define BOREAS_CAT_(a, b) a##b
#define BOREAS_CAT(a, b) BOREAS_CAT_(a, b)

#if BOREAS_W == 1
#define BOREAS_W_SUFFIX
#elif BOREAS_W == 2 || BOREAS_W == 4 || BOREAS_W == 8 || BOREAS_W == 16
#define BOREAS_W_SUFFIX BOREAS_W
#else
#error "BOREAS_W must be 1, 2, 4, 8 or 16"
#endif

/* The kernel's types: float and int at width 1, floatW and intW above. */
typedef BOREAS_CAT(float, BOREAS_W_SUFFIX) boreas_f;
typedef BOREAS_CAT(int, BOREAS_W_SUFFIX) boreas_i;

#define BOREAS_W_INLINE inline __attribute__((always_inline))

/* Value conversions at the kernel's width (toward zero for floats to ints, as a C cast). */
#define boreas_to_f(i) BOREAS_CAT(convert_float, BOREAS_W_SUFFIX)(i)
#define boreas_to_i(x) BOREAS_CAT(convert_int, BOREAS_W_SUFFIX)(x)
/* Bit casts at the kernel's width. */
#define boreas_as_f(i) BOREAS_CAT(as_float, BOREAS_W_SUFFIX)(i)
#define boreas_as_i(x) BOREAS_CAT(as_int, BOREAS_W_SUFFIX)(x)

/* Each lane loads its own element: the grid's trilinear corners, per-item records. */
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
BOREAS_W_INLINE boreas_f BOREAS_CAT(boreas_gather, BOREAS_W)(__global const float* p, boreas_i i) {
  return BOREAS_LANES_GATHER(boreas_f, p, i);
}
BOREAS_W_INLINE boreas_i BOREAS_CAT(boreas_gather_int, BOREAS_W)(__global const int* p, boreas_i i) {
  return BOREAS_LANES_GATHER(boreas_i, p, i);
}
#endif

/* The least and the sum of an int vector's lanes, by halves. */
#define BOREAS_LANES_FN inline __attribute__((always_inline, overloadable))
BOREAS_LANES_FN int boreas_lanes_min(int2 v) { return min(v.x, v.y); }
BOREAS_LANES_FN int boreas_lanes_min(int4 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_LANES_FN int boreas_lanes_min(int8 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_LANES_FN int boreas_lanes_min(int16 v) { return boreas_lanes_min(min(v.lo, v.hi)); }
BOREAS_LANES_FN int boreas_lanes_sum(int2 v) { return v.x + v.y; }
BOREAS_LANES_FN int boreas_lanes_sum(int4 v) { return boreas_lanes_sum(v.lo + v.hi); }
BOREAS_LANES_FN int boreas_lanes_sum(int8 v) { return boreas_lanes_sum(v.lo + v.hi); }
BOREAS_LANES_FN int boreas_lanes_sum(int16 v) { return boreas_lanes_sum(v.lo + v.hi); }

/* The same at the kernel's width (the value itself at width 1). */
#if BOREAS_W == 1
#define boreas_hmin_w(v) (v)
#define boreas_hsum_w(v) (v)
#else
#define boreas_hmin_w(v) boreas_lanes_min(v)
#define boreas_hsum_w(v) boreas_lanes_sum(v)
#endif

/* p[i] per lane at the kernel's width. */
#if BOREAS_W == 1
#define boreas_gather_w(p, i) ((p)[i])
#else
#define boreas_gather_w(p, i) BOREAS_CAT(boreas_gather, BOREAS_W)((p), (i))
#endif

/* The same from ints. */
#if BOREAS_W == 1
#define boreas_gather_wi(p, i) ((p)[i])
#else
#define boreas_gather_wi(p, i) BOREAS_CAT(boreas_gather_int, BOREAS_W)((p), (i))
#endif

/* 0, 1, ..., W-1: the lane's offset from the work-item's first item. */
#if BOREAS_W == 1
#define BOREAS_LANES 0
#elif BOREAS_W == 2
#define BOREAS_LANES (int2)(0, 1)
#elif BOREAS_W == 4
#define BOREAS_LANES (int4)(0, 1, 2, 3)
#elif BOREAS_W == 8
#define BOREAS_LANES (int8)(0, 1, 2, 3, 4, 5, 6, 7)
#else
#define BOREAS_LANES (int16)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
#endif

/* W floats of p from index first on, of a plane of count floats. A work-item whose W
 * items run past the plane's end (the last one, when count is not a multiple of W) reads
 * the last item again in the lanes beyond it, so nothing is read past the buffer; full
 * ones load with one vload. At width 1 this is p[min(first, count - 1)], today's form. */
BOREAS_W_INLINE boreas_f boreas_load_w(__global const float* p, int first, int count) {
#if BOREAS_W == 1
  return p[min(first, count - 1)];
#else
  if (first + BOREAS_W <= count) return BOREAS_CAT(vload, BOREAS_W)(0, p + first);
  return boreas_gather_w(p, min(first + BOREAS_LANES, count - 1));
#endif
}

/* The same for a plane of ints (their bits moved as floats: no arithmetic touches them). */
BOREAS_W_INLINE boreas_i boreas_load_wi(__global const int* p, int first, int count) {
  return boreas_as_i(boreas_load_w((__global const float*)p, first, count));
}

/* k / d per lane for 0 <= k < 2^31 and d > 0, exactly (a vertex's branch and ring from
 * its index). AVX-512 has no integer division, so above width 1 the quotient comes from a
 * float division, corrected by the remainder twice: the first estimate is within k 2^-23
 * of the quotient, the second within one, the selects make it exact. */
BOREAS_W_INLINE boreas_i boreas_div_w(boreas_i k, int d) {
#if BOREAS_W == 1
  return k / d;
#else
  const float inv = 1.0f / (float)d;
  boreas_i q = boreas_to_i(boreas_to_f(k) * inv);
  q += boreas_to_i(floor(boreas_to_f(k - q * d) * inv));
  boreas_i r = k - q * d;
  q = select(q, q + 1, r >= d);
  return select(q, q - 1, r < 0);
#endif
}

/* Stores the lanes of v whose items are below count (the rest were copies, see
 * boreas_load_w). At width 1 the clamped item is written, with the value every copy of
 * it computed, which keeps the store free of a branch. */
BOREAS_W_INLINE void boreas_store_w(boreas_f v, __global float* p, int first, int count) {
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
