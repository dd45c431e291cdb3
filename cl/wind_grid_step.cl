/* boreas: one step of the force-field grid (Endo et al. sec. 4.1: the force propagates to
 * adjacent cells each step and is changed by the objects in the field).
 *
 * Per cell, reading only the previous grid (ping-pong), in this order:
 *  1. transport: semi-Lagrangian backtrace along the total flow (sine sum + grid) over dt,
 *     trilinear sample of the previous grid there (Stam, "Stable Fluids");
 *  2. diffusion: mixed with the mean of the 6 neighbours by 1 - exp(-6 nu dt / h^2), the
 *     exact relaxation of the discrete Laplacian toward that mean;
 *  3. decay: times exp(-lambda dt);
 *  4. forcing: flow primitives and gusts drive the cell toward the sum of their velocity
 *     fields T with rate coverage / response_time, integrated exactly: T + (v - T) e^(-K dt);
 *  5. obstacles: a solid cell holds minus the sine sum, so the total wind there is zero;
 *     a fluid cell next to a solid face loses the total wind's component normal to that
 *     face, into or out of it (a free-slip wall: no flux through the face, the tangential
 *     flow goes on along it, so the wind is deflected around the obstacle, not stopped).
 * Why this scheme: each of 1-4 is a convex combination of previous values and targets
 * (or a scaling by a factor <= 1), and 5 only removes components, so no value can grow
 * beyond the largest input for any dt: unconditionally stable, no CFL limit. The price
 * is first-order accuracy in time and some numerical diffusion from the interpolation.
 * With nothing to force and no solids, a zero grid stays exactly zero. */
#include "shared/wind_sample.h"

/* Smooth compact falloff, 1 at the primitive's position and 0 at its radius. */
inline float boreas_flow_coverage(float d2, float radius) {
  if (radius <= 0.0f) return 1.0f;
  float q = 1.0f - d2 / (radius * radius);
  q = max(q, 0.0f);
  return q * q;
}

/* Velocity of one primitive at offset r from its position. Source, sink and vortex rise
 * linearly over the inner quarter of the radius so that they have no singular core. */
inline float3 boreas_flow_velocity(const BoreasGpuForcing f, float3 r, float coverage) {
  float3 dir = (float3)(f.dir_x, f.dir_y, f.dir_z);
  float d = length(r);
  float core = max(0.25f * f.radius, 1e-6f);
  float ramp = min(d / core, 1.0f) * coverage * f.strength;
  float3 radial = d > 1e-6f ? r / d : (float3)(0.0f);
  float3 around = cross(dir, r - dot(r, dir) * dir);
  float around_len = length(around);
  float3 swirl = around_len > 1e-6f ? around / around_len : (float3)(0.0f);
  float3 v = dir * (f.strength * coverage);
  v = f.type == BOREAS_GPU_FLOW_SOURCE ? radial * ramp : v;
  v = f.type == BOREAS_GPU_FLOW_SINK ? -radial * ramp : v;
  v = f.type == BOREAS_GPU_FLOW_VORTEX ? swirl * ramp : v;
  return v;
}

__kernel void boreas_wind_grid_step(__global const float4* in, __global float4* out,
                                    __global const float2* slab,
                                    __global const BoreasGpuForcing* forcing,
                                    BoreasGpuGrid g, BoreasGpuGridStep s) {
  int i = get_global_id(0);
  int j = get_global_id(1);
  int k = get_global_id(2);
  if (i >= g.nx || j >= g.ny || k >= g.nz) return;
  int idx = boreas_grid_index(g, i, j, k);
  float4 self = in[idx];
  float2 sine2 = slab[k * g.nx + i];
  float3 sine = (float3)(sine2.x, 0.0f, sine2.y);

  /* 1. transport */
  float3 cell = (float3)((float)i, (float)j, (float)k);
  float3 total = sine + self.xyz;
  float3 advected = boreas_grid_trilinear(in, g, cell - total * s.dt_over_cell);

  /* 2. diffusion: neighbours clamped at the grid's edge (zero-gradient boundary) */
  float4 xm = in[boreas_grid_index(g, max(i - 1, 0), j, k)];
  float4 xp = in[boreas_grid_index(g, min(i + 1, g.nx - 1), j, k)];
  float4 ym = in[boreas_grid_index(g, i, max(j - 1, 0), k)];
  float4 yp = in[boreas_grid_index(g, i, min(j + 1, g.ny - 1), k)];
  float4 zm = in[boreas_grid_index(g, i, j, max(k - 1, 0))];
  float4 zp = in[boreas_grid_index(g, i, j, min(k + 1, g.nz - 1))];
  float3 mean = (xm.xyz + xp.xyz + ym.xyz + yp.xyz + zm.xyz + zp.xyz) * (1.0f / 6.0f);
  float3 v = mix(advected, mean, s.diffusion_mix);

  /* 3. decay */
  v *= s.decay_factor;

  /* 4. forcing */
  if (s.forcing_count > 0) {
    float3 p = (float3)(g.origin_x, g.origin_y, g.origin_z) + (cell + 0.5f) * g.cell_size;
    float3 target = (float3)(0.0f);
    float coverage_max = 0.0f;
    for (int n = 0; n < s.forcing_count; ++n) {
      const BoreasGpuForcing f = forcing[n];
      float3 r = p - (float3)(f.pos_x, f.pos_y, f.pos_z);
      float c = boreas_flow_coverage(dot(r, r), f.radius);
      target += boreas_flow_velocity(f, r, c);
      coverage_max = max(coverage_max, c);
    }
    float keep = boreas_exp2(-coverage_max * s.drive_exponent);
    v = mix(target, v, keep);
  }

  /* 5. obstacles */
  float solid = self.w;
  if (g.solid_count > 0) {
    float3 t = sine + v;
    t.x = xp.w != 0.0f || xm.w != 0.0f ? 0.0f : t.x;
    t.y = yp.w != 0.0f || ym.w != 0.0f ? 0.0f : t.y;
    t.z = zp.w != 0.0f || zm.w != 0.0f ? 0.0f : t.z;
    v = solid != 0.0f ? -sine : t - sine;
  }
  out[idx] = (float4)(v, solid);
}
