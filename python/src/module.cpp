// boreas for Python: the extension module boreas._boreas — errors, the world, and the calls
// that take no world (devices, built-in species, defaults, preprocessing mesh trees). The
// package boreas (python/boreas/) builds the Pythonic API on it.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arrays.h"
#include "convert.h"
#include "errors.h"
#include "world.h"

namespace py = pybind11;
using namespace boreas_py;

namespace {

py::list devices() {
  std::vector<boreas_device_info> list;
  {
    py::gil_scoped_release release;
    int count = 0;
    check(boreas_list_devices(nullptr, 0, &count));
    list.resize(size_t(count));
    if (count > 0) {
      int written = count;
      check(boreas_list_devices(list.data(), count, &written));
      list.resize(size_t(std::min(written, count)));
    }
  }
  py::list out;
  for (const boreas_device_info& d : list) out.append(to_dict(d));
  return out;
}

int choose_device(py::object request) {
  std::string storage = request.is_none() ? std::string() : request.cast<std::string>();
  int index = -1;
  py::gil_scoped_release release;
  check(boreas_choose_device(request.is_none() ? nullptr : storage.c_str(), &index));
  return index;
}

template <typename Name>
py::list names(Name name) {
  py::list out;
  for (int i = 0; const char* n = name(i); ++i) out.append(n);
  return out;
}

py::dict preprocess_mesh_tree(py::handle def, const std::string& out_path) {
  MeshTreeDef tree;
  mesh_tree_from(def, &tree);
  boreas_mesh_tree_info info{};
  {
    py::gil_scoped_release release;
    check(boreas_preprocess_mesh_tree(&tree.def, out_path.c_str(), &info));
  }
  return to_dict(info);
}

}  // namespace

PYBIND11_MODULE(_boreas, m) {
  m.doc() = "The C API of boreas (boreas.h) for the package boreas; use boreas, not this.";
  register_errors(m);
  bind_world(m);

  m.def("devices", &devices, "boreas_list_devices: a list of dicts.");
  m.def("choose_device", &choose_device, py::arg("request") = py::none(),
        "boreas_choose_device: the index in devices() a request picks.");
  m.def(
      "builtin_species", [] { return names(boreas_builtin_species); },
      "boreas_builtin_species: the built-in tree species' names.");
  m.def(
      "builtin_underbrush_species", [] { return names(boreas_builtin_underbrush_species); },
      "boreas_builtin_underbrush_species: the built-in underbrush species' names.");
  m.def(
      "lidar_preset_names", [] { return names(boreas_lidar_preset_name); },
      "boreas_lidar_preset_name: the LiDAR presets' names.");
  m.def(
      "lidar_preset",
      [](const std::string& name) {
        boreas_lidar_def def{};
        check(boreas_lidar_preset(name.c_str(), &def));
        return to_dict(def);
      },
      py::arg("name"), "boreas_lidar_preset: the preset's def as a dict.");
  m.def("defaults", &all_defaults, "Every boreas_default_*() def, as dicts by kind.");
  m.def(
      "status_name",
      [](int status) { return std::string(boreas_status_name(boreas_status(status))); },
      py::arg("status"), "boreas_status_name.");
  m.def("preprocess_mesh_tree", &preprocess_mesh_tree, py::arg("mesh_tree"), py::arg("out_path"),
        "boreas_preprocess_mesh_tree; the info as a dict.");
  m.attr("BRANCH_DTYPE") = branch_dtype();
  m.attr("LEAF_DTYPE") = leaf_dtype();
  m.attr("VERTEX_DTYPE") = vertex_dtype();
  m.attr("COMPONENT_DTYPE") = component_dtype();
  m.attr("MEADOW_PART_DTYPE") = meadow_part_dtype();
  m.attr("MEADOW_VERTEX_DTYPE") = meadow_vertex_dtype();
  m.attr("MEADOW_VERTEX_STRIDE") = BOREAS_MEADOW_VERTEX_STRIDE;
  m.attr("HIT_DTYPE") = hit_dtype();
  m.attr("LIDAR_POINT_DTYPE") = lidar_point_dtype();
  m.attr("PIXEL_LABEL_DTYPE") = pixel_label_dtype();
  // The library's limits (boreas.h, "Limits") under their C names less BOREAS_.
  m.attr("WORLD_MAX_COORDINATE") = BOREAS_WORLD_MAX_COORDINATE;
  m.attr("STEP_MAX_SECONDS") = BOREAS_STEP_MAX_SECONDS;
  m.attr("WIND_MAX_SPEED") = BOREAS_WIND_MAX_SPEED;
  m.attr("WIND_MAX_WAVES") = BOREAS_WIND_MAX_WAVES;
  m.attr("WIND_SAMPLE_MAX_POINTS") = BOREAS_WIND_SAMPLE_MAX_POINTS;
  m.attr("GRID_MAX_RESOLUTION") = BOREAS_GRID_MAX_RESOLUTION;
  m.attr("GRID_MAX_CELLS") = BOREAS_GRID_MAX_CELLS;
  m.attr("MEADOW_MAX_COMPONENTS") = BOREAS_MEADOW_MAX_COMPONENTS;
  m.attr("MEADOW_MAX_DENSITY") = BOREAS_MEADOW_MAX_DENSITY;
  m.attr("MEADOW_MAX_SPECIES") = BOREAS_MEADOW_MAX_SPECIES;
  m.attr("MEADOW_MAX_SEED_POINTS") = BOREAS_MEADOW_MAX_SEED_POINTS;
  m.attr("PLANT_MAX_COMPONENTS") = BOREAS_PLANT_MAX_COMPONENTS;
  m.attr("COLLIDER_MAX_SPEED") = BOREAS_COLLIDER_MAX_SPEED;
  m.attr("COLLIDER_MAX_SPIN") = BOREAS_COLLIDER_MAX_SPIN;
  m.attr("IMAGE_MAX_FLOATS") = BOREAS_IMAGE_MAX_FLOATS;
  m.attr("LIDAR_MAX_CHANNELS") = BOREAS_LIDAR_MAX_CHANNELS;
  m.attr("LIDAR_MAX_RAYS_PER_TURN") = BOREAS_LIDAR_MAX_RAYS_PER_TURN;
  m.attr("DEPTH_CAMERA_MAX_PIXELS") = BOREAS_DEPTH_CAMERA_MAX_PIXELS;
  m.attr("SKIN_MAX_SEGMENTS") = BOREAS_SKIN_MAX_SEGMENTS;
  m.attr("ANIMATION_MAX_FRAMES") = BOREAS_ANIMATION_MAX_FRAMES;
  m.attr("ANIMATION_MAX_MORPH_FRAMES") = BOREAS_ANIMATION_MAX_MORPH_FRAMES;
  m.attr("ANIMATION_MAX_CLUMPS") = BOREAS_ANIMATION_MAX_CLUMPS;
  m.attr("ANIMATION_MAX_WARMUP_SECONDS") = BOREAS_ANIMATION_MAX_WARMUP_SECONDS;
  m.attr("__version__") = boreas_version();  // the loaded library's
}
