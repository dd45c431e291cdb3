// boreas: the meadows of a world on the device — blocks, part records, levels of detail,
// the step, readbacks.
#include "underbrush/underbrush_batch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>

#include "errors.h"
#include "free_places.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "shared/underbrush_math.h"
#include "underbrush/frame_pack.h"

namespace boreas::impl {
namespace {

constexpr int kStrip = 2 * BOREAS_UB_JOINTS;

// Padding that does nothing: far away, no reach, no momentum.
BoreasGpuImpulse silent_impulse() {
  return BoreasGpuImpulse{1e18f, 1e18f, 1e18f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
}

// A meadow's part records with their table offsets moved by `table_first`.
void append_parts(const Meadow& m, int64_t table_first, std::vector<BoreasGpuPart>* out) {
  for (const MeadowPart& mp : m.parts) {
    BoreasGpuPart g = mp.gpu;
    g.forward += int32_t(table_first);
    g.inverse += int32_t(table_first);
    g.breaking += int32_t(table_first);
    g.widths += int32_t(table_first);
    out->push_back(g);
  }
}

// A buffer with room for used + more elements of elem bytes, the used ones copied over:
// `buffer` itself while it has the room, else a bigger one (doubling) that replaces it.
void grow_buffer(Runtime& runtime, cl::Buffer& buffer, size_t& capacity, size_t used, size_t more,
                 size_t elem, const char* what) {
  if (used + more <= capacity && buffer() != nullptr) return;
  // Doubling stops at the largest allocation (UnderbrushBatch::fitting keeps what is used
  // within it; 0: the driver does not say).
  const uint64_t largest = runtime.max_allocation();
  const size_t most = largest > 0 ? size_t(largest / elem) : SIZE_MAX;
  const size_t grown = std::max(used + more, std::min(std::max(2 * capacity, size_t(64)), most));
  cl::Buffer bigger = runtime.buffer(CL_MEM_READ_ONLY, grown * elem, what);
  if (used > 0)
    BOREAS_CL_CHECK(runtime.queue().enqueueCopyBuffer(buffer, bigger, 0, 0, used * elem));
  buffer = bigger;
  capacity = grown;
}

// How far from its rest box each component of a piece may reach a collider, m: its center
// of mass stays within its reach (times its scale) of its base, its push reaches as far
// again (boreas_ub_push_size), and a part on a parent has its base moved by `follow` times
// the parent's center of mass's move from rest, itself at most twice the parent's reach
// plus the parent's base's move. Parents come before their parts, in the same piece
// (meadow.cpp), which finds each by how far back it is.
std::vector<float> reach_bounds(const Meadow& m, const float* frame, const int32_t* index,
                                int count) {
  const size_t n = size_t(count);
  std::vector<double> base_move(n, 0.0), reach(n, 0.0);
  std::vector<float> out(n);
  for (size_t c = 0; c < n; ++c) {
    const int ci = int(c);
    const BoreasGpuPart& g = m.parts[size_t(part_of(index, int(n), ci))].gpu;
    reach[c] = double(g.reach) * unpack_frame(index, int(n), ci).scale;
    const size_t parent = size_t(parent_of(index, int(n), ci));
    if (parent < c)
      base_move[c] = frame[BOREAS_UB_FRAME_FOLLOW * n + c] *
                     (2.0 * reach[parent] + base_move[parent]);
    out[c] = float(base_move[c] + 2.0 * reach[c]);
  }
  return out;
}

// Grows a staged device buffer to hold `count` elements of `elem` bytes (doubling; the
// capacity changes only once the new buffer is there).
template <typename Staged>
void grow_staged(Runtime& runtime, Staged& s, size_t count, size_t elem, const char* what) {
  if (count <= s.capacity && s.buffer() != nullptr) return;
  const size_t capacity = std::max({count, 2 * s.capacity, size_t(16)});
  s.buffer = runtime.buffer(CL_MEM_READ_WRITE, capacity * elem, what);
  s.capacity = capacity;
}

}  // namespace

UnderbrushBatch::UnderbrushBatch(Runtime& runtime, std::shared_ptr<PlaceNumbers> tile_numbers)
    : runtime_(runtime),
      tile_numbers_(tile_numbers ? std::move(tile_numbers) : std::make_shared<PlaceNumbers>()) {}

int64_t UnderbrushBatch::max_components() const {
  constexpr int64_t kByIndex = std::numeric_limits<int32_t>::max() / BOREAS_UB_FRAME_PLANES;
  const uint64_t largest = runtime_.max_allocation();  // 0: the driver does not say
  if (largest == 0) return kByIndex;
  return std::min<int64_t>(kByIndex,
                           int64_t(largest / (uint64_t(BOREAS_UB_FRAME_PLANES) * sizeof(float))));
}

size_t UnderbrushBatch::fitting(const Meadows& meadows, size_t first) const {
  // The components as add() would find them once packed (the live ones and the sink), and
  // the part records and shape tables as it appends them (after the dead ones).
  const int64_t most = max_components();
  const uint64_t largest = runtime_.max_allocation();
  const uint64_t most_parts = largest > 0 ? largest / sizeof(BoreasGpuPart) : UINT64_MAX,
                 most_tables = largest > 0 ? largest / sizeof(float) : UINT64_MAX;
  int64_t used = components_.used();
  uint64_t parts = parts_host_.size(), tables = tables_host_.size();
  size_t k = first;
  for (; k < meadows.size(); ++k) {
    const Meadow& m = meadows[k]->meadow;
    if (used + m.count > most || parts + m.parts.size() > most_parts ||
        tables + m.tables.size() > most_tables)
      break;
    used += m.count;
    parts += m.parts.size();
    tables += m.tables.size();
  }
  return k - first;
}

const UnderbrushBatch::Slot& UnderbrushBatch::slot_of(uint64_t key) const {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "underbrush batch has no meadow with key " + std::to_string(key));
  return slots_[size_t(it->second)];
}

int UnderbrushBatch::first(uint64_t key) const { return slot_of(key).first; }

void UnderbrushBatch::relayout(int64_t capacity, bool pack) {
  if (capacity > std::numeric_limits<int32_t>::max() / BOREAS_UB_FRAME_PLANES)
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "underbrush: " + std::to_string(capacity) +
                                         " components pass one batch's 2^31-float planes");
  const size_t c = size_t(capacity);
  const std::string label = "underbrush (" + std::to_string(capacity) + " components)";
  cl::Buffer state[2], frame, index;
  for (auto& s : state)
    s = runtime_.buffer(CL_MEM_READ_WRITE, size_t(BOREAS_UB_STATE_PLANES) * c * sizeof(float),
                        label.c_str());
  frame = runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_UB_FRAME_PLANES) * c * sizeof(float),
                          label.c_str());
  index = runtime_.buffer(CL_MEM_READ_ONLY, size_t(BOREAS_UB_INDEX_PLANES) * c * sizeof(int32_t),
                          label.c_str());
  const PlanePair sets[] = {
      {&state_[0], &state[0], BOREAS_UB_STATE_PLANES, sizeof(float)},
      {&state_[1], &state[1], BOREAS_UB_STATE_PLANES, sizeof(float)},
      {&frame_, &frame, BOREAS_UB_FRAME_PLANES, sizeof(float)},
      {&index_, &index, BOREAS_UB_INDEX_PLANES, sizeof(int32_t)},
  };
  std::vector<Slot*> live;
  std::vector<std::pair<int64_t, int64_t>> blocks;
  for (Slot& slot : slots_)
    if (slot.meadow) {
      live.push_back(&slot);
      blocks.push_back({slot.first, slot.meadow->meadow.count});
    }
  const BlockPlan plan = plan_block_moves(blocks, pack);
  if (components_.capacity == 0) {
    // A new batch: the sink, a component of part 0 fixed to itself at the origin (the
    // no-op tiles' target; part 0 exists once a meadow does).
    std::vector<float> zeros(std::max(BOREAS_UB_FRAME_PLANES, BOREAS_UB_STATE_PLANES), 0.0f);
    std::vector<int32_t> sink_index(BOREAS_UB_INDEX_PLANES, 0);
    const double up[3] = {0.0, 1.0, 0.0}, east[3] = {1.0, 0.0, 0.0};
    sink_index[BOREAS_UB_INDEX_LINK] = pack_link(0, 0, "underbrush sink");
    sink_index[BOREAS_UB_INDEX_AXIS] = pack_axis(up);
    sink_index[BOREAS_UB_INDEX_TURN] =
        pack_turn(sink_index[BOREAS_UB_INDEX_AXIS], east, 1.0, "underbrush sink");
    for (auto& s : state)
      runtime_.write_planes(s, c, 0, zeros.data(), 1, 1, BOREAS_UB_STATE_PLANES);
    runtime_.write_planes(frame, c, 0, zeros.data(), 1, 1, BOREAS_UB_FRAME_PLANES);
    runtime_.write_planes(index, c, 0, sink_index.data(), 1, 1, BOREAS_UB_INDEX_PLANES,
                          sizeof(int32_t));
  } else {
    copy_block_moves(runtime_, plan.moves, sets, std::size(sets), size_t(components_.capacity), c);
  }
  BOREAS_CL_CHECK(runtime_.queue().finish());
  for (size_t k = 0; k < live.size(); ++k) live[k]->first = int32_t(plan.to[k]);
  if (pack) components_.packed(plan.end);
  components_.capacity = capacity;
  state_[0] = state[0];
  state_[1] = state[1];
  frame_ = frame;
  index_ = index;
  if (plan.moves_any) rebuild_tiles_ = true;
}

