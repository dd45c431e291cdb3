// boreas: the host side of tile launches (cl/shared/launch_tiles.h). A batch keeps several
// lists of tiles (one per launch: a level, a level of detail), each in a device buffer of
// its own, and changes them as its objects change: an object's tiles are one segment of a
// list, appended when it comes and overwritten with no-op tiles when it goes, and only
// those tiles are uploaded. A list whose dead tiles pass an eighth of it asks to be rebuilt
// (a dead tile costs a work-group like a live one), which keeps the work per change
// amortized O(the object's tiles).
//
// A no-op tile covers item 0 alone, with static entry 0 and root 0: a batch keeps entry 0
// of its planes as a sink that no object owns and whose update is harmless.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "runtime/runtime.h"
#include "shared/launch_tiles.h"

namespace boreas::impl {

// What the tiles of one range share besides their items (cl/shared/launch_tiles.h).
struct TileShared {
  int64_t static_first = 0;  // the range's first item's static entry
  int32_t root = 0;          // where parent indices count from
  float value = 0.0f;
  float scale = 1.0f;
  float scale_root = 1.0f;
  int32_t object = 0;  // BOREAS_TILE_OBJECT
};

class TileLists {
 public:
  explicit TileLists(int lists) : lists_(size_t(lists)) {}

  using Shared = TileShared;

  // Where an object's tiles sit in one list.
  struct Segment {
    int list = 0;
    int32_t first = 0;  // tile index
    int32_t count = 0;  // tiles
  };

  // Empties every list (before a rebuild).
  void clear();
  // Appends items [first, first + count) to list l, in tiles of at most `width` items,
  // each carrying `shared`, its static entry counted up by the tile's offset in the range.
  // Uploaded by flush().
  Segment add(int l, int64_t first, int64_t count, int width, const Shared& shared = Shared{});
  // Turns a segment's tiles into no-op tiles (uploaded by flush()).
  void kill(const Segment& s);
  // Whether some list's dead tiles pass an eighth of it (and are enough to matter): the
  // owner should clear() and add everything again.
  bool wants_rebuild() const;

  // Tiles in list l (live and dead), and its ints (BOREAS_TILE_INTS per tile) for the
  // native twins.
  size_t size(int l) const { return lists_[size_t(l)].ints.size() / BOREAS_TILE_INTS; }
  const std::vector<int32_t>& list(int l) const { return lists_[size_t(l)].ints; }

  // Writes what changed since the last flush to the device: the tiles touched, or a whole
  // list after clear() or when its buffer grew (or shrank: a rebuilt list below a quarter
  // of its buffer moves into one it fills at least half of).
  void flush(Runtime& runtime);
  const cl::Buffer& buffer(int l) const { return lists_[size_t(l)].buffer; }
  size_t capacity(int l) const { return lists_[size_t(l)].capacity; }  // tiles its buffer holds

 private:
  struct List {
    std::vector<int32_t> ints;
    std::vector<std::pair<int32_t, int32_t>> dirty;  // tile ranges [first, end) to upload
    bool all_dirty = true;
    int64_t dead = 0;
    cl::Buffer buffer;
    size_t capacity = 0;  // tiles the buffer holds
  };
  std::vector<List> lists_;
};

}  // namespace boreas::impl
