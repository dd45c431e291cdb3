/* boreas: colliders against imported trees (shared/mesh_tree_contact.h says the model). One
 * work-item per tree that a collider's swept bounds meet this step, or that one met
 * recently and is still springing back; it runs over its own branches in order (parents
 * first), so the loads it passes to the parents need no atomics and sum in one order.
 * Not a hot kernel: the host launches it for those trees only. Run after
 * mesh_tree_branches.cl (it reads the wind the step just wrote) and before the vertices. */
#include "shared/mesh_tree_contact.h"

/* The hardest-pressed segment point of branch b against collider c: lambda (N) at point
 * p with collider normal n, or lambda < 0 when no segment touches. */
typedef struct BoreasMeshTreePress {
  float lambda;
  float px, py, pz, nx, ny, nz;
} BoreasMeshTreePress;

void boreas_mesh_tree_press(__global const float* contact, int b, __global const float* branches,
                            __global const int* links, int nb, __global const float* state,
                            __global const float* trees, int nt, __global const float* noise,
                            __global const float* bend, __global const BoreasGpuCollider* c,
                            BoreasMeshTreePress* best) {
  best->lambda = -1.0f;
  for (int k = 1; k <= BOREAS_MESH_TREE_CONTACT_SEGMENTS; ++k) {
    BoreasMeshTreeSample p;
    boreas_mesh_tree_nearest(contact, k, b, branches, links, nb, state, trees, nt, noise, bend, c,
                             &p);
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

/* What the tree's branches push collider c (pair q) with, into pair_out. */
void boreas_mesh_tree_reaction(__global const float* contact, int first, int count,
                               __global const float* branches, __global const int* links, int nb,
                               __global const float* state, __global const float* trees, int nt,
                               __global const float* noise, __global const float* bend,
                               __global const BoreasGpuCollider* c, __global float* out) {
  float f[3] = {0.0f, 0.0f, 0.0f}, torque[3] = {0.0f, 0.0f, 0.0f}, touching = 0.0f;
  float ex = c->cx + c->dx, ey = c->cy + c->dy, ez = c->cz + c->dz;
  for (int j = 0; j < count; ++j) {
    BoreasMeshTreePress press;
    boreas_mesh_tree_press(contact, first + j, branches, links, nb, state, trees, nt, noise, bend,
                           c, &press);
    if (press.lambda < 0.0f) continue;
    float fx = -press.lambda * press.nx, fy = -press.lambda * press.ny,
          fz = -press.lambda * press.nz;
    float rx = press.px - ex, ry = press.py - ey, rz = press.pz - ez;
    f[0] += fx;
    f[1] += fy;
    f[2] += fz;
    torque[0] += ry * fz - rz * fy;
    torque[1] += rz * fx - rx * fz;
    torque[2] += rx * fy - ry * fx;
    touching += 1.0f;
  }
  for (int a = 0; a < 3; ++a) {
    out[a] = f[a];
    out[3 + a] = torque[a];
  }
  out[6] = touching;
}

__kernel void boreas_mesh_tree_contact(
    __global const float* contact, __global const float* branches, __global const int* links,
    int nb, __global const float* state, __global const float* trees, int nt,
    __global const float* noise, __global const float* bend_in, __global float* bend_out,
    __global const int* active, int active_count, __global const int* pairs,
    __global const BoreasGpuCollider* colliders, __global float* pair_out, float dt) {
  int i = get_global_id(0);
  if (i >= active_count) return;
  int first = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 0];
  int count = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 1];
  int first_pair = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 2];
  int pair_count = active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 3];
  if (active[BOREAS_MESH_TREE_ACTIVE_INTS * i + 4] != 0) {
    for (int j = 0; j < count; ++j)
      for (int p = 0; p < BOREAS_MESH_TREE_BEND_FLOATS; ++p) bend_out[p * nb + first + j] = 0.0f;
    return;
  }
  for (int j = 0; j < count; ++j)
    boreas_mesh_tree_spring_back(contact, nb, first + j, bend_in, bend_out, dt);
  for (int pass = 0; pass < BOREAS_MESH_TREE_CONTACT_PASSES; ++pass)
    for (int j = 0; j < count; ++j)
      for (int k = 1; k <= BOREAS_MESH_TREE_CONTACT_SEGMENTS; ++k)
        for (int q = first_pair; q < first_pair + pair_count; ++q) {
          __global const BoreasGpuCollider* c = &colliders[pairs[q]];
          BoreasMeshTreeSample p;
          boreas_mesh_tree_nearest(contact, k, first + j, branches, links, nb, state, trees, nt,
                                   noise, bend_out, c, &p);
          BoreasColliderDistance d = boreas_mesh_tree_against(&p, c);
          if (d.distance < 0.0f)
            boreas_mesh_tree_push(&p, contact, nb, bend_out, -d.distance, d.normal.x, d.normal.y,
                                  d.normal.z, dt);
        }
  for (int q = first_pair; q < first_pair + pair_count; ++q)
    boreas_mesh_tree_reaction(contact, first, count, branches, links, nb, state, trees, nt, noise,
                              bend_out, &colliders[pairs[q]],
                              pair_out + BOREAS_MESH_TREE_PAIR_FLOATS * q);
}
