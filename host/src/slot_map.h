// boreas: the one id pool behind every kind of object a world holds. An id is a slot index,
// a generation bumped when the slot is freed (so a removed id is caught instead of reaching
// the slot's next tenant) and a tag naming the issuing world and the kind (so an id of
// another world, or of another kind cast in C, is caught too). Generations start at 1 and
// tags are never 0, so the all-zero id is null for every kind.
#pragma once

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"

namespace boreas::impl {

// The kinds, in the low 4 bits of a tag. 0 is no kind (the null id).
enum class IdKind : uint32_t {
  tree = 1,
  mesh_tree,
  blobtree,
  meadow,
  collider,
  emitter,
  primitive,
  gust,
  lidar,
};

inline const char* id_kind_name(uint32_t kind) {
  switch (static_cast<IdKind>(kind)) {
    case IdKind::tree:
      return "tree";
    case IdKind::mesh_tree:
      return "mesh tree";
    case IdKind::blobtree:
      return "blobtree";
    case IdKind::meadow:
      return "meadow";
    case IdKind::collider:
      return "collider";
    case IdKind::emitter:
      return "emitter";
    case IdKind::primitive:
      return "flow primitive";
    case IdKind::gust:
      return "gust";
    case IdKind::lidar:
      return "LiDAR";
  }
  return nullptr;
}

template <typename Id>
struct IdTraits;
#define BOREAS_ID_TRAITS(type, id_kind)     \
  template <>                               \
  struct IdTraits<type> {                   \
    static constexpr IdKind kind = id_kind; \
  };
BOREAS_ID_TRAITS(boreas_tree_id, IdKind::tree)
BOREAS_ID_TRAITS(boreas_mesh_tree_id, IdKind::mesh_tree)
BOREAS_ID_TRAITS(boreas_blobtree_id, IdKind::blobtree)
BOREAS_ID_TRAITS(boreas_meadow_id, IdKind::meadow)
BOREAS_ID_TRAITS(boreas_collider_id, IdKind::collider)
BOREAS_ID_TRAITS(boreas_emitter_id, IdKind::emitter)
BOREAS_ID_TRAITS(boreas_primitive_id, IdKind::primitive)
BOREAS_ID_TRAITS(boreas_gust_id, IdKind::gust)
BOREAS_ID_TRAITS(boreas_lidar_id, IdKind::lidar)
#undef BOREAS_ID_TRAITS

// A serial number per world of this process, 1 .. 2^28 - 1 (then round again): the upper
// 28 bits of its ids' tags.
inline uint32_t claim_world_serial() {
  static std::atomic<uint32_t> next{0};
  return next.fetch_add(1, std::memory_order_relaxed) % ((1u << 28) - 1) + 1;
}

template <typename Id, typename T>
class SlotMap {
  static constexpr uint32_t kind = static_cast<uint32_t>(IdTraits<Id>::kind);

 public:
  explicit SlotMap(uint32_t world_serial) : tag_(world_serial << 4 | kind) {}

  // Takes the most recently freed slot, or a new one: O(1), so a forest of many objects
  // is built in time proportional to its size.
  Id insert(T value) {
    uint32_t i;
    if (!free_.empty()) {
      i = free_.back();
      free_.pop_back();
    } else {
      i = static_cast<uint32_t>(slots_.size());
      slots_.push_back({});
    }
    slots_[i].value = std::move(value);
    ++live_;
    return Id{i, slots_[i].generation, tag_};
  }
  // Live objects.
  size_t size() const { return live_; }
  T& get(Id id) {
    check(id);
    return *slots_[id.index].value;
  }
  // Throws BOREAS_ERROR_NOT_FOUND naming the kind and what the id is instead: null, of
  // another kind, of another world, or removed.
  void check(Id id) const {
    const char* name = id_kind_name(kind);
    if (id.index == 0 && id.generation == 0 && id.tag == 0)
      fail(BOREAS_ERROR_NOT_FOUND,
           std::string("the null ") + name + " id (all zero: nothing is added under it)");
    const uint32_t id_kind = id.tag & 15u;
    if (id_kind != kind) {
      const char* other = id_kind_name(id_kind);
      fail(BOREAS_ERROR_NOT_FOUND, "id " + text(id) + " is not a " + name + " id" +
                                       (other ? std::string(" but a ") + other + " id"
                                              : std::string(" (its kind is unknown)")));
    }
    if (id.tag != tag_)
      fail(BOREAS_ERROR_NOT_FOUND,
           std::string(name) + " id " + text(id) + " belongs to another world");
    if (id.index >= slots_.size() || !slots_[id.index].value ||
        slots_[id.index].generation != id.generation)
      fail(BOREAS_ERROR_NOT_FOUND,
           std::string("no ") + name + " with id " + text(id) +
               (kind == uint32_t(IdKind::primitive) || kind == uint32_t(IdKind::gust)
                    ? " (removed, expired, or never added)"
                    : " (removed, or never added)"));
  }
  void erase(Id id) {
    check(id);
    release(id.index);
  }
  // Calls f(value) for every live object, in slot order.
  template <typename F>
  void for_each(F&& f) {
    for (auto& s : slots_)
      if (s.value) f(*s.value);
  }
  template <typename F>
  void for_each(F&& f) const {
    for (const auto& s : slots_)
      if (s.value) f(*s.value);
  }
  // Calls f(id, value) for every live object, in slot order.
  template <typename F>
  void for_each_id(F&& f) const {
    for (size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].value) f(Id{uint32_t(i), slots_[i].generation, tag_}, *slots_[i].value);
  }
  // Removes every live object for which keep(value) is false.
  template <typename F>
  void keep_if(F&& keep) {
    for (size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].value && !keep(*slots_[i].value)) release(static_cast<uint32_t>(i));
  }

 private:
  static std::string text(Id id) {
    return "{" + std::to_string(id.index) + ", " + std::to_string(id.generation) + ", " +
           std::to_string(id.tag) + "}";
  }
  void release(uint32_t i) {
    slots_[i].value.reset();
    // Skips 0 on wrapping, so a slot reused 2^32 times still never issues a null id.
    if (++slots_[i].generation == 0) slots_[i].generation = 1;
    free_.push_back(i);
    --live_;
  }

  struct Slot {
    std::optional<T> value;
    uint32_t generation = 1;
  };
  uint32_t tag_;
  std::vector<Slot> slots_;
  std::vector<uint32_t> free_;
  size_t live_ = 0;
};

}  // namespace boreas::impl
