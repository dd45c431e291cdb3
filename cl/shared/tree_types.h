/* boreas: the device layout of trees — every per-branch quantity is a plane of floats
 * (structure of arrays), plane k of a buffer with stride n starting at float k * n.
 * Planes rather than packed structs because PoCL vectorizes across work-items only when
 * each load and store is a plain float at the work-item's index (cl/shared/tree_math.h).
 * Compiles as OpenCL C and C++; host code uses the same indices.
 */
#ifndef BOREAS_CL_SHARED_TREE_TYPES_H
#define BOREAS_CL_SHARED_TREE_TYPES_H

/* Animated state, ping-pong (written by tree_step.cl each step): the four world-space
 * control points and the orientation vector O the branch's Sloan frame starts from. */
#define BOREAS_TREE_STATE_P0 0 /* x, y, z: planes 0, 1, 2 */
#define BOREAS_TREE_STATE_P1 3
#define BOREAS_TREE_STATE_P2 6
#define BOREAS_TREE_STATE_P3 9
#define BOREAS_TREE_STATE_O 12
#define BOREAS_TREE_STATE_PLANES 15

/* Static shape and attachment (from the generator). */
#define BOREAS_TREE_SHAPE_LOCAL_P1 0 /* unpositioned control points P1..P3, x y z each */
#define BOREAS_TREE_SHAPE_LOCAL_P2 3
#define BOREAS_TREE_SHAPE_LOCAL_P3 6
#define BOREAS_TREE_SHAPE_V 9           /* where P0 sits on the parent, Bezier parameter */
#define BOREAS_TREE_SHAPE_COS_THETA 10  /* angle around the parent */
#define BOREAS_TREE_SHAPE_SIN_THETA 11
#define BOREAS_TREE_SHAPE_COS_ALPHA 12  /* down angle */
#define BOREAS_TREE_SHAPE_SIN_ALPHA 13
/* The bend's target is F* = (COMPLIANCE sqrt(s) + DRAG s |u|) u for a tree of scale s and
 * the wind u relative to the tip: one of the two is 0 (the tree's load, linear or drag). */
#define BOREAS_TREE_SHAPE_COMPLIANCE 14 /* linear load: bend per unit wind, m / (m/s) */
#define BOREAS_TREE_SHAPE_W2 15         /* bend weight of P2: (2/3)^gamma (P3's is 1) */
#define BOREAS_TREE_SHAPE_DRAG 16       /* drag load: bend per squared wind, m / (m/s)^2 */
#define BOREAS_TREE_SHAPE_PLANES 17

/* Branch response over one step of dt (host-computed for the current dt): the bend
 * factor F follows its target F* as x = F - F*, u = dF/dt with
 * x' = a x + b u, u' = c x + d u; quasi-static branches have a = b = c = d = 0. */
#define BOREAS_TREE_RESPONSE_A 0
#define BOREAS_TREE_RESPONSE_B 1
#define BOREAS_TREE_RESPONSE_C 2
#define BOREAS_TREE_RESPONSE_D 3
#define BOREAS_TREE_RESPONSE_PLANES 4

/* Response state, updated in place: F (x y z) and dF/dt (x y z). */
#define BOREAS_TREE_MOTION_F 0
#define BOREAS_TREE_MOTION_DF 3
#define BOREAS_TREE_MOTION_PLANES 6

/* Radius functions of the deformer (BoreasBranchRadius, in its field order). */
#define BOREAS_TREE_RADIUS_PLANES 9

/* Leaves: static placement on a last-level branch. */
#define BOREAS_TREE_LEAF_V 0
#define BOREAS_TREE_LEAF_COS_THETA 1
#define BOREAS_TREE_LEAF_SIN_THETA 2
#define BOREAS_TREE_LEAF_COS_ALPHA 3
#define BOREAS_TREE_LEAF_SIN_ALPHA 4
#define BOREAS_TREE_LEAF_STEM 5 /* petiole length, m */
#define BOREAS_TREE_LEAF_COS_ROLL 6 /* the blade turned about its axis (LeafBend): its normal */
#define BOREAS_TREE_LEAF_SIN_ROLL 7 /* is cos(roll) y + sin(roll) z of the attachment frame */
#define BOREAS_TREE_LEAF_PLANES 8

/* A leaf instance (a record of cl/tree_leaves.cl, made when read): blade base position,
 * blade axis (unit), blade normal (unit). */
#define BOREAS_TREE_LEAF_OUT_POSITION 0
#define BOREAS_TREE_LEAF_OUT_AXIS 3
#define BOREAS_TREE_LEAF_OUT_NORMAL 6
#define BOREAS_TREE_LEAF_OUT_PLANES 9

/* Deformer output: position, normal, uv. */
#define BOREAS_TREE_VERTEX_POSITION 0
#define BOREAS_TREE_VERTEX_NORMAL 3
#define BOREAS_TREE_VERTEX_UV 6
#define BOREAS_TREE_VERTEX_PLANES 8

#endif
