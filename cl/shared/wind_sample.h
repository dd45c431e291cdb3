/* boreas: the wind at a point, for any kernel (trees and underbrush call this).
 * wind(p, t) = sine_sum(p.x, p.z, t) + fade(p) trilinear(grid, p), and zero inside solid
 * cells; the sine sum exact, or with BOREAS_WIND_INTERPOLATED bilinear in the step's slab
 * of column centers. Compiles as OpenCL C and as C/C++ (width 1), so the native benchmark
 * twins run this text; the double-precision host reference, written apart from it, is
 * host/src/reference/wind_reference.cpp.
 *
 * Written once for any SIMD width (wind_sample_width.inc, see simd_width.h): at width 1
 * in scalar floats on purpose, because on PoCL (LLVM 15) the loop vectorizer refuses any
 * instruction of vector type (float2/3/4 values, whole-struct copies) inside the
 * work-item loop, and a kernel that is not vectorized runs one lane at a time; at the
 * kernel's width BOREAS_W in floatW, which PoCL compiles straight to that width. Every
 * helper is inlined (BOREAS_FN): PoCL vectorizes across work-items only a loop with no
 * calls. */
#ifndef BOREAS_CL_SHARED_WIND_SAMPLE_H
#define BOREAS_CL_SHARED_WIND_SAMPLE_H

#include "shared/fast_math.h"
#include "shared/simd_width.h"
#include "shared/wind_types.h"

/* Waves are summed over a compile-time number of slots (the host pads the set with
 * silent waves up to it) so the loop unrolls and the work-item loop around the kernel
 * stays innermost, which LLVM's vectorizer needs. -1 sums wave_count waves in a plain
 * loop (sets beyond the largest slot count). */
#ifndef BOREAS_WAVE_SLOTS
#define BOREAS_WAVE_SLOTS -1
#endif

/* 1: the plants' kernels read the sine sum from the step's slab (wind_sampling
 * interpolated, boreas.h); 0: they evaluate it at every point. */
#ifndef BOREAS_WIND_INTERPOLATED
#define BOREAS_WIND_INTERPOLATED 0
#endif

BOREAS_FN int boreas_grid_cells(const BoreasGpuGrid g) { return g.nx * g.ny * g.nz; }

/* At width 1 (host and kernels) and at the kernel's SIMD width, where it is wider. */
#define BOREAS_WIDTH_BODY "shared/wind_sample_width.inc"
#include "shared/width_instantiate.inc"

#endif
