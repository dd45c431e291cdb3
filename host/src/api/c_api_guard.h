// boreas: what every C entry point shares: the world behind a handle, and the guard that
// turns exceptions into a boreas_status and the per-thread message of boreas_last_error.
// No exception crosses the C ABI.
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>
#include <new>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"
#include "world.h"

struct boreas_world_s {
  boreas::impl::World world;
  explicit boreas_world_s(const boreas_world_def& def) : world(def) {}
};

namespace boreas::api {

// The message of the last failed call on this thread (c_api.cpp).
std::string& last_error();

template <typename F>
boreas_status guarded(const char* function, F&& body) {
  std::string& message = last_error();
  message.clear();
  try {
    body();
    return BOREAS_OK;
  } catch (const boreas::impl::Error& e) {
    message = std::string(function) + ": " + e.what();
    return e.status();
  } catch (const std::bad_alloc&) {
    message = std::string(function) + ": out of host memory";
    return BOREAS_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    message = std::string(function) + ": internal error: " + e.what();
    return BOREAS_ERROR_INTERNAL;
  } catch (...) {
    message = std::string(function) + ": internal error";
    return BOREAS_ERROR_INTERNAL;
  }
}

// The world behind a handle, refused while one of its own calls is running (a call from
// inside its progress callback: World::check_unlocked).
inline boreas::impl::World& world_of(boreas_world w) {
  if (w == nullptr) boreas::impl::fail_argument("world is NULL");
  w->world.check_unlocked();
  return w->world;
}

// The one output-array rule of the API (boreas.h, "Output arrays"): out NULL asks for
// the count; otherwise capacity must hold every item, or nothing is written (count
// included) and the message names the size needed.
template <typename T>
void copy_out(const std::vector<T>& items, T* out, int capacity, int* count) {
  if (!count) boreas::impl::fail_argument("count is NULL");
  if (items.size() > static_cast<size_t>(INT32_MAX))
    boreas::impl::fail_argument("more than 2^31 items (" + std::to_string(items.size()) + ")");
  if (out && capacity < static_cast<int>(items.size()))
    boreas::impl::fail_argument("capacity " + std::to_string(capacity) + " is below the " +
                                std::to_string(items.size()) +
                                " items to write (call with out NULL for the count)");
  if (out) std::copy(items.begin(), items.end(), out);
  *count = static_cast<int>(items.size());
}

}  // namespace boreas::api
