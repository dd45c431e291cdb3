// boreas: tiles the record kernels read that are not kept per tree: the deformer's, made
// for the (tree, level) ranges of one call (TreeBatch::mesh, benchmarks), and the fixed
// permutation by which a view thins a tree's leaves (cl/tree_leaves.cl).
#pragma once

#include <cstdint>
#include <vector>

namespace boreas::impl {

// One (tree, level) range for cl/tree_deform.cl: `count` branches of one level, from state
// entry `first` and template entry `static_first`, each a grid of (rings + 1) x (sides + 1)
// vertices, their radius times `scale`, written from vertex `out_first`.
struct DeformRange {
  int64_t first = 0, static_first = 0;
  int32_t count = 0, rings = 0, sides = 0;
  float scale = 1.0f;
  int64_t out_first = 0;
};

// The deformer's tiles for the ranges (cl/shared/launch_tiles.h, read as tree_deform.cl
// says), at most `width` vertices a tile. Fails (OUT_OF_MEMORY) past 2^31 vertices.
std::vector<int32_t> deform_tiles(const std::vector<DeformRange>& ranges, int width);

// Leaf j of a tree of n leaves has rank (j * inverse) mod n; rank m is leaf (m * stride)
// mod n. stride is the integer nearest n / golden ratio that is prime to n (1 for n < 3):
// the leaves of ranks below any k are spread evenly over the tree's leaf order (a Weyl
// sequence), so thinning to the first k ranks thins every twig alike.
struct LeafPermutation {
  int32_t stride = 1, inverse = 1;
};
LeafPermutation leaf_permutation(int32_t n);

}  // namespace boreas::impl
