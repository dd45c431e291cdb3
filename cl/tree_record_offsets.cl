/* boreas: the first stage of a view's tree records (boreas_world_enqueue_tree_records,
 * cl/shared/tree_records.h): each slot culled (shared/tree_cull.h), and where each tree's
 * records go, in slot order, by prefix sums in one work-group (its work-items take
 * consecutive runs of slots: each run culled and summed, an exclusive scan of the runs,
 * then each run placed from its start). So the records of a batch's trees are packed in
 * slot order, the same for the same world whatever the timing; culling in the same group
 * saves a launch, and a sphere test per tree is little beside the scan's pass.
 *
 * A call covers the world's batches one after another: the first starts its counts at 0,
 * each later one at the counts the one before left in the indirect buffer.
 * Capacity: a drawn tree's records are written only where all its branch and leaf records
 * and its range record fit in the caller's buffers; since the ends grow with the slot
 * order, the trees written are the first ones, up to the first that does not fit. An
 * impostor is written where its record fits. The indirect buffer's commands count the
 * records written; its NEEDED words the records the view asked for (the size a caller
 * should grow its buffers to).
 * This kernel writes the impostor records (its tree's base (its row's offset,
 * shared/tree_origin.h), scale, rotation, template, and
 * its trunk's first piece's tip's displacement from rest, read from the state), the range
 * records and the indirect buffer, and each row's record offsets (-1: none), which the
 * record kernels read. */
#include "shared/tree_cull.h"
#include "shared/tree_origin.h"
#include "shared/tree_records.h"
#include "shared/tree_types.h"
#include "shared/tree_state.h"

#define BOREAS_KINDS 4 /* branch records, leaf records, impostors, ranges */

__kernel void boreas_tree_record_offsets(__global const BoreasTreeView* views, int slots, BoreasRecordView view,
                                         __global int* table, __global const float* state, int n,
                                         __global float* impostors, __global int* ranges,
                                         __global uint* indirect, __global const float* offsets) {
  __local int sums[BOREAS_KINDS][BOREAS_TREE_OFFSETS_GROUP];
  __local int written[BOREAS_KINDS];
  const int lid = (int)get_local_id(0), size = (int)get_local_size(0);
  const int chunk = (slots + size - 1) / size;
  const int s0 = min(lid * chunk, slots), s1 = min(s0 + chunk, slots);
  int at[BOREAS_KINDS] = {0, 0, 0, 0};
  for (int s = s0; s < s1; ++s) {
    __global int* row = table + s * BOREAS_TREE_OUT_INTS;
    boreas_tree_cull_row(views + s, &view, row);
    at[0] += row[BOREAS_TREE_OUT_BRANCHES];
    at[1] += row[BOREAS_TREE_OUT_KEPT];
    at[2] += row[BOREAS_TREE_OUT_KIND] == BOREAS_TREE_KIND_IMPOSTOR;
    at[3] += row[BOREAS_TREE_OUT_KIND] == BOREAS_TREE_KIND_DRAWN;
  }
  for (int k = 0; k < BOREAS_KINDS; ++k) sums[k][lid] = at[k];
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0) {
    for (int k = 0; k < BOREAS_KINDS; ++k) {
      int total = view.first_batch ? 0 : (int)indirect[BOREAS_TREE_INDIRECT_NEEDED + k];
      for (int t = 0; t < size; ++t) {
        const int x = sums[k][t];
        sums[k][t] = total;
        total += x;
      }
      indirect[BOREAS_TREE_INDIRECT_NEEDED + k] = (uint)total;
      written[k] = view.first_batch ? 0 : (int)indirect[k == 3 ? BOREAS_TREE_INDIRECT_RANGES : 4 * k + 1];
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  for (int k = 0; k < BOREAS_KINDS; ++k) at[k] = sums[k][lid];
  int ends[BOREAS_KINDS] = {0, 0, 0, 0};
  for (int s = s0; s < s1; ++s) {
    __global int* row = table + s * BOREAS_TREE_OUT_INTS;
    __global const BoreasTreeView* t = views + s;
    const int kind = row[BOREAS_TREE_OUT_KIND];
    row[BOREAS_TREE_OUT_BRANCH_FIRST] = row[BOREAS_TREE_OUT_LEAF_FIRST] = -1;
    if (kind == BOREAS_TREE_KIND_DRAWN) {
      const int nb = row[BOREAS_TREE_OUT_BRANCHES], nl = row[BOREAS_TREE_OUT_KEPT];
      if (at[0] + nb <= view.branch_capacity && at[1] + nl <= view.leaf_capacity &&
          at[3] < view.range_capacity) {
        row[BOREAS_TREE_OUT_BRANCH_FIRST] = at[0];
        row[BOREAS_TREE_OUT_LEAF_FIRST] = at[1];
        __global int* r = ranges + (size_t)at[3] * BOREAS_TREE_RANGE_WORDS;
        r[BOREAS_TREE_RANGE_ID_INDEX] = t->id_index;
        r[BOREAS_TREE_RANGE_ID_GENERATION] = t->id_generation;
        r[BOREAS_TREE_RANGE_BRANCH_FIRST] = at[0];
        r[BOREAS_TREE_RANGE_BRANCH_COUNT] = nb;
        r[BOREAS_TREE_RANGE_LEAF_FIRST] = at[1];
        r[BOREAS_TREE_RANGE_LEAF_COUNT] = nl;
        r[BOREAS_TREE_RANGE_LEAVES] = t->leaves;
        r[BOREAS_TREE_RANGE_LEAF_STRIDE] = nl < t->leaves ? t->leaf_stride : 1;
        ends[0] = at[0] + nb;
        ends[1] = at[1] + nl;
        ends[3] = at[3] + 1;
      }
      at[0] += nb;
      at[1] += nl;
      at[3] += 1;
    } else if (kind == BOREAS_TREE_KIND_IMPOSTOR) {
      if (at[2] < view.impostor_capacity) {
        __global float* o = impostors + (size_t)at[2] * BOREAS_TREE_IMPOSTOR_WORDS;
        for (int a = 0; a < 3; ++a) {
          o[a] = offsets[s * BOREAS_TREE_OFFSET_FLOATS + a]; /* the base, in the caller's frame */
          /* The trunk is the tree's first branch, the entry after its root. */
          o[6 + a] = t->branches > 0 ? state[BOREAS_TREE_AT(BOREAS_TREE_STATE_P3 + a, n, t->root + 1)] - t->rest_tip[a]
                                     : 0.0f;
          o[9 + a] = 0.0f;
        }
        o[3] = t->scale;
        o[4] = t->rotation;
        o[5] = (float)t->template_index;
        ends[2] = at[2] + 1;
      }
      at[2] += 1;
    }
  }
  for (int k = 0; k < BOREAS_KINDS; ++k) atomic_max(&written[k], ends[k]);
  barrier(CLK_LOCAL_MEM_FENCE);
  if (lid == 0) {
    for (int k = 0; k < 3; ++k) {
      indirect[4 * k + 0] = (uint)view.vertices[k];
      indirect[4 * k + 1] = (uint)written[k];
      indirect[4 * k + 2] = 0u;
      indirect[4 * k + 3] = 0u;
    }
    indirect[BOREAS_TREE_INDIRECT_RANGES] = (uint)written[3];
    for (int k = 1; k < 4; ++k) indirect[BOREAS_TREE_INDIRECT_RANGES + k] = 0u;
  }
}
