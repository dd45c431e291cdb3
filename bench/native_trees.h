// boreas: native C++ twins of the tree kernels (cl/tree_step.cl, cl/tree_deform.cl,
// cl/tree_leaves.cl), the yardstick boreas_bench compares them with. They include
// cl/shared/tree_math.h with BOREAS_FAST_MATH 1, so the geometry and the polynomials are
// the kernels' own text, and read and write the same planes (cl/shared/tree_types.h) in
// the layout TreeBatch uses (host/src/trees/tree_batch.h). OpenMP threads over blocks of
// branches, SIMD within a block; the wind is native_wind_block (bench/native_wind.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shared/wind_types.h"
#include "trees/tree_layout.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "trees/tree_tiles.h"

namespace boreas::bench {

// One tree as TreeBatch holds it: its parameters (position, levels, response) and model.
using NativeTreeSource = impl::TreeLayoutSource;

// A batch of trees in the layout of trees/tree_layout.h (TreeBatch's), held on the host,
// with the tile lists TreeBatch launches in each mode (trees/tree_tiles.h, every tree at
// full detail).
// State and motion are ping-pong pairs; `current` is the committed one.
struct NativeTrees {
  int tree_count = 0;
  int n = 1;  // plane stride: the sink, roots and branches
  // Template planes (each tree's own block at its entries; parents local to its root).
  std::vector<int32_t> parents;
  std::vector<float> shape, radius, response;
  std::vector<float> state[2], motion[2];
  std::vector<double> omega, zeta;  // 0 for quasi-static branches and roots
  double response_dt = -1.0;
  int current = 0;
  // Leaves (all trees' leaves in order), planes of stride leaf_n.
  int leaf_count = 0;
  int leaf_n = 1;
  std::vector<int32_t> leaves;  // packed (cl/shared/leaf_pack.h)
  // Each tree's root entry; its branch b is at tree_first + 1 + b.
  std::vector<int32_t> tree_first;
  impl::TileLists tiles[2] = {impl::TileLists(impl::kTreeListCount),
                              impl::TileLists(impl::kTreeListCount)};  // lagged, exact
  // Each tree's first leaf (its template's leaves, at its own place here), scale and
  // petiole (m, scaled: the leaf tiles' value).
  std::vector<int32_t> tree_leaf_first;
  std::vector<float> tree_scale;
  std::vector<float> tree_leaf_petiole;

  int branch_count() const { return n - 1 - tree_count; }
};

// Items per tile, as TreeBatch on a CPU device (Runtime::group_size).
constexpr int kTileWidth = 64;

// The layout and the unbent rest state of these trees (impl::tree_layout).
NativeTrees native_tree_layout(const std::vector<NativeTreeSource>& trees);

// The response planes for a step of dt (TreeBatch::upload_response).
void native_tree_response(NativeTrees& trees, double dt);

// The wind the step kernels read (PlantWind): waves padded or not, the grid's buffer.
struct NativeTreeWind {
  const BoreasGpuWave* waves = nullptr;
  int wave_count = 0;
  const float* grid = nullptr;  // the 4 planes, then the slab where interpolated
  BoreasGpuGrid g{};
  bool interpolated = false;  // PlantWind::interpolated
};

// cl/tree_step.cl over the tiles given (BOREAS_TILE_INTS ints each): same arguments, same
// result; carry: the BOREAS_TREE_CARRY build.
void native_tree_step(const float* parent_state, float* state, const int32_t* parents,
                      const float* shape, const float* response, const float* motion_in,
                      float* motion_out, int n, int sn, const int32_t* tiles, int tile_count,
                      float carry_hold, bool carry, const NativeTreeWind& wind);

// TreeBatch::enqueue_step + commit, natively, over the tiles' lists: one pass over all
// branches (lagged: parents from the committed state) or one pass per level (exact:
// parents from the state being written). Leaves are not computed (see native_tree_leaves).
void native_trees_step(NativeTrees& trees, bool exact, double dt, const NativeTreeWind& wind);

// cl/tree_deform.cl for `count` branches from `first` (their radius functions from
// `static_first`, stride sn, the radius times scale), each (rings + 1) x (sides + 1)
// vertices, into planes of stride out_n from vertex out_first.
void native_tree_deform(const float* state, int n, const float* radius, int sn, int first,
                        int static_first, int count, float scale, int rings, int sides, float* out,
                        int out_n, int out_first);

// cl/tree_leaves.cl: one tree's `count` leaves (packed template leaves from static_first,
// stride sm; parents counted from `root`; the petiole at the tree's scale) as records into
// out from record out_first.
void native_tree_leaves(const float* state, int n, const int32_t* leaves, int sm,
                        int static_first, int count, int root, float petiole, float* out,
                        int out_first);

}  // namespace boreas::bench
