// boreas: independent host work spread over the machine's cores — growing a batch's tree
// templates and laying out their blocks, each a pure function of its inputs, so the
// results are the same bytes whatever the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "errors.h"

namespace boreas::impl {

// The threads host work may use: BOREAS_THREADS (1..1024; an engine that runs boreas
// beside its own workers sets 1), else every core. A bad value is refused with an Error
// naming it.
inline size_t host_threads() {
  const char* text = std::getenv("BOREAS_THREADS");
  if (!text || !*text) return std::max(1u, std::thread::hardware_concurrency());
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1 || value > 1024)
    fail_argument(std::string("BOREAS_THREADS must be a whole number from 1 to 1024 (got '") +
                  text + "')");
  return size_t(value);
}

// Calls body(i) for i in [0, count), on up to host_threads() threads (inline for one item
// or one thread). If some calls throw, every other call still runs to its end and the
// exception of the lowest i is rethrown, so the error a caller sees does not depend on
// timing.
template <typename Body>
void parallel_for(size_t count, const Body& body) {
  // One item needs no thread, nor BOREAS_THREADS read (and so refused) to run it.
  const size_t threads = count <= 1 ? count : std::min(count, host_threads());
  if (threads <= 1) {
    for (size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<size_t> next{0};
  std::mutex guard;
  size_t failed_at = count;
  std::exception_ptr failure;
  auto work = [&] {
    for (size_t i = next++; i < count; i = next++) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(guard);
        if (i < failed_at) {
          failed_at = i;
          failure = std::current_exception();
        }
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (size_t t = 1; t < threads; ++t) {
    try {
      pool.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running share the rest
    }
  }
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace boreas::impl
