// boreas for Python: the wind methods of boreas._boreas.World — sampling (into a caller's
// array without a copy), waves, gusts, flow primitives, solids and the grid.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <string>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

// out= as given, if it is a writeable C-contiguous float32 array of shape (n, 3).
py::array_t<float> checked_out(py::handle out, py::ssize_t n) {
  if (!py::isinstance<py::array>(out))
    throw py::type_error("out must be a numpy.ndarray, not " +
                         std::string(py::str(py::type::of(out).attr("__name__"))));
  py::array a = py::reinterpret_borrow<py::array>(out);
  if (!py::array_t<float>::check_(a))
    throw py::value_error("out must have dtype float32, not " + std::string(py::str(a.dtype())));
  if (a.ndim() != 2 || a.shape(0) != n || a.shape(1) != 3)
    throw py::value_error("out must have shape (" + std::to_string(n) + ", 3), the points' shape");
  if (!(a.flags() & py::array::c_style)) throw py::value_error("out must be C-contiguous");
  if (!(a.flags() & py::detail::npy_api::NPY_ARRAY_ALIGNED_))
    throw py::value_error("out must be aligned (a float32 view at an odd byte offset is not)");
  if (!a.writeable()) throw py::value_error("out must be writeable");
  return py::reinterpret_borrow<py::array_t<float>>(out);
}

py::array_t<float> sample(World& w, py::handle points, py::handle out) {
  py::array_t<float> p = as_points(points, "points");
  py::ssize_t n = p.shape(0);
  py::array_t<float> result =
      out.is_none() ? py::array_t<float>({n, py::ssize_t(3)}) : checked_out(out, n);
  if (n > std::numeric_limits<int>::max() / 3)
    throw py::value_error("too many points for one call: " + std::to_string(n));
  const float* xyz = p.data();
  float* force = result.mutable_data();
  // Sampling into the points' own memory: read them from a copy.
  std::vector<float> copy;
  if (n > 0 && xyz < force + 3 * n && force < xyz + 3 * n) {
    copy.assign(xyz, xyz + 3 * n);
    xyz = copy.data();
  }
  w.call([&](boreas_world cw) { check(boreas_wind_sample(cw, xyz, int(n), force)); });
  return result;
}

}  // namespace

void bind_wind(py::class_<World>& cls) {
  cls.def("wind_sample", &sample, py::arg("points"), py::arg("out") = py::none(),
          "boreas_wind_sample: (N, 3) float32 m/s at (N, 3) points, m.");
  cls.def(
      "wind_set_waves",
      [](World& w, py::handle waves, float blend) {
        std::vector<boreas_wave> list = waves_from(waves);
        w.call([&](boreas_world cw) {
          check(boreas_wind_set_waves(cw, list.empty() ? nullptr : list.data(), int(list.size()),
                                      blend));
        });
      },
      py::arg("waves"), py::arg("blend") = 0.0f, "boreas_wind_set_waves.");
  cls.def(
      "wind_add_gust",
      [](World& w, py::handle def) {
        boreas_gust_def gust = gust_from(def);
        boreas_gust_id id{};
        w.call([&](boreas_world cw) { check(boreas_wind_add_gust(cw, &gust, &id)); });
        return id_to_py(id);
      },
      py::arg("gust"), "boreas_wind_add_gust; returns the id.");
  cls.def(
      "wind_remove_gust",
      [](World& w, py::handle id) {
        auto gust = id_from<boreas_gust_id>(id);
        w.call([&](boreas_world cw) { check(boreas_wind_remove_gust(cw, gust)); });
      },
      py::arg("id"), "boreas_wind_remove_gust.");
  cls.def(
      "wind_add_primitive",
      [](World& w, py::handle def) {
        boreas_flow_primitive_def p = primitive_from(def);
        boreas_primitive_id id{};
        w.call([&](boreas_world cw) { check(boreas_wind_add_primitive(cw, &p, &id)); });
        return id_to_py(id);
      },
      py::arg("primitive"), "boreas_wind_add_primitive; returns the id.");
  cls.def(
      "wind_remove_primitive",
      [](World& w, py::handle id) {
        auto p = id_from<boreas_primitive_id>(id);
        w.call([&](boreas_world cw) { check(boreas_wind_remove_primitive(cw, p)); });
      },
      py::arg("id"), "boreas_wind_remove_primitive.");
  cls.def(
      "wind_add_solid_box",
      [](World& w, py::handle min, py::handle max) {
        float lo[3], hi[3];
        vec3_from(min, lo, "min");
        vec3_from(max, hi, "max");
        w.call([&](boreas_world cw) { check(boreas_wind_add_solid_box(cw, lo, hi)); });
      },
      py::arg("min"), py::arg("max"), "boreas_wind_add_solid_box (m).");
  cls.def(
      "wind_set_solid_mask",
      [](World& w, py::handle mask) {
        if (mask.is_none()) {
          w.call([&](boreas_world cw) { check(boreas_wind_set_solid_mask(cw, nullptr, 0)); });
          return;
        }
        auto bytes = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(mask);
        if (!bytes) throw py::type_error("mask must be an array-like of booleans or bytes");
        const uint8_t* data = bytes.data();
        int64_t count = int64_t(bytes.size());
        w.call([&](boreas_world cw) { check(boreas_wind_set_solid_mask(cw, data, count)); });
      },
      py::arg("mask"), "boreas_wind_set_solid_mask: cells x fastest, then y, then z.");
  cls.def(
      "wind_grid",
      [](World& w) {
        boreas_grid_def g{};
        w.call([&](boreas_world cw) { check(boreas_wind_get_grid(cw, &g)); });
        return to_dict(g);
      },
      "boreas_wind_get_grid, as a dict.");
  cls.def(
      "wind_grid_values",
      [](World& w) {
        boreas_grid_def g{};
        std::vector<float> cells = w.call([&](boreas_world cw) {
          check(boreas_wind_get_grid(cw, &g));
          std::vector<float> out(size_t(g.resolution[0]) * g.resolution[1] * g.resolution[2] * 4);
          check(boreas_wind_get_grid_values(cw, out.data(), int64_t(out.size())));
          return out;
        });
        return adopt(std::move(cells),
                     {g.resolution[2], g.resolution[1], g.resolution[0], py::ssize_t(4)});
      },
      "boreas_wind_get_grid_values: (nz, ny, nx, 4) float32 (m/s x, y, z; 1 if solid).");
}

}  // namespace boreas_py
