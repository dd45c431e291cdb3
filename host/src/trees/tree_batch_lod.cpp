// boreas: a tree batch's levels of detail — each tree's from the focus points, the blends
// of trees that change level, and the tile lists that the levels decide.
#include <algorithm>
#include <cmath>
#include <limits>

#include "shared/tree_types.h"
#include "trees/tree_batch.h"

namespace boreas::impl {

void TreeBatch::set_focus(const std::vector<double>& xyz) { focus_ = xyz; }

std::array<int64_t, kTreeLodCount> TreeBatch::lod_counts() const {
  std::array<int64_t, kTreeLodCount> counts{};
  for (const Slot& s : slots_)
    if (s.tree) ++counts[size_t(s.lod)];
  return counts;
}

TreeLod TreeBatch::lod_of(const TreeParams& params) const {
  const size_t points = focus_.size() / 3;
  if (points == 0) return TreeLod::kFull;
  const auto& p = params.position;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < points; ++f) {
    const double dx = p[0] - focus_[3 * f], dy = p[1] - focus_[3 * f + 1],
                 dz = p[2] - focus_[3 * f + 2];
    nearest = std::min(nearest, dx * dx + dy * dy + dz * dz);
  }
  return tree_lod_at(params, std::sqrt(nearest));
}

void TreeBatch::update_lods(double dt) {
  const float resume_hold = float(std::exp(-dt / kResumeTimeConstant));
  const bool new_dt = dt != hold_dt_;
  hold_dt_ = dt;
  stepped_ = carried_ = 0;
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    bool retile = change_lod(slot, dt);
    const float hold = slot.resume_left > 0.0 ? resume_hold : 0.0f;
    if (hold != slot.hold && (hold == 0.0f || slot.hold == 0.0f || new_dt)) retile = true;
    slot.hold = hold;
    slot.resume_left = std::max(0.0, slot.resume_left - dt);
    if (retile) {
      // Its branches may be updated in other steps from now on: both halves of the state
      // start equal, so none shows an older value whatever its new rate and phase.
      if (!slot.frozen) copy_to_next_state(slot);
      if (!rebuild_tiles_) {
        untile(slot);
        tile(slot);
      }
    }
    if (!slot.frozen) {
      const TreeModel& m = *slot.tree->model;
      const int64_t stepped = m.level_begin[size_t(stepped_levels(m, slot.lod))];
      stepped_ += stepped;
      carried_ += int64_t(m.branch_count()) - stepped;
    }
  }
}

bool TreeBatch::change_lod(Slot& slot, double dt) {
  // A tree a collider pushed in the last step is stepped whole while a collider still
  // reaches it; one a collider only reaches keeps its level, but is stepped at least far,
  // so its trunk and limbs meet the collider (tree_batch_contacts.cpp).
  TreeLod lod = lod_of(slot.tree->params);
  if (slot.touching) lod = slot.pushed ? TreeLod::kFull : std::min(lod, TreeLod::kFar);
  if (lod != slot.lod) {
    // Finer than before: the branches that start again ease into the wind.
    if (lod < slot.lod) slot.resume_left = kResumeTime;
    slot.settle_left = lod == TreeLod::kFrozen ? kSettleTime : 0.0;
    slot.frozen = false;
    slot.lod = lod;
    return true;
  }
  if (lod == TreeLod::kFrozen && !slot.frozen) {
    slot.settle_left -= dt;
    if (slot.settle_left <= 0.0) {
      // Settled: its last state goes to both halves of the ping-pong state, so leaving
      // it alone from now on shows it still.
      copy_to_next_state(slot);
      slot.frozen = true;
      return true;
    }
  }
  return false;
}

void TreeBatch::copy_to_next_state(const Slot& slot) {
  const int next = 1 - current_;
  const size_t c = size_t(entries_.capacity);
  runtime_.copy_planes(state_[current_], c, size_t(slot.first), state_[next], c, size_t(slot.first),
                       size_t(slot.count), BOREAS_TREE_STATE_PLANES);
  runtime_.copy_planes(motion_[current_], c, size_t(slot.first), motion_[next], c,
                       size_t(slot.first), size_t(slot.count), BOREAS_TREE_MOTION_PLANES);
}

TreeTileSource TreeBatch::tile_source(const Slot& slot) const {
  const Template& t = template_of(slot);
  TreeTileSource at;
  at.first = slot.first;
  at.static_first = t.first;
  at.scale = slot.tree->params.scale;
  return at;
}

void TreeBatch::tile(Slot& slot) {
  if (slot.frozen) return;
  // The phase of its carried branches: from its key, which moves never change and which is
  // the same whatever chunk of a world holds the tree (world_chunks.cpp), so a split
  // forest carries each tree in the same steps as a whole one. Keys count from 1 in add
  // order: a world that never removed a tree gets the phases its slots gave before.
  const int phase = int((slot.tree->key - 1) & 0xffff);
  add_tree_tiles(tiles_, mode_, *slot.tree->model, tile_source(slot), slot.lod, slot.hold, phase,
                 int(runtime_.group_size()), &slot.tiles);
}

void TreeBatch::untile(Slot& slot) {
  for (const TileLists::Segment& s : slot.tiles) tiles_.kill(s);
  slot.tiles.clear();
}

void TreeBatch::rebuild_tiles() {
  tiles_.clear();
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    slot.tiles.clear();
    tile(slot);
  }
  rebuild_tiles_ = false;
}

}  // namespace boreas::impl