void UnderbrushBatch::repack_parts() {
  std::vector<BoreasGpuPart> parts;
  std::vector<float> tables;
  for (Slot& slot : slots_) {
    if (!slot.meadow) continue;
    const Meadow& m = slot.meadow->meadow;
    slot.part_first = int32_t(parts.size());
    slot.table_first = int64_t(tables.size());
    append_parts(m, slot.table_first, &parts);
    tables.insert(tables.end(), m.tables.begin(), m.tables.end());
  }
  if (parts.empty()) parts.push_back(BoreasGpuPart{});
  if (tables.empty()) tables.push_back(0.0f);
  cl::Buffer p = runtime_.buffer(CL_MEM_READ_ONLY, parts.size() * sizeof(BoreasGpuPart),
                                 "underbrush part records");
  cl::Buffer t =
      runtime_.buffer(CL_MEM_READ_ONLY, tables.size() * sizeof(float), "underbrush shape tables");
  runtime_.upload(p, parts);
  runtime_.upload(t, tables);
  parts_ = p;
  tables_ = t;
  parts_capacity_ = parts.size();
  tables_capacity_ = tables.size();
  parts_host_ = std::move(parts);
  tables_host_ = std::move(tables);
  dead_parts_ = dead_tables_ = 0;
  parts_dt_ = -1.0;
  rebuild_tiles_ = true;  // the tiles carry the part bases
}

