/* boreas: imported trees, per vertex (Kusternig sec. 5.2-5.3) — trunk vertices swayed by
 * their four levels' weights, and leaf vertices carried by their petiole's sway, turned
 * towards the wind and fluttered by the tree's rolling noise. Run after
 * mesh_tree_branches.cl (and mesh_tree_contact.cl) on the state they wrote. The global
 * sizes may exceed the counts; extra work-items redo the last vertex.
 *
 * Built with BOREAS_MESH_TREE_CONTACTS 1 while a collider bends some tree: each vertex
 * then also moves by its branches' contact bend (shared/mesh_tree_contact.h); without it
 * `bend` is not read, so a world where no collider touches a tree pays nothing for them. */
#include "shared/mesh_tree_contact.h"

#ifndef BOREAS_MESH_TREE_CONTACTS
#define BOREAS_MESH_TREE_CONTACTS 0
#endif

/* The contact bend, under BOREAS_MESH_TREE_CONTACTS only. */
void boreas_mesh_tree_vertex_bend(float w0, float w1, float w2, float w3, int b,
                                  __global const int* links, int nb, __global const float* bend,
                                  float* dx, float* dy, float* dz) {
#if BOREAS_MESH_TREE_CONTACTS
  boreas_mesh_tree_bend_offset(w0, w1, w2, w3, b, links, nb, bend, dx, dy, dz);
#endif
}

/* Trunk: positions out, 3 floats per vertex (boreas_mesh_tree_trunk_vertex). */
__kernel void boreas_mesh_tree_trunk(__global const float* vertices,
                                     __global const int* vertex_branch, int nv, int count,
                                     __global const float* branches, __global const int* links,
                                     int nb, __global const float* state,
                                     __global const float* trees, int nt,
                                     __global const float* noise, __global const float* bend,
                                     __global float* out) {
  int i = min((int)get_global_id(0), count - 1);
  float dx, dy, dz;
  boreas_mesh_tree_displacement(vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
                                vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i],
                                vertex_branch[i], branches, links, nb, state, trees, nt, noise, &dx,
                                &dy, &dz);
  boreas_mesh_tree_vertex_bend(vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 0) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 1) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 2) * nv + i],
                               vertices[(BOREAS_MESH_TREE_TRUNK_WEIGHT + 3) * nv + i],
                               vertex_branch[i], links, nb, bend, &dx, &dy, &dz);
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
                                      __global const float* noise, __global const float* bend,
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
  boreas_mesh_tree_vertex_bend(leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 0) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 1) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 2) * nl + l],
                               leaves[(BOREAS_MESH_TREE_LEAF_WEIGHT + 3) * nl + l], b, links, nb,
                               bend, &dx, &dy, &dz);
  BoreasMeshTreeTurn turn;
  boreas_mesh_tree_leaf_turn(state, nb, b, leaves, nl, l, trees, nt, t, &turn);
  boreas_mesh_tree_leaf_vertex(&turn, dx, dy, dz, vertices, nv, i, leaves, nl, l, trees, nt, t,
                               roll, noise, out, i, 6, 1);
}
