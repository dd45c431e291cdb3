/* boreas: the wide nodes' boxes after a refit (host/src/rays/bvh_wide.h): each slot of a
 * wide node takes the box of the binary node it stands for, which the refit just updated
 * (cl/ray_refit.cl). A work-item a run of wide nodes (jobs: first wide node, how many);
 * an empty slot (gather -1) keeps its empty box. */
#include "shared/ray_types.h"

__kernel void boreas_ray_wide_gather(__global const float* nodes, __global const int* gather,
                                     __global const int* jobs, int count, __global float* wide) {
  int i = (int)get_global_id(0);
  if (i >= count) return;
  int first = jobs[2 * i], n = jobs[2 * i + 1];
  for (int w = first; w < first + n; ++w) {
    __global float* out = wide + (size_t)w * BOREAS_RAY_WIDE_WORDS;
    for (int k = 0; k < 4; ++k) {
      int b = gather[4 * w + k];
      if (b < 0) continue;
      __global const float* node = nodes + (size_t)b * BOREAS_RAY_NODE_WORDS;
      for (int axis = 0; axis < 3; ++axis) {
        out[BOREAS_RAY_WIDE_LO + 4 * axis + k] = node[axis];
        out[BOREAS_RAY_WIDE_HI + 4 * axis + k] = node[4 + axis];
      }
    }
  }
}
