/* boreas: leaf instances from the trees' animated branches, written as records (the
 * blade's base, axis and normal: BOREAS_LEAF_RECORD_FLOATS floats, boreas_cl.h) — each leaf
 * re-attached to its last-level branch exactly as a child branch is (boreas_attach), its
 * blade starting a petiole's length (the template's, times the tree's scale) out along its
 * axis, its blade turned about that axis by its roll (LeafBend). Its parent, place and
 * turns come packed in two ints (cl/shared/leaf_pack.h, boreas_leaf_unpack). A leaf is a function of
 * its branch's current state alone, so leaves are made when they are read
 * (boreas_tree_get_leaves, boreas_tree_enqueue_leaf_records,
 * boreas_world_enqueue_tree_records), never stored or stepped: a forest's hundreds of
 * millions of leaves cost nothing until drawn.
 *
 * One launch covers any set of trees: one work-group per tile of the batch's leaf tiles
 * (cl/shared/launch_tiles.h), a tile a run of one tree's leaves (up to the group's
 * work-items times BOREAS_W): FIRST its first leaf's
 * index in the tree, COUNT, STATIC that leaf's entry in the template's leaf planes
 * (stride sm), ROOT the tree's root entry (the parents count from it), VALUE the
 * petiole's length (the template's times the tree's scale, m), OBJECT its slot's row (the
 * out table's, and the offsets' added to each position: shared/tree_origin.h). Each
 * work-item places BOREAS_W consecutive leaves of its tile (simd_width.h), their parents
 * gathered per lane; lanes past the tile's count redo its last leaf. A leaf's branch is
 * read through boreas_tree_gather_pose (tree_state.h: stored, posed (posed, stride pn: the
 * settled branches the host posed for this launch) or derived; motion and shape, stride sn,
 * for the derived ones). Records interleave their floats, so they are written
 * lane by lane.
 *
 * Where a leaf's record goes: with one_tree, record out_first + its index (the per-tree
 * call, launched over that tree's tiles alone). Otherwise its tree's row of the out table
 * (cl/shared/tree_records.h) says: no leaf first, nothing; all leaves kept, record
 * out_first + first + its index, the same bits as the per-tree call; `kept` of n leaves,
 * leaf j is kept where its rank (j * inverse) mod n is below kept, written at first + rank
 * with its axis times the row's size factor (its length and width grow by it, so the kept
 * leaves cover what all did). The ranks are a fixed permutation of the tree's leaves (leaf
 * (m * stride) mod n has rank m, stride close to n / golden ratio and prime to n): the
 * kept leaves are spread evenly along the tree's leaf order, so every twig is thinned
 * alike, and their count is known before they are made, so the records pack with no
 * counting pass. */
#include "shared/launch_tiles.h"
#include "shared/leaf_pack.h"
#include "shared/tree_origin.h"
#include "shared/tree_records.h"
#include "shared/tree_state.h"

