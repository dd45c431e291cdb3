/* boreas: tile launches. The host lists tiles of consecutive items (a tree's branches of
 * one level, a tree's leaves) and launches one work-group per tile, so one launch covers
 * any set of ranges (every tree of a level of detail, skipping the removed ones) with
 * plain contiguous loads inside each tile. A tile holds at most the group size of items;
 * work-items past its count redo its last item (same inputs, same result, so the
 * duplicate writes agree). Layout: BOREAS_TILE_INTS ints per tile (host:
 * host/src/runtime/launch_tiles.h). Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_LAUNCH_TILES_H
#define BOREAS_CL_SHARED_LAUNCH_TILES_H

#define BOREAS_TILE_FIRST 0 /* first item */
#define BOREAS_TILE_COUNT 1 /* items, 1..group size */
#define BOREAS_TILE_VALUE 2 /* a float (its bits) the tile's items share, or 0 */
#define BOREAS_TILE_INTS 4  /* one int left free keeps tiles 16-byte aligned */

#ifdef __OPENCL_C_VERSION__
/* This work-item's tile, counted from `tile_first` (a launch may start inside a list). */
inline __attribute__((always_inline)) int boreas_tile(int tile_first) { return tile_first + (int)get_group_id(0); }

/* The float the tile carries. */
inline __attribute__((always_inline)) float boreas_tile_value(__global const int* tiles, int tile) {
  return as_float(tiles[tile * BOREAS_TILE_INTS + BOREAS_TILE_VALUE]);
}

/* This work-item's item in its tile. */
inline __attribute__((always_inline)) int boreas_tile_item(__global const int* tiles, int tile) {
  return tiles[tile * BOREAS_TILE_INTS + BOREAS_TILE_FIRST] +
         min((int)get_local_id(0), tiles[tile * BOREAS_TILE_INTS + BOREAS_TILE_COUNT] - 1);
}
#endif

#endif
