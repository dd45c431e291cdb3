/* boreas: casting rays (boreas_world_cast_rays): one work-item per ray through the
 * two-level structure (cl/shared/ray_cast.h) to its nearest hit, written as a boreas_hit
 * record (BOREAS_RAY_HIT_WORDS words: distance, point, normal, kind, object id, part).
 * Rays are boreas_ray records (origin, direction, max distance), checked before the
 * launch; the direction is normalized here. */
#include "shared/ray_cast.h"

__kernel void boreas_ray_cast(__global const float* top, __global const int* top_items, int top_root,
                              __global const float* nodes, __global const int* items,
                              __global const int* instances, __global const float* branches,
                              __global const float* shapes, __global const float* leaves,
                              __global const float* positions, __global const float* trunks,
                              __global const float* crowns, __global const float* strips,
                              __global const int* ints, __global const float* rays, int first_ray,
                              __global float* hits, int first_hit, int count) {
  int i = (int)get_global_id(0);
  if (i >= count) return;
  BoreasRayScene s;
  s.top = top;
  s.top_items = top_items;
  s.top_root = top_root;
  s.nodes = nodes;
  s.items = items;
  s.instances = instances;
  s.branches = branches;
  s.shapes = shapes;
  s.leaves = leaves;
  s.positions = positions;
  s.trunks = trunks;
  s.crowns = crowns;
  s.strips = strips;
  s.ints = ints;
  __global const float* in = rays + (size_t)(first_ray + i) * BOREAS_RAY_RAY_FLOATS;
  BoreasV3 o = boreas_v3(in[0], in[1], in[2]);
  BoreasV3 d = boreas_v3_normalize(boreas_v3(in[3], in[4], in[5]));
  BoreasRay r = boreas_ray_make(o, d);
  BoreasRayHit h = boreas_ray_cast(&s, &r, in[6]);
  __global float* out = hits + (size_t)(first_hit + i) * BOREAS_RAY_HIT_WORDS;
  __global int* out_int = (__global int*)out;
  if (h.kind == BOREAS_RAY_HIT_NONE) {
    out[0] = INFINITY;
    for (int w = 1; w < 7; ++w) out[w] = 0.0f;
    for (int w = 7; w < 11; ++w) out_int[w] = 0;
    out_int[11] = -1;
    return;
  }
  BoreasV3 p = boreas_v3_madd(o, d, h.t);
  __global const int* inst = instances + (size_t)h.instance * BOREAS_RAY_INST_WORDS;
  out[0] = h.t;
  out[1] = p.x;
  out[2] = p.y;
  out[3] = p.z;
  out[4] = h.normal.x;
  out[5] = h.normal.y;
  out[6] = h.normal.z;
  out_int[7] = h.kind;
  out_int[8] = inst[BOREAS_RAY_INST_ID];
  out_int[9] = inst[BOREAS_RAY_INST_ID + 1];
  out_int[10] = inst[BOREAS_RAY_INST_ID + 2];
  out_int[11] = h.part;
}
