/* boreas: colliders against imported trees (shared/mesh_tree_contact.h says the model).
 * boreas_mesh_tree_contact: one work-item per tree that a collider's swept bounds meet this
 * step, or that one met recently and is still springing back; it runs over its own
 * branches in order (parents first), so the loads it passes to the parents need no atomics
 * and sum in one order. Not a hot kernel: the host launches it for those trees only, after
 * mesh_tree_branches.cl (it reads the wind the step just wrote). Then, after the vertex
 * kernels, boreas_mesh_tree_bend_trunk and _leaves add the bends to those trees' vertices.
 * Positions are the tree's own (its branches' points less its TREE_ORIGIN), and so are its
 * pairs' collider records (colliders[q] for pair q, the host's double position less the
 * tree's: MeshTreeBatch::enqueue_contacts), so a tree far out is pushed as one near 0. */
#include "shared/mesh_tree_contact.h"

/* The hardest-pressed segment point of branch b against collider c: lambda (N) at point
 * p with collider normal n, or lambda < 0 when no segment touches. */
typedef struct BoreasMeshTreePress {
  float lambda;
  float px, py, pz, nx, ny, nz;
} BoreasMeshTreePress;

void boreas_mesh_tree_press(__global const float* contact, int b, __global const int* links, int nb,
                            const BoreasMeshTreeChain* chain, __global const float* bend,
                            __global const BoreasGpuCollider* c, BoreasMeshTreePress* best) {
  best->lambda = -1.0f;
  if (!boreas_mesh_tree_may_meet(chain, c)) return;
  for (int k = 1; k <= BOREAS_MESH_TREE_CONTACT_SEGMENTS; ++k) {
    BoreasMeshTreeSample p;
    boreas_mesh_tree_nearest(contact, k, b, links, nb, chain, c, &p);
    BoreasColliderDistance d = boreas_mesh_tree_against(&p, c);
    if (d.distance > BOREAS_MESH_TREE_CONTACT_SLOP) continue;
    float ux = 0.0f, uy = 0.0f, uz = 0.0f;
    for (int j = 0; j < 4; ++j) {
      ux += p.w[j] * bend[(BOREAS_MESH_TREE_BEND_OFFSET + 0) * nb + p.a[j]];
      uy += p.w[j] * bend[(BOREAS_MESH_TREE_BEND_OFFSET + 1) * nb + p.a[j]];
      uz += p.w[j] * bend[(BOREAS_MESH_TREE_BEND_OFFSET + 2) * nb + p.a[j]];
    }
    float along = ux * d.normal.x + uy * d.normal.y + uz * d.normal.z;
    float lambda = fmax(along, 0.0f) / fmax(p.compliance, 1e-30f);
    if (lambda <= best->lambda) continue;
    best->lambda = lambda;
    best->px = p.x;
    best->py = p.y;
    best->pz = p.z;
    best->nx = d.normal.x;
    best->ny = d.normal.y;
    best->nz = d.normal.z;
  }
}

/* Adds what branch b pushes collider c with to out (force, torque, count). */
void boreas_mesh_tree_react(__global const float* contact, int b, __global const int* links, int nb,
                            const BoreasMeshTreeChain* chain, __global const float* bend,
                            __global const BoreasGpuCollider* c, __global float* out) {
  BoreasMeshTreePress press;
  boreas_mesh_tree_press(contact, b, links, nb, chain, bend, c, &press);
  if (press.lambda < 0.0f) return;
  float fx = -press.lambda * press.nx, fy = -press.lambda * press.ny, fz = -press.lambda * press.nz;
  float rx = press.px - (c->cx + c->dx), ry = press.py - (c->cy + c->dy),
        rz = press.pz - (c->cz + c->dz);
  out[0] += fx;
  out[1] += fy;
  out[2] += fz;
  out[3] += ry * fz - rz * fy;
  out[4] += rz * fx - rx * fz;
  out[5] += rx * fy - ry * fx;
  out[6] += 1.0f;
}

/* Pushes branch b out of collider c, segment by segment, taking its chain again after each
 * push; returns whether any segment touches it (lies within BOREAS_MESH_TREE_CONTACT_SLOP). */
int boreas_mesh_tree_push_out(__global const float* contact, int b, __global const float* branches,
                              __global const int* links, int nb, __global const float* state,
                              __global const float* trees, int nt, __global const float* noise,
                              __global float* bend, __global const BoreasGpuCollider* c, float dt,
                              BoreasMeshTreeChain* chain) {
  if (!boreas_mesh_tree_may_meet(chain, c)) return 0;
  int touched = 0;
  for (int k = 1; k <= BOREAS_MESH_TREE_CONTACT_SEGMENTS; ++k) {
    BoreasMeshTreeSample p;
    boreas_mesh_tree_nearest(contact, k, b, links, nb, chain, c, &p);
    BoreasColliderDistance d = boreas_mesh_tree_against(&p, c);
    touched |= d.distance <= BOREAS_MESH_TREE_CONTACT_SLOP;
    if (d.distance >= 0.0f) continue;
    boreas_mesh_tree_push(&p, contact, nb, bend, -d.distance, d.normal.x, d.normal.y, d.normal.z,
                          dt);
    boreas_mesh_tree_chain(contact, b, branches, links, nb, state, trees, nt, noise, bend, chain);
  }
  return touched;
}