// The part records and shape tables of meadows being added, written past the used ends of
// the device's buffers (or of bigger ones that replace them), not yet the batch's.
struct UnderbrushBatch::NewParts {
  std::vector<BoreasGpuPart> parts;
  std::vector<float> tables;
  std::vector<int32_t> part_first;  // per meadow
  std::vector<int64_t> table_first;
  cl::Buffer parts_buffer, tables_buffer;
  size_t parts_capacity = 0, tables_capacity = 0;
};

void UnderbrushBatch::add(const Meadows& meadows) {
  if (meadows.empty()) return;
  const int64_t need = components_needed(meadows);
  // Room for the components (runtime/block_space.h: holes packed on the way).
  if (!components_.fits(need))
    relayout(components_.grown(need, kMinComponents, max_components()), components_.dead > 0);
  // Written past the used ends of the device's buffers, and finished, before the batch
  // changes: a failure up to here leaves it as it was.
  const NewParts parts = write_new_parts(meadows);
  const int64_t first = components_.end;
  const std::vector<std::vector<TileBox>> boxes = write_new_components(meadows, first, need);
  BOREAS_CL_CHECK(runtime_.queue().finish());

  // Everything is on the device: the batch takes the meadows.
  take_new_parts(parts);
  int64_t at = first;
  for (size_t k = 0; k < meadows.size(); ++k) {
    take_meadow(meadows[k], at, parts.part_first[k], parts.table_first[k], boxes[k]);
    at += meadows[k]->meadow.count;
  }
  components_.end += need;
  component_count_ += need;
}

int64_t UnderbrushBatch::components_needed(const Meadows& meadows) const {
  int64_t need = 0;
  for (const auto& m : meadows) {
    if (by_key_.count(m->key))
      fail(BOREAS_ERROR_INTERNAL, "meadow key " + std::to_string(m->key) + " added twice");
    need += m->meadow.count;
  }
  return need;
}

UnderbrushBatch::NewParts UnderbrushBatch::write_new_parts(const Meadows& meadows) {
  // Part records and tables appended (their buffers grow by doubling on the device).
  NewParts n;
  n.part_first.resize(meadows.size());
  n.table_first.resize(meadows.size());
  for (size_t k = 0; k < meadows.size(); ++k) {
    const Meadow& m = meadows[k]->meadow;
    n.part_first[k] = int32_t(parts_host_.size() + n.parts.size());
    n.table_first[k] = int64_t(tables_host_.size() + n.tables.size());
    append_parts(m, n.table_first[k], &n.parts);
    n.tables.insert(n.tables.end(), m.tables.begin(), m.tables.end());
  }
  if (n.table_first.back() + int64_t(meadows.back()->meadow.tables.size()) >
      std::numeric_limits<int32_t>::max())
    fail(BOREAS_ERROR_OUT_OF_MEMORY, "underbrush: the meadows' shape tables pass 2^31 floats");
  n.parts_buffer = parts_;
  n.tables_buffer = tables_;
  n.parts_capacity = parts_capacity_;
  n.tables_capacity = tables_capacity_;
  grow_buffer(runtime_, n.parts_buffer, n.parts_capacity, parts_host_.size(), n.parts.size(),
              sizeof(BoreasGpuPart), "underbrush part records");
  grow_buffer(runtime_, n.tables_buffer, n.tables_capacity, tables_host_.size(), n.tables.size(),
              sizeof(float), "underbrush shape tables");
  if (parts_dt_ > 0.0)
    for (BoreasGpuPart& g : n.parts)
      g.recovery_loss = static_cast<float>(-std::expm1(-parts_dt_ / double(g.recovery_time)));
  runtime_.write(n.parts_buffer, parts_host_.size() * sizeof(BoreasGpuPart),
                 n.parts.size() * sizeof(BoreasGpuPart), n.parts.data());
  runtime_.write(n.tables_buffer, tables_host_.size() * sizeof(float),
                 n.tables.size() * sizeof(float), n.tables.data());
  return n;
}

std::vector<std::vector<UnderbrushBatch::TileBox>> UnderbrushBatch::write_new_components(
    const Meadows& meadows, int64_t first, int64_t count) {
  // Each meadow's components uploaded from its own planes, or placed a bounded piece at a
  // time from its plantings (meadow.h, place_piece) and uploaded piece by piece: the host
  // holds at most one piece besides the device's planes. Their tiles' boxes are gathered
  // on the way (the pieces are not kept).
  std::vector<std::vector<TileBox>> boxes(meadows.size());
  int64_t at = first;
  MeadowPiece piece;
  for (size_t k = 0; k < meadows.size(); ++k) {
    const Meadow& m = meadows[k]->meadow;
    boxes[k] = empty_boxes(m.count);
    if (m.plantings.empty()) {
      upload_piece(m.frame.data(), m.index.data(), m.rest_state.data(), m.count, at);
      add_to_boxes(m, m.frame.data(), m.index.data(), 0, m.count, &boxes[k]);
    } else {
      int next = 0;
      for (size_t pi = 0; pi < m.plantings.size();) {
        size_t end = pi;
        for (int64_t size = 0;
             end < m.plantings.size() && (end == pi || size < piece_components_); ++end)
          size += components_of(m, m.plantings[end]);
        place_piece(m, pi, end, next, &piece);
        upload_piece(piece.frame.data(), piece.index.data(), piece.rest_state.data(), piece.count,
                     at + next);
        add_to_boxes(m, piece.frame.data(), piece.index.data(), next, piece.count, &boxes[k]);
        next += piece.count;
        pi = end;
      }
    }
    at += m.count;
  }
  const size_t c = size_t(components_.capacity);
  runtime_.copy_planes(state_[current_], c, size_t(first), state_[1 - current_], c, size_t(first),
                       size_t(count), BOREAS_UB_STATE_PLANES);
  return boxes;
}

