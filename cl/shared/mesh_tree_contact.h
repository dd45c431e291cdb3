/* boreas: colliders against imported trees (mesh_tree_contact.cl), through their branch
 * hierarchy, for mesh_tree_contact.cl (OpenCL C, width 1; the host reads the layouts in
 * mesh_tree_contact_types.h).
 *
 * The model. An imported tree's vertices move by weights w_k (already raised to the bend
 * exponent) of the branches animating its four levels (mesh_tree_math.h). A collider adds
 * one more such term: every branch a that animates a level carries a contact bend O_a (m at
 * weight 1, world), so a point with weights w_k on a branch animated by a_k moves by
 * sum_k w_k O_{a_k} besides the wind. O_a is a damped spring: stiffness k_a at weight 1,
 * the level's frequency (boreas_mesh_level_def.frequency) and a damping ratio, so a bent
 * branch springs back, damped, at its own frequency once the collider has gone.
 *
 * The stiffness. A branch is a cantilever (Euler-Bernoulli): its tip takes
 * k_tip = 3 E I / L^3, I = pi r^4 / 4, with r its thickest radius, L its length and E
 * green wood's modulus (7 GPa, the species' default in trees/species.h). Its tip moves by
 * w_tip O_a, so k_a = k_tip w_tip^2 gives the tip that stiffness in this model.
 *
 * The push. Each branch is a chain of cones along its skeleton (BOREAS_MESH_TREE_CONTACT_
 * SEGMENTS of them, radii holding the branch's vertices). On each, the point nearest the
 * collider; inside it by depth delta (along the collider's outward normal n), it is moved
 * out by the least-energy change of the O of the branches that move it:
 * O_{a_k} += w_k c_k delta n / sum_j w_j^2 c_j (c = 1 / k), so the
 * branch itself and its parent, grandparent and stem share the push by their compliance —
 * a twig gives way, the stem hardly — and the load passes to the parents as the wind's
 * does. The velocities take the change over dt (position-based dynamics: a branch leaves
 * a moving collider at its speed). A branch bends at most so far that its tip moves half
 * its length: past that a kinematic collider (which nothing stops) passes through it. The
 * segments of a tree are pushed in branch order (parents first), twice
 * (BOREAS_MESH_TREE_CONTACT_PASSES); a branch whose sphere cannot meet a collider skips its
 * segments, and a pass that finds nothing touching ends the solve.
 *
 * The reaction. A branch in contact (a segment within BOREAS_MESH_TREE_CONTACT_SLOP of the
 * collider after the push) pushes the collider back with lambda = k_p max(n . u, 0) along
 * -n at its hardest-pressed segment point, where u = sum_k w_k O_{a_k} is the contact bend
 * there and k_p = 1 / sum_j w_j^2 c_j the point's stiffness: the bent branches' spring at
 * that point, quasi-static (their inertia and damping are neglected). */
#ifndef BOREAS_CL_SHARED_MESH_TREE_CONTACT_H
#define BOREAS_CL_SHARED_MESH_TREE_CONTACT_H

#include "shared/collider_math.h"
#include "shared/mesh_tree_contact_types.h"
#include "shared/mesh_tree_math.h"

/* The contact bend sum_k w_k O_{a_k} of a point with weights w0..w3 on branch b, added to
 * (dx, dy, dz): for the branches' points and the bend kernels' vertices. */
BOREAS_FN void boreas_mesh_tree_bend_offset(float w0, float w1, float w2, float w3, int b,
                                            BOREAS_GLOBAL const int* links, int nb,
                                            BOREAS_GLOBAL const float* bend, float* dx, float* dy,
                                            float* dz) {
  /* Written out, not looped, as boreas_mesh_tree_displacement: one work-item a vertex. */
  int a0 = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 0) * nb + b];
  int a1 = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 1) * nb + b];
  int a2 = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 2) * nb + b];
  int a3 = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 3) * nb + b];
  BOREAS_GLOBAL const float* o = bend + BOREAS_MESH_TREE_BEND_OFFSET * nb;
  *dx += w0 * o[a0] + w1 * o[a1] + w2 * o[a2] + w3 * o[a3];
  o += nb;
  *dy += w0 * o[a0] + w1 * o[a1] + w2 * o[a2] + w3 * o[a3];
  o += nb;
  *dz += w0 * o[a0] + w1 * o[a1] + w2 * o[a2] + w3 * o[a3];
}

/* Branch b's bend after a free step of dt s (backward Euler of the damped spring: stable
 * at any dt), from bend_in into bend_out. */
