/* boreas: the ray structure's device layout, shared by the kernels (cl/ray_*.cl), the host
 * that fills it (host/src/rays/) and the native twin. Compiles as OpenCL C and as C/C++.
 *
 * Two levels (host/src/rays/ray_scene.h says why): a bounding volume hierarchy (BVH) per
 * object instance (a tree, an imported tree's part, a meadow, a BlobTree, a ground, the
 * solid boxes), refitted on the device when rays are cast after a step, and one over the
 * instances, built on the host from their refitted root boxes.
 *
 * A node is BOREAS_RAY_NODE_WORDS 4-byte words: min x y z (float), then a (int), max x y z
 * (float), then count (int). count > 0: a leaf whose primitives are entries a .. a + count
 * - 1 of the primitive list (each the primitive's index within its instance); count == 0:
 * an inner node whose children are nodes a and a + 1. Node indices are absolute (into the
 * one node buffer of their level). */
#ifndef BOREAS_CL_SHARED_RAY_TYPES_H
#define BOREAS_CL_SHARED_RAY_TYPES_H

#define BOREAS_RAY_NODE_WORDS 8

/* Where a node with nothing below it stands: min = max = this on every axis, a point no
 * ray's slabs meet (cl/ray_refit.cl, boreas_ray_refit_node, says why not an inverted box);
 * the host leaves an instance whose root is there out of the hierarchy over instances. */
#define BOREAS_RAY_NOWHERE 3.40282347e+38f

/* A wide node: an inner node of an instance's binary hierarchy at an even depth with its
 * children's children (a child that is a leaf standing for itself) as up to four slots,
 * their boxes stored together so that the cast tests all four as one 4-lane operation
 * (cl/shared/ray_wide.h; collapsed by host/src/rays/bvh_wide.h, its boxes gathered from
 * the refitted binary nodes by cl/ray_wide.cl). BOREAS_RAY_WIDE_WORDS 4-byte words: min x
 * of slots 0..3, min y, min z, max x, max y, max z (float), then each slot's a (int), then
 * each slot's count (int): count > 0: a leaf whose primitives are entries a .. a + count -
 * 1 of the primitive list; count == 0: an inner slot, a the wide node (absolute index);
 * count < 0: an empty slot (its box empty, min > max, so that no ray enters it). */
#define BOREAS_RAY_WIDE_WORDS 32
#define BOREAS_RAY_WIDE_LO 0
#define BOREAS_RAY_WIDE_HI 12
#define BOREAS_RAY_WIDE_A 24
#define BOREAS_RAY_WIDE_COUNT 28

/* The deepest leaf of a hierarchy (the root at depth 0): the instances' one and each
 * instance's. The host's builder keeps every hierarchy within them (host/src/rays/
 * bvh_build.cpp: where its split would pass the bound it halves by count); a traversal,
 * nearer child first, holds at most depth + 1 nodes (cl/shared/ray_cast.h's stacks). */
#define BOREAS_RAY_TOP_DEPTH 31
#define BOREAS_RAY_DEPTH 63

/* What an instance is made of (BOREAS_RAY_INST_TYPE). */
#define BOREAS_RAY_TYPE_TREE 0      /* a generated tree: primitives are its bark's bands
                                       (a ring of a branch: its swept quads), then its
                                       leaves, each its quad cut to its outline */
#define BOREAS_RAY_TYPE_TRIANGLES 1 /* indexed triangles over 3-float positions */
#define BOREAS_RAY_TYPE_STRIPS 2    /* a meadow: primitives are components' triangle strips */
#define BOREAS_RAY_TYPE_BOXES 3     /* axis-aligned boxes (min xyz, max xyz) */

/* The hit kinds (boreas.h's boreas_hit_kind; the host checks they agree). */
#define BOREAS_RAY_HIT_NONE 0
#define BOREAS_RAY_HIT_BRANCH 1
#define BOREAS_RAY_HIT_LEAF 2
#define BOREAS_RAY_HIT_MESH_TRUNK 3
#define BOREAS_RAY_HIT_MESH_LEAF 4
#define BOREAS_RAY_HIT_UNDERBRUSH 5
#define BOREAS_RAY_HIT_BLOBTREE 6
#define BOREAS_RAY_HIT_GROUND 7
#define BOREAS_RAY_HIT_SOLID_BOX 8

/* An instance record: BOREAS_RAY_INST_WORDS ints. */
#define BOREAS_RAY_INST_TYPE 0      /* BOREAS_RAY_TYPE_* */
#define BOREAS_RAY_INST_HIT_KIND 1  /* BOREAS_RAY_HIT_* of its surfaces (a tree's leaves: LEAF) */
#define BOREAS_RAY_INST_ID 2        /* 3 words: the object's id (index, generation, tag) */
#define BOREAS_RAY_INST_ROOT 5      /* its root node */
/* Trees: */
#define BOREAS_RAY_INST_BRANCHES 6  /* first of its branch records (curves, this cast) */
#define BOREAS_RAY_INST_SHAPES 7    /* first of its template's branch shapes */
#define BOREAS_RAY_INST_LEAVES 8    /* first of its template's leaf records */
#define BOREAS_RAY_INST_SCALE 9     /* float bits: the tree's scale */
#define BOREAS_RAY_INST_OUTLINE 10  /* its leaves' outline kind */
#define BOREAS_RAY_INST_PLACED 11   /* first of its leaves placed at this cast */
#define BOREAS_RAY_INST_BAND_COUNT 12 /* its bark bands: primitives below are bands, the
                                         rest its leaves (leaf = primitive - this) */