void UnderbrushBatch::upload_piece(const float* frame, const int32_t* index,
                                   const float* rest_state, int count, int64_t at) {
  // Blocking writes (Runtime::write_planes): the piece may be reused once they return.
  const size_t c = size_t(components_.capacity), n = size_t(count);
  runtime_.write_planes(state_[current_], c, size_t(at), rest_state, n, n, BOREAS_UB_STATE_PLANES);
  runtime_.write_planes(frame_, c, size_t(at), frame, n, n, BOREAS_UB_FRAME_PLANES);
  runtime_.write_planes(index_, c, size_t(at), index, n, n, BOREAS_UB_INDEX_PLANES,
                        sizeof(int32_t));
}

std::vector<UnderbrushBatch::TileBox> UnderbrushBatch::empty_boxes(int count) const {
  const int width = int(runtime_.group_size());
  TileBox empty;
  for (int a = 0; a < 3; ++a) {
    empty.lo[a] = std::numeric_limits<float>::max();
    empty.hi[a] = -std::numeric_limits<float>::max();
  }
  return std::vector<TileBox>(size_t((count + width - 1) / width), empty);
}

void UnderbrushBatch::add_to_boxes(const Meadow& m, const float* frame, const int32_t* index,
                                   int first, int count, std::vector<TileBox>* boxes) const {
  // The box of each tile's components' rest bases and centres of mass, in the world's
  // coordinates (the planes are the meadow's: meadow.h), for the focus and the colliders,
  // and how far beyond it they reach. Min and max: the same whatever the pieces.
  const size_t width = runtime_.group_size(), n = size_t(count);
  const std::vector<float> reach = reach_bounds(m, frame, index, count);
  for (size_t i = 0; i < n; ++i) {
    TileBox& box = (*boxes)[(size_t(first) + i) / width];
    for (int a = 0; a < 3; ++a)
      for (int plane : {BOREAS_UB_FRAME_BASE, BOREAS_UB_FRAME_REST}) {
        const float v = float(double(frame[size_t(plane + a) * n + i]) + m.origin[size_t(a)]);
        box.lo[a] = std::min(box.lo[a], v);
        box.hi[a] = std::max(box.hi[a], v);
      }
    box.margin = std::max(box.margin, reach[i]);
  }
}

void UnderbrushBatch::take_new_parts(const NewParts& n) {
  parts_ = n.parts_buffer;
  tables_ = n.tables_buffer;
  parts_capacity_ = n.parts_capacity;
  tables_capacity_ = n.tables_capacity;
  parts_host_.insert(parts_host_.end(), n.parts.begin(), n.parts.end());
  tables_host_.insert(tables_host_.end(), n.tables.begin(), n.tables.end());
}

void UnderbrushBatch::take_meadow(const std::shared_ptr<const MeadowInstance>& meadow,
                                  int64_t first, int32_t part_first, int64_t table_first,
                                  const std::vector<TileBox>& boxes) {
  const Meadow& m = meadow->meadow;
  const int width = int(runtime_.group_size());
  Slot slot;
  slot.meadow = meadow;
  slot.first = int32_t(first);
  slot.part_first = part_first;
  slot.table_first = table_first;
  const int32_t s = claim_place(slots_, free_slots_, Slot{});
  for (int32_t offset = 0; offset < m.count; offset += width) {
    Tile tile;
    tile.slot = s;
    tile.offset = offset;
    tile.count = std::min(width, m.count - offset);
    const TileBox& box = boxes[size_t(offset / width)];
    std::copy_n(box.lo, 3, tile.lo);
    std::copy_n(box.hi, 3, tile.hi);
    tile.margin = box.margin;
    tile.rate = rate_of(tile, m.params);
    tile.number = tile_numbers_->claim();
    slot.tiles.push_back(claim_place(tiles_host_, free_tiles_, std::move(tile)));
  }
  grid_stale_ = true;
  slots_[size_t(s)] = std::move(slot);
  by_key_.emplace(meadow->key, s);
  if (!rebuild_tiles_)
    for (int32_t t : slots_[size_t(s)].tiles) tile_add(t);
}

void UnderbrushBatch::remove(uint64_t key) {
  auto it = by_key_.find(key);
  if (it == by_key_.end())
    fail(BOREAS_ERROR_INTERNAL, "underbrush batch has no meadow with key " + std::to_string(key));
  const int32_t s = it->second;
  Slot& slot = slots_[size_t(s)];
  const Meadow& m = slot.meadow->meadow;
  for (int32_t t : slot.tiles) {
    tiles_.kill(tiles_host_[size_t(t)].segment);
    tile_numbers_->release(tiles_host_[size_t(t)].number);
    tiles_host_[size_t(t)] = Tile{};
    tiles_host_[size_t(t)].count = 0;
    free_tiles_.push_back(t);
  }
  grid_stale_ = true;
  components_.release(slot.first, m.count);
  component_count_ -= m.count;
  dead_parts_ += int64_t(m.parts.size());
  dead_tables_ += int64_t(m.tables.size());
  slot = Slot{};
  free_slots_.push_back(s);
  by_key_.erase(it);
  if (by_key_.empty()) {
    components_.clear();
    tiles_.clear();
    // No meadow left: the buffers go back to their smallest (runtime/block_space.h).
    try {
      if (components_.wants_shrinking(kMinComponents))
        relayout(components_.shrunk(kMinComponents), true);
    } catch (const Error&) {
    }
    return;
  }
  // Holes past half: pack; live components below a quarter of the capacity: pack them
  // into smaller buffers (runtime/block_space.h). Device copies, amortized over the
  // removals that made the holes; the part records and tables with them. A failure
  // leaves the holes where they were.
  try {
    if (components_.wants_shrinking(kMinComponents) || components_.wants_packing()) {
      relayout(components_.shrunk(kMinComponents), true);
      repack_parts();
    } else if (2 * dead_tables_ > int64_t(tables_host_.size())) {
      repack_parts();
    }
  } catch (const Error&) {
  }
}

