// boreas: the bookkeeping of a batch's planes when objects come and go — an index space
// of blocks that grows by doubling, leaves holes where blocks go, is packed once the holes
// pass half of it, and packs and halves once its live entries fall below a quarter of it;
// and the device copies that move blocks into new buffers. Trees, meadows and imported
// trees keep their planes so (trees/tree_batch.h, underbrush/underbrush_batch.h,
// mesh_trees/mesh_tree_batch.h).
//
// The capacity follows the live entries with hysteresis: a space grows only when its live
// entries and the new ones pass three quarters of it after packing (else it packs in
// place: the removals that made the holes, a quarter of it at least, paid for the
// copies), and to at least double, so a grown space is more than three eighths full; it
// shrinks only below a quarter full, to the smallest halving that keeps the live entries
// within half of it. Adding and removing at either edge therefore moves nothing until an
// eighth of the capacity has come or gone, and a population that churns below its largest
// size U keeps the capacity under 8/3 U (it grows only from below 4/3 U).
#pragma once

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "runtime/runtime.h"

namespace boreas::impl {

// [1, end) used (entry 0 is the batch's sink, no object's), `dead` entries in holes.
struct BlockSpace {
  int64_t end = 1;
  int64_t dead = 0;
  int64_t capacity = 0;

  // Entries a packed space would hold: the live ones and the sink.
  int64_t used() const { return end - dead; }
  bool fits(int64_t more) const { return end + more <= capacity; }
  bool wants_packing() const { return dead > 0 && 2 * dead > end; }
  // A capacity for `more` entries after the live ones (when they do not fit after end):
  // the present one where they fill at most three quarters of it once packed, else at
  // least double it; at least `minimum`, and at most `maximum` where the live and new
  // entries fit in that (a batch's buffers within the device's largest allocation: the
  // caller checks that they fit first, TreeBatch::fitting).
  int64_t grown(int64_t more, int64_t minimum,
                int64_t maximum = std::numeric_limits<int64_t>::max()) const;
  // Whether the live entries are below a quarter of a capacity above `minimum`, and the
  // capacity to pack them into then: halved until they would fill more than half of the
  // next halving, or it would pass below `minimum`.
  bool wants_shrinking(int64_t minimum) const {
    return capacity > minimum && 4 * used() < capacity;
  }
  int64_t shrunk(int64_t minimum) const;
  // The smallest halving of the capacity (not below `minimum`) that the live entries fill
  // at most three quarters of, grown's threshold: for entries let go for good rather than
  // by churn (a tree's settled finest level: trees/tree_batch.h), so a space sits between
  // 3/8 and 3/4 full after it. It still grows only past 3/4 and shrinks only below 1/4, so
  // adding and removing at its edge moves nothing until an eighth of it came or went.
  int64_t fitted(int64_t minimum) const;
  // A block goes: the last one shortens the space, any other leaves a hole.
  void release(int64_t first, int64_t count);
  // After packing: the live entries from 1 on.
  void packed(int64_t new_end) {
    end = new_end;
    dead = 0;
  }
  void clear() {
    end = 1;
    dead = 0;
  }
};

// One buffer of a set of planes that moves together: the old and the new buffer, its
// planes and their element size.
struct PlanePair {
  cl::Buffer* from;
  cl::Buffer* to;
  int planes;
  size_t elem;
};

// A block's move: `length` entries from `from` to `to`.
struct BlockMove {
  int64_t from, to, length;
};

// Where the blocks of a space go in a relayout. blocks: (first, count) of each live object,
// in any order. Each keeps its place, or with `pack` the blocks are laid one after another
// after the sink in the order of their firsts (so a space's order survives packing, and
// spaces that hold an object's blocks in the same order stay in step).
struct BlockPlan {
  std::vector<BlockMove> moves;  // sorted by `from`, as copy_block_moves takes them
  std::vector<int64_t> to;       // each block's new first, in the order given
  int64_t end = 1;               // the space's end after packing
  bool moves_any = false;        // whether any block changes place
};
BlockPlan plan_block_moves(const std::vector<std::pair<int64_t, int64_t>>& blocks, bool pack);

// Device copies of the moves (sorted by `from`; runs that move together merged, one copy
// per buffer per run), after entry 0 (the sink), from buffers of stride old_stride into
// buffers of stride new_stride.
void copy_block_moves(Runtime& runtime, std::vector<BlockMove> moves, const PlanePair* sets,
                      size_t set_count, size_t old_stride, size_t new_stride);

}  // namespace boreas::impl
