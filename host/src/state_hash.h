// boreas: one number for a world's simulated state (boreas_world_get_state_hash), to check that
// the same inputs give bit-identical results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "fnv1a.h"

namespace boreas::impl {

// FNV-1a (fnv1a.h) over the values it is fed, in order.
class StateHash {
 public:
  void bytes(const void* data, size_t count) { hash_.add(data, count); }
  // Records of 4-byte fields (floats and int32s, so no padding) or plain numbers, by
  // their bits: -0 and +0 differ, as do NaNs of different payloads.
  template <typename T>
  void values(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % 4 == 0 &&
                  std::alignment_of_v<T> <= 8);
    const uint64_t n = v.size();
    bytes(&n, sizeof n);  // so that moving a value from one list to the next changes it
    bytes(v.data(), v.size() * sizeof(T));
  }
  void value(double x) { bytes(&x, sizeof x); }
  uint64_t digest() const { return hash_.value(); }

 private:
  Fnv1a64 hash_;
};

}  // namespace boreas::impl