void UnderbrushBatch::set_focus(const std::vector<double>& xyz) { focus_ = xyz; }

int UnderbrushBatch::rate_of(const Tile& tile, const MeadowParams& params) const {
  const size_t points = focus_.size() / 3;
  if (points == 0) return 1;
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t f = 0; f < points; ++f) {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double p = focus_[3 * f + size_t(a)];
      const double d = p < tile.lo[a] ? tile.lo[a] - p : p > tile.hi[a] ? p - tile.hi[a] : 0.0;
      d2 += d * d;
    }
    nearest = std::min(nearest, d2);
  }
  const double d = std::sqrt(nearest);
  return d <= params.lod[0] ? 1 : d <= params.lod[1] ? 4 : d <= params.lod[2] ? 16 : 0;
}

void UnderbrushBatch::tile_add(int32_t t) {
  Tile& tile = tiles_host_[size_t(t)];
  tile.segment = TileLists::Segment{};
  if (tile.rate == 0) return;
  const Slot& slot = slots_[size_t(tile.slot)];
  TileLists::Shared shared;
  shared.static_first = slot.part_first;  // the part index is not per item: see the kernel
  shared.root = slot.first;
  // The meadow's origin and slot (cl/shared/underbrush_types.h, BOREAS_UB_TILE_ORIGIN).
  shared.value = float(slot.meadow->meadow.origin[0]);
  shared.scale = float(slot.meadow->meadow.origin[1]);
  shared.scale_root = float(slot.meadow->meadow.origin[2]);
  shared.object = tile.slot;
  // Its phase: the low bits of its number, which equals its index in tiles_host_ in a world
  // of one chunk and follows the world's order of meadows in a world of several.
  tile.segment =
      tiles_.add(rate_list(tile.rate, tile.number & (tile.rate - 1)), slot.first + tile.offset,
                 tile.count, int(runtime_.group_size()), shared);
}

void UnderbrushBatch::rebuild_tiles() {
  tiles_.clear();
  for (size_t t = 0; t < tiles_host_.size(); ++t)
    if (tiles_host_[t].count > 0) tile_add(int32_t(t));
  rebuild_tiles_ = false;
}

void UnderbrushBatch::update_rates() {
  changed_.clear();
  for (size_t t = 0; t < tiles_host_.size(); ++t) {
    Tile& tile = tiles_host_[t];
    if (tile.count == 0) continue;
    const Slot& slot = slots_[size_t(tile.slot)];
    const int rate = touch_count_[t] > 0 ? 1 : rate_of(tile, slot.meadow->meadow.params);
    if (rate == tile.rate) continue;
    // Both halves of its state equal from now on, whatever its new rate and phase.
    changed_.add(0, slot.first + tile.offset, tile.count, int(runtime_.group_size()));
    tile.rate = rate;
    if (!rebuild_tiles_) {
      tiles_.kill(tile.segment);
      tile_add(int32_t(t));
    }
  }
}

std::array<int64_t, 4> UnderbrushBatch::components_by_rate() const {
  std::array<int64_t, 4> counts{};
  for (const Tile& t : tiles_host_)
    if (t.count > 0)
      counts[size_t(t.rate == 1 ? 0 : t.rate == 4 ? 1 : t.rate == 16 ? 2 : 3)] += t.count;
  return counts;
}

void UnderbrushBatch::upload_parts(double dt) {
  if (dt == parts_dt_) return;
  for (BoreasGpuPart& g : parts_host_) {
    g.recovery_loss = static_cast<float>(-std::expm1(-dt / double(g.recovery_time)));
  }
  runtime_.upload(parts_, parts_host_);
  parts_dt_ = dt;
}

void UnderbrushBatch::upload_phases(const PlantWind& wind) {
  // Every slot's row of the waves' phases at its meadow's origin (empty slots: zeros).
  const size_t count = size_t(std::max(wind.wave_count, 1));
  std::vector<float>& rows = phase_staging_;
  rows.assign(std::max<size_t>(slots_.size(), 1) * count, 0.0f);
  for (size_t s = 0; s < slots_.size(); ++s) {
    if (!slots_[s].meadow) continue;
    const std::array<double, 3>& o = slots_[s].meadow->meadow.origin;
    wind.phases_at(o[0], o[2], rows.data() + s * count);
  }
  grow_staged(runtime_, phases_, rows.size(), sizeof(float), "meadow wave phases");
  runtime_.upload_async(phases_.buffer, rows);
}

