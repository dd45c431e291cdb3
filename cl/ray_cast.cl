/* boreas: casting rays (boreas_world_cast_rays): one work-item per ray through the
 * two-level structure (cl/shared/ray_cast.h) to its nearest hit, written as a boreas_hit
 * record (BOREAS_RAY_HIT_WORDS words: distance, point, normal, kind, object id, part;
 * boreas_ray_cast_record). Rays are boreas_ray records (origin, direction, max distance),
 * checked before the launch. */
#include "shared/ray_cast.h"

__kernel void boreas_ray_cast(__global const float* top, __global const int* top_items, int top_root,
                              __global const float* wide, __global const int* items,
                              __global const int* instances, __global const float* branches,
                              __global const float* shapes, __global const float* records,
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
  s.wide = wide;
  s.items = items;
  s.instances = instances;
  s.branches = branches;
  s.shapes = shapes;
  s.records = records;
  s.positions = positions;
  s.trunks = trunks;
  s.crowns = crowns;
  s.strips = strips;
  s.ints = ints;
  __global float* out = hits + (size_t)(first_hit + i) * BOREAS_RAY_HIT_WORDS;
  boreas_ray_cast_record(&s, rays + (size_t)(first_ray + i) * BOREAS_RAY_RAY_FLOATS, out,
                         (__global int*)out);
}
