// boreas: where a batch's trees stand (issue 40, cl/shared/tree_origin.h). Their state is
// kept relative to each tree's base, so what a step does to a tree does not depend on where
// it stands; these are the tables that put the base back: the step's places (the base and
// each wave's phase there, for the wind) and the readers' offsets (base - output origin,
// for the records), and the colliders brought to a tree's base for its contact launch.
//
// The phases are a row per tree, computed each step in double. Per ~256 m cell of trees
// would compute and upload fewer rows, but per tree is already cheap beside the step it
// feeds: 10,000 trees with 4 waves are 40,000 phases (a multiply-add and a floor each in
// double) and 320 KB uploaded, against a forest step of tens of milliseconds
// (bench/RESULTS.md), and a row per tree needs no cell table and gives each tree the
// wind of a tree at 0 (bit for bit where the phase is the same).
#include <algorithm>
#include <cmath>

#include "trees/tree_batch.h"

namespace boreas::impl {

TreeParams at_own_base(const TreeParams& params) {
  TreeParams local = params;
  local.position = {0.0, 0.0, 0.0};
  return local;
}

void TreeBatch::upload_places(const PlantWind& wind) {
  const int floats = BOREAS_TREE_PLACE_FLOATS(wind.wave_count);
  const size_t rows = slots_.size() + 1;
  places_host_.assign(rows * size_t(floats), 0.0f);
  for (const Slot& slot : slots_) {
    if (!slot.tree) continue;
    float* r = &places_host_[size_t(place_row(slot)) * size_t(floats)];
    const auto& at = slot.tree->params.position;
    for (int a = 0; a < 3; ++a) r[BOREAS_TREE_PLACE_BASE + a] = float(at[size_t(a)]);
    if (wind.wave_count > 0) wind.phases_at(at[0], at[2], r + BOREAS_TREE_PLACE_PHASES);
  }
  const size_t bytes = places_host_.size() * sizeof(float);
  if (bytes > places_capacity_) {
    places_capacity_ = std::max(bytes, 2 * places_capacity_);
    places_ = runtime_.buffer(CL_MEM_READ_ONLY, places_capacity_, "tree places");
  }
  runtime_.upload_async(places_, places_host_);
}

std::array<float, 3> TreeBatch::offset_of(const Slot& slot, const Origin& output_origin) {
  std::array<float, 3> o{};
  for (size_t a = 0; a < 3; ++a)
    o[a] = float(slot.tree->params.position[a] - output_origin[a]);
  return o;
}

const cl::Buffer& TreeBatch::reader_offsets(const Origin* output_origin, const Slot* only) {
  // One rule: the table is every row's offset for one origin (nullptr's zeros:
  // offsets_zero_) as of view generation offsets_generation_, and is kept while both hold,
  // so a view call per frame over an unchanged forest walks no tree and uploads nothing.
  const bool zero = output_origin == nullptr;
  if (offsets_() && offsets_generation_ == view_generation_ && zero == offsets_zero_ &&
      (zero || *output_origin == offsets_origin_))
    return offsets_;
  const size_t rows = slots_.size() + 1;
  const size_t row_bytes = BOREAS_TREE_OFFSET_FLOATS * sizeof(float);
  if (only && offsets_() && rows * row_bytes <= offsets_capacity_) {
    // One tree's call reads its row alone: that row written (16 bytes), so a caller reading
    // every tree in turn pays per tree, not per forest; the table is then no one origin's.
    std::array<float, BOREAS_TREE_OFFSET_FLOATS> row{};
    if (output_origin) {
      const std::array<float, 3> o = offset_of(*only, *output_origin);
      std::copy(o.begin(), o.end(), row.begin());
    }
    runtime_.write(offsets_, size_t(place_row(*only)) * row_bytes, row_bytes, row.data());
    offsets_generation_ = kNoGeneration;
    return offsets_;
  }
  runtime_.count_table_rows(slots_.size());
  std::vector<float> offsets(rows * BOREAS_TREE_OFFSET_FLOATS, 0.0f);
  if (output_origin)
    for (const Slot& slot : slots_) {
      if (!slot.tree) continue;
      const std::array<float, 3> o = offset_of(slot, *output_origin);
      std::copy(o.begin(), o.end(), &offsets[size_t(place_row(slot)) * BOREAS_TREE_OFFSET_FLOATS]);
    }
  const size_t bytes = offsets.size() * sizeof(float);
  if (bytes > offsets_capacity_) {
    offsets_capacity_ = std::max(bytes, 2 * offsets_capacity_);
    offsets_ = runtime_.buffer(CL_MEM_READ_ONLY, offsets_capacity_, "tree reader offsets");
  }
  runtime_.write(offsets_, 0, bytes, offsets.data());
  offsets_generation_ = view_generation_;
  offsets_zero_ = zero;
  if (!zero) offsets_origin_ = *output_origin;
  return offsets_;
}

BoreasGpuCollider TreeBatch::relative_collider(BoreasGpuCollider c,
                                               const std::array<double, 3>& center,
                                               const Slot& slot) {
  // Its position at the step's start (in double: its pose's origin + position) less the
  // base, rounded once: exact to float near the base wherever the tree stands (its move
  // and axes are directions or differences).
  const auto& at = slot.tree->params.position;
  c.cx = float(center[0] - at[0]);
  c.cy = float(center[1] - at[1]);
  c.cz = float(center[2] - at[2]);
  return c;
}

}  // namespace boreas::impl
