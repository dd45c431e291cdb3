/* boreas: what each touched tree's branches pushed each of its colliders back with over a
 * step, summed on the device: one work-item per (touched tree, collider) pair, each adding
 * its tree's branch records (cl/shared/tree_contact.h) for that collider in branch order,
 * so the sums are the same bits every run and the host reads a pair's sum, not its
 * branches' records (TreeBatch::add_contacts).
 * Pairs: 4 ints each (the tree's first record row, its entries, its collider count, the
 * collider's place among them); out: 8 floats each (force x, y, z in N, torque x, y, z in
 * N m, branches touching, 0). Width 1. */
#include "shared/tree_types.h"

__kernel void boreas_tree_contact_sums(__global const float* records, __global const int* pairs,
                                       int pair_count, __global float* out) {
  int p = (int)get_global_id(0);
  if (p >= pair_count) return;
  int record = pairs[4 * p], entries = pairs[4 * p + 1], colliders = pairs[4 * p + 2],
      j = pairs[4 * p + 3];
  float fx = 0.0f, fy = 0.0f, fz = 0.0f, tx = 0.0f, ty = 0.0f, tz = 0.0f, touching = 0.0f;
  /* Entry 0, the tree's root, is never stepped nor written. */
  for (int branch = 1; branch < entries; ++branch) {
    __global const float* r =
        records + ((size_t)record + (size_t)branch * (size_t)colliders + (size_t)j) *
                      BOREAS_TREE_CONTACT_RECORD_FLOATS;
    fx += r[BOREAS_TREE_CONTACT_RECORD_FORCE];
    fy += r[BOREAS_TREE_CONTACT_RECORD_FORCE + 1];
    fz += r[BOREAS_TREE_CONTACT_RECORD_FORCE + 2];
    tx += r[BOREAS_TREE_CONTACT_RECORD_TORQUE];
    ty += r[BOREAS_TREE_CONTACT_RECORD_TORQUE + 1];
    tz += r[BOREAS_TREE_CONTACT_RECORD_TORQUE + 2];
    touching += r[BOREAS_TREE_CONTACT_RECORD_TOUCHING] > 0.0f ? 1.0f : 0.0f;
  }
  __global float* o = out + 8 * (size_t)p;
  o[0] = fx;
  o[1] = fy;
  o[2] = fz;
  o[3] = tx;
  o[4] = ty;
  o[5] = tz;
  o[6] = touching;
  o[7] = 0.0f;
}