__kernel void boreas_tree_leaves(__global const float* state, __global const float* motion, int n,
                                 __global const float* shape, int sn, __global const float* settled,
                                 int tn, __global const float* posed, int pn, __global const int* leaves,
                                 int sm, __global const int* tiles,
                                 int tile_first, __global const int* table, int one_tree,
                                 __global float* out, int out_first,
                                 __global const float* offsets) {
  const int tile = boreas_tile(tile_first);
  const int first = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST);
  const int count = boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT);
  const int static_first = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC);
  const int root = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT);
  const float petiole = boreas_tile_float(tiles, tile, BOREAS_TILE_VALUE);
  int base = out_first, kept = 0, all = 0, inverse = 1;
  float factor = 1.0f;
  if (!one_tree) {
    __global const int* row = table + boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT) * BOREAS_TREE_OUT_INTS;
    if (row[BOREAS_TREE_OUT_LEAF_FIRST] < 0) return;
    base += row[BOREAS_TREE_OUT_LEAF_FIRST];
    kept = row[BOREAS_TREE_OUT_KEPT];
    all = row[BOREAS_TREE_OUT_LEAVES];
    inverse = row[BOREAS_TREE_OUT_INVERSE];
    factor = as_float(row[BOREAS_TREE_OUT_FACTOR]);
  }
  const bool thinned = kept < all;
  int k = (int)get_local_id(0) * BOREAS_W; /* the first lane's leaf in the tile */
  /* A work-item wholly past the count has nothing to write (at width 1 it would rewrite the
   * last leaf's same bits): a short tile (the ray structure's runs) costs its leaves. */
  if (k >= count) return;
  const BOREAS_LEAF_PLACE leaf = boreas_leaf_load_w(leaves, sm, static_first, k, count);
  BOREAS_I p = root + leaf.entry;
  BOREAS_V3 o;
  BOREAS_BEZIER c = boreas_tree_gather_pose(state, motion, shape, settled, posed, n, sn, tn, pn, p, &o);
  BOREAS_ATTACH a = boreas_attach(c, o, leaf.v, leaf.cos_theta, leaf.sin_theta, leaf.cos_alpha,
                                  leaf.sin_alpha);
  BOREAS_V3 position = boreas_v3_madd(a.origin, a.x, petiole);
  /* From the tree's base to the caller's frame (shared/tree_origin.h): its row's offset. */
  const BoreasV3 offset = boreas_tree_offset(offsets, boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT));
  position.x += offset.x;
  position.y += offset.y;
  position.z += offset.z;
  BOREAS_V3 normal = boreas_v3_lin2(a.y, leaf.cos_roll, a.z, leaf.sin_roll);
  /* The 9 values of each lane, then each lane's record. */
  float v[BOREAS_TREE_LEAF_OUT_PLANES][BOREAS_W];
#if BOREAS_W == 1
#define BOREAS_LANES_OUT(x, plane) v[plane][0] = (x)
#else
#define BOREAS_LANES_OUT(x, plane) BOREAS_CAT(vstore, BOREAS_W)((x), 0, v[plane])
#endif
  BOREAS_LANES_OUT(position.x, BOREAS_TREE_LEAF_OUT_POSITION + 0);
  BOREAS_LANES_OUT(position.y, BOREAS_TREE_LEAF_OUT_POSITION + 1);
  BOREAS_LANES_OUT(position.z, BOREAS_TREE_LEAF_OUT_POSITION + 2);
  BOREAS_LANES_OUT(a.x.x, BOREAS_TREE_LEAF_OUT_AXIS + 0);
  BOREAS_LANES_OUT(a.x.y, BOREAS_TREE_LEAF_OUT_AXIS + 1);
  BOREAS_LANES_OUT(a.x.z, BOREAS_TREE_LEAF_OUT_AXIS + 2);
  BOREAS_LANES_OUT(normal.x, BOREAS_TREE_LEAF_OUT_NORMAL + 0);
  BOREAS_LANES_OUT(normal.y, BOREAS_TREE_LEAF_OUT_NORMAL + 1);
  BOREAS_LANES_OUT(normal.z, BOREAS_TREE_LEAF_OUT_NORMAL + 2);
#undef BOREAS_LANES_OUT
  /* At width 1 a work-item past the count redoes (and rewrites) the tile's last leaf; a
   * wider one stores no lane past it. (Chosen by the preprocessor: a width test inside the
   * loop's condition is a logical operator with a constant operand, which clang warns of.) */
#if BOREAS_W == 1
  const int lanes = 1;
#else
  const int lanes = min(BOREAS_W, count - k);
#endif
  for (int l = 0; l < lanes; ++l) {
    const int j = first + min(k + l, count - 1);
    int r = j;
    if (thinned) {
      r = (int)(((long)j * (long)inverse) % (long)all);
      if (r >= kept) continue;
      for (int f = 0; f < 3; ++f) v[BOREAS_TREE_LEAF_OUT_AXIS + f][l] *= factor;
    }
    __global float* rec = out + (size_t)(base + r) * BOREAS_TREE_LEAF_OUT_PLANES;
    for (int f = 0; f < BOREAS_TREE_LEAF_OUT_PLANES; ++f) rec[f] = v[f][l];
  }
}
