/* boreas: evaluates one fast-math function over arrays, so tests can bound its error
 * against double precision on the device itself. which: 0 sin, 1 cos, 2 exp2, 3 log2,
 * 4 pow(a, b), 5..9 the same through the per-device selection (boreas_sin, ...),
 * 10 sin of a phase in cycles, 11 the same through the selection, 12 atan2(a, b), 13 the
 * same through the selection. */
#include "shared/fast_math.h"

__kernel void boreas_fast_math_probe(__global const float* a, __global const float* b,
                                     __global float* out, int count, int which) {
  int id = get_global_id(0);
  if (id >= count) return;
  float x = a[id];
  float y = b[id];
  float r = 0.0f;
  switch (which) {
    case 0: r = boreas_poly_sin(x); break;
    case 1: r = boreas_poly_cos(x); break;
    case 2: r = boreas_poly_exp2(x); break;
    case 3: r = boreas_poly_log2(x); break;
    case 4: r = boreas_poly_pow(x, y); break;
    case 5: r = boreas_sin(x); break;
    case 6: r = boreas_cos(x); break;
    case 7: r = boreas_exp2(x); break;
    case 8: r = boreas_log2(x); break;
    case 9: r = boreas_pow(x, y); break;
    case 10: r = boreas_poly_sin_cycle(x); break;
    case 11: r = boreas_sin_cycle(x); break;
    case 12: r = boreas_poly_atan2(x, y); break;
    default: r = boreas_atan2(x, y); break;
  }
  out[id] = r;
}

/* The same at the kernel's SIMD width (BOREAS_W): each work-item evaluates W neighbouring
 * items in vector types, through boreas_load_w/boreas_store_w, so tests can hold every
 * width to width 1 bit for bit, tails included. which as above. */
__kernel void boreas_fast_math_probe_wide(__global const float* a, __global const float* b,
                                          __global float* out, int count, int which) {
  int first = (int)get_global_id(0) * BOREAS_W;
  if (first >= count) return;
  BOREAS_F x = boreas_load_w(a, first, count);
  BOREAS_F y = boreas_load_w(b, first, count);
  BOREAS_F r = (BOREAS_F)(0.0f);
  switch (which) {
    case 0: r = boreas_poly_sin(x); break;
    case 1: r = boreas_poly_cos(x); break;
    case 2: r = boreas_poly_exp2(x); break;
    case 3: r = boreas_poly_log2(x); break;
    case 4: r = boreas_poly_pow(x, y); break;
    case 5: r = boreas_sin(x); break;
    case 6: r = boreas_cos(x); break;
    case 7: r = boreas_exp2(x); break;
    case 8: r = boreas_log2(x); break;
    case 9: r = boreas_pow(x, y); break;
    case 10: r = boreas_poly_sin_cycle(x); break;
    case 11: r = boreas_sin_cycle(x); break;
    case 12: r = boreas_poly_atan2(x, y); break;
    default: r = boreas_atan2(x, y); break;
  }
  boreas_store_w(r, out, first, count);
}
