// boreas benchmarks: the state of the benchmark that runs now, kept across Google
// Benchmark's calls of one row (it calls a benchmark function several times while it picks
// an iteration count, and once per repetition) and shared by rows with the same key, so
// set-up (uploads, warm-up, checks against a native twin) happens once; the previous key's
// state is freed before the next is made. One slot per executable (boreas_bench,
// boreas_render_bench).
#pragma once

#include <functional>
#include <memory>
#include <string>

namespace boreas::bench_support {

struct Fixture {
  virtual ~Fixture() = default;
};

struct FixtureSlot {
  std::string key;
  std::unique_ptr<Fixture> held;
};

inline FixtureSlot& fixture_slot() {
  static FixtureSlot slot;
  return slot;
}

// The fixture for `key`, made by `make` unless it is the one held.
template <typename T>
T& fixture(const std::string& key, const std::function<std::unique_ptr<T>()>& make) {
  FixtureSlot& slot = fixture_slot();
  if (slot.key != key || !slot.held) {
    slot.held.reset();  // free the last benchmark's memory before making the next
    slot.key.clear();
    slot.held = make();
    slot.key = key;
  }
  return static_cast<T&>(*slot.held);
}

// Frees the fixture held (before the contexts and devices it uses go).
inline void release_fixture() {
  fixture_slot().held.reset();
  fixture_slot().key.clear();
}

}  // namespace boreas::bench_support
