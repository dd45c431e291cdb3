// boreas: a tree batch's levels of detail — each tree's from the focus points, the blends
// of trees that change level, and the tile lists that the levels decide.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "runtime/launch.h"
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
  // Settled trees this step steps or touches come back first (whole, or not at all).
  unsettle(slots_to_unsettle());
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    bool retile = change_lod(slot, dt);
    retile = update_derivation(slot, dt) || retile;
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
      carried_ += int64_t(m.branch_count()) - stepped;  // carried or derived: not stepped
    }
  }
  settle_slots();
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

int64_t TreeBatch::branches_derived() const {
  int64_t derived = 0;
  for (const Slot& slot : slots_)
    if (slot.tree && slot.derived) {
      const TreeModel& m = *slot.tree->model;
      derived += m.branch_count() - m.level_begin[size_t(derivable_level(m, slot.lod))];
    }
  return derived;
}

bool TreeBatch::update_derivation(Slot& slot, double dt) {
  const TreeModel& m = *slot.tree->model;
  if (!derivation_ || derivable_level(m, slot.lod) == m.levels) {
    // Stepped (or carried) again: the step writes its level over the marks from now on,
    // and it settles anew before it is derived again.
    slot.derive_left = kSettleTime;
    const bool was = slot.derived;
    if (was) write_derived_poses(slot);
    slot.derived = false;
    return was;
  }
  if (slot.derived) return false;
  // Carried while its bend decays, then derived (its F stays where the last carry left it).
  slot.derive_left -= dt;
  if (slot.derive_left > 0.0) return false;
  write_derived_marks(slot);
  slot.derived = true;
  return true;
}

void TreeBatch::write_derived_marks(const Slot& slot) {
  if (own_count(slot) < slot.count) return write_settled_inputs(slot);  // no own marks
  int32_t begin = 0;
  const std::vector<float> marks = derived_marks(slot, &begin, false);
  const size_t count = marks.size() / 4;
  for (int h = 0; h < 2; ++h)
    runtime_.write_planes(state_[h], size_t(entries_.capacity), size_t(slot.first + block_index(begin)),
                          marks.data(), count, count, 4);
}

std::vector<float> TreeBatch::derived_marks(const Slot& slot, int32_t* first, bool settled) const {
  const TreeModel& m = *slot.tree->model;
  const int level = derivable_level(m, slot.lod);
  const int32_t begin = m.level_begin[size_t(level)], end = m.level_begin[size_t(level) + 1];
  const size_t count = size_t(end - begin);
  *first = begin;
  // Planes 0..3 of each derived entry (cl/shared/tree_state.h): the mark, its parent's
  // entry and its template entry (int bits), its tree's scale.
  std::vector<float> marks(4 * count);
  const int32_t mark = BOREAS_TREE_DERIVED_MARK;
  float mark_bits;
  std::memcpy(&mark_bits, &mark, sizeof mark_bits);
  std::fill_n(marks.begin(), count, mark_bits);
  derived_inputs(m, level, slot.first, template_of(slot).first, float(slot.tree->params.scale),
                 marks.data() + count, count, 0, settled);
  return marks;
}

void TreeBatch::derived_inputs(const TreeModel& m, int level, int32_t root, int32_t static_first,
                               float scale, float* out, size_t stride, size_t at, bool settled) {
  const int32_t begin = m.level_begin[size_t(level)], end = m.level_begin[size_t(level) + 1];
  auto bits = [](int32_t i) {
    float f;
    std::memcpy(&f, &i, sizeof f);
    return f;
  };
  for (int32_t b = begin; b < end; ++b) {
    const int32_t parent = m.packed ? m.packed->branches[size_t(b)].parent : m.branches[size_t(b)].parent;
    const size_t k = at + size_t(b - begin);
    out[k] = bits(settled && parent >= begin ? parent - b : root + (parent < 0 ? 0 : block_index(parent)));
    out[stride + k] = bits(static_first + block_index(b));
    out[2 * stride + k] = scale;
  }
}

void TreeBatch::rewrite_derived_marks() {
  for (const Slot& slot : slots_)
    if (slot.tree && slot.derived) write_derived_marks(slot);
  // No branch is posed any more (its marks are back).
  if (any_posed_) BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(posed_, cl_int(0), 0, posed_capacity_ * sizeof(cl_int)));
  any_posed_ = false;
}

void TreeBatch::tile_derived(Slot& slot) {
  // A settled level has no own entries to pose into: its readers derive it. Nor does a
  // level with split pieces get posed in place: one launch would write a piece's parent
  // while the piece reads it (its readers derive its chains).
  if (!slot.derived || own_count(slot) < slot.count) return;
  const TreeModel& m = *slot.tree->model;
  const int level = derivable_level(m, slot.lod);
  if (level_has_splits(m, level)) return;
  const int32_t begin = m.level_begin[size_t(level)];
  TileLists::Shared shared;
  shared.root = slot.first;
  shared.scale = float(slot.tree->params.scale);
  shared.static_first = template_of(slot).first + block_index(begin);
  shared.object = int32_t(&slot - slots_.data()) + 1;
  slot.derive_tiles = derive_tiles_.add(0, slot.first + block_index(begin),
                                        m.level_begin[size_t(level) + 1] - begin,
                                        int(runtime_.group_size()), shared);
}

void TreeBatch::untile_derived(Slot& slot) {
  derive_tiles_.kill(slot.derive_tiles);
  slot.derive_tiles = TileLists::Segment{};
}

