// boreas fuzzing: what every harness shares. An input the library refuses with its own
// boreas::impl::Error is the expected answer to bad input; anything else escaping (another
// exception, a crash, a sanitizer report, a leak, a timeout) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "errors.h"

namespace boreas::fuzz {

inline std::string text_of(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Runs f, taking boreas's own refusals as answers.
template <typename F>
int refused_or_read(F&& f) {
  try {
    f();
  } catch (const boreas::impl::Error&) {
  }
  return 0;
}

}  // namespace boreas::fuzz
