/* boreas: imported trees, per branch — the wind at the branch's middle, relative to the
 * branch's own motion, low-passed with its level's response time (a trunk answers a gust
 * slower than a twig; the air's drag on the moving branch lengthens it), and each stem
 * rolls its tree's leaf noise downwind (Kusternig sec. 5.3). One work-item per branch;
 * reads state_in, writes state_out (the host swaps them when the step commits). The
 * global size may exceed count; extra work-items redo the last branch. */
#include "shared/mesh_tree_math.h"
#include "shared/wind_sample.h"

__kernel void boreas_mesh_tree_branches(__global const float* branches, __global const int* links,
                                        int nb, int count, __global const float* state_in,
                                        __global float* state_out, __global const float* trees,
                                        int nt, __global const float* roll_in,
                                        __global float* roll_out, float dt,
                                        __global const BoreasGpuWave* waves, int wave_count,
                                        __global const float* wave_phases,
                                        __global const float* grid, BoreasGpuGrid g) {
  int b = min((int)get_global_id(0), count - 1);
  int t = links[BOREAS_MESH_TREE_BRANCH_TREE * nb + b];
  /* The branch's center is its tree's (mesh_tree_types.h, TREE_ORIGIN); the waves' phases
   * at the tree's origin are row t of wave_phases. */
  float wx, wy, wz;
  boreas_wind_sample_local(trees[(BOREAS_MESH_TREE_TREE_ORIGIN + 0) * nt + t],
                           trees[(BOREAS_MESH_TREE_TREE_ORIGIN + 1) * nt + t],
                           trees[(BOREAS_MESH_TREE_TREE_ORIGIN + 2) * nt + t],
                           branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 0) * nb + b],
                           branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 1) * nb + b],
                           branches[(BOREAS_MESH_TREE_BRANCH_CENTER + 2) * nb + b], waves, wave_count,
                           wave_phases + t * wave_count, grid, g, &wx, &wy, &wz);
  float sx, sy, sz;
  boreas_mesh_tree_follow(branches, links, nb, b, trees, nt, t, state_in, state_out, dt, wx, wy, wz,
                          &sx, &sy, &sz);
  if (links[BOREAS_MESH_TREE_BRANCH_IS_STEM * nb + b] != 0)
    boreas_mesh_tree_roll(trees, nt, t, roll_in, roll_out, sx, sz, dt);
}
