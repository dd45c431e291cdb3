// boreas: the tree generator's random numbers — splitmix64 streams keyed by (seed, stem,
// purpose), with boreas's own uniform mapping, so a tree is the same on every machine and
// standard library (std:: distributions are not specified bit for bit).
#pragma once

#include <cstdint>

namespace boreas::impl {

// splitmix64's output function (Steele, Lea and Flood 2014): a bijective 64-bit mixer.
inline uint64_t splitmix64_mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class TreeRandom {
 public:
  // One independent stream per (seed, stream, purpose): a stem's draws depend only on the
  // seed and the stem's index, never on how many numbers other stems drew before it.
  TreeRandom(uint64_t seed, uint64_t stream, uint64_t purpose)
      : state_(splitmix64_mix(splitmix64_mix(seed ^ 0x6a09e667f3bcc909ull) +
                              splitmix64_mix(stream * 0x9e3779b97f4a7c15ull + purpose))) {}

  uint64_t next_u64() {
    state_ += 0x9e3779b97f4a7c15ull;
    return splitmix64_mix(state_);
  }
  // Uniform in [0, 1): the top 53 bits, exactly representable.
  double uniform01() { return double(next_u64() >> 11) * 0x1.0p-53; }
  // Uniform in [-1, 1).
  double uniform_pm1() { return 2.0 * uniform01() - 1.0; }
  // Weber-Penn's "+- amount": uniform in [-amount, amount).
  double vary(double amount) { return amount * uniform_pm1(); }

 private:
  uint64_t state_;
};

}  // namespace boreas::impl
