/* boreas: state carried across a step unchanged, for items a step leaves alone (levels of
 * detail: underbrush components updated every r-th step; trees' carried branches write both
 * halves in their update instead, cl/tree_step.cl). The
 * state is a ping-pong pair: an item not written in a step would show its value from two
 * steps before once the halves swap, so in the step after each update its planes are
 * copied from the current half to the next; from then on both halves agree until its next
 * update. Items come in tiles (shared/launch_tiles.h). Two sets of planes in one launch:
 * BOREAS_COPY_PLANES_A of (a_in, a_out) and BOREAS_COPY_PLANES_B of (b_in, b_out), stride n. */
#include "shared/launch_tiles.h"

#ifdef BOREAS_WIDE_PLANES
#define BOREAS_COPY_AT(p, n, i) ((size_t)(p) * (size_t)(n) + (size_t)(i))
#else
#define BOREAS_COPY_AT(p, n, i) ((p) * (n) + (i))
#endif

#ifndef BOREAS_COPY_PLANES_A
#define BOREAS_COPY_PLANES_A 1
#endif
#ifndef BOREAS_COPY_PLANES_B
#define BOREAS_COPY_PLANES_B 0
#endif

__kernel void boreas_tile_copy(__global const float* a_in, __global float* a_out, __global const float* b_in,
                               __global float* b_out, int n, __global const int* tiles, int tile_first) {
  int tile = boreas_tile(tile_first);
  int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + boreas_tile_offset(tiles, tile);
#pragma unroll
  for (int p = 0; p < BOREAS_COPY_PLANES_A; ++p) a_out[BOREAS_COPY_AT(p, n, i)] = a_in[BOREAS_COPY_AT(p, n, i)];
#pragma unroll
  for (int p = 0; p < BOREAS_COPY_PLANES_B; ++p) b_out[BOREAS_COPY_AT(p, n, i)] = b_in[BOREAS_COPY_AT(p, n, i)];
}
