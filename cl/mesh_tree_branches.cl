/* boreas: imported trees, per branch — the wind at the branch's middle, low-passed with
 * its level's response time (a trunk answers a gust slower than a twig), and each stem
 * rolls its tree's leaf noise downwind (Kusternig sec. 5.3). One work-item per branch;
 * reads state_in, writes state_out (the host swaps them when the step commits). The
 * global size may exceed count; extra work-items redo the last branch. */
#include "shared/mesh_tree_types.h"
#include "shared/wind_sample.h"

__kernel void boreas_mesh_tree_branches(__global const float* branches, __global const int* links,
                                        int nb, int count, __global const float* state_in,
                                        __global float* state_out, __global const float* trees,
                                        int nt, __global const float* roll_in,
                                        __global float* roll_out, float dt,
                                        __global const BoreasGpuWave* waves, int wave_count,
                                        __global const float* grid, BoreasGpuGrid g) {
  int b = min((int)get_global_id(0), count - 1);
  float wx, wy, wz;
  boreas_wind_sample(branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 0) * nb + b],
                     branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 1) * nb + b],
                     branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 2) * nb + b], waves, wave_count, grid, g,
                     &wx, &wy, &wz);
  int t = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  /* Backward Euler of dW/dt = (wind - W) / tau: stable for any dt, no exp. A tree's
   * first step starts at the wind, so a tree placed in a steady wind does not swing. */
  float k = dt / (branches[BOREAS_MESH_TREE_BRANCH_TAU * nb + b] + dt);
  k = trees[BOREAS_MESH_TREE_TREE_FRESH * nt + t] != 0.0f ? 1.0f : k;
  float sx = state_in[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b];
  float sy = state_in[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b];
  float sz = state_in[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b];
  sx = fma(k, wx - sx, sx);
  sy = fma(k, wy - sy, sy);
  sz = fma(k, wz - sz, sz);
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 0) * nb + b] = sx;
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 1) * nb + b] = sy;
  state_out[(BOREAS_MESH_TREE_STATE_WIND + 2) * nb + b] = sz;
  /* The stem moves the leaf noise by its wind * dt (frozen turbulence carried downwind),
   * kept in one tile so the float keeps its precision. */
  if (links[BOREAS_MESH_TREE_BRANCH_IS_STEM * nb + b] != 0) {
    float inv_tile = trees[BOREAS_MESH_TREE_TREE_INV_TILE * nt + t];
    float u = roll_in[(BOREAS_MESH_TREE_ROLL + 0) * nt + t] + sx * dt * inv_tile;
    float v = roll_in[(BOREAS_MESH_TREE_ROLL + 1) * nt + t] + sz * dt * inv_tile;
    roll_out[(BOREAS_MESH_TREE_ROLL + 0) * nt + t] = u - floor(u);
    roll_out[(BOREAS_MESH_TREE_ROLL + 1) * nt + t] = v - floor(v);
  }
}
