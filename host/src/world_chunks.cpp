// boreas: a world's trees and meadows in chunks, so that a world is limited by the device's
// memory and not by its largest single buffer (CL_DEVICE_MAX_MEM_ALLOC_SIZE: PoCL allocates
// at most 4 GiB at once on some machines, and 100,000 aspens' state planes alone would
// take 6.9 GiB in one).
//
// A chunk is a whole TreeBatch: its own blocks, template blocks, tiles and record tables,
// every buffer within the largest allocation (TreeBatch::fitting, space_limits). Why whole
// batches rather than several buffers inside one batch:
//  - a tree's block never straddles two chunks, and a block's indices (parents, children,
//    leaves) are local to its root, so the kernels keep chunk-local indices and need no
//    change; every launch of a step, a record call or a contact pass is the batch's own,
//    once per chunk (a handful), never once per tree;
//  - the batch already is the unit that grows, packs, shrinks, steps and commits all or
//    none, so a chunk inherits all of that, and a world that fits in one allocation is
//    exactly what it was: one batch, the same launches, the same bits;
//  - the one-call records path already writes several batches into the same caller
//    buffers (the view's first_batch: counts continued across batches).
// What it costs: a template block is held once per chunk that has trees of it (a few MB
// for an aspen, against the gigabytes of the trees' own planes that make a world split),
// and the colliders' push-back is summed chunk by chunk (the same sums, in another order:
// equal to rounding, not to the bit, where one collider touches trees of two chunks).
// A tree stays in the chunk it was added to; each chunk shrinks with its own population
// (runtime/block_space.h), and one left empty is dropped (chunk 0 is kept). A chunk made
// after the world's first steps takes the world's step count and focus, and what picks the
// steps a carried branch or a slow meadow tile is updated in does not depend on the chunk
// (a tree's key; a tile's number, shared by the meadow chunks: PlaceNumbers), so a split
// world steps to the same bits as a whole one.
//
// Meadows are chunked alike (UnderbrushBatch: its component planes within the allocation);
// a meadow is one block, never split.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "errors.h"
#include "world.h"

namespace boreas::impl {

TreeBatch& World::tree_batch(const TreeInstance& tree) {
  for (const auto& chunk : tree_chunks(tree.params.mode))
    if (chunk->holds(tree.key)) return *chunk;
  fail(BOREAS_ERROR_INTERNAL, "no tree chunk holds the tree with key " + std::to_string(tree.key));
}

std::vector<TreeBatch*> World::all_tree_batches() const {
  std::vector<TreeBatch*> all;
  for (const auto& mode : chunks_)
    for (const auto& chunk : mode) all.push_back(chunk.get());
  return all;
}

void World::order_for_chunks(const TreeBatch::Trees& trees, const std::vector<int>& def_index,
                             TreeBatch::Trees* ordered, std::vector<int>* index) const {
  // As given where the first chunk takes them all (a world that fits one allocation adds
  // as it always did); else grouped by template (stable), so that a chunk holds few
  // template blocks and every chunk but the last of a run is filled by trees.
  std::vector<size_t> order(trees.size());
  for (size_t t = 0; t < order.size(); ++t) order[t] = t;
  const auto& chunks = chunks_[!trees.empty() && trees[0]->params.mode == BOREAS_TREE_EXACT];
  if (chunks.size() > 1 || chunks.front()->fitting(trees, 0) < trees.size())
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return trees[a]->template_key < trees[b]->template_key;
    });
  for (size_t t : order) {
    ordered->push_back(trees[t]);
    index->push_back(def_index[t]);
  }
}

