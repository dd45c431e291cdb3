// boreas for Python: the world under boreas.World. It owns one boreas_world and runs every
// call on it with the GIL released and the world's lock held: the C API lets one thread at
// a time use a world, so Python threads may share a World (their calls take turns) while
// other Python code runs during long steps, samples and adds.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <mutex>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"

namespace boreas_py {

class World {
 public:
  explicit World(const boreas_world_def& def);  // with the GIL held; releases it to create
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Destroys the C world; later calls raise boreas.Error. Closing twice is fine.
  void close();
  bool closed() const { return closed_; }  // without the lock: never wait for it holding the GIL

  // fn(boreas_world) with the GIL released and the lock held. fn must not touch Python
  // objects (it may take the GIL back, as a progress callback does). Throws BindingError
  // when the world is closed or when called from inside another call on this world.
  template <typename Fn>
  auto call(Fn&& fn) -> decltype(fn(std::declval<boreas_world>())) {
    if (caller_.load() == std::this_thread::get_id())
      throw BindingError("a callback must not call into the world it reports on");
    pybind11::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!world_) throw BindingError("the world is closed");
    struct Caller {
      std::atomic<std::thread::id>& id;
      explicit Caller(std::atomic<std::thread::id>& i) : id(i) { id = std::this_thread::get_id(); }
      ~Caller() { id = std::thread::id(); }
    } caller(caller_);
    return fn(world_);
  }

 private:
  std::mutex mutex_;
  boreas_world world_ = nullptr;  // null once closed
  std::atomic<bool> closed_{false};
  std::atomic<std::thread::id> caller_{};  // the thread inside call(), if any
};

// A list the C API hands out as "count, then copy" (get(world, out, capacity, &count)):
// the count first (out NULL), then a copy into exactly that many items, under one hold of
// the lock so that nothing changes in between.
template <typename T, typename Get>
std::vector<T> read_list(World& world, Get get) {
  return world.call([&](boreas_world w) {
    int count = 0;
    check(get(w, nullptr, 0, &count));
    std::vector<T> out(static_cast<size_t>(count));
    if (count > 0) {
      int written = count;
      check(get(w, out.data(), count, &written));
      if (written != count)
        throw StatusError(BOREAS_ERROR_INTERNAL, "a list changed size between two reads");
    }
    return out;
  });
}

// Ids travel through Python as (index, generation, tag) tuples of ints.
template <typename Id>
pybind11::tuple id_to_py(Id id) {
  return pybind11::make_tuple(id.index, id.generation, id.tag);
}

template <typename Id>
Id id_from(pybind11::handle obj) {
  try {
    auto t = obj.cast<std::tuple<uint32_t, uint32_t, uint32_t>>();
    return Id{std::get<0>(t), std::get<1>(t), std::get<2>(t)};
  } catch (const pybind11::cast_error&) {
    throw pybind11::type_error("an id is a tuple of three integers (index, generation, tag)");
  }
}

// The parts of the class boreas._boreas.World, bound in one file each.
void bind_world(pybind11::module_& m);
void bind_wind(pybind11::class_<World>& cls);
void bind_plants(pybind11::class_<World>& cls);
void bind_mesh_trees(pybind11::class_<World>& cls);
void bind_sensors(pybind11::class_<World>& cls);
void bind_skin(pybind11::module_& m, pybind11::class_<World>& cls);

}  // namespace boreas_py
