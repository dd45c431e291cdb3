// boreas for Python: creating, closing and destroying the world under boreas.World.
#include "world.h"

namespace py = pybind11;

namespace boreas_py {

World::World(const boreas_world_def& def) {
  boreas_world created = nullptr;
  {
    py::gil_scoped_release release;  // kernels may compile for seconds
    check(boreas_world_create(&def, &created));
  }
  world_ = created;
}

World::~World() {
  // The last reference is gone, so no call is running on this world. Tearing down its
  // OpenCL objects may take a while: other threads run meanwhile.
  if (world_) {
    py::gil_scoped_release release;
    boreas_world_destroy(world_);
  }
}

void World::close() {
  if (caller_.load() == std::this_thread::get_id())
    throw BindingError("a callback must not close the world it reports on");
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex_);
  if (world_) boreas_world_destroy(world_);
  world_ = nullptr;
  closed_ = true;
}

}  // namespace boreas_py
