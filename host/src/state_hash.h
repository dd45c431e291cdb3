// boreas: one number for a world's simulated state (boreas_world_state_hash), to check that
// the same inputs give bit-identical results.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace boreas::impl {

// FNV-1a (64 bits) over the bytes it is fed, in order. Not cryptographic: two states that
// differ in one bit differ in their hashes for all practical purposes, which is what a
// determinism check needs; cheap and with nothing to vendor.
class StateHash {
 public:
  void bytes(const void* data, size_t count) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < count; ++i) {
      hash_ ^= p[i];
      hash_ *= kPrime;
    }
  }
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
  uint64_t digest() const { return hash_; }

 private:
  static constexpr uint64_t kPrime = 1099511628211ull;
  uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace boreas::impl
