/* boreas: the buffer layouts of the imported-tree wind kernels (Kusternig sec. 5), shared
 * by the kernels and the host. Every table is planar (one plane of `stride` values per
 * quantity): xyz side by side would invite LLVM's SLP vectorizer to pack them into vector
 * values, which stop PoCL from vectorizing across work-items (see wind_types.h). */
#ifndef BOREAS_CL_SHARED_MESH_TREE_TYPES_H
#define BOREAS_CL_SHARED_MESH_TREE_TYPES_H

/* Float planes per branch (stride = branch count of the batch). */
#define BOREAS_MESH_TREE_BRANCH_AXIS 0    /* 3: unit, base -> tip */
#define BOREAS_MESH_TREE_BRANCH_UP 3      /* 3: unit, the noise's second sway direction */
#define BOREAS_MESH_TREE_BRANCH_RIGHT 6   /* 3: unit, the first */
#define BOREAS_MESH_TREE_BRANCH_CENTER 9  /* 3: m, where the wind is sampled (tree's) */
#define BOREAS_MESH_TREE_BRANCH_PHASE 12  /* 2: noise lookup offset, tiles */
#define BOREAS_MESH_TREE_BRANCH_TAU 14    /* response time of its level, s */
#define BOREAS_MESH_TREE_BRANCH_FLOATS 15

/* Int planes per branch. */
#define BOREAS_MESH_TREE_BRANCH_ANIMATED_BY 0 /* 4: the branch animating level k (batch index) */
#define BOREAS_MESH_TREE_BRANCH_TREE 4        /* the tree (batch index) */
#define BOREAS_MESH_TREE_BRANCH_IS_STEM 5     /* 1 for the tree's stem, which rolls the leaf noise */
#define BOREAS_MESH_TREE_BRANCH_INTS 6

/* State planes per branch: the wind it feels, m/s, low-passed with its level's response
 * time. Double-buffered by the host so that a failed step changes nothing. */
#define BOREAS_MESH_TREE_STATE_WIND 0 /* 3 */
#define BOREAS_MESH_TREE_STATE_FLOATS 3

/* Float planes per tree (stride = tree count), written by the host every step. */
#define BOREAS_MESH_TREE_TREE_BEND 0      /* 4: per level, m at weight 1 in 10 m/s of wind normal
                                      to the branch */
#define BOREAS_MESH_TREE_TREE_SWAY 4      /* 4: per level, m at weight 1 in 10 m/s */
#define BOREAS_MESH_TREE_TREE_CLOCK 8     /* 4: per level, frequency * time reduced to one tile */
#define BOREAS_MESH_TREE_TREE_FLUTTER 12  /* m at a leaf's tip in 10 m/s */
#define BOREAS_MESH_TREE_TREE_TURN 13     /* 0..1: how far leaves turn into a strong wind */
#define BOREAS_MESH_TREE_TREE_INV_TILE 14 /* 1 / the leaf noise's tile size, 1/m */
#define BOREAS_MESH_TREE_TREE_FRESH 15    /* 1 on the tree's first step: state starts at the wind */
/* The load L = DRAG |W|^2 (|W| VOGEL_SPEED)^VOGEL_B (the power above |W| = 1 / VOGEL_SPEED
 * only): the tree's drag normalized to 0.8 at 10 m/s (mesh_trees/mesh_tree_drag.h). */
#define BOREAS_MESH_TREE_TREE_DRAG 16        /* 1 / (m/s)^2 */
#define BOREAS_MESH_TREE_TREE_VOGEL_B 17     /* Vogel's exponent of the leafy share, no unit */
#define BOREAS_MESH_TREE_TREE_VOGEL_SPEED 18 /* 1 / the reference speed, 1 / (m/s) */
/* 3: m, the tree's place in the world (its def's position, an exact float): every position
 * of the branch, trunk, leaf and leaf-vertex tables, and of the vertices the kernels write,
 * is relative to it (so a tree far from 0 keeps the precision it has at 0); the wind is
 * sampled relative to it (wind_sample.h, boreas_wind_sample_local). */
#define BOREAS_MESH_TREE_TREE_ORIGIN 19
#define BOREAS_MESH_TREE_TREE_FLOATS 22

/* Tree state planes: the leaf noise rolled downwind, tiles in [0, 1). Double-buffered. */
#define BOREAS_MESH_TREE_ROLL 0 /* 2 */
#define BOREAS_MESH_TREE_ROLL_FLOATS 2

/* Float planes per trunk vertex (stride = trunk vertex count). */
#define BOREAS_MESH_TREE_TRUNK_REST 0    /* 3: m, the tree's (TREE_ORIGIN) */
#define BOREAS_MESH_TREE_TRUNK_WEIGHT 3  /* 4: w_k^bend_exponent */
#define BOREAS_MESH_TREE_TRUNK_FLOATS 7

/* Float planes per leaf (stride = leaf count). */
#define BOREAS_MESH_TREE_LEAF_PETIOLE 0  /* 3: m, the tree's (TREE_ORIGIN) */
#define BOREAS_MESH_TREE_LEAF_AXIS 3     /* 3: unit */
#define BOREAS_MESH_TREE_LEAF_WEIGHT 6   /* 4: w_k^bend_exponent of the trunk vertex at the petiole */
#define BOREAS_MESH_TREE_LEAF_FLOATS 10

/* Float planes per leaf vertex (stride = leaf vertex count). */
#define BOREAS_MESH_TREE_LEAF_VERTEX_REST 0   /* 3: m, the tree's (TREE_ORIGIN) */
#define BOREAS_MESH_TREE_LEAF_VERTEX_NORMAL 3 /* 3: unit, rest */
#define BOREAS_MESH_TREE_LEAF_VERTEX_TIP 6    /* distance from the petiole over the leaf's length */
#define BOREAS_MESH_TREE_LEAF_VERTEX_FLOATS 7

/* The wind speed that the per-level amplitudes are given at, m/s (the load is 0.8 there). */
#define BOREAS_MESH_TREE_REFERENCE_SPEED 10.0f

/* The noise textures: per tree, channel 0 then channel 1, each size * size floats. */
#define BOREAS_MESH_TREE_NOISE_SIZE 256

#endif
