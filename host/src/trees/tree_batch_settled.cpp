// boreas: the settled space (cl/shared/tree_types.h, BOREAS_TREE_SETTLED_*): derived
// branches held apart from the trees' own planes, with only what their pose is derived from.
#include <algorithm>
#include <limits>
#include <cstring>
#include <vector>

#include "errors.h"
#include "runtime/cl_check.h"
#include "trees/tree_batch.h"
#include "trees/tree_tiles.h"

namespace boreas::impl {

int32_t TreeBatch::settled_begin(const Slot& slot) const {
  if (slot.settled_first < 0) return slot.count;
  const TreeModel& m = *slot.tree->model;
  return block_index(m.level_begin[size_t(derivable_level(m, slot.lod))]);
}

int32_t TreeBatch::settled_root(const Slot& slot) const {
  if (slot.settled_first < 0) return slot.first;
  return int32_t(entries_.capacity) + slot.settled_first - settled_begin(slot);
}

void TreeBatch::settled_split(uint64_t key, int32_t* own, int32_t* settled_entry) const {
  const Slot& slot = slot_of(key);
  const int32_t begin = settled_begin(slot);
  *own = begin - 1;
  *settled_entry = settled_root(slot) + begin;
}

void TreeBatch::drop_settled() {
  if (!settled_copy_) return;
  for (Slot& slot : slots_) slot.settled_first = -1;
  settled_ = cl::Buffer();
  settled_entries_ = Space{};
  settled_copy_ = false;
  records_stale_ = true;
}

int32_t TreeBatch::own_count(const Slot& slot) const {
  return settled_copy_ ? slot.count : settled_begin(slot);
}

int64_t TreeBatch::branches_settled() const {
  int64_t settled = 0;
  for (const Slot& slot : slots_)
    if (slot.tree) settled += slot.count - own_count(slot);
  return settled;
}

void TreeBatch::write_settled_inputs(const Slot& slot) {
  int32_t begin = 0;
  const std::vector<float> marks = derived_marks(slot, &begin, true);
  const size_t count = marks.size() / 4;
  // Parent, template entry, scale: the marks' planes 1..3.
  runtime_.write_planes(settled_, size_t(settled_entries_.capacity), size_t(slot.settled_first),
                        marks.data() + count, count, count, 3);
}

void TreeBatch::relayout_settled(int64_t capacity, bool pack, int planes) {
  const size_t c = size_t(capacity), old = size_t(settled_entries_.capacity);
  cl::Buffer settled = runtime_.buffer(CL_MEM_READ_WRITE, size_t(planes) * c * sizeof(float),
                                       "tree settled planes");
  // Zero: the sink, and the rate planes where they are new (a still batch's dF/dt is 0).
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(settled, 0.0f, 0, size_t(planes) * c * sizeof(float)));
  std::vector<Slot*> live;
  std::vector<std::pair<int64_t, int64_t>> blocks;
  for (Slot& slot : slots_)
    if (slot.tree && slot.settled_first >= 0) {
      live.push_back(&slot);
      blocks.push_back({slot.settled_first, slot.count - own_count(slot)});
    }
  const BlockPlan plan = plan_block_moves(blocks, pack);
  if (old > 0) {
    const PlanePair set{&settled_, &settled, std::min(planes, settled_planes_), sizeof(float)};
    copy_block_moves(runtime_, plan.moves, &set, 1, old, c);
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  // Nothing failed: the batch takes the buffer.
  for (size_t k = 0; k < live.size(); ++k) live[k]->settled_first = int32_t(plan.to[k]);
  if (pack) settled_entries_.packed(plan.end);
  settled_entries_.capacity = capacity;
  settled_ = settled;
  settled_planes_ = planes;
  if (plan.moves_any) records_stale_ = true;  // readers' settled indices moved
}

void TreeBatch::trim_settled() {
  if (settled_copy_ || settled_entries_.capacity == 0) return;
  if (settled_entries_.used() == 1) {
    // Nothing settled: no buffer (readers are given the shape planes and stride 0).
    settled_ = cl::Buffer();
    settled_entries_ = Space{};
    return;
  }
  if (settled_entries_.wants_shrinking(kMinEntries) || settled_entries_.wants_packing())
    relayout_settled(settled_entries_.shrunk(kMinEntries), true, settled_planes_);
}

void TreeBatch::settle_slots() {
  if (!settling_ || !derivation_ || settled_copy_) return;
  // A slot a collider touches (or touched in the last step: its contact planes are live)
  // keeps its own entries.
  std::vector<Slot*> settling;
  int64_t need = 0;
  for (Slot& slot : slots_)
    if (slot.tree && slot.derived && slot.settled_first < 0 && !slot.touching && !slot.touched) {
      settling.push_back(&slot);
      const TreeModel& m = *slot.tree->model;
      need += m.branch_count() - m.level_begin[size_t(derivable_level(m, slot.lod))];
    }
  if (settling.empty()) return;
  // Room first; settling is only memory: where it is refused, they stay as they are.
  if (!settled_room(need, entries_.capacity)) return;
  for (Slot* slot : settling) settle(*slot);
  // The released tails are holes (or the space's end): the own planes pack, and fit to
  // what is left (runtime/block_space.h, fitted: a settled level is not expected back
  // soon); a refusal leaves them where they are.
  try {
    const int64_t fitted = entries_.fitted(kMinEntries);
    if (fitted < entries_.capacity || entries_.wants_packing()) relayout_trees(fitted, true);
  } catch (const Error&) {
  }
}
void TreeBatch::settle(Slot& slot) {
  // Its inputs, F and the broken flag (and dF/dt where the batch holds rates), as the
  // last carry left them: equal in both halves (update_derivation), so one copy.
  const size_t n = size_t(entries_.capacity), c = size_t(settled_entries_.capacity);
  int32_t begin = 0;
  const std::vector<float> marks = derived_marks(slot, &begin, true);
  const int32_t own = block_index(begin), count = int32_t(marks.size() / 4);
  const size_t at = size_t(settled_entries_.end), from = size_t(slot.first + own);
  runtime_.write_planes(settled_, c, at, marks.data() + count, size_t(count), size_t(count), 3);
  runtime_.copy_planes(motion_[current_], n, from, settled_, c, at + size_t(BOREAS_TREE_SETTLED_F) * c,
                       size_t(count), BOREAS_TREE_MOTION_STILL_PLANES);
  if (holds_rates())
    runtime_.copy_planes(motion_[current_], n, from + size_t(BOREAS_TREE_MOTION_DF) * n, settled_, c,
                         at + size_t(BOREAS_TREE_SETTLED_DF) * c, size_t(count), 3);
  settled_entries_.end += count;
  // Its finest level leaves the own planes: no derive tiles (readers derive it from the
  // settled planes), and the tail of its block released.
  if (!rebuild_tiles_) untile_derived(slot);
  entries_.release(slot.first + own, count);
  slot.settled_first = int32_t(at);
  rerecord_tree(int32_t(&slot - slots_.data()));
}

void TreeBatch::rerecord_tree(int32_t s) {
  // Its record tiles and view row anew (its id kept): the others' stay.
  if (records_stale_) return;
  for (TileLists::Segment& segment : slots_[size_t(s)].record_tiles) {
    record_tiles_.kill(segment);
    segment = TileLists::Segment{};
  }
  record_tree(s);
}

std::vector<int32_t> TreeBatch::slots_to_unsettle() const {
  std::vector<int32_t> out;
  for (size_t s = 0; s < slots_.size(); ++s) {
    const Slot& slot = slots_[s];
    if (!slot.tree || own_count(slot) == slot.count) continue;
    // What change_lod and update_derivation will find: a collider's touch steps it (or
    // its contact launch reads it); a level of detail that steps the finest level.
    const TreeModel& m = *slot.tree->model;
    if (slot.touching || !settling_ || !derivation_ ||
        derivable_level(m, lod_of(slot.tree->params)) == m.levels)
      out.push_back(int32_t(s));
  }
  return out;
}

void TreeBatch::unsettle(const std::vector<int32_t>& which) {
  if (which.empty() || settled_copy_) return;
  // Room for every whole block first (make_room's path): where it does not fit after the
  // end, the space is packed (grown if need be) with these blocks whole. All new buffers
  // are made before anything changes: a refusal leaves them settled, the batch as it was.
  int64_t need = 0;
  for (int32_t s : which) need += slots_[size_t(s)].count;
  std::vector<int32_t> old_first(which.size());
  for (size_t k = 0; k < which.size(); ++k) old_first[k] = slots_[size_t(which[k])].first;
  const bool packed = !entries_.fits(need);
  if (packed) relayout_trees(entries_.grown(need, kMinEntries, space_limits().entries), true, &which);
  const size_t n = size_t(entries_.capacity), c = size_t(settled_entries_.capacity);
  for (int32_t s : which) {
    Slot& slot = slots_[size_t(s)];
    const int32_t own = own_count(slot), count = slot.count - own;
    if (!packed) {
      if (slot.first + own == entries_.end) {
        entries_.end += count;  // its tail is the space's end: taken back in place
      } else {
        // After the end: its own entries moved there, plane by plane (one buffer).
        const int64_t to = entries_.end;
        entries_.end += slot.count;
        auto move = [&](const cl::Buffer& b, int planes) {
          for (int p = 0; p < planes; ++p)
            BOREAS_CL_CHECK(runtime_.queue().enqueueCopyBuffer(
                b, b, (size_t(p) * n + size_t(slot.first)) * sizeof(float),
                (size_t(p) * n + size_t(to)) * sizeof(float), size_t(own) * sizeof(float)));
        };
        for (int h = 0; h < 2; ++h) {
          move(state_[h], BOREAS_TREE_STATE_PLANES);
          move(motion_[h], motion_planes_);
        }
        entries_.release(slot.first, own);
        slot.first = int32_t(to);
      }
    }
    // Its marks, F and the broken flag (and dF/dt) back in both halves, as they were.
    const size_t at = size_t(slot.settled_first), to = size_t(slot.first + own);
    slot.settled_first = -1;
    write_derived_marks(slot);
    for (int h = 0; h < 2; ++h) {
      runtime_.copy_planes(settled_, c, at + size_t(BOREAS_TREE_SETTLED_F) * c, motion_[h], n, to,
                           size_t(count), BOREAS_TREE_MOTION_STILL_PLANES);
      if (holds_rates() && settled_planes_ == BOREAS_TREE_SETTLED_RATE_PLANES)
        runtime_.copy_planes(settled_, c, at + size_t(BOREAS_TREE_SETTLED_DF) * c, motion_[h], n,
                             to + size_t(BOREAS_TREE_MOTION_DF) * n, size_t(count), 3);
      else if (holds_rates())  // settled while the batch was still: its dF/dt is 0
        for (int p = BOREAS_TREE_MOTION_DF; p < BOREAS_TREE_MOTION_PLANES; ++p)
          BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
              motion_[h], 0.0f, (size_t(p) * n + to) * sizeof(float), size_t(count) * sizeof(float)));
    }
    settled_entries_.release(int64_t(at), count);
    if (!rebuild_tiles_) {
      untile(slot);
      tile(slot);
    }
    rerecord_tree(s);
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  try {
    trim_settled();
  } catch (const Error&) {
  }
}

