// boreas: objects addressed by boreas_id — a slot index and a generation bumped when the
// slot is freed, so a removed id is caught instead of reaching the slot's next tenant.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"

namespace boreas::impl {

template <typename T>
class SlotMap {
 public:
  explicit SlotMap(const char* what) : what_(what) {}

  // Takes the most recently freed slot, or a new one: O(1), so a forest of many objects
  // is built in time proportional to its size.
  boreas_id insert(T value) {
    int i;
    if (!free_.empty()) {
      i = free_.back();
      free_.pop_back();
    } else {
      i = static_cast<int>(slots_.size());
      slots_.push_back({});
    }
    slots_[size_t(i)].value = std::move(value);
    ++live_;
    return boreas_id{i, slots_[size_t(i)].generation};
  }
  // Live objects.
  size_t size() const { return live_; }
  T& get(boreas_id id) {
    if (id.index < 0 || id.index >= static_cast<int>(slots_.size()) ||
        !slots_[size_t(id.index)].value || slots_[size_t(id.index)].generation != id.generation)
      fail(BOREAS_ERROR_NOT_FOUND,
           std::string("no ") + what_ + " with id {" + std::to_string(id.index) + ", " +
               std::to_string(id.generation) + "} (removed, or never added)");
    return *slots_[size_t(id.index)].value;
  }
  void erase(boreas_id id) {
    get(id);
    release(size_t(id.index));
  }
  // Calls f(value) for every live object, in slot order.
  template <typename F>
  void for_each(F&& f) {
    for (auto& s : slots_)
      if (s.value) f(*s.value);
  }
  // Removes every live object for which keep(value) is false.
  template <typename F>
  void keep_if(F&& keep) {
    for (size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].value && !keep(*slots_[i].value)) release(i);
  }

 private:
  void release(size_t i) {
    slots_[i].value.reset();
    ++slots_[i].generation;
    free_.push_back(static_cast<int>(i));
    --live_;
  }

  struct Slot {
    std::optional<T> value;
    uint32_t generation = 0;
  };
  const char* what_;
  std::vector<Slot> slots_;
  std::vector<int> free_;
  size_t live_ = 0;
};

}  // namespace boreas::impl
