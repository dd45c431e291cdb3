// boreas tests: the capacity rule of block spaces (runtime/block_space.h) — packed in place
// where holes leave room, doubled where they do not, packed and halved below a quarter
// full, and no resize back and forth when objects come and go at either edge — and the
// tile lists' buffers that follow the same rule when rebuilt (runtime/launch_tiles.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "runtime/block_space.h"
#include "runtime/launch_tiles.h"
#include "runtime/runtime.h"

namespace boreas::impl {
namespace {

BlockSpace space(int64_t end, int64_t dead, int64_t capacity) {
  BlockSpace s;
  s.end = end;
  s.dead = dead;
  s.capacity = capacity;
  return s;
}

TEST(BlockSpace, GrowsOnlyWhenPackingLeavesLessThanAQuarterFree) {
  // A new space: exactly what is asked, or the minimum.
  EXPECT_EQ(space(1, 0, 0).grown(1000, 256), 1000 + 1);
  EXPECT_EQ(space(1, 0, 0).grown(10, 256), 256);
  // Full, no holes: at least double.
  EXPECT_EQ(space(1000, 0, 1000).grown(10, 256), 2000);
  EXPECT_EQ(space(1000, 0, 1000).grown(5000, 256), 6000);
  // Holes that leave a quarter free once packed: the same capacity (packed in place).
  EXPECT_EQ(space(1000, 400, 1000).grown(150, 256), 1000);  // 750 of 1000
  EXPECT_EQ(space(1000, 400, 1000).grown(151, 256), 2000);  // 751: doubled
  // What fits after the end needs nothing.
  EXPECT_EQ(space(500, 0, 1000).grown(500, 256), 1000);
}

TEST(BlockSpace, GrowsAtMostToTheMaximumWhereTheEntriesFitIt) {
  // A chunk's limit (TreeBatch::space_limits): doubling stops there.
  EXPECT_EQ(space(1000, 0, 1000).grown(10, 256, 1500), 1500);
  EXPECT_EQ(space(1000, 0, 1000).grown(500, 256, 1500), 1500);
  EXPECT_EQ(space(1, 0, 0).grown(10, 256, 100), 100);  // below the minimum too
  // Where they do not fit, what they need (the buffer is then refused: the caller asks
  // TreeBatch::fitting first).
  EXPECT_EQ(space(1000, 0, 1000).grown(501, 256, 1500), 1501);
  // Below it nothing changes.
  EXPECT_EQ(space(1000, 0, 1000).grown(10, 256, 4000), 2000);
}

TEST(BlockSpace, ShrinksBelowAQuarterIntoTheSmallestHalvingAtMostHalfFull) {
  EXPECT_FALSE(space(250, 0, 1000).wants_shrinking(64));  // a quarter: stays
  EXPECT_EQ(space(250, 0, 1000).shrunk(64), 1000);
  EXPECT_TRUE(space(249, 0, 1000).wants_shrinking(64));
  EXPECT_EQ(space(249, 0, 1000).shrunk(64), 500);  // 249 of 500
  // Holes count as free: 100 live of 1024 go to 256 (100 > 64, so not 128).
  EXPECT_EQ(space(700, 600, 1024).shrunk(16), 256);
  // Never below the minimum, and a space at its minimum stays.
  EXPECT_EQ(space(1, 0, 4096).shrunk(256), 256);
  EXPECT_FALSE(space(1, 0, 256).wants_shrinking(256));
  // After a shrink the space is more than a quarter and at most half full.
  for (int64_t used = 2; used < 4000; used += 37) {
    const BlockSpace s = space(used, 0, 16384);
    if (!s.wants_shrinking(8)) continue;
    const int64_t c = s.shrunk(8);
    EXPECT_LE(2 * used, c) << used;
    EXPECT_TRUE(4 * used > c || c / 2 < 8) << used;
  }
}

// Objects of `size` entries come and go at the end of a space that follows the rule, as a
// batch drives it (grow before an add that does not fit, shrink after a remove).
struct Driven {
  BlockSpace s;
  int64_t minimum = 64;
  int resizes = 0;
  void resize(int64_t c) {
    if (c != s.capacity) ++resizes;
    s.packed(s.used());
    s.capacity = c;
  }
  void add(int64_t size) {
    if (!s.fits(size)) resize(s.grown(size, minimum));
    s.end += size;
  }
  void remove_last(int64_t size) {
    s.release(s.end - size, size);
    if (s.wants_shrinking(minimum)) resize(s.shrunk(minimum));
  }
};

TEST(BlockSpace, FitsIntoTheSmallestHalvingAtMostThreeQuartersFull) {
  EXPECT_EQ(space(375, 0, 1000).fitted(64), 500);   // 375 of 500: three quarters
  EXPECT_EQ(space(376, 0, 1000).fitted(64), 1000);  // would be more: stays
  EXPECT_EQ(space(700, 600, 1024).fitted(16), 256);  // 100 live: not 100 of 128
  EXPECT_EQ(space(1, 0, 4096).fitted(256), 256);     // never below the minimum
  for (int64_t used = 2; used < 4000; used += 37) {
    const BlockSpace s = space(used, 0, 16384);
    const int64_t c = s.fitted(8);
    EXPECT_LE(4 * used, 3 * c) << used;  // within grown's threshold: no growth at once
    EXPECT_TRUE(8 * used > 3 * c || c / 2 < 8) << used;  // and the smallest such halving
    // Neither grows nor shrinks at once after it.
    BlockSpace after = s;
    after.capacity = c;
    after.packed(used);
    EXPECT_FALSE(after.wants_shrinking(8) && after.shrunk(8) < c) << used;
    EXPECT_EQ(after.grown(0, 8), c) << used;
  }
}

TEST(BlockSpace, AddingAndRemovingAtEitherEdgeDoesNotThrash) {
  // At the growth edge: full, then one more object and back, many times.
  Driven d;
  d.s = space(1000, 0, 1000);  // exactly full
  for (int k = 0; k < 50; ++k) {
    d.add(10);
    d.remove_last(10);
  }
  EXPECT_EQ(d.resizes, 1) << "one growth, then nothing";
  // At the shrink edge: just above a quarter, then one object fewer and back.
  Driven e;
  e.s = space(1001, 0, 4000);  // just above a quarter
  for (int k = 0; k < 50; ++k) {
    e.remove_last(10);
    e.add(10);
  }
  EXPECT_EQ(e.resizes, 1) << "one shrink, then nothing";
}

TEST(BlockSpace, AChurningPopulationKeepsTheCapacityWithinItsBound) {
  // Objects of 1..40 entries come and go at random places (holes), never more than U
  // live: the capacity stays under 8/3 U.
  BlockSpace s;
  const int64_t limit = 2000;
  std::vector<std::pair<int64_t, int64_t>> live;  // (first, size)
  uint64_t x = 12345;
  auto next = [&] { return (x = x * 6364136223846793005ull + 1442695040888963407ull) >> 33; };
  int64_t largest = 1, live_entries = 0;
  for (int k = 0; k < 20000; ++k) {
    const int64_t size = 1 + int64_t(next() % 40);
    if (live_entries + size <= limit && (next() % 2 == 0 || live.empty())) {
      if (!s.fits(size)) {
        s.capacity = s.grown(size, 64);
        int64_t end = 1;  // packed, in order
        for (auto& [first, n] : live) first = end, end += n;
        s.packed(end);
      }
      live.push_back({s.end, size});
      s.end += size;
      live_entries += size;
      largest = std::max(largest, 1 + live_entries);
    } else if (!live.empty()) {
      const size_t i = size_t(next() % live.size());
      s.release(live[i].first, live[i].second);
      live_entries -= live[i].second;
      live.erase(live.begin() + ptrdiff_t(i));
      if (s.wants_shrinking(64) || s.wants_packing()) {
        s.capacity = s.shrunk(64);
        int64_t end = 1;
        for (auto& [first, n] : live) first = end, end += n;
        s.packed(end);
      }
    }
    ASSERT_TRUE(3 * s.capacity < 8 * largest || s.capacity == 64) << "step " << k;
    ASSERT_LE(s.end, s.capacity);
  }
}

TEST(TileLists, ARebuiltListThatFillsLessThanAQuarterOfItsBufferShrinksIt) {
  Runtime runtime(nullptr, "");
  TileLists lists(1);
  lists.add(0, 1, 64 * 1000, 1);  // 64,000 tiles of one item
  lists.flush(runtime);
  const size_t full = lists.capacity(0);
  ASSERT_GE(full, size_t(64000));
  // Rebuilt with a quarter of them: the buffer stays (hysteresis) ...
  lists.clear();
  lists.add(0, 1, 16000, 1);
  lists.flush(runtime);
  EXPECT_EQ(lists.capacity(0), full);
  // ... and with fewer, it goes into one the tiles fill at least half of, holding them.
  lists.clear();
  lists.add(0, 1, 1000, 1);
  lists.flush(runtime);
  EXPECT_EQ(lists.capacity(0), size_t(2000));
  std::vector<int32_t> back(lists.list(0).size());
  runtime.read(lists.buffer(0), 0, back.size() * sizeof(int32_t), back.data());
  EXPECT_EQ(back, lists.list(0));
}

}  // namespace
}  // namespace boreas::impl