#define BOREAS_RAY_INST_BANDS 13    /* first of its template's bands */
#define BOREAS_RAY_INST_RECORDS 14  /* item k's primitive record is record k + this */
/* Triangles: positions from float `VERTICES` (stride `STRIDE` floats), triangles from int
 * `INDICES` (3 each, relative to VERTICES in vertices). Strips: vertices of
 * BOREAS_RAY_STRIP_STRIDE per component from VERTICES (8 floats each, the meadow vertex),
 * counts from `INDICES`. Boxes: 6 floats each from VERTICES. */
#define BOREAS_RAY_INST_VERTICES 6
#define BOREAS_RAY_INST_STRIDE 7
#define BOREAS_RAY_INST_INDICES 8
#define BOREAS_RAY_INST_BUFFER 9    /* triangles: 0 the static positions, 1 the swayed
                                       trunks (3 floats), 2 the swayed leaves (6 floats) */
#define BOREAS_RAY_INST_PART_FIRST 10 /* strips: a hit's part is its component here plus
                                         this (the instance is a run of a meadow's) */
/* Every type: its hierarchy's root as a wide node (BOREAS_RAY_WIDE_*), which the cast
 * walks; the binary nodes (ROOT) are what the refit updates. */
#define BOREAS_RAY_INST_WIDE_ROOT 15
#define BOREAS_RAY_INST_WORDS 16

/* A branch's curve as of this cast: P0..P3 and the frame's start vector O (15 floats),
 * padded to 16. */
#define BOREAS_RAY_BRANCH_FLOATS 16
/* A template branch's shape: the radius functions (the first 9 floats of
 * BoreasBranchRadius, in its order, at scale 1), rings, sides, the tip's cap and the beads'
 * phase. */
#define BOREAS_RAY_SHAPE_RADIUS 0
#define BOREAS_RAY_SHAPE_RINGS 9
#define BOREAS_RAY_SHAPE_SIDES 10
#define BOREAS_RAY_SHAPE_TIP_CAP 11
#define BOREAS_RAY_SHAPE_BULGE_PHASE 12
#define BOREAS_RAY_SHAPE_BOUND 13   /* the largest of its bands' bounds (scale 1) */
#define BOREAS_RAY_SHAPE_FLOATS 14
/* A template's bark band: ring `ring` of branch `branch` (the quads between rings ring and
 * ring + 1 of the deformer's grid), and the bound on the swept surface's distance from the
 * curve over that ring at scale 1 (boreas_ray_radius_bound, m). */
#define BOREAS_RAY_BAND_BRANCH 0
#define BOREAS_RAY_BAND_RING 1
#define BOREAS_RAY_BAND_BOUND 2
#define BOREAS_RAY_BAND_FLOATS 4
/* A template leaf's blade at scale 1 (LeafModel): length and width, m. */
#define BOREAS_RAY_LEAF_LENGTH 0
#define BOREAS_RAY_LEAF_WIDTH 1
#define BOREAS_RAY_LEAF_FLOATS 2
/* A leaf placed at this cast (cl/tree_leaves.cl's record): the blade's base, axis and
 * normal (BOREAS_TREE_LEAF_OUT_*). */
#define BOREAS_RAY_PLACED_FLOATS 9

/* A tree's primitive as the cast reads it: records in its hierarchy's item order (item k's
 * at k + BOREAS_RAY_INST_RECORDS), written at each update by the kernels that make the
 * primitives' boxes, so that a leaf node's primitives lie together and the cast reaches a
 * leaf's plane in one load (through the item list and the placed leaves it was two
 * dependent cache misses: bench/RESULTS.md, "Issue 37, seventh round: rays4"). The last
 * word (int bits) says which: a leaf's index (>= 0), or -1 for a bark band.
 * A leaf: its blade's base, unit axis and unit normal (placed at this cast, normalized),
 * length and width at the tree's scale. A band: its template band's branch, ring and bound
 * (BOREAS_RAY_BAND_*, the same floats). */
#define BOREAS_RAY_PRIM_BASE 0
#define BOREAS_RAY_PRIM_AXIS 3
#define BOREAS_RAY_PRIM_NORMAL 6
#define BOREAS_RAY_PRIM_LENGTH 9
#define BOREAS_RAY_PRIM_WIDTH 10
#define BOREAS_RAY_PRIM_INDEX 11
#define BOREAS_RAY_PRIM_FLOATS 12

/* A meadow component's strip: boreas_meadow_vertex records (position first) */
#define BOREAS_RAY_STRIP_STRIDE 18
#define BOREAS_RAY_STRIP_VERTEX_FLOATS 8

/* Rays and hits as boreas_cl.h lays them out. */
#define BOREAS_RAY_RAY_FLOATS 7
#define BOREAS_RAY_HIT_WORDS 12

#endif
