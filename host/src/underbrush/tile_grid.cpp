// boreas: the colliders' broadphase over underbrush tiles (a uniform grid on the ground).
#include "underbrush/tile_grid.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace boreas::impl {

int64_t TileGrid::cell_of(double v) { return int64_t(std::floor(v / kCell)); }

uint64_t TileGrid::key(int64_t ix, int64_t iz) {
  return (uint64_t(uint32_t(int32_t(ix))) << 32) | uint64_t(uint32_t(int32_t(iz)));
}

void TileGrid::build(const std::vector<Bounds>& boxes, const std::vector<bool>& live) {
  boxes_ = boxes;
  cells_.clear();
  wide_.clear();
  seen_.assign(boxes.size(), 0);
  queries_ = 0;
  for (size_t t = 0; t < boxes.size(); ++t) {
    if (!live[t]) continue;
    const Bounds& b = boxes[t];
    const int64_t x0 = cell_of(b.lo[0]), x1 = cell_of(b.hi[0]);
    const int64_t z0 = cell_of(b.lo[2]), z1 = cell_of(b.hi[2]);
    if ((x1 - x0 + 1) * (z1 - z0 + 1) > kMaxCells) {
      wide_.push_back(int32_t(t));
      continue;
    }
    for (int64_t ix = x0; ix <= x1; ++ix)
      for (int64_t iz = z0; iz <= z1; ++iz) cells_[key(ix, iz)].push_back(int32_t(t));
  }
}

void TileGrid::query(const Bounds& b, std::vector<int32_t>* out) const {
  if (++queries_ == 0) {  // the stamps wrapped: start them afresh
    std::fill(seen_.begin(), seen_.end(), 0);
    queries_ = 1;
  }
  const size_t start = out->size();
  auto take = [&](int32_t t) {
    if (seen_[size_t(t)] == queries_ || !boxes_[size_t(t)].overlaps(b)) return;
    seen_[size_t(t)] = queries_;
    out->push_back(t);
  };
  for (int32_t t : wide_) take(t);
  // A collider's box is small beside the meadow: its cells, each looked up (a box beyond
  // kMaxCells cells has its cells' tiles found by walking the filed ones instead).
  const int64_t x0 = cell_of(b.lo[0]), x1 = cell_of(b.hi[0]);
  const int64_t z0 = cell_of(b.lo[2]), z1 = cell_of(b.hi[2]);
  if ((x1 - x0 + 1) * (z1 - z0 + 1) <= int64_t(cells_.size())) {
    for (int64_t ix = x0; ix <= x1; ++ix)
      for (int64_t iz = z0; iz <= z1; ++iz) {
        auto it = cells_.find(key(ix, iz));
        if (it != cells_.end())
          for (int32_t t : it->second) take(t);
      }
  } else {
    for (const auto& [k, tiles] : cells_)
      for (int32_t t : tiles) take(t);
  }
  std::sort(out->begin() + std::ptrdiff_t(start), out->end());
}

}  // namespace boreas::impl