void UnderbrushBatch::enqueue_step(double dt, const PlantWind& wind,
                                   const StepColliders& colliders,
                                   const std::vector<BoreasGpuImpulse>& impulses,
                                   std::vector<cl::Event>* events) {
  contacts_[1 - contacts_current_].colliders.clear();
  if (by_key_.empty()) return;
  upload_parts(dt);
  find_touches(colliders);
  update_rates();
  if (rebuild_tiles_ || tiles_.wants_rebuild()) rebuild_tiles();
  tiles_.flush(runtime_);
  changed_.flush(runtime_);
  const std::string defines = wind.defines() + upload_impulses(impulses);
  upload_phases(wind);
  const bool touched = upload_touches(colliders);
  // Tiles whose rate changed start with equal halves; then every rate's tiles of this
  // step's phase are stepped, and those stepped in the previous step are carried across.
  // Colliders reach only rate-1 tiles (update_rates).
  copy_list(changed_.buffer(0), changed_.size(0), events);
  for (int rate : kRates) {
    const int list = rate_list(rate, int(step_index_ % uint64_t(rate)));
    if (tiles_.size(list) > 0) {
      step_list(list,
                defines + slot_define("BOREAS_UB_RATE", rate) +
                    slot_define("BOREAS_UB_COLLIDERS", rate == 1 && touched ? 1 : 0),
                dt, wind, static_cast<int>(impulses.size()), events);
    }
    if (rate > 1) {
      const int copied = rate_list(rate, int((step_index_ + uint64_t(rate) - 1) % uint64_t(rate)));
      copy_list(tiles_.buffer(copied), tiles_.size(copied), events);
    }
  }
  if (touched) enqueue_contacts(events);
}

void UnderbrushBatch::find_touches(const StepColliders& colliders) {
  const size_t tiles = tiles_host_.size();
  touch_first_.assign(tiles, 0);
  touch_count_.assign(tiles, 0);
  touch_colliders_.clear();
  if (colliders.empty()) return;
  if (grid_stale_) {
    std::vector<Bounds> boxes(tiles);
    std::vector<bool> live(tiles);
    for (size_t t = 0; t < tiles; ++t) {
      const Tile& tile = tiles_host_[t];
      live[t] = tile.count > 0;
      for (size_t a = 0; a < 3; ++a) {
        boxes[t].lo[a] = double(tile.lo[a]) - tile.margin;
        boxes[t].hi[a] = double(tile.hi[a]) + tile.margin;
      }
    }
    grid_.build(boxes, live);
    grid_stale_ = false;
  }
  // (tile, collider) pairs, sorted: each tile's colliders in the step's order.
  std::vector<std::pair<int32_t, int32_t>> hits;
  std::vector<int32_t> found;
  for (size_t c = 0; c < colliders.bounds.size(); ++c) {
    found.clear();
    grid_.query(colliders.bounds[c], &found);
    for (int32_t t : found) hits.push_back({t, int32_t(c)});
  }
  std::sort(hits.begin(), hits.end());
  for (const auto& [t, c] : hits) {
    if (touch_count_[size_t(t)]++ == 0) touch_first_[size_t(t)] = int32_t(touch_colliders_.size());
    touch_colliders_.push_back(c);
  }
}

bool UnderbrushBatch::upload_touches(const StepColliders& colliders) {
  if (touch_colliders_.empty()) return false;
  // The rate-1 list's (first, count) per tile of the launch: 0 for those no collider reaches.
  std::vector<int32_t>& per_tile = tile_collider_staging_;
  per_tile.assign(2 * std::max<size_t>(tiles_.size(0), 1), 0);
  std::vector<int32_t>& pairs = pair_staging_;
  pairs.clear();
  Contacts& pending = contacts_[1 - contacts_current_];
  // A record per touch, relative to its tile's meadow: touch e of tile t is record e.
  collider_staging_.resize(touch_colliders_.size());
  for (size_t t = 0; t < tiles_host_.size(); ++t) {
    if (touch_count_[t] == 0) continue;
    const Tile& tile = tiles_host_[t];
    const Slot& slot = slots_[size_t(tile.slot)];
    if (tile.rate != 1 || tile.segment.list != 0)
      fail(BOREAS_ERROR_INTERNAL, "underbrush: a tile a collider reaches is not stepped at rate 1");
    per_tile[2 * size_t(tile.segment.first)] = touch_first_[t];
    per_tile[2 * size_t(tile.segment.first) + 1] = touch_count_[t];
    for (int32_t j = 0; j < touch_count_[t]; ++j) {
      const int32_t e = touch_first_[t] + j;
      const int32_t c = touch_colliders_[size_t(e)];
      collider_staging_[size_t(e)] = colliders.relative(c, slot.meadow->meadow.origin);
      pairs.insert(pairs.end(), {slot.first + tile.offset, tile.count, slot.part_first,
                                 slot.first, e});
      pending.colliders.push_back(c);
    }
  }
  const size_t pair_count = pending.colliders.size();
  grow_staged(runtime_, colliders_, collider_staging_.size(), sizeof(BoreasGpuCollider),
              "colliders");
  grow_staged(runtime_, tile_colliders_, per_tile.size(), sizeof(int32_t), "tile colliders");
  grow_staged(runtime_, pairs_, pairs.size(), sizeof(int32_t), "contact pairs");
  grow_staged(runtime_, pending.out, pair_count * BOREAS_UB_PAIR_FLOATS, sizeof(float),
              "contact sums");
  runtime_.upload_async(colliders_.buffer, collider_staging_);
  runtime_.upload_async(tile_colliders_.buffer, per_tile);
  runtime_.upload_async(pairs_.buffer, pairs);
  return true;
}

