// boreas: FNV-1a, 64 bits (Fowler, Noll and Vo's hash), the one hash behind the kernel
// binary cache's keys and checksums, the species files' keys, the preprocessed trees' keys
// and the world's state hash. Not cryptographic: two inputs that differ in a bit differ in
// their hashes for all practical purposes, the same bytes hash the same on every machine,
// and there is nothing to vendor.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace boreas::impl {

class Fnv1a64 {
 public:
  Fnv1a64& add(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
      hash_ ^= bytes[i];
      hash_ *= 0x100000001b3ull;
    }
    return *this;
  }
  // Little-endian whatever the host, so that a value hashes the same on every machine.
  Fnv1a64& add_u64(uint64_t v) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(v >> (8 * i));
    return add(bytes, sizeof(bytes));
  }
  // With its length first, so that "ab" + "c" and "a" + "bc" differ.
  Fnv1a64& add_string(const std::string& s) {
    add_u64(s.size());
    return add(s.data(), s.size());
  }
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 0xcbf29ce484222325ull;  // the offset basis
};

inline uint64_t fnv1a64(const void* data, size_t size) { return Fnv1a64().add(data, size).value(); }

}  // namespace boreas::impl