void TreeBatch::pose_derived(int32_t first, int32_t count, bool use_table) {
  // Blocks moved since the tiles were made: the readers derive each branch themselves.
  if (count == 0 || rebuild_tiles_ || !posing_) return;
  const size_t rows = slots_.size() + 1;
  if (posed_capacity_ < rows) {
    mark_posed();  // the flags are lost with their buffer
    posed_capacity_ = std::max(rows, 2 * posed_capacity_);
    posed_ = runtime_.buffer(CL_MEM_READ_WRITE, posed_capacity_ * sizeof(cl_int), "tree posed rows");
    BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(posed_, cl_int(0), 0, posed_capacity_ * sizeof(cl_int)));
  }
  derive_tiles_.flush(runtime_);
  cl::Kernel& k = runtime_.kernel("tree_derive.cl", "boreas_tree_derive", plane_defines());
  launch(runtime_, k, Items(size_t(count) * runtime_.group_size()), state_[current_],
         motion_[current_], int(entries_.capacity), parents_, shape_, int(static_entries_.capacity),
         derive_tiles_.buffer(0), int(first), use_table ? table_buffer_ : posed_, int(use_table),
         posed_, 0);
  any_posed_ = true;
}

void TreeBatch::mark_posed() {
  if (!any_posed_) return;
  derive_tiles_.flush(runtime_);
  const size_t tiles = derive_tiles_.size(0);
  if (tiles > 0) {
    cl::Kernel& k = runtime_.kernel("tree_derive.cl", "boreas_tree_derive", plane_defines());
    launch(runtime_, k, Items(tiles * runtime_.group_size()), state_[current_], motion_[current_],
           int(entries_.capacity), parents_, shape_, int(static_entries_.capacity),
           derive_tiles_.buffer(0), 0, posed_, 0, posed_, 1);
  }
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(posed_, cl_int(0), 0, posed_capacity_ * sizeof(cl_int)));
  any_posed_ = false;
}

void TreeBatch::set_derivation(bool on) { derivation_ = on; }

void TreeBatch::carry_derived_branches(const PlantWind& wind) {
  drop_settled();
  std::vector<int32_t> settled;
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree && own_count(slots_[s]) < slots_[s].count) settled.push_back(int32_t(s));
  unsettle(settled);
  // Tier by tier (a split piece after its parent), as the step carries them.
  TileLists tiles(kMaxTreeTiers);
  int lists = 0;
  for (Slot& slot : slots_) {
    if (!slot.tree || !slot.derived) continue;
    lists = std::max(lists, add_derived_tier_tiles(tiles, slot, 0));
    slot.derived = false;
    slot.derive_left = 0.0;
    untile(slot);
    tile(slot);
  }
  if (tiles.size(0) == 0) return;
  tiles.flush(runtime_);
  tiles_.flush(runtime_);
  cl::Kernel& carry = runtime_.kernel("tree_step.cl", "boreas_tree_step",
                                      step_defines(wind) + "#define BOREAS_TREE_CARRY 1\n");
  const cl::Buffer& s = state_[current_];
  const cl::Buffer& mo = motion_[current_];
  if (!breaks_()) breaks_ = runtime_.buffer(CL_MEM_READ_WRITE, sizeof(cl_int), "tree breaks");
  upload_places(wind);  // not read by a carry, but bound
  for (int l = 0; l < lists; ++l)
    launch(runtime_, carry, Items(tiles.size(l) * runtime_.group_size()).per_work_item(size_t(step_width())),
           s, s, parents_, shape_, response_planes(), mo, mo, s, mo, int(entries_.capacity),
           int(static_entries_.capacity), tiles.buffer(l), 0, 1.0f, *wind.waves, wind.wave_count,
           *wind.grid, wind.grid_layout, places_, breaks_);
  BOREAS_CL_CHECK(runtime_.queue().finish());
}

void TreeBatch::copy_to_next_state(const Slot& slot) {
  const int next = 1 - current_;
  const size_t c = size_t(entries_.capacity), own = size_t(own_count(slot));
  runtime_.copy_planes(state_[current_], c, size_t(slot.first), state_[next], c, size_t(slot.first),
                       own, BOREAS_TREE_STATE_PLANES);
  runtime_.copy_planes(motion_[current_], c, size_t(slot.first), motion_[next], c,
                       size_t(slot.first), own, size_t(motion_planes_));
}

TreeTileSource TreeBatch::tile_source(const Slot& slot) const {
  const Template& t = template_of(slot);
  TreeTileSource at;
  at.first = slot.first;
  at.static_first = t.first;
  at.scale = slot.tree->params.scale;
  at.object = place_row(slot);  // its row of the step's places (shared/tree_origin.h)
  return at;
}

void TreeBatch::tile(Slot& slot) {
  tile_derived(slot);
  if (slot.frozen) return;
  // The phase of its carried branches: from its key, which moves never change and which is
  // the same whatever chunk of a world holds the tree (world_chunks.cpp), so a split
  // forest carries each tree in the same steps as a whole one. Keys count from 1 in add
  // order: a world that never removed a tree gets the phases its slots gave before.
  const int phase = int((slot.tree->key - 1) & 0xffff);
  add_tree_tiles(tiles_, mode_, *slot.tree->model, tile_source(slot), slot.lod, slot.hold, phase,
                 int(runtime_.group_size()), &slot.tiles, slot.derived);
}

void TreeBatch::untile(Slot& slot) {
  for (const TileLists::Segment& s : slot.tiles) tiles_.kill(s);
  slot.tiles.clear();
  untile_derived(slot);
}

void TreeBatch::rebuild_tiles() {
  tiles_.clear();
  derive_tiles_.clear();
  for (Slot& slot : slots_) {
    if (!slot.tree) continue;
    slot.tiles.clear();
    slot.derive_tiles = TileLists::Segment{};
    tile(slot);
  }
  rebuild_tiles_ = false;
}

}  // namespace boreas::impl