void UnderbrushBatch::enqueue_contacts(std::vector<cl::Event>* events) {
  const Contacts& pending = contacts_[1 - contacts_current_];
  const int count = int(pending.colliders.size());
  cl::Kernel& k = runtime_.kernel("underbrush_contacts.cl", "boreas_underbrush_contacts");
  cl::Event event = launch(runtime_, k, Items(size_t(count)), state_[current_], frame_, index_,
                           parts_, int(components_.capacity), colliders_.buffer, pairs_.buffer,
                           count, pending.out.buffer);
  if (events) events->push_back(event);
}

void UnderbrushBatch::add_contacts(std::vector<ContactSum>* sums) {
  const Contacts& c = contacts_[contacts_current_];
  if (c.colliders.empty()) return;
  std::vector<float> out(c.colliders.size() * BOREAS_UB_PAIR_FLOATS);
  runtime_.read(c.out.buffer, 0, out.size() * sizeof(float), out.data());
  // In the pairs' order (tile, then collider), in double: the same bits every run.
  for (size_t p = 0; p < c.colliders.size(); ++p)
    (*sums)[size_t(c.colliders[p])].add(out.data() + p * BOREAS_UB_PAIR_FLOATS);
}

std::string UnderbrushBatch::upload_impulses(const std::vector<BoreasGpuImpulse>& impulses) {
  std::vector<BoreasGpuImpulse>& m = impulse_staging_;
  m = impulses;
  int impulse_slots = pad_to_slots(m, silent_impulse());
  if (m.empty()) m.push_back(silent_impulse());  // a valid buffer even with no impulses
  if (m.size() > impulse_capacity_) {
    // The capacity changes only once the buffer is there: a refused allocation keeps both.
    const size_t capacity = std::max<size_t>(m.size(), 16);
    impulses_ = runtime_.buffer(CL_MEM_READ_ONLY, capacity * sizeof(BoreasGpuImpulse), "impulses");
    impulse_capacity_ = capacity;
  }
  runtime_.upload_async(impulses_, m);
  // A valid buffer for every collider argument, read only by steps that have colliders.
  grow_staged(runtime_, colliders_, 1, sizeof(BoreasGpuCollider), "colliders");
  grow_staged(runtime_, tile_colliders_, 1, sizeof(int32_t), "tile colliders");
  return slot_define("BOREAS_IMPULSE_SLOTS", impulse_slots);
}

void UnderbrushBatch::copy_list(const cl::Buffer& tiles, size_t count,
                                std::vector<cl::Event>* events) {
  if (count == 0) return;
  const int next = 1 - current_;
  const int n = int(components_.capacity);
  // A tile of group_size() components per group.
  const size_t tile = runtime_.group_size();
  cl::Kernel& k = runtime_.kernel("tile_copy.cl", "boreas_tile_copy",
                                  slot_define("BOREAS_COPY_PLANES_A", BOREAS_UB_STATE_PLANES));
  cl::Event event = launch(runtime_, k, Items(count * tile), state_[current_], state_[next],
                           state_[current_], state_[next], n, tiles, 0);
  if (events) events->push_back(event);
}

void UnderbrushBatch::step_list(int list, const std::string& defines, double dt,
                                const PlantWind& wind, int impulses,
                                std::vector<cl::Event>* events) {
  const int next = 1 - current_;
  const int n = int(components_.capacity);
  // A tile of group_size() components per group.
  const size_t tile = runtime_.group_size();
  cl::Kernel& k = runtime_.kernel("underbrush_step.cl", "boreas_underbrush_step", defines);
  // simd_width() components per work-item (underbrush_step.cl).
  const Items items = Items(tiles_.size(list) * tile).per_work_item(size_t(runtime_.simd_width()));
  cl::Event event = launch(runtime_, k, items, state_[current_], state_[next], frame_, index_,
                           parts_, tables_, n, static_cast<float>(dt), static_cast<float>(kGravity),
                           *wind.waves, wind.wave_count, phases_.buffer, *wind.grid,
                           wind.grid_layout, colliders_.buffer, tile_colliders_.buffer, impulses_,
                           impulses, tiles_.buffer(list), 0);
  if (events) events->push_back(event);
}

void UnderbrushBatch::commit() {
  contacts_current_ = 1 - contacts_current_;
  if (by_key_.empty()) return;
  current_ = 1 - current_;
  ++step_index_;
}

void UnderbrushBatch::enqueue_vertices(const std::vector<VertexDraw>& draws, const float* camera,
                                       const cl::Buffer& out, const cl::Buffer& counts,
                                       const Origin& output_origin) {
  draw_staging_.clear();
  int64_t items = 0;
  for (const VertexDraw& d : draws) {
    const Slot& s = slot_of(d.key);
    const int count = d.count < 0 ? s.meadow->meadow.count - d.first : d.count;
    if (count <= 0) continue;
    BoreasUbDraw t{};
    t.item_first = int32_t(items);
    t.first = s.first + d.first;
    t.count = count;
    t.part_first = s.part_first;
    t.out_first = int32_t(d.out_first);
    // No camera: everything at full detail.
    for (int a = 0; a < 3; ++a) t.lod[a] = camera ? s.meadow->meadow.params.lod[size_t(a)] : 3e38f;
    // The camera in the meadow's coordinates, and the shift of its strips to the output's.
    const std::array<double, 3>& origin = s.meadow->meadow.origin;
    for (int a = 0; a < 3; ++a) {
      t.camera[a] = camera ? float(double(camera[a]) - origin[size_t(a)]) : 0.0f;
      t.offset[a] = float(origin[size_t(a)] - output_origin[size_t(a)]);
    }
    draw_staging_.push_back(t);
    items += count;
  }
  if (items == 0) return;
  if (draw_capacity_ < draw_staging_.size()) {
    draw_capacity_ = std::max(draw_staging_.size(), 2 * draw_capacity_);
    draws_ = runtime_.buffer(CL_MEM_READ_ONLY, draw_capacity_ * sizeof(BoreasUbDraw),
                             "meadow draw table");
  }
  // Blocking: the table is a few bytes a meadow, and the next call may rewrite it.
  runtime_.write(draws_, 0, draw_staging_.size() * sizeof(BoreasUbDraw), draw_staging_.data());
  cl::Kernel& k = runtime_.kernel("underbrush_vertices.cl", "boreas_underbrush_vertices");
  launch(runtime_, k, Items(size_t(items)), state_[current_], index_, parts_, tables_,
         int(components_.capacity), draws_, int(draw_staging_.size()),
         int(items), out, counts);
}

