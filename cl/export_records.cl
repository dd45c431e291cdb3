/* boreas: device records for renderers that draw straight from OpenCL buffers (CL-GL
 * interop, boreas_cl.h). The state lives in planes (structure of arrays) because that is
 * what PoCL vectorizes; a renderer wants one record per instance (array of structures),
 * which a vertex shader reads with one index. This kernel gathers a range of one tree's
 * branches (its state, its template's radius functions at its scale) into such records: a
 * copy, no math, so nothing can differ from boreas_tree_get_branches. Leaf records are
 * made by cl/tree_leaves.cl itself (leaves are made when read).
 *
 * Branch record (BOREAS_BRANCH_RECORD_FLOATS = 28): P0..P3 (x y z each), O (x y z), then
 * the 9 radius-function values in BoreasBranchRadius's order, the broken flag (0 or 1) and
 * three zeros (a record of seven vec4s).
 * One work-item per record; the global size may exceed count (extra items redo the last). */
#include "shared/tree_state.h"

__kernel void boreas_export_branch_records(__global const float* state, __global const float* motion, int n,
                                           __global const float* radius, int sn, int first, int static_first,
                                           int count, float scale, __global float* out, int out_first) {
  int k = min((int)get_global_id(0), count - 1);
  int i = first + k;
  int j = static_first + k;
  __global float* o = out + (size_t)(out_first + k) * BOREAS_TREE_RECORD_FLOATS;
  for (int p = 0; p < BOREAS_TREE_STATE_PLANES; ++p) o[p] = state[BOREAS_TREE_AT(p, n, i)];
  /* The template's radius functions; only the radius itself is a length. */
  for (int p = 0; p < BOREAS_TREE_RADIUS_PLANES; ++p) o[BOREAS_TREE_STATE_PLANES + p] = radius[BOREAS_TREE_AT(p, sn, j)];
  o[BOREAS_TREE_STATE_PLANES] *= scale;
  o[BOREAS_TREE_RECORD_BROKEN] = motion[BOREAS_TREE_AT(BOREAS_TREE_MOTION_BROKEN, n, i)];
  for (int p = BOREAS_TREE_RECORD_BROKEN + 1; p < BOREAS_TREE_RECORD_FLOATS; ++p) o[p] = 0.0f;
}
