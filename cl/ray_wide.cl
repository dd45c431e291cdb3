/* boreas: the wide nodes' boxes after a refit (host/src/rays/bvh_wide.h): each wide node
 * is packed again (cl/shared/ray_wide.h, boreas_ray_wide_pack) from the boxes of the binary
 * nodes its slots stand for, which the refit just updated (cl/ray_refit.cl). A work-item
 * a run of wide nodes (jobs: first wide node, how many); an empty slot (gather -1) packs
 * as the builder's empty box. */
#include "shared/ray_wide.h"

__kernel void boreas_ray_wide_gather(__global const float* nodes, __global const int* gather,
                                     __global const int* jobs, int count, __global float* wide) {
  int i = (int)get_global_id(0);
  if (i >= count) return;
  int first = jobs[2 * i], n = jobs[2 * i + 1];
  for (int w = first; w < first + n; ++w) {
    float box[24];
    for (int k = 0; k < 4; ++k) {
      int b = gather[4 * w + k];
      __global const float* node = nodes + (size_t)(b < 0 ? 0 : b) * BOREAS_RAY_NODE_WORDS;
      for (int axis = 0; axis < 3; ++axis) {
        box[6 * k + axis] = b < 0 ? INFINITY : node[axis];
        box[6 * k + 3 + axis] = b < 0 ? -INFINITY : node[4 + axis];
      }
    }
    boreas_ray_wide_pack(wide + (size_t)w * BOREAS_RAY_WIDE_WORDS, box);
  }
}
