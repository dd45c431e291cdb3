// boreas: tile lists for tile launches (launch_tiles.h).
#include "runtime/launch_tiles.h"

#include <algorithm>
#include <cstring>

#include "errors.h"

namespace boreas::impl {

namespace {

int32_t float_bits(float value) {
  int32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// A dead tile costs a whole work-group (its lanes all redo the sink), as a live one does:
// a list is rebuilt once its dead tiles pass an eighth of it (so they cost at most that),
// and a handful never ask.
constexpr int64_t kMinDeadForRebuild = 64;
constexpr int64_t kDeadFraction = 8;

}  // namespace

void TileLists::clear() {
  for (List& l : lists_) {
    l.ints.clear();
    l.dirty.clear();
    l.all_dirty = true;
    l.dead = 0;
  }
}

TileLists::Segment TileLists::add(int l, int64_t first, int64_t count, int width,
                                  const Shared& shared) {
  List& list = lists_[size_t(l)];
  Segment s;
  s.list = l;
  s.first = int32_t(list.ints.size() / BOREAS_TILE_INTS);
  for (int64_t at = 0; at < count; at += width) {
    const int64_t item = first + at, static_item = shared.static_first + at;
    if (item > INT32_MAX || static_item > INT32_MAX)
      fail(BOREAS_ERROR_OUT_OF_MEMORY,
           "a tile launch reached item 2^31: too many items in one batch");
    int32_t tile[BOREAS_TILE_INTS] = {};
    tile[BOREAS_TILE_FIRST] = int32_t(item);
    tile[BOREAS_TILE_COUNT] = int32_t(std::min<int64_t>(width, count - at));
    tile[BOREAS_TILE_STATIC] = int32_t(static_item);
    tile[BOREAS_TILE_ROOT] = shared.root;
    tile[BOREAS_TILE_VALUE] = float_bits(shared.value);
    tile[BOREAS_TILE_SCALE] = float_bits(shared.scale);
    tile[BOREAS_TILE_SCALE_ROOT] = float_bits(shared.scale_root);
    tile[BOREAS_TILE_OBJECT] = shared.object;
    list.ints.insert(list.ints.end(), tile, tile + BOREAS_TILE_INTS);
    ++s.count;
  }
  if (s.count > 0) list.dirty.emplace_back(s.first, s.first + s.count);
  return s;
}

void TileLists::kill(const Segment& s) {
  if (s.count == 0) return;
  List& list = lists_[size_t(s.list)];
  for (int32_t t = s.first; t < s.first + s.count; ++t) {
    int32_t* tile = &list.ints[size_t(t) * BOREAS_TILE_INTS];
    std::fill(tile, tile + BOREAS_TILE_INTS, 0);  // the sink: item, static entry and root 0
    tile[BOREAS_TILE_COUNT] = 1;
    tile[BOREAS_TILE_SCALE] = tile[BOREAS_TILE_SCALE_ROOT] = float_bits(1.0f);
  }
  list.dead += s.count;
  list.dirty.emplace_back(s.first, s.first + s.count);
}

bool TileLists::wants_rebuild() const {
  for (const List& l : lists_) {
    const int64_t tiles = int64_t(l.ints.size() / BOREAS_TILE_INTS);
    if (l.dead >= kMinDeadForRebuild && kDeadFraction * l.dead > tiles) return true;
  }
  return false;
}

void TileLists::flush(Runtime& runtime) {
  constexpr size_t kTileBytes = BOREAS_TILE_INTS * sizeof(int32_t);
  constexpr size_t kMinTiles = 64;
  for (List& l : lists_) {
    const size_t tiles = l.ints.size() / BOREAS_TILE_INTS;
    if (tiles == 0 && l.capacity == 0) {  // never used: no buffer (nothing launches it)
      l.dirty.clear();
      l.all_dirty = false;
      continue;
    }
    // A rebuilt list that fills less than a quarter of its buffer goes into one it fills
    // at least half of (the block spaces' rule, runtime/block_space.h), host ints too.
    if (l.all_dirty && l.capacity > kMinTiles && 4 * tiles < l.capacity) {
      l.buffer = runtime.buffer(CL_MEM_READ_ONLY, std::max(2 * tiles, kMinTiles) * kTileBytes,
                                "tile list");
      l.capacity = std::max(2 * tiles, kMinTiles);
      if (4 * l.ints.size() < l.ints.capacity()) l.ints.shrink_to_fit();
    }
    if (tiles > l.capacity || l.buffer() == nullptr) {
      const size_t capacity = std::max<size_t>({tiles, 2 * l.capacity, kMinTiles});
      cl::Buffer grown = runtime.buffer(CL_MEM_READ_ONLY, capacity * kTileBytes, "tile list");
      // What the device holds already moves on the device; only new tiles are uploaded.
      if (!l.all_dirty && l.capacity > 0)
        BOREAS_CL_CHECK(
            runtime.queue().enqueueCopyBuffer(l.buffer, grown, 0, 0, l.capacity * kTileBytes));
      l.buffer = grown;
      l.capacity = capacity;
    }
    if (l.all_dirty) {
      runtime.write(l.buffer, 0, tiles * kTileBytes, l.ints.data());
    } else {
      // Touching ranges merged: a batch of appends is one upload.
      std::sort(l.dirty.begin(), l.dirty.end());
      size_t k = 0;
      while (k < l.dirty.size()) {
        int32_t first = l.dirty[k].first, end = l.dirty[k].second;
        for (++k; k < l.dirty.size() && l.dirty[k].first <= end; ++k)
          end = std::max(end, l.dirty[k].second);
        runtime.write(l.buffer, size_t(first) * kTileBytes, size_t(end - first) * kTileBytes,
                      &l.ints[size_t(first) * BOREAS_TILE_INTS]);
      }
    }
    l.dirty.clear();
    l.all_dirty = false;
  }
}

}  // namespace boreas::impl
