/* boreas: tile launches. The host lists tiles of consecutive items (a tree's branches of
 * one level, a tree's leaves) and launches one work-group per tile, so one launch covers
 * any set of ranges (every tree of a level of detail, skipping the removed ones) with
 * plain contiguous loads inside each tile. A tile holds at most the group size of items;
 * work-items past its count redo its last item (same inputs, same result, so the
 * duplicate writes agree; a kernel that writes what it reads sends them to entry 0, the
 * batch's sink, instead: tree_step.cl's carry).
 *
 * Besides its items a tile says where their shared, static data start (a tree's template
 * block: trees of one template share it), its tree's root entry, and two floats for its
 * items (tree_step.cl: the resume blend and the tree's scale). Layout: BOREAS_TILE_INTS
 * ints per tile (host: host/src/runtime/launch_tiles.h). Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_LAUNCH_TILES_H
#define BOREAS_CL_SHARED_LAUNCH_TILES_H

#define BOREAS_TILE_FIRST 0  /* first item */
#define BOREAS_TILE_COUNT 1  /* items, 1..group size */
#define BOREAS_TILE_STATIC 2 /* the first item's static (shared) entry; or, for a batch
                               * that adds each tile alone, its object's static base
                               * (the underbrush: a meadow's first part record) */
#define BOREAS_TILE_ROOT 3   /* the entry the items' parent indices count from */
#define BOREAS_TILE_VALUE 4  /* a float (its bits) the items share, or 0 */
#define BOREAS_TILE_SCALE 5  /* a float: the items' tree's scale, or 1 */
#define BOREAS_TILE_SCALE_ROOT 6 /* a float: the square root of that scale */
#define BOREAS_TILE_OBJECT 7 /* an int of the items' object, or 0 (tree_step.cl's contact
                              * variant: the touched tree) */
#define BOREAS_TILE_INTS 8   /* 32-byte aligned tiles */

#ifdef __OPENCL_C_VERSION__
#include "shared/simd_width.h"

/* This work-item's tile, counted from `tile_first` (a launch may start inside a list). */
BOREAS_FN int boreas_tile(int tile_first) { return tile_first + (int)get_group_id(0); }

/* A field of the tile. */
BOREAS_FN int boreas_tile_int(__global const int* tiles, int tile, int field) {
  return tiles[tile * BOREAS_TILE_INTS + field];
}
BOREAS_FN float boreas_tile_float(__global const int* tiles, int tile, int field) {
  return as_float(tiles[tile * BOREAS_TILE_INTS + field]);
}

/* This work-item's place in its tile: its item is FIRST + it, its static entry STATIC + it. */
BOREAS_FN int boreas_tile_offset(__global const int* tiles, int tile) {
  return min((int)get_local_id(0), tiles[tile * BOREAS_TILE_INTS + BOREAS_TILE_COUNT] - 1);
}
#endif

#endif
