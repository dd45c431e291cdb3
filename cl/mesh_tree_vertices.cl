/* boreas: imported trees, per vertex (Kusternig sec. 5.2-5.3) — trunk vertices swayed by
 * their four levels' weights, and leaf vertices carried by their petiole's sway, turned
 * towards the wind and fluttered by the tree's rolling noise. Run after
 * mesh_tree_branches.cl on the state it wrote. The global sizes may exceed the counts;
 * extra work-items redo the last vertex. */
#include "shared/mesh_tree_math.h"

/* Trunk: positions out, 3 floats per vertex (boreas_mesh_tree_trunk_vertex). */
__kernel void boreas_mesh_tree_trunk(__global const float* vertices,
                                     __global const int* vertex_branch, int nv, int count,
                                     __global const float* branches, __global const int* links,
                                     int nb, __global const float* state,
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
  boreas_mesh_tree_trunk_vertex(vertices, nv, i, dx, dy, dz, out, i, 3, 1);
}

/* Leaves: position and normal out, 6 floats per vertex: carried by the petiole's sway,
 * turned towards the wind and fluttered (boreas_mesh_tree_leaf_turn,
 * boreas_mesh_tree_leaf_vertex). */
__kernel void boreas_mesh_tree_leaves(__global const float* vertices,
                                      __global const int* vertex_leaf, int nv, int count,
                                      __global const float* leaves, __global const int* leaf_branch,
                                      int nl, __global const float* branches,
                                      __global const int* links, int nb,
                                      __global const float* state, __global const float* trees,
                                      int nt, __global const float* roll,
                                      __global const float* noise, __global float* out) {
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
  BoreasMeshTreeTurn turn;
  boreas_mesh_tree_leaf_turn(state, nb, b, leaves, nl, l, trees, nt, t, &turn);
  boreas_mesh_tree_leaf_vertex(&turn, dx, dy, dz, vertices, nv, i, leaves, nl, l, trees, nt, t,
                               roll, noise, out, i, 6, 1);
}