BOREAS_FN void boreas_mesh_tree_spring_back(BOREAS_GLOBAL const float* contact, int nb, int b,
                                            BOREAS_GLOBAL const float* bend_in,
                                            BOREAS_GLOBAL float* bend_out, float dt) {
  float omega = contact[BOREAS_MESH_TREE_CONTACT_OMEGA * nb + b];
  float k = omega * omega * dt;
  float d = 1.0f / (1.0f + 2.0f * BOREAS_MESH_TREE_CONTACT_DAMPING * omega * dt + k * dt);
  for (int a = 0; a < 3; ++a) {
    float o = bend_in[(BOREAS_MESH_TREE_BEND_OFFSET + a) * nb + b];
    float v = (bend_in[(BOREAS_MESH_TREE_BEND_VELOCITY + a) * nb + b] - k * o) * d;
    bend_out[(BOREAS_MESH_TREE_BEND_OFFSET + a) * nb + b] = o + dt * v;
    bend_out[(BOREAS_MESH_TREE_BEND_VELOCITY + a) * nb + b] = v;
  }
}

/* The point a share t along segment k (1..S) of branch b as it stands now (rest, the
 * wind's sway, the contact bend: all linear in the weights, so the point between two is
 * theirs interpolated), with its weights, the branches animating it, its radius, and
 * sum_j w_j^2 c_j. */
typedef struct BoreasMeshTreeSample {
  float x, y, z;
  float w[4];
  int a[4];
  float radius;     /* m */
  float compliance; /* sum_j w_j^2 c_j, m/N */
} BoreasMeshTreeSample;

/* Point k (0..S) of branch b, displaced: into (x, y, z). */
BOREAS_FN void boreas_mesh_tree_contact_point(
    BOREAS_GLOBAL const float* contact, int k, int b, BOREAS_GLOBAL const float* branches,
    BOREAS_GLOBAL const int* links, int nb, BOREAS_GLOBAL const float* state,
    BOREAS_GLOBAL const float* trees, int nt, BOREAS_GLOBAL const float* noise,
    BOREAS_GLOBAL const float* bend, float* x, float* y, float* z) {
  float w0 = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + 0) * nb + b];
  float w1 = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + 1) * nb + b];
  float w2 = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + 2) * nb + b];
  float w3 = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + 3) * nb + b];
  float dx, dy, dz;
  boreas_mesh_tree_displacement(w0, w1, w2, w3, b, branches, links, nb, state, trees, nt, noise,
                                &dx, &dy, &dz);
  boreas_mesh_tree_bend_offset(w0, w1, w2, w3, b, links, nb, bend, &dx, &dy, &dz);
  *x = contact[(BOREAS_MESH_TREE_CONTACT_POINT + 3 * k + 0) * nb + b] + dx;
  *y = contact[(BOREAS_MESH_TREE_CONTACT_POINT + 3 * k + 1) * nb + b] + dy;
  *z = contact[(BOREAS_MESH_TREE_CONTACT_POINT + 3 * k + 2) * nb + b] + dz;
}

/* A branch's points as it stands now (boreas_mesh_tree_contact_point), and the sphere
 * around them and their radii. */
typedef struct BoreasMeshTreeChain {
  float x[BOREAS_MESH_TREE_CONTACT_POINTS], y[BOREAS_MESH_TREE_CONTACT_POINTS],
      z[BOREAS_MESH_TREE_CONTACT_POINTS];
  float cx, cy, cz, reach; /* m: everything of the branch lies within reach of c */
} BoreasMeshTreeChain;

BOREAS_FN void boreas_mesh_tree_chain(BOREAS_GLOBAL const float* contact, int b,
                                      BOREAS_GLOBAL const float* branches,
                                      BOREAS_GLOBAL const int* links, int nb,
                                      BOREAS_GLOBAL const float* state,
                                      BOREAS_GLOBAL const float* trees, int nt,
                                      BOREAS_GLOBAL const float* noise,
                                      BOREAS_GLOBAL const float* bend, BoreasMeshTreeChain* chain) {
  for (int k = 0; k < BOREAS_MESH_TREE_CONTACT_POINTS; ++k)
    boreas_mesh_tree_contact_point(contact, k, b, branches, links, nb, state, trees, nt, noise,
                                   bend, &chain->x[k], &chain->y[k], &chain->z[k]);
  const int last = BOREAS_MESH_TREE_CONTACT_POINTS - 1;
  chain->cx = 0.5f * (chain->x[0] + chain->x[last]);
  chain->cy = 0.5f * (chain->y[0] + chain->y[last]);
  chain->cz = 0.5f * (chain->z[0] + chain->z[last]);
  float reach = 0.0f;
  for (int k = 0; k < BOREAS_MESH_TREE_CONTACT_POINTS; ++k) {
    float dx = chain->x[k] - chain->cx, dy = chain->y[k] - chain->cy, dz = chain->z[k] - chain->cz;
    reach = BOREAS_FMAX(reach, BOREAS_SQRT(dx * dx + dy * dy + dz * dz) +
                                   contact[(BOREAS_MESH_TREE_CONTACT_RADIUS + k) * nb + b]);
  }
  chain->reach = reach;
}

/* Whether the branch may meet collider c this step: its sphere against the sphere holding
 * everything c sweeps (about its mid-step position). A cheap reject before the segments. */
