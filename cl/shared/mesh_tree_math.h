/* boreas: the per-vertex sway of imported trees (Kusternig sec. 5.2), for the vertex
 * kernels. OpenCL C only; the double-precision twin is host/src/reference/
 * mesh_tree_reference.cpp. Scalar floats and no transcendental builtins, so that PoCL
 * vectorizes the work-item loop (shared/notes: pocl-performance).
 *
 * A vertex with weights w_k (already raised to the bend exponent) moves by
 *   sum_k w_k * L(W_k) * ( bend_k * W_k,perp / |W_k| + sway_k * (n0 * right_k + n1 * up_k) )
 * where branch k is the one animating level k, W_k the wind it feels, W_k,perp its part
 * normal to the branch, (n0, n1) the two noise channels at the branch's phase moved along
 * by its level's clock, and L the load: q / (1 + q / ceiling), q = |W|^2 / (10 m/s)^2 —
 * drag grows with the square of the speed and is capped, since displacing vertices
 * (rather than rotating branches) stretches limbs without bound. */
#ifndef BOREAS_CL_SHARED_MESH_TREE_MATH_H
#define BOREAS_CL_SHARED_MESH_TREE_MATH_H

#include "shared/mesh_tree_types.h"
#include "shared/simd_width.h"

/* The squared-speed load, 0 in calm. */
BOREAS_FN float boreas_mesh_tree_load(float s2) {
  float q = s2 * (1.0f / (BOREAS_MESH_TREE_REFERENCE_SPEED * BOREAS_MESH_TREE_REFERENCE_SPEED));
  return q / (1.0f + q * (1.0f / BOREAS_MESH_TREE_LOAD_CEILING));
}

/* Bilinear lookup with wrap-around in one tree's noise (both channels), u and v in tiles;
 * texel i covers [i, i+1) / size and holds the value at its center (noise_texture.h). */
BOREAS_FN void boreas_mesh_tree_noise(__global const float* noise, float u, float v, float* n0,
                                      float* n1) {
  const int size = BOREAS_MESH_TREE_NOISE_SIZE;
  float x = (u - floor(u)) * (float)size - 0.5f;
  float y = (v - floor(v)) * (float)size - 0.5f;
  float x0 = floor(x);
  float y0 = floor(y);
  float fx = x - x0;
  float fy = y - y0;
  int i0 = ((int)x0) & (size - 1);
  int j0 = ((int)y0) & (size - 1);
  int i1 = (i0 + 1) & (size - 1);
  int j1 = (j0 + 1) & (size - 1);
  int a = j0 * size + i0, b = j0 * size + i1, c = j1 * size + i0, d = j1 * size + i1;
  float w00 = (1.0f - fx) * (1.0f - fy), w10 = fx * (1.0f - fy), w01 = (1.0f - fx) * fy, w11 = fx * fy;
  __global const float* second = noise + size * size;
  *n0 = w00 * noise[a] + w10 * noise[b] + w01 * noise[c] + w11 * noise[d];
  *n1 = w00 * second[a] + w10 * second[b] + w01 * second[c] + w11 * second[d];
}

/* One level's term for a vertex of weight w animated by branch a of tree t. */
BOREAS_FN void boreas_mesh_tree_level(int k, float w, int a, int t, __global const float* branches,
                                      int nb, __global const float* state,
                                      __global const float* trees, int nt,
                                      __global const float* noise, float* dx, float* dy,
                                      float* dz) {
  float wx = state[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + a];
  float wy = state[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + a];
  float wz = state[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + a];
  float ax = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 0) * nb + a];
  float ay = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 1) * nb + a];
  float az = branches[(BOREAS_MESH_TREE_BRANCH_AXIS + 2) * nb + a];
  float s2 = wx * wx + wy * wy + wz * wz;
  float load = w * boreas_mesh_tree_load(s2);
  float along = wx * ax + wy * ay + wz * az;
  float bend = load * trees[(BOREAS_MESH_TREE_TREE_BEND + k) * nt + t] * rsqrt(s2 + 1e-12f);
  float sway = load * trees[(BOREAS_MESH_TREE_TREE_SWAY + k) * nt + t];
  float n0, n1;
  boreas_mesh_tree_noise(
      noise + (size_t)t * 2 * BOREAS_MESH_TREE_NOISE_SIZE * BOREAS_MESH_TREE_NOISE_SIZE,
      branches[BOREAS_MESH_TREE_BRANCH_PHASE * nb + a] +
          trees[(BOREAS_MESH_TREE_TREE_CLOCK + k) * nt + t],
      branches[(BOREAS_MESH_TREE_BRANCH_PHASE + 1) * nb + a], &n0, &n1);
  float r = sway * n0, u = sway * n1;
  *dx += bend * (wx - along * ax) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 0) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 0) * nb + a];
  *dy += bend * (wy - along * ay) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 1) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 1) * nb + a];
  *dz += bend * (wz - along * az) + r * branches[(BOREAS_MESH_TREE_BRANCH_RIGHT + 2) * nb + a] +
         u * branches[(BOREAS_MESH_TREE_BRANCH_UP + 2) * nb + a];
}

/* The displacement of a point with weights w[0..3] on branch b (all four levels). */
BOREAS_FN void boreas_mesh_tree_displacement(
    float w0, float w1, float w2, float w3, int b, __global const float* branches,
    __global const int* links, int nb, __global const float* state, __global const float* trees,
    int nt, __global const float* noise, float* dx, float* dy, float* dz) {
  int t = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  *dx = 0.0f;
  *dy = 0.0f;
  *dz = 0.0f;
  boreas_mesh_tree_level(0, w0, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 0) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(1, w1, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 1) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(2, w2, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 2) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
  boreas_mesh_tree_level(3, w3, links[(BOREAS_MESH_TREE_BRANCH_ANIMATED_BY + 3) * nb + b], t,
                         branches, nb, state, trees, nt, noise, dx, dy, dz);
}

#endif
