// boreas: tables whose freed places are reused (the batches' slots, templates and tiles):
// an index stays valid while its item lives, and a removal costs nothing but its place.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace boreas::impl {

// Puts item in the last freed place of items (free lists the freed indices), or at the
// end; returns its index.
template <typename T>
int32_t claim_place(std::vector<T>& items, std::vector<int32_t>& free, T item) {
  int32_t index;
  if (!free.empty()) {
    index = free.back();
    free.pop_back();
    items[size_t(index)] = std::move(item);
  } else {
    index = int32_t(items.size());
    items.push_back(std::move(item));
  }
  return index;
}

// Numbers claimed and released as claim_place gives out and frees indices (the last freed
// first, else the next unused), kept apart from any one table: several batches (a world's
// chunks, world_chunks.cpp) that share one number their items as one table would.
class PlaceNumbers {
 public:
  int32_t claim() {
    if (free_.empty()) return next_++;
    const int32_t n = free_.back();
    free_.pop_back();
    return n;
  }
  void release(int32_t n) { free_.push_back(n); }

 private:
  int32_t next_ = 0;
  std::vector<int32_t> free_;
};

}  // namespace boreas::impl