/* Whether the tree's branches [first, first + count) have come to rest: every bend and its
 * rate below BOREAS_MESH_TREE_QUIET_BEND and _RATE. */
int boreas_mesh_tree_quiet(__global const float* bend, int nb, int first, int count) {
  float most = 0.0f, fastest = 0.0f;
  for (int j = first; j < first + count; ++j)
    for (int a = 0; a < 3; ++a) {
      most = fmax(most, fabs(bend[(BOREAS_MESH_TREE_BEND_OFFSET + a) * nb + j]));
      fastest = fmax(fastest, fabs(bend[(BOREAS_MESH_TREE_BEND_VELOCITY + a) * nb + j]));
    }
  return most < BOREAS_MESH_TREE_QUIET_BEND && fastest < BOREAS_MESH_TREE_QUIET_RATE;
}

__kernel void boreas_mesh_tree_contact(
    __global const float* contact, __global const float* branches, __global const int* links,
    int nb, __global const float* state, __global const float* trees, int nt,
    __global const float* noise, __global const float* bend_in, __global float* bend_out,
    __global const int* active, int active_count, __global const BoreasGpuCollider* colliders, __global float* pair_out, __global int* quiet_out,
    float dt) {
  int i = get_global_id(0);
  if (i >= active_count) return;
  int first = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 0];
  int count = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 1];
  int first_pair = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 2];
  int pair_count = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 3];
  if (active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 4] != 0) {
    for (int j = 0; j < count; ++j)
      for (int p = 0; p < BOREAS_MESH_TREE_BEND_FLOATS; ++p) bend_out[p * nb + first + j] = 0.0f;
    quiet_out[i] = 1;
    return;
  }
  for (int j = 0; j < count; ++j)
    boreas_mesh_tree_spring_back(contact, nb, first + j, bend_in, bend_out, dt);
  for (int q = first_pair; q < first_pair + pair_count; ++q)
    for (int f = 0; f < BOREAS_MESH_TREE_PAIR_FLOATS; ++f)
      pair_out[BOREAS_MESH_TREE_PAIR_FLOATS * q + f] = 0.0f;
  /* A pass that finds no branch touching any collider pushes nothing: the next would find
   * the same, and the reaction nothing to sum. */
  int touched = 0;
  for (int pass = 0; pass < BOREAS_MESH_TREE_CONTACT_PASSES && (pass == 0 || touched); ++pass)
    for (int j = 0; j < count && pair_count > 0; ++j) {
      BoreasMeshTreeChain chain;
      boreas_mesh_tree_chain(contact, first + j, branches, links, nb, state, trees, nt, noise,
                             bend_out, &chain);
      for (int q = first_pair; q < first_pair + pair_count; ++q)
        touched |= boreas_mesh_tree_push_out(contact, first + j, branches, links, nb, state, trees,
                                             nt, noise, bend_out, &colliders[q], dt, &chain);
    }
  quiet_out[i] = !touched && boreas_mesh_tree_quiet(bend_out, nb, first, count);
  /* The reaction once every push is done, branch by branch in order (the sums' order). */
  for (int j = 0; j < count && touched; ++j) {
    BoreasMeshTreeChain chain;
    boreas_mesh_tree_chain(contact, first + j, branches, links, nb, state, trees, nt, noise,
                           bend_out, &chain);
    for (int q = first_pair; q < first_pair + pair_count; ++q)
      boreas_mesh_tree_react(contact, first + j, links, nb, &chain, bend_out, &colliders[q],
                             pair_out + BOREAS_MESH_TREE_PAIR_FLOATS * q);
  }
}

/* The bends added to the vertices the vertex kernels (mesh_tree_vertices.cl) just wrote,
 * over one run of a batch's vertices [first, first + count) that belongs to trees in
 * contact: only those trees pay for it. Positions only: a bend moves a leaf, it does not
 * turn it. */
__kernel void boreas_mesh_tree_bend_trunk(__global const float* vertices,
                                          __global const int* vertex_branch, int nv, int first,
                                          int count, __global const int* links, int nb,
                                          __global const float* bend, __global float* out) {
  int g = get_global_id(0);
  if (g >= count) return;
  int i = first + g;
  float dx = 0.0f, dy = 0.0f, dz = 0.0f;
  boreas_mesh_tree_bend_offset(vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i],
                               vertex_branch[i], links, nb, bend, &dx, &dy, &dz);
  out[3 * i + 0] += dx;
  out[3 * i + 1] += dy;
  out[3 * i + 2] += dz;
}

__kernel void boreas_mesh_tree_bend_leaves(__global const int* vertex_leaf, int first, int count,
                                           __global const float* leaves,
                                           __global const int* leaf_branch, int nl,
                                           __global const int* links, int nb,
                                           __global const float* bend, __global float* out) {
  int g = get_global_id(0);
  if (g >= count) return;
  int i = first + g;
  int l = vertex_leaf[i];
  float dx = 0.0f, dy = 0.0f, dz = 0.0f;
  boreas_mesh_tree_bend_offset(leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 0) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 1) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 2) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 3) * nl + l], leaf_branch[l],
                               links, nb, bend, &dx, &dy, &dz);
  out[6 * i + 0] += dx;
  out[6 * i + 1] += dy;
  out[6 * i + 2] += dz;
}
