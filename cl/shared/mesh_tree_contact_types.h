/* boreas: the buffer layouts of colliders against imported trees (mesh_tree_contact.h says
 * the model), shared by the kernels and the host. Planar, as mesh_tree_types.h. */
#ifndef BOREAS_CL_SHARED_MESH_TREE_CONTACT_TYPES_H
#define BOREAS_CL_SHARED_MESH_TREE_CONTACT_TYPES_H

/* Segments per branch along its skeleton: points at 0, 1/S, ..., 1 of its length, each
 * with a radius (the tube between two is their cone). */
#define BOREAS_MESH_TREE_CONTACT_SEGMENTS 6
#define BOREAS_MESH_TREE_CONTACT_POINTS (BOREAS_MESH_TREE_CONTACT_SEGMENTS + 1)

/* Float planes per branch of the contact table (stride = branch capacity), static. */
#define BOREAS_MESH_TREE_CONTACT_POINT 0 /* 3 per point: m, the tree's (TREE_ORIGIN), at rest */
#define BOREAS_MESH_TREE_CONTACT_WEIGHT (3 * BOREAS_MESH_TREE_CONTACT_POINTS) /* 4 per point */
#define BOREAS_MESH_TREE_CONTACT_RADIUS (7 * BOREAS_MESH_TREE_CONTACT_POINTS) /* 1 per point, m */
/* 1 / k_a, m/N; then the level's natural frequency, rad/s */
#define BOREAS_MESH_TREE_CONTACT_COMPLIANCE (8 * BOREAS_MESH_TREE_CONTACT_POINTS)
#define BOREAS_MESH_TREE_CONTACT_OMEGA (BOREAS_MESH_TREE_CONTACT_COMPLIANCE + 1)
#define BOREAS_MESH_TREE_CONTACT_LIMIT (BOREAS_MESH_TREE_CONTACT_OMEGA + 1) /* largest |O_a|, m */
#define BOREAS_MESH_TREE_CONTACT_FLOATS (BOREAS_MESH_TREE_CONTACT_LIMIT + 1)

/* Contact state planes per branch (stride = branch capacity), double-buffered. */
#define BOREAS_MESH_TREE_BEND_OFFSET 0   /* 3: O_a, m at weight 1 */
#define BOREAS_MESH_TREE_BEND_VELOCITY 3 /* 3: dO_a/dt, m/s */
#define BOREAS_MESH_TREE_BEND_FLOATS 6

/* Per tree in the step's contact launch, 5 ints: its first branch, branch count, first pair,
 * pair count, and 1 where its bends have settled and are zeroed instead (two steps, one per
 * half of the state); per pair (a tree and a collider whose bounds meet), the collider's
 * index. */
#define BOREAS_MESH_TREE_ACTIVE_INTS 5

/* Per pair, what the tree pushes the collider with: force (3, N), torque about the
 * collider's end position (3, N m), branches in contact (1). */
#define BOREAS_MESH_TREE_PAIR_FLOATS 7

#define BOREAS_MESH_TREE_CONTACT_PASSES 2
#define BOREAS_MESH_TREE_CONTACT_DAMPING 0.15f /* damping ratio, as trees' default */
#define BOREAS_MESH_TREE_CONTACT_SLOP 1e-3f    /* m: a segment this near a collider touches it */
/* A tree no collider touches whose bends (m at weight 1) and their rates (m/s) are all
 * below these has come to rest: its bends are zeroed and it leaves the contact launch. */
#define BOREAS_MESH_TREE_QUIET_BEND 1e-4f
#define BOREAS_MESH_TREE_QUIET_RATE 1e-3f

#endif
