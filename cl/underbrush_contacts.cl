/* boreas: what the components of a tile push a collider back with over a step — one
 * work-item per (tile, collider) pair that the host's broadphase found (UnderbrushBatch),
 * each summing its tile's components in their order, so the sums are the same bits every
 * run (the host adds the pairs up in their order: no atomics).
 * It reads the state the step read (state_in, still there until the next step) and
 * recomputes each component's center of mass as underbrush_step.cl carried it with its
 * base, so each push is the one the step applied: the reaction is minus the component's
 * mass times it (boreas_ub_add_reaction).
 * Pairs: BOREAS_UB_PAIR_INTS ints each (the tile's first component, its count, its part
 * base and root as in its tile record, the index of the collider's record relative to the
 * tile's meadow: components and collider both in the meadow's coordinates); out: BOREAS_UB_PAIR_FLOATS
 * floats each (force x, y, z in N, torque x, y, z in N m about the collider's position at
 * the step's end, contacts). Width 1: the pairs are few, the components of each at most a
 * tile. */
#include "shared/underbrush_math.h"

__kernel void boreas_underbrush_contacts(__global const float* state_in, __global const float* frame,
                                         __global const int* index,
                                         __global const BoreasGpuPart* parts, int n,
                                         __global const BoreasGpuCollider* colliders,
                                         __global const int* pairs, int pair_count,
                                         __global float* out) {
  int pair = min((int)get_global_id(0), pair_count - 1);
  __global const int* q = pairs + BOREAS_UB_PAIR_INTS * pair;
  int first = q[0], count = q[1], part_first = q[2]; /* q[3], the root: parents are relative */
  __global const BoreasGpuCollider* c = colliders + q[4];
  BoreasV3 force = boreas_v3(0.0f, 0.0f, 0.0f), torque = force;
  float contacts = 0.0f;
  for (int j = 0; j < count; ++j) {
    int i = first + j;
    int link = index[BOREAS_UB_INDEX_LINK * n + i];
    int p = part_first + boreas_ub_link_part(link);
    int parent = i - boreas_ub_link_back(link);
    BoreasV3 base = boreas_ub_base(frame, state_in, n, i, parent);
    BoreasV3 base_before = boreas_tree_load3(state_in, n, BOREAS_UB_STATE_BASE, i);
    BoreasV3 x = boreas_v3_add(boreas_tree_load3(state_in, n, BOREAS_UB_STATE_X, i),
                               boreas_v3_sub(base, base_before));
    float scale = boreas_ub_unpack_scale(index[BOREAS_UB_INDEX_TURN * n + i]);
    float reach = parts[p].reach * scale;
    boreas_ub_add_reaction(x, c, reach, parts[p].collider_push,
                           1.0f / boreas_ub_inv_mass(parts[p].inv_mass, scale), &force, &torque,
                           &contacts);
  }
  __global float* o = out + BOREAS_UB_PAIR_FLOATS * pair; /* past the last: its twin */
  o[0] = force.x;
  o[1] = force.y;
  o[2] = force.z;
  o[3] = torque.x;
  o[4] = torque.y;
  o[5] = torque.z;
  o[6] = contacts;
  o[7] = 0.0f;
}
