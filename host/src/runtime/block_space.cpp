// boreas: block spaces and block moves (block_space.h).
#include "runtime/block_space.h"

#include <algorithm>

namespace boreas::impl {

int64_t BlockSpace::grown(int64_t more, int64_t minimum, int64_t maximum) const {
  if (fits(more)) return std::max(capacity, minimum);
  const int64_t need = used() + more;
  if (4 * need <= 3 * capacity) return std::max(capacity, minimum);
  return std::max(need, std::min(std::max({need, 2 * capacity, minimum}), maximum));
}

int64_t BlockSpace::shrunk(int64_t minimum) const {
  if (!wants_shrinking(minimum)) return capacity;
  int64_t c = capacity;
  while (c / 2 >= minimum && 2 * used() <= c / 2) c /= 2;
  return c;
}

int64_t BlockSpace::fitted(int64_t minimum) const {
  int64_t c = capacity;
  while (c / 2 >= minimum && 4 * used() <= 3 * (c / 2)) c /= 2;
  return c;
}

void BlockSpace::release(int64_t first, int64_t count) {
  if (first + count == end)
    end -= count;
  else
    dead += count;
}

BlockPlan plan_block_moves(const std::vector<std::pair<int64_t, int64_t>>& blocks, bool pack) {
  std::vector<size_t> order(blocks.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return blocks[a].first < blocks[b].first; });
  BlockPlan plan;
  plan.to.resize(blocks.size());
  for (size_t k : order) {
    const auto [from, count] = blocks[k];
    const int64_t to = pack ? plan.end : from;
    plan.moves.push_back({from, to, count});
    plan.to[k] = to;
    plan.end = to + count;
    plan.moves_any = plan.moves_any || to != from;
  }
  return plan;
}

void copy_block_moves(Runtime& runtime, std::vector<BlockMove> moves, const PlanePair* sets,
                      size_t set_count, size_t old_stride, size_t new_stride) {
  moves.insert(moves.begin(), BlockMove{0, 0, 1});
  size_t k = 0;
  while (k < moves.size()) {
    BlockMove run = moves[k];
    for (++k; k < moves.size() && moves[k].from == run.from + run.length &&
              moves[k].to == run.to + run.length;
         ++k)
      run.length += moves[k].length;
    if (run.length <= 0) continue;
    for (const PlanePair* set = sets; set != sets + set_count; ++set)
      runtime.copy_planes(*set->from, old_stride, size_t(run.from), *set->to, new_stride,
                          size_t(run.to), size_t(run.length), size_t(set->planes), set->elem);
  }
}

}  // namespace boreas::impl