std::vector<TreeBatch::SettledRange> TreeBatch::copy_derived_to_settled() {
  drop_settled();
  // Settled trees come back first: a copy keeps every own entry.
  std::vector<int32_t> back;
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree && slots_[s].settled_first >= 0) back.push_back(int32_t(s));
  unsettle(back);
  std::vector<SettledRange> ranges;
  std::vector<Slot*> settled_slots;
  std::vector<std::vector<float>> marks;
  int64_t end = 1;  // entry 0: the sink, as in every space
  for (Slot& slot : slots_) {
    if (!slot.tree || !slot.derived) continue;
    int32_t begin = 0;
    marks.push_back(derived_marks(slot, &begin, true));
    SettledRange r;
    r.count = int32_t(marks.back().size() / 4);
    r.own_first = slot.first + block_index(begin);
    r.settled_first = int32_t(end);
    r.static_first = template_of(slot).first + block_index(begin);
    r.scale = float(slot.tree->params.scale);
    ranges.push_back(r);
    settled_slots.push_back(&slot);
    end += r.count;
  }
  // All new before the batch takes it: a failed allocation leaves every reader on the own
  // planes (their marks and motion are never changed here).
  const int64_t capacity = std::max(kMinEntries, end);
  cl::Buffer settled = runtime_.buffer(
      CL_MEM_READ_WRITE, size_t(BOREAS_TREE_SETTLED_PLANES) * size_t(capacity) * sizeof(float),
      "tree settled planes");
  BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(
      settled, 0.0f, 0, size_t(BOREAS_TREE_SETTLED_PLANES) * size_t(capacity) * sizeof(float)));
  for (size_t r = 0; r < ranges.size(); ++r) {
    const SettledRange& s = ranges[r];
    const size_t count = size_t(s.count);
    // Parent, template entry, scale: the marks' planes 1..3 (the state may hold poses now).
    runtime_.write_planes(settled, size_t(capacity), size_t(s.settled_first), marks[r].data() + count,
                          count, count, 3);
    // F and the broken flag, as the last carry left them (equal in both halves).
    runtime_.copy_planes(motion_[current_], size_t(entries_.capacity), size_t(s.own_first), settled,
                         size_t(capacity), size_t(s.settled_first) + size_t(BOREAS_TREE_SETTLED_F) * size_t(capacity),
                         count, 4);
  }
  settled_ = settled;
  settled_entries_ = Space{};
  settled_entries_.end = end;
  settled_entries_.capacity = capacity;
  settled_planes_ = BOREAS_TREE_SETTLED_PLANES;
  settled_copy_ = true;
  for (size_t r = 0; r < ranges.size(); ++r) settled_slots[r]->settled_first = ranges[r].settled_first;
  records_stale_ = true;  // the readers' tiles anew, from the settled entries
  return ranges;
}

}  // namespace boreas::impl