BOREAS_FN int boreas_mesh_tree_may_meet(const BoreasMeshTreeChain* chain,
                                        BOREAS_GLOBAL const BoreasGpuCollider* c) {
  float mx = c->cx + 0.5f * c->dx - chain->cx, my = c->cy + 0.5f * c->dy - chain->cy,
        mz = c->cz + 0.5f * c->dz - chain->cz;
  float sweep = 0.5f * BOREAS_SQRT(c->dx * c->dx + c->dy * c->dy + c->dz * c->dz);
  float size = BOREAS_SQRT(c->hx * c->hx + c->hy * c->hy + c->hz * c->hz) + c->radius;
  float reach = chain->reach + sweep + size;
  return mx * mx + my * my + mz * mz <= reach * reach;
}

/* The point of segment k (1..S) of branch b nearest collider c's position at mid-step (the
 * segment's point that meets it first for a sphere; for a capsule or box, the one at its
 * middle across the branch), from the branch's points. */
BOREAS_FN void boreas_mesh_tree_nearest(BOREAS_GLOBAL const float* contact, int k, int b,
                                        BOREAS_GLOBAL const int* links, int nb,
                                        const BoreasMeshTreeChain* chain,
                                        BOREAS_GLOBAL const BoreasGpuCollider* c,
                                        BoreasMeshTreeSample* p) {
  float ax = chain->x[k - 1], ay = chain->y[k - 1], az = chain->z[k - 1];
  float ex = chain->x[k] - ax, ey = chain->y[k] - ay, ez = chain->z[k] - az;
  float mx = c->cx + 0.5f * c->dx - ax, my = c->cy + 0.5f * c->dy - ay,
        mz = c->cz + 0.5f * c->dz - az;
  float t = (mx * ex + my * ey + mz * ez) / (ex * ex + ey * ey + ez * ez + 1e-20f);
  t = BOREAS_CLAMP(t, 0.0f, 1.0f);
  p->x = ax + t * ex;
  p->y = ay + t * ey;
  p->z = az + t * ez;
  float c2 = 0.0f;
  for (int j = 0; j < 4; ++j) {
    float w_a = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * (k - 1) + j) * nb + b];
    float w_b = contact[(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + j) * nb + b];
    p->w[j] = w_a + t * (w_b - w_a);
    p->a[j] = links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + j) * nb + b];
    c2 += p->w[j] * p->w[j] * contact[BOREAS_MESH_TREE_CONTACT_COMPLIANCE * nb + p->a[j]];
  }
  float r_a = contact[(BOREAS_MESH_TREE_CONTACT_RADIUS + k - 1) * nb + b];
  float r_b = contact[(BOREAS_MESH_TREE_CONTACT_RADIUS + k) * nb + b];
  p->radius = r_a + t * (r_b - r_a);
  p->compliance = c2;
}

/* Moves point p out of a collider by depth along n: the bends of its animating branches
 * change by the least-energy share (above), each kept within its limit (a branch bends at
 * most so far; a kinematic collider pushing on passes through it), their velocities by
 * the change over dt. */
BOREAS_FN void boreas_mesh_tree_push(const BoreasMeshTreeSample* p,
                                     BOREAS_GLOBAL const float* contact, int nb,
                                     BOREAS_GLOBAL float* bend, float depth, float nx, float ny,
                                     float nz, float dt) {
  float share = depth / BOREAS_FMAX(p->compliance, 1e-30f);
  for (int k = 0; k < 4; ++k) {
    /* Levels below the branch's own repeat it with weight 0: no share. */
    int a = p->a[k];
    float f = share * p->w[k] * contact[BOREAS_MESH_TREE_CONTACT_COMPLIANCE * nb + a];
    BOREAS_GLOBAL float* o = bend + BOREAS_MESH_TREE_BEND_OFFSET * nb + a;
    BOREAS_GLOBAL float* v = bend + BOREAS_MESH_TREE_BEND_VELOCITY * nb + a;
    float ox = o[0] + f * nx, oy = o[nb] + f * ny, oz = o[2 * nb] + f * nz;
    float limit = contact[BOREAS_MESH_TREE_CONTACT_LIMIT * nb + a];
    float size = BOREAS_SQRT(ox * ox + oy * oy + oz * oz);
    float keep = size > limit ? limit / size : 1.0f;
    ox *= keep;
    oy *= keep;
    oz *= keep;
    v[0] += (ox - o[0]) / dt;
    v[nb] += (oy - o[nb]) / dt;
    v[2 * nb] += (oz - o[2 * nb]) / dt;
    o[0] = ox;
    o[nb] = oy;
    o[2 * nb] = oz;
  }
}

/* Point p against collider c: the signed distance from the tube's surface there. */
BOREAS_FN BoreasColliderDistance
boreas_mesh_tree_against(const BoreasMeshTreeSample* p, BOREAS_GLOBAL const BoreasGpuCollider* c) {
  BoreasColliderDistance d = boreas_collider_distance(boreas_v3(p->x, p->y, p->z), c);
  d.distance -= p->radius;
  return d;
}

#endif
