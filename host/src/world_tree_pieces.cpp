// boreas: a world's add of trees in pieces — the templates grown a round at a time and
// each piece's trees handed to the batches before the next is grown, so that growing
// 1,000 distinct trees does not hold 1,000 whole models (an aspen's is 2.4 MB, a hundred
// times what the world keeps of it once its block is on the device: TreeModel::Packed).
//
// The add stays all or none. Nothing a piece changes is visible before the call returns
// (the trees get their ids at its end), the trees' keys are given in the call's order
// before any piece, and a piece's trees are added as one call of add_to_tree_chunks; so a
// failure in any piece (a template that will not grow, the device's memory) takes the
// earlier pieces' trees back out of the chunks, drops the chunks the call made and moves
// every other chunk back into buffers of the capacities it had (TreeBatch::restore_room):
// the state, the counted device memory and what later adds and steps give are those of a
// world that never saw the call. Where each tree's state lies within a batch does not
// change its bits (each branch is stepped from its own entries and its parent's), so the
// pieces give the bits of one piece.
#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

#include "errors.h"
#include "parallel_for.h"
#include "world.h"

namespace boreas::impl {

void World::reserve_for_the_rest(const TreeBatch::Room (&before)[2], size_t trees, size_t taken) {
  // The first piece's trees are a sample of the call's (in the order their templates are
  // first needed): each first chunk grown at once to what they took, times trees / taken,
  // and a sixteenth more, so the later pieces rarely double a space and the add ends without
  // a copy to fit it (fit_room). A world split over chunks grows as before; a refused
  // reservation is no failure (the pieces then grow the spaces themselves).
  if (chunks_[0].size() > 1 || chunks_[1].size() > 1 || taken == 0) return;
  const double scale = double(trees) / double(taken) * 1.0625;
  auto more = [&](int64_t had, int64_t now) { return had + int64_t(double(now - had) * scale); };
  for (int m = 0; m < 2; ++m) {
    TreeBatch& chunk = *chunks_[m].front();
    const TreeBatch::Room now = chunk.used_room();
    if (now == before[m]) continue;
    try {
      chunk.reserve_room({more(before[m].own, now.own), more(before[m].settled, now.settled),
                          more(before[m].template_entries, now.template_entries),
                          more(before[m].template_leaves, now.template_leaves)});
    } catch (const Error&) {
    }
  }
}

void World::add_tree_pieces(TreeTemplates::Request& request,
                            const std::vector<std::shared_ptr<TreeInstance>>& all, bool name_defs,
                            const std::function<void(int, const Error&)>& named) {
  // The trees of each template grown (by_grow[1 + g]); those of living templates go with
  // the first piece (by_grow[0]).
  const size_t grows = request.grows();
  std::vector<std::vector<int>> by_grow(grows + 1);
  for (int i = 0; i < int(all.size()); ++i)
    by_grow[size_t(1 + request.grow_index(i))].push_back(i);
  // A round keeps every thread busy a while (templates differ in their time to grow).
  const size_t round = 4 * (all.size() > 1 ? host_threads() : 1);
  const size_t kept[2] = {chunks_[0].size(), chunks_[1].size()};
  std::vector<TreeBatch::Room> rooms[2];
  for (int m = 0; m < 2; ++m)
    for (const auto& chunk : chunks_[m]) rooms[m].push_back(chunk->room());
  std::vector<int> added;
  add_peak_whole_bytes_ = 0;
  // What each first chunk held before: the first piece's take, scaled, is the add's.
  TreeBatch::Room piece_used[2] = {chunks_[0].front()->used_room(), chunks_[1].front()->used_room()};
  try {
    size_t grown = 0, handed = 0, pieces = 0;
    do {
      const size_t end = std::min(grows, grown + round);
      request.grow(grown, end, named);
      grown = end;
      add_peak_whole_bytes_ = std::max(add_peak_whole_bytes_, request.whole_bytes());
      if (grown < grows && request.whole_bytes() < add_piece_bytes_) continue;
      TreeBatch::Trees piece[2];
      std::vector<int> def_index[2];
      for (size_t b = handed == 0 ? 0 : 1 + handed; b < 1 + grown; ++b)
        for (int i : by_grow[b]) {
          TreeInstance& tree = *all[size_t(i)];
          tree.model = request.of(i).model;
          tree.template_key = request.of(i).key;
          const int m = tree.params.mode == BOREAS_TREE_EXACT ? 1 : 0;
          piece[m].push_back(all[size_t(i)]);
          def_index[m].push_back(i);
        }
      // The chunks take the piece whole or not at all (world_chunks.cpp).
      add_to_tree_chunks(piece, def_index, name_defs);
      for (int m = 0; m < 2; ++m) added.insert(added.end(), def_index[m].begin(), def_index[m].end());
      // The device holds the piece's blocks: the world keeps its models packed (their
      // leaves grow again for the few readers that need them).
      request.pack(handed, grown);
      for (int m = 0; m < 2; ++m)
        for (int i : def_index[m]) all[size_t(i)]->model = request.of(i).model;
      handed = grown;
      if (++pieces == 1 && handed < grows) reserve_for_the_rest(piece_used, all.size(), added.size());
    } while (handed < grows);
    // Where the reservation guessed short (or the world is split over chunks) the pieces
    // doubled a space: fitted to what it holds where it passes that by a quarter (a
    // failure here leaves the space bigger, that is all).
    if (pieces > 1) {
      for (int m = 0; m < 2; ++m)
        for (size_t c = 0; c < chunks_[m].size(); ++c) try {
            chunks_[m][c]->fit_room(c < kept[m] ? rooms[m][c] : TreeBatch::Room{});
          } catch (const Error&) {
          }
    }
  } catch (...) {
    for (int m = 0; m < 2; ++m) {
      chunks_[m].resize(kept[m]);  // the chunks this call made, with their trees
      for (size_t c = 0; c < kept[m]; ++c) {
        TreeBatch& chunk = *chunks_[m][c];
        for (int i : added)
          if (chunk.holds(all[size_t(i)]->key)) chunk.remove(all[size_t(i)]->key);
        try {
          chunk.restore_room(rooms[m][c]);
        } catch (const Error&) {
          // Refused memory: the chunk keeps the bigger buffers, its trees as they were.
        }
      }
    }
    throw;
  }
}

}  // namespace boreas::impl
