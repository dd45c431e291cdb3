// boreas for Python: boreas._boreas.World, its creation and closing, stepping, and what it
// reports (time, device, step statistics, memory, state hash). boreas.World wraps it.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

std::unique_ptr<World> create(py::object device, py::object cache_dir, py::object grid,
                              py::object waves) {
  boreas_world_def def = boreas_default_world_def();
  std::string device_storage, cache_storage;
  if (!device.is_none()) {
    device_storage = device.cast<std::string>();
    def.device = device_storage.c_str();
  }
  if (!cache_dir.is_none()) {
    cache_storage = cache_dir.cast<std::string>();
    def.cache_dir = cache_storage.c_str();
  }
  def.grid = grid_from(grid);
  std::vector<boreas_wave> wave_list = waves_from(waves);
  def.waves = wave_list.empty() ? nullptr : wave_list.data();
  def.wave_count = int(wave_list.size());
  return std::make_unique<World>(def);
}

}  // namespace

void bind_world(py::module_& m) {
  py::class_<World> cls(m, "World",
                        "The C world under boreas.World (use that): one boreas_world, its calls "
                        "made with the GIL released and a lock held.");
  cls.def(py::init(&create), py::arg("device") = py::none(), py::arg("cache_dir") = py::none(),
          py::arg("grid") = py::none(), py::arg("waves") = py::none(),
          "World(device, cache_dir, grid: dict, waves: list[dict]) (boreas_world_create).");
  cls.def("close", &World::close, "Destroys the C world (boreas_world_destroy); idempotent.");
  cls.def_property_readonly("closed", &World::closed, "True once closed.");
  cls.def(
      "step",
      [](World& w, float dt) {
        w.call([&](boreas_world cw) { check(boreas_world_step(cw, dt)); });
      },
      py::arg("dt"), "boreas_world_step: advances by dt seconds.");
  cls.def(
      "time",
      [](World& w) { return w.call([](boreas_world cw) { return boreas_world_get_time(cw); }); },
      "boreas_world_get_time: simulated seconds.");
  cls.def(
      "device",
      [](World& w) {
        boreas_device_info info{};
        w.call([&](boreas_world cw) { check(boreas_world_get_device(cw, &info)); });
        return to_dict(info);
      },
      "boreas_world_get_device, as a dict.");
  cls.def(
      "step_stats",
      [](World& w) {
        boreas_step_stats stats{};
        w.call([&](boreas_world cw) { check(boreas_world_get_step_stats(cw, &stats)); });
        return to_dict(stats);
      },
      "boreas_world_get_step_stats, as a dict.");
  cls.def(
      "memory",
      [](World& w) {
        boreas_memory_info info{};
        w.call([&](boreas_world cw) { check(boreas_world_get_memory(cw, &info)); });
        return to_dict(info);
      },
      "boreas_world_get_memory, as a dict.");
  cls.def(
      "state_hash",
      [](World& w) {
        uint64_t hash = 0;
        w.call([&](boreas_world cw) { check(boreas_world_get_state_hash(cw, &hash)); });
        return hash;
      },
      "boreas_world_get_state_hash.");
  cls.def(
      "set_focus",
      [](World& w, py::handle points) {
        py::array_t<float> p = as_points(points, "points");
        const float* data = p.data();
        if (p.shape(0) > py::ssize_t(std::numeric_limits<int>::max()))
          throw py::value_error("too many focus points: " + std::to_string(p.shape(0)));
        int count = int(p.shape(0));
        w.call([&](boreas_world cw) {
          check(boreas_world_set_focus(cw, count ? data : nullptr, count));
        });
      },
      py::arg("points"), "boreas_world_set_focus: (N, 3) points, m.");
  cls.def(
      "set_output_origin",
      [](World& w, std::optional<std::array<double, 3>> origin) {
        w.call([&](boreas_world cw) {
          check(boreas_world_set_output_origin(cw, origin ? origin->data() : nullptr));
        });
      },
      py::arg("origin"), "boreas_world_set_output_origin: 3 doubles, m; None: world coordinates.");

  bind_wind(cls);
  bind_plants(cls);
  bind_mesh_trees(cls);
  bind_sensors(cls);
  bind_skin(m, cls);
}

}  // namespace boreas_py
