// boreas: the broadphase between colliders and a batch's underbrush tiles — each tile's box
// (its components' rest bases and centres of mass, grown by how far they and their push
// reach) filed in the cells of a uniform grid over the ground (XZ), so a collider finds the
// tiles it may touch by the cells under its swept box: the work is in proportion to the
// tiles near colliders, not to all tiles times all colliders.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "colliders/collider.h"

namespace boreas::impl {

class TileGrid {
 public:
  // Files every box whose `live` is true (index = tile index); replaces what was filed.
  void build(const std::vector<Bounds>& boxes, const std::vector<bool>& live);
  // Appends to `out` each tile whose box meets `b`, once, in increasing tile order.
  void query(const Bounds& b, std::vector<int32_t>* out) const;
  bool empty() const { return boxes_.empty(); }

 private:
  // Cells of kCell m square; a box over more than kMaxCells cells goes on the list every
  // query reads (a tall plant's tile, a hand-made meadow's scattered one).
  static constexpr double kCell = 2.0;
  static constexpr int64_t kMaxCells = 64;
  static int64_t cell_of(double v);
  static uint64_t key(int64_t ix, int64_t iz);

  std::vector<Bounds> boxes_;
  std::unordered_map<uint64_t, std::vector<int32_t>> cells_;
  std::vector<int32_t> wide_;
  mutable std::vector<uint32_t> seen_;  // per tile: the query that last listed it
  mutable uint32_t queries_ = 0;
};

}  // namespace boreas::impl