void UnderbrushBatch::vertices(uint64_t key, const float* camera, std::vector<float>* vertices,
                               std::vector<int32_t>* counts, const Origin& output_origin) {
  const Slot& s = slot_of(key);
  const int count = s.meadow->meadow.count;
  vertices->assign(size_t(count) * kStrip * 8, 0.0f);
  counts->assign(size_t(count), 0);
  if (count == 0) return;
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, size_t(count) * kStrip * 8 * sizeof(float),
                                   "meadow strips");
  cl::Buffer cnt =
      runtime_.buffer(CL_MEM_WRITE_ONLY, size_t(count) * sizeof(int32_t), "meadow strip counts");
  enqueue_vertices({{key, 0}}, camera, out, cnt, output_origin);
  runtime_.read(out, 0, vertices->size() * sizeof(float), vertices->data());
  runtime_.read(cnt, 0, counts->size() * sizeof(int32_t), counts->data());
}

template <typename T>
std::vector<T> UnderbrushBatch::read_meadow_planes(const cl::Buffer& buffer, uint64_t key,
                                                   int planes) {
  const Slot& s = slot_of(key);
  const size_t count = size_t(s.meadow->meadow.count);
  std::vector<T> out(size_t(planes) * std::max<size_t>(count, 1));
  runtime_.read_planes(buffer, size_t(components_.capacity), size_t(s.first), out.data(), count,
                       count, size_t(planes), sizeof(T));
  return out;
}

std::vector<float> UnderbrushBatch::read_meadow_state(uint64_t key) {
  return read_meadow_planes<float>(state_[current_], key, BOREAS_UB_STATE_PLANES);
}

std::vector<float> UnderbrushBatch::read_meadow_frame(uint64_t key) {
  return read_meadow_planes<float>(frame_, key, BOREAS_UB_FRAME_PLANES);
}

std::vector<int32_t> UnderbrushBatch::read_meadow_index(uint64_t key) {
  return read_meadow_planes<int32_t>(index_, key, BOREAS_UB_INDEX_PLANES);
}

std::vector<boreas_component> UnderbrushBatch::components(uint64_t key,
                                                          const Origin& output_origin) {
  const Slot& s = slot_of(key);
  const Meadow& m = s.meadow->meadow;
  // The host keeps none of the component planes (drop_uploaded): all from the device.
  const std::vector<float> state = read_meadow_state(key), frame = read_meadow_frame(key);
  const std::vector<int32_t> index = read_meadow_index(key);
  const size_t n = size_t(std::max(m.count, 1));
  std::vector<boreas_component> out(size_t(m.count));
  for (int c = 0; c < m.count; ++c) {
    const size_t i = size_t(c);
    boreas_component& o = out[size_t(c)];
    const int parent = parent_of(index.data(), int(n), c);
    // Positions from the meadow's local coordinates to the output's, in double.
    for (int a = 0; a < 3; ++a) {
      const double shift = m.origin[size_t(a)] - output_origin[size_t(a)];
      o.base[a] = float(state[size_t(BOREAS_UB_STATE_BASE + a) * n + i] + shift);
      o.center_of_mass[a] = float(state[size_t(BOREAS_UB_STATE_X + a) * n + i] + shift);
      o.velocity[a] = state[size_t(BOREAS_UB_STATE_V + a) * n + i];
      o.rest_center_of_mass[a] = float(frame[size_t(BOREAS_UB_FRAME_REST + a) * n + i] + shift);
    }
    o.broken = static_cast<int32_t>(state[size_t(BOREAS_UB_STATE_BROKEN) * n + i]);
    const MeadowPart& part = m.parts[size_t(part_of(index.data(), int(n), c))];
    o.species = part.species;
    o.part = part.part;
    o.parent = parent == c ? -1 : parent;
  }
  return out;
}

std::vector<boreas_meadow_part> UnderbrushBatch::parts(uint64_t key) {
  const Meadow& m = slot_of(key).meadow->meadow;
  std::vector<boreas_meadow_part> out;
  for (size_t s = 0; s < m.params.species.size(); ++s) {
    const std::vector<PartDef>& defs = m.params.species[s].parts;
    for (size_t p = 0; p < defs.size(); ++p) {
      boreas_meadow_part o{};
      o.species = int32_t(s);
      o.part = int32_t(p);
      std::snprintf(o.name, sizeof o.name, "%s", defs[p].name.c_str());
      for (int c = 0; c < 3; ++c) o.color[c] = float(defs[p].color[c]);
      o.translucency = float(defs[p].translucency);
      out.push_back(o);
    }
  }
  return out;
}

}  // namespace boreas::impl
