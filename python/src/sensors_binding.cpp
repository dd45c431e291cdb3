// boreas for Python: the rays and sensors of boreas._boreas.World — cast_rays, LiDARs and
// their points, depth images. Results come back as structured NumPy arrays over the C
// structs (arrays.h), without a copy.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <climits>
#include <cmath>
#include <string>
#include <vector>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

// origins and directions (N, 3); max_distance a number or N numbers.
py::array cast_rays(World& w, py::handle origins, py::handle directions, py::handle max_distance) {
  py::array_t<float> o = as_points(origins, "origins"), d = as_points(directions, "directions");
  const py::ssize_t n = o.shape(0);
  if (d.shape(0) != n)
    throw py::value_error("directions has " + std::to_string(d.shape(0)) + " rows, origins " +
                          std::to_string(n));
  if (n > py::ssize_t(INT_MAX)) throw py::value_error("more than 2^31 - 1 rays in one call");
  auto m = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(max_distance);
  if (!m) throw py::type_error("max_distance must be a number or an array of N numbers");
  if (!(m.ndim() == 0 || (m.ndim() == 1 && m.shape(0) == n)))
    throw py::value_error("max_distance must be a number or have shape (" + std::to_string(n) +
                          ",)");
  std::vector<boreas_ray> rays(static_cast<size_t>(n));
  const float* od = o.data();
  const float* dd = d.data();
  const float* md = m.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      rays[size_t(i)].origin[a] = od[3 * i + a];
      rays[size_t(i)].direction[a] = dd[3 * i + a];
    }
    rays[size_t(i)].max_distance = m.ndim() == 0 ? md[0] : md[i];
  }
  std::vector<boreas_hit> hits(static_cast<size_t>(n));
  if (n > 0)
    w.call([&](boreas_world cw) {
      check(boreas_world_cast_rays(cw, rays.data(), int(n), hits.data()));
    });
  return adopt(std::move(hits), hit_dtype(), {n});
}

py::tuple add_lidar(World& w, py::handle def, py::handle preset) {
  boreas_lidar_def base = boreas_default_lidar_def();
  if (!preset.is_none()) check(boreas_lidar_preset(preset.cast<std::string>().c_str(), &base));
  LidarDef lidar;
  lidar_from(def, base, &lidar);
  boreas_lidar_id id{};
  w.call([&](boreas_world cw) { check(boreas_world_add_lidar(cw, &lidar.def, &id)); });
  return id_to_py(id);
}

boreas_lidar_points which_from(const std::string& which) {
  if (which == "step") return BOREAS_LIDAR_LAST_STEP;
  if (which == "sweep") return BOREAS_LIDAR_LAST_SWEEP;
  throw py::value_error("which must be 'sweep' or 'step', not '" + which + "'");
}

py::array lidar_points(World& w, py::handle id_obj, const std::string& which) {
  auto id = id_from<boreas_lidar_id>(id_obj);
  const boreas_lidar_points from = which_from(which);
  std::vector<boreas_lidar_point> v = read_list<boreas_lidar_point>(
      w, [&](boreas_world cw, boreas_lidar_point* out, int capacity, int* count) {
        return boreas_lidar_get_points(cw, id, from, out, capacity, count);
      });
  const py::ssize_t n = py::ssize_t(v.size());
  return adopt(std::move(v), lidar_point_dtype(), {n});
}

py::tuple capture_depth(World& w, py::handle camera_obj) {
  const boreas_depth_camera_def camera = depth_camera_from(camera_obj);
  // The C call checks the def; sizes here only when it is sane enough to allocate.
  const bool sized = camera.width > 0 && camera.height > 0 &&
                     int64_t(camera.width) * camera.height <= BOREAS_DEPTH_CAMERA_MAX_PIXELS;
  const size_t pixels = sized ? size_t(camera.width) * size_t(camera.height) : 0;
  std::vector<float> depth(pixels);
  std::vector<boreas_pixel_label> labels(pixels);
  w.call([&](boreas_world cw) {
    check(boreas_world_capture_depth(cw, &camera, sized ? depth.data() : nullptr,
                                     sized ? labels.data() : nullptr));
  });
  const py::ssize_t h = camera.height, wd = camera.width;
  return py::make_tuple(adopt(std::move(depth), {h, wd}),
                        adopt(std::move(labels), pixel_label_dtype(), {h, wd}));
}

}  // namespace

void bind_sensors(py::class_<World>& cls) {
  cls.def("cast_rays", &cast_rays, py::arg("origins"), py::arg("directions"),
          py::arg("max_distance"), "boreas_world_cast_rays: a structured array of hits.");
  cls.def("add_lidar", &add_lidar, py::arg("lidar"), py::arg("preset") = py::none(),
          "boreas_world_add_lidar over the defaults or a preset's def; returns the id.");
  cls.def(
      "remove_lidar",
      [](World& w, py::handle id) {
        auto lidar = id_from<boreas_lidar_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_lidar(cw, lidar)); });
      },
      py::arg("id"), "boreas_world_remove_lidar.");
  cls.def(
      "lidar_set_pose",
      [](World& w, py::handle id, py::handle pose_obj) {
        auto lidar = id_from<boreas_lidar_id>(id);
        const boreas_pose pose = pose_from(pose_obj, "pose");
        w.call([&](boreas_world cw) { check(boreas_lidar_set_pose(cw, lidar, &pose)); });
      },
      py::arg("id"), py::arg("pose"), "boreas_lidar_set_pose (pose a dict).");
  cls.def("lidar_points", &lidar_points, py::arg("id"), py::arg("which"),
          "boreas_lidar_get_points ('sweep' or 'step'): a structured array.");
  cls.def(
      "lidar_info",
      [](World& w, py::handle id) {
        auto lidar = id_from<boreas_lidar_id>(id);
        boreas_lidar_info info{};
        w.call([&](boreas_world cw) { check(boreas_lidar_get_info(cw, lidar, &info)); });
        return to_dict(info);
      },
      py::arg("id"), "boreas_lidar_get_info, as a dict.");
  cls.def("capture_depth", &capture_depth, py::arg("camera"),
          "boreas_world_capture_depth: (depth (H, W) float32, labels (H, W)).");
}

}  // namespace boreas_py
