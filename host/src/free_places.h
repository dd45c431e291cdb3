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

}  // namespace boreas::impl
