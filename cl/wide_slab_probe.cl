/* boreas probe (issue 22): the sine slab of wind_sine_slab.cl, and the wind at points of
 * wind_sample_points.cl, with explicit vector width: each work-item computes
 * BOREAS_PROBE_W (8 or 16) neighbouring columns or points in OpenCL vector types, to
 * measure whether PoCL turns float16 into 512-bit code where its own work-item vectorizer
 * stops at 8 lanes, and what the grid's gathers cost when each lane loads its own cell.
 * Same math as cl/shared/fast_math.h and wind_sample.h, written for vectors with select.
 * The slab's global size is (nx / W, nz), nx a multiple of W; the points' count / W, count
 * a multiple of W. Not part of the library. */
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
/* Each lane loads its own element: p[i.s0], ..., p[i.sf]. */
#define GATHER(p, i)                                                                       \
  (vf)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3], (p)[(i).s4], (p)[(i).s5],       \
       (p)[(i).s6], (p)[(i).s7], (p)[(i).s8], (p)[(i).s9], (p)[(i).sa], (p)[(i).sb],       \
       (p)[(i).sc], (p)[(i).sd], (p)[(i).se], (p)[(i).sf])
#else
typedef float8 vf;
typedef int8 vi;
#define VSTORE vstore8
#define AS_VF as_float8
#define AS_VI as_int8
#define CONVERT_VI convert_int8
#define CONVERT_VF convert_float8
#define VLOAD vload8
#define LANES (vf)(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f)
#define GATHER(p, i)                                                                       \
  (vf)((p)[(i).s0], (p)[(i).s1], (p)[(i).s2], (p)[(i).s3], (p)[(i).s4], (p)[(i).s5],       \
       (p)[(i).s6], (p)[(i).s7])
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

/* The sine sum at W points (x, z). */
BOREAS_VINLINE void v_sine_sum(vf x, vf z, __global const BoreasGpuWave* waves, vf* out_x, vf* out_z) {
  vf fx = (vf)(0.0f), fz = (vf)(0.0f);
#pragma unroll
  for (int w = 0; w < BOREAS_WAVE_SLOTS; ++w) {
    const float dx = waves[w].dir_x, dz = waves[w].dir_z;
    vf u = fma(fma((vf)(dx), x, dz * z), (vf)(waves[w].cycles_per_meter), (vf)(waves[w].phase_cycles));
    u -= floor(u + 0.5f);
    vf base = fma(v_sin_cycle(u), (vf)(0.5f), (vf)(0.5f));
    vf s = waves[w].amplitude * v_pow(base, waves[w].sharpness);
    fx = fma((vf)(dx), s, fx);
    fz = fma((vf)(dz), s, fz);
  }
  *out_x = fx;
  *out_z = fz;
}

/* boreas_wind_sample (wind_sample.h) for W points read from planes. */
__kernel void boreas_wide_sample_points_probe(__global const float* points, __global float* force, int count,
                                              __global const BoreasGpuWave* waves, int wave_count,
                                              __global const float* grid, BoreasGpuGrid g) {
  const int i0 = (int)get_global_id(0) * BOREAS_PROBE_W;
  const vf px = VLOAD(0, points + i0), py = VLOAD(0, points + count + i0), pz = VLOAD(0, points + 2 * count + i0);
  vf sx, sz;
  v_sine_sum(px, pz, waves, &sx, &sz);
  const float inv_h = 1.0f / g.cell_size;
  const vf cx = (px - g.origin_x) * inv_h, cy = (py - g.origin_y) * inv_h, cz = (pz - g.origin_z) * inv_h;
  /* Trilinear between cell centres, clamped to the outermost ones. */
  const vf tx = clamp(cx - 0.5f, 0.0f, (float)(g.nx - 1));
  const vf ty = clamp(cy - 0.5f, 0.0f, (float)(g.ny - 1));
  const vf tz = clamp(cz - 0.5f, 0.0f, (float)(g.nz - 1));
  const vf x0 = floor(tx), y0 = floor(ty), z0 = floor(tz);
  const vf fx = tx - x0, fy = ty - y0, fz = tz - z0;
  const vi i = CONVERT_VI(x0), j = CONVERT_VI(y0), k = CONVERT_VI(z0);
  const vi di = min(i + 1, g.nx - 1) - i;
  const vi dj = (min(j + 1, g.ny - 1) - j) * g.nx;
  const vi dk = (min(k + 1, g.nz - 1) - k) * (g.nx * g.ny);
  const vi c000 = (k * g.ny + j) * g.nx + i;
  const vi c100 = c000 + di, c010 = c000 + dj, c110 = c010 + di;
  const vi c001 = c000 + dk, c101 = c001 + di, c011 = c001 + dj, c111 = c011 + di;
  const vf w000 = (1.0f - fx) * (1.0f - fy) * (1.0f - fz), w100 = fx * (1.0f - fy) * (1.0f - fz);
  const vf w010 = (1.0f - fx) * fy * (1.0f - fz), w110 = fx * fy * (1.0f - fz);
  const vf w001 = (1.0f - fx) * (1.0f - fy) * fz, w101 = fx * (1.0f - fy) * fz;
  const vf w011 = (1.0f - fx) * fy * fz, w111 = fx * fy * fz;
  const int plane = g.nx * g.ny * g.nz;
  vf r[3];
#pragma unroll
  for (int a = 0; a < 3; ++a) {
    __global const float* p = grid + a * plane;
    r[a] = w000 * GATHER(p, c000) + w100 * GATHER(p, c100) + w010 * GATHER(p, c010) +
           w110 * GATHER(p, c110) + w001 * GATHER(p, c001) + w101 * GATHER(p, c101) +
           w011 * GATHER(p, c011) + w111 * GATHER(p, c111);
  }
  /* The fade beyond the sides, by the max-norm distance outside the extent. */
  const float hx = 0.5f * (float)g.nx, hz = 0.5f * (float)g.nz;
  const vf outside = max(max(fabs(cx - hx) - hx, fabs(cz - hz) - hz), (vf)(0.0f));
  const vf s = clamp(1.0f - outside * g.fade_per_cell, 0.0f, 1.0f);
  const vf fade = s * s * (3.0f - 2.0f * s);
  /* Zero inside solid cells within the extent. */
  const vf fi = floor(cx), fj = floor(cy), fk = floor(cz);
  const vi inside = isgreaterequal(fi, (vf)(0.0f)) & isgreaterequal(fj, (vf)(0.0f)) &
                    isgreaterequal(fk, (vf)(0.0f)) & isless(fi, (vf)((float)g.nx)) &
                    isless(fj, (vf)((float)g.ny)) & isless(fk, (vf)((float)g.nz));
  const vi ci = CONVERT_VI(clamp(fi, 0.0f, (float)(g.nx - 1)));
  const vi cj = CONVERT_VI(clamp(fj, 0.0f, (float)(g.ny - 1)));
  const vi ck = CONVERT_VI(clamp(fk, 0.0f, (float)(g.nz - 1)));
  const vi cell = (ck * g.ny + cj) * g.nx + ci;
  const vf flag = GATHER(grid + 3 * plane, cell);
  const vi solid = inside & (vi)(g.solid_count > 0 ? -1 : 0) & isnotequal(flag, (vf)(0.0f));
  VSTORE(select(sx + r[0] * fade, (vf)(0.0f), solid), 0, force + i0);
  VSTORE(select(r[1] * fade, (vf)(0.0f), solid), 0, force + count + i0);
  VSTORE(select(sz + r[2] * fade, (vf)(0.0f), solid), 0, force + 2 * count + i0);
}
