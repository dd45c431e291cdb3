/* boreas: imported trees, per vertex (Kusternig sec. 5.2-5.3) — trunk vertices swayed by
 * their four levels' weights, and leaf vertices carried by their petiole's sway, turned
 * towards the wind and fluttered by the tree's rolling noise. Run after
 * mesh_tree_branches.cl on the state it wrote. The global sizes may exceed the counts;
 * extra work-items redo the last vertex. */
#include "shared/mesh_tree_math.h"

/* Trunk: positions out, 3 floats per vertex (the normals stay the rest normals: the sway
 * is smooth along a branch, and re-deriving normals would need the neighbours). */
__kernel void boreas_mesh_tree_trunk(__global const float* vertices, __global const int* vertex_branch,
                                     int nv, int count, __global const float* branches,
                                     __global const int* links, int nb, __global const float* state,
                                     __global const float* trees, int nt,
                                     __global const float* noise, __global float* out) {
  int i = min((int)get_global_id(0), count - 1);
  float dx, dy, dz;
  boreas_mesh_tree_displacement(vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i],
                                vertex_branch[i], branches, links, nb, state, trees, nt, noise, &dx,
                                &dy, &dz);
  out[3 * i + 0] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 0) * nv + i] + dx;
  out[3 * i + 1] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 1) * nv + i] + dy;
  out[3 * i + 2] = vertices[(BOREAS_MESH_TREE_TRUNK_REST + 2) * nv + i] + dz;
}

/* Leaves: position and normal out, 6 floats per vertex. The leaf turns rigidly about its
 * petiole by the rotation taking its axis a to a' = normalize((1 - f) a + f W/|W|), with
 * f = turn * L / (1 + L) (a fraction of the way into the wind that grows with the load
 * and never reaches it); R v = c v + k x v + k (k.v) / (1 + c), k = a x a', c = a.a'
 * (Rodrigues without the angle: no trigonometry). Its vertices then move by the rolling
 * noise in the wind direction and up, scaled by their distance from the petiole, so
 * gusts run through the crown as the noise moves downwind. */
__kernel void boreas_mesh_tree_leaves(__global const float* vertices, __global const int* vertex_leaf,
                                      int nv, int count, __global const float* leaves,
                                      __global const int* leaf_branch, int nl,
                                      __global const float* branches, __global const int* links,
                                      int nb, __global const float* state,
                                      __global const float* trees, int nt,
                                      __global const float* roll, __global const float* noise,
                                      __global float* out) {
  int i = min((int)get_global_id(0), count - 1);
  int l = vertex_leaf[i];
  int b = leaf_branch[l];
  int t = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  float dx, dy, dz;
  boreas_mesh_tree_displacement(leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 0) * nl + l],
                                leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 1) * nl + l],
                                leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 2) * nl + l],
                                leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 3) * nl + l], b, branches,
                                links, nb, state, trees, nt, noise, &dx, &dy, &dz);

  float wx = state[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b];
  float wy = state[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b];
  float wz = state[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b];
  float s2 = wx * wx + wy * wy + wz * wz;
  float load = boreas_mesh_tree_load(s2);
  float inv_s = rsqrt(s2 + 1e-12f);
  float ux = wx * inv_s, uy = wy * inv_s, uz = wz * inv_s;

  float ax = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 0) * nl + l];
  float ay = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 1) * nl + l];
  float az = leaves[(BOREAS_MESH_TREE_LEAF_AXIS + 2) * nl + l];
  float f = trees[BOREAS_MESH_TREE_TREE_TURN * nt + t] * load / (1.0f + load);
  float px = fma(f, ux - ax, ax), py = fma(f, uy - ay, ay), pz = fma(f, uz - az, az);
  float inv_p = rsqrt(px * px + py * py + pz * pz + 1e-12f);
  px *= inv_p;
  py *= inv_p;
  pz *= inv_p;
  float kx = ay * pz - az * py, ky = az * px - ax * pz, kz = ax * py - ay * px;
  float c = ax * px + ay * py + az * pz;
  /* In calm f is 0 and the rotation exactly the identity (a' = a up to rounding). */
  int still = f == 0.0f;
  kx = still ? 0.0f : kx;
  ky = still ? 0.0f : ky;
  kz = still ? 0.0f : kz;
  c = still ? 1.0f : c;
  float h = 1.0f / fmax(1.0f + c, 1e-4f);

  float petx = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 0) * nl + l];
  float pety = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 1) * nl + l];
  float petz = leaves[(BOREAS_MESH_TREE_LEAF_PETIOLE + 2) * nl + l];
  float rx = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 0) * nv + i];
  float ry = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 1) * nv + i];
  float rz = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_REST + 2) * nv + i];
  float ox = rx - petx, oy = ry - pety, oz = rz - petz;
  /* R o - o, added to the rest position (not R o to the petiole): in calm it is exactly
   * 0, so a leaf at rest stays bit for bit where it was. */
  float ko = kx * ox + ky * oy + kz * oz;
  float cm1 = c - 1.0f;
  float qx = cm1 * ox + (ky * oz - kz * oy) + kx * ko * h;
  float qy = cm1 * oy + (kz * ox - kx * oz) + ky * ko * h;
  float qz = cm1 * oz + (kx * oy - ky * ox) + kz * ko * h;
  float nx = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 0) * nv + i];
  float ny = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 1) * nv + i];
  float nz = vertices[(BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL + 2) * nv + i];
  float kn = kx * nx + ky * ny + kz * nz;
  float mx = c * nx + (ky * nz - kz * ny) + kx * kn * h;
  float my = c * ny + (kz * nx - kx * nz) + ky * kn * h;
  float mz = c * nz + (kx * ny - ky * nx) + kz * kn * h;

  float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + t];
  float n0, n1;
  boreas_mesh_tree_noise(
      noise + (size_t)t * 2 * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE,
      rx * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 0) * nt + t],
      rz * inv_tile - roll[(BOREAS_MESH_TREE_ROLL + 1) * nt + t], &n0, &n1);
  float flutter = trees[BOREAS_MESH_TREE_TREE_FLUTTER * nt + t] * load *
                  vertices[BOREAS_MESH_TREE_LEAF_VERTEX_TIP * nv + i];
  out[6 * i + 0] = rx + (dx + qx + flutter * n0 * ux);
  out[6 * i + 1] = ry + (dy + qy + flutter * (n0 * uy + n1));
  out[6 * i + 2] = rz + (dz + qz + flutter * n0 * uz);
  out[6 * i + 3] = mx;
  out[6 * i + 4] = my;
  out[6 * i + 5] = mz;
}