void World::add_to_tree_chunks(const TreeBatch::Trees (&trees)[2],
                               const std::vector<int> (&def_index)[2], bool name_defs) {
  // Where each run of trees goes is decided before anything changes (fitting reads the
  // chunks' present spaces; new chunks are empty). A tree that fits no empty chunk is
  // refused, naming it, before any chunk takes anything.
  struct Part {
    int mode;
    size_t chunk, first, count;
  };
  std::vector<Part> parts;
  size_t kept[2] = {chunks_[0].size(), chunks_[1].size()};
  TreeBatch::Trees ordered[2];
  std::vector<int> index[2];
  for (int m = 0; m < 2; ++m) {
    const boreas_tree_mode mode = m == 1 ? BOREAS_TREE_EXACT : BOREAS_TREE_LAGGED;
    order_for_chunks(trees[m], def_index[m], &ordered[m], &index[m]);
    size_t t = 0, c = 0;
    while (t < ordered[m].size()) {
      if (c == chunks_[m].size()) {
        chunks_[m].push_back(std::make_unique<TreeBatch>(*runtime_, mode, template_numbers_[m]));
        chunks_[m].back()->set_step_index(steps_);
        chunks_[m].back()->set_focus(focus_);
      }
      const size_t n = chunks_[m][c]->fitting(ordered[m], t);
      if (n == 0 && chunks_[m][c]->empty()) {
        chunks_[m].resize(kept[m]);  // nothing was taken: the new chunks go again
        chunks_[1 - m].resize(kept[1 - m]);
        const int i = index[m][t];
        const std::string what =
            (name_defs ? "defs[" + std::to_string(i) + "]: " : std::string()) +
            "the tree does not fit one chunk of tree buffers: its planes (or its template's) "
            "would pass the largest buffer " +
            runtime_->device().name + " allocates at once (" +
            std::to_string(runtime_->max_allocation()) +
            " bytes; BOREAS_MAX_ALLOCATION may set it lower)";
        fail(BOREAS_ERROR_OUT_OF_MEMORY, what);
      }
      if (n > 0) parts.push_back({m, c, t, n});
      t += n;
      ++c;
    }
  }
  // Each part one add (all or none in its chunk); a failure takes the earlier parts' trees
  // back out and drops the chunks made for this call.
  size_t done = 0;
  try {
    for (; done < parts.size(); ++done) {
      const Part& p = parts[done];
      const auto first = ordered[p.mode].begin() + ptrdiff_t(p.first);
      chunks_[p.mode][p.chunk]->add(TreeBatch::Trees(first, first + ptrdiff_t(p.count)));
    }
  } catch (...) {
    for (size_t k = 0; k < done; ++k) {
      const Part& p = parts[k];
      for (size_t t = p.first; t < p.first + p.count; ++t)
        chunks_[p.mode][p.chunk]->remove(ordered[p.mode][t]->key);
    }
    for (int m = 0; m < 2; ++m) chunks_[m].resize(kept[m]);
    throw;
  }
}

UnderbrushBatch& World::meadow_batch(const MeadowInstance& meadow) {
  for (const auto& chunk : meadow_chunks_)
    if (chunk->holds(meadow.key)) return *chunk;
  fail(BOREAS_ERROR_INTERNAL,
       "no meadow chunk holds the meadow with key " + std::to_string(meadow.key));
}

std::vector<UnderbrushBatch*> World::all_meadow_batches() const {
  std::vector<UnderbrushBatch*> all;
  for (const auto& chunk : meadow_chunks_) all.push_back(chunk.get());
  return all;
}

void World::add_to_meadow_chunks(const UnderbrushBatch::Meadows& meadows, bool name_defs) {
  // As the trees', in the call's order: a meadow is one block, never split, so one bigger
  // than a whole chunk is refused naming it.
  struct Part {
    size_t chunk, first, count;
  };
  std::vector<Part> parts;
  const size_t kept = meadow_chunks_.size();
  size_t k = 0, c = 0;
  while (k < meadows.size()) {
    if (c == meadow_chunks_.size()) {
      meadow_chunks_.push_back(std::make_unique<UnderbrushBatch>(*runtime_, meadow_tile_numbers_));
      meadow_chunks_.back()->set_step_index(steps_);
      meadow_chunks_.back()->set_focus(focus_);
    }
    const size_t n = meadow_chunks_[c]->fitting(meadows, k);
    if (n == 0 && meadow_chunks_[c]->empty()) {
      meadow_chunks_.resize(kept);
      fail(BOREAS_ERROR_OUT_OF_MEMORY,
           (name_defs ? "defs[" + std::to_string(k) + "]: " : std::string()) + "the meadow's " +
               std::to_string(meadows[k]->meadow.count) +
               " components do not fit one chunk of underbrush buffers: their planes would pass "
               "the largest buffer " +
               runtime_->device().name + " allocates at once (" +
               std::to_string(runtime_->max_allocation()) +
               " bytes; BOREAS_MAX_ALLOCATION may set it lower)");
    }
    if (n > 0) parts.push_back({c, k, n});
    k += n;
    ++c;
  }
  size_t done = 0;
  try {
    for (; done < parts.size(); ++done) {
      const auto first = meadows.begin() + ptrdiff_t(parts[done].first);
      meadow_chunks_[parts[done].chunk]->add(
          UnderbrushBatch::Meadows(first, first + ptrdiff_t(parts[done].count)));
    }
  } catch (...) {
    for (size_t p = 0; p < done; ++p)
      for (size_t i = parts[p].first; i < parts[p].first + parts[p].count; ++i)
        meadow_chunks_[parts[p].chunk]->remove(meadows[i]->key);
    meadow_chunks_.resize(kept);
    throw;
  }
}

}  // namespace boreas::impl
