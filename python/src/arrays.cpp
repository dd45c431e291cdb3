// boreas for Python: the structured dtypes mirroring boreas.h's output structs, and the
// conversion of point arrays.
#include "arrays.h"

#include <cstddef>
#include <initializer_list>

#include "boreas/boreas.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

struct Field {
  const char* name;
  const char* format;  // NumPy's, little-endian as the device writes: "<f4", "(4,3)<f4"
  size_t offset;
};

py::dtype make_dtype(std::initializer_list<Field> fields, size_t itemsize) {
  py::list names, formats, offsets;
  for (const Field& f : fields) {
    names.append(f.name);
    formats.append(f.format);
    offsets.append(f.offset);
  }
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = itemsize;
  return py::dtype::from_args(spec);
}

// A dtype made on first use and kept (module state lives as long as the process).
template <typename Make>
py::dtype cached(py::dtype*& slot, Make make) {
  if (!slot) slot = new py::dtype(make());
  return *slot;
}

py::dtype* branch = nullptr;
py::dtype* leaf = nullptr;
py::dtype* vertex = nullptr;
py::dtype* component = nullptr;
py::dtype* meadow_vertex = nullptr;
py::dtype* meadow_part = nullptr;
py::dtype* hit = nullptr;
py::dtype* lidar_point = nullptr;
py::dtype* pixel_label = nullptr;

}  // namespace

py::dtype branch_dtype() {
  return cached(branch, [] {
    return make_dtype({{"control_points", "(4,3)<f4", offsetof(boreas_branch, control_points)},
                       {"orientation", "(3,)<f4", offsetof(boreas_branch, orientation)},
                       {"level", "<i4", offsetof(boreas_branch, level)},
                       {"parent", "<i4", offsetof(boreas_branch, parent)},
                       {"parent_v", "<f4", offsetof(boreas_branch, parent_v)},
                       {"radius", "<f4", offsetof(boreas_branch, radius)},
                       {"length", "<f4", offsetof(boreas_branch, length)},
                       {"broken", "<i4", offsetof(boreas_branch, broken)}},
                      sizeof(boreas_branch));
  });
}

py::dtype leaf_dtype() {
  return cached(leaf, [] {
    return make_dtype({{"position", "(3,)<f4", offsetof(boreas_leaf, position)},
                       {"axis", "(3,)<f4", offsetof(boreas_leaf, axis)},
                       {"normal", "(3,)<f4", offsetof(boreas_leaf, normal)},
                       {"length", "<f4", offsetof(boreas_leaf, length)},
                       {"width", "<f4", offsetof(boreas_leaf, width)},
                       {"branch", "<i4", offsetof(boreas_leaf, branch)}},
                      sizeof(boreas_leaf));
  });
}

py::dtype vertex_dtype() {
  return cached(vertex, [] {
    return make_dtype({{"position", "(3,)<f4", offsetof(boreas_vertex, position)},
                       {"normal", "(3,)<f4", offsetof(boreas_vertex, normal)},
                       {"uv", "(2,)<f4", offsetof(boreas_vertex, uv)}},
                      sizeof(boreas_vertex));
  });
}

py::dtype component_dtype() {
  return cached(component, [] {
    return make_dtype(
        {{"base", "(3,)<f4", offsetof(boreas_component, base)},
         {"center_of_mass", "(3,)<f4", offsetof(boreas_component, center_of_mass)},
         {"velocity", "(3,)<f4", offsetof(boreas_component, velocity)},
         {"rest_center_of_mass", "(3,)<f4", offsetof(boreas_component, rest_center_of_mass)},
         {"broken", "<i4", offsetof(boreas_component, broken)},
         {"species", "<i4", offsetof(boreas_component, species)},
         {"part", "<i4", offsetof(boreas_component, part)},
         {"parent", "<i4", offsetof(boreas_component, parent)}},
        sizeof(boreas_component));
  });
}

py::dtype meadow_part_dtype() {
  return cached(meadow_part, [] {
    return make_dtype({{"species", "<i4", offsetof(boreas_meadow_part, species)},
                       {"part", "<i4", offsetof(boreas_meadow_part, part)},
                       {"name", "S32", offsetof(boreas_meadow_part, name)},
                       {"color", "(3,)<f4", offsetof(boreas_meadow_part, color)},
                       {"translucency", "<f4", offsetof(boreas_meadow_part, translucency)}},
                      sizeof(boreas_meadow_part));
  });
}

py::dtype meadow_vertex_dtype() {
  return cached(meadow_vertex, [] {
    return make_dtype({{"position", "(3,)<f4", offsetof(boreas_meadow_vertex, position)},
                       {"normal", "(3,)<f4", offsetof(boreas_meadow_vertex, normal)},
                       {"uv", "(2,)<f4", offsetof(boreas_meadow_vertex, uv)}},
                      sizeof(boreas_meadow_vertex));
  });
}

py::dtype hit_dtype() {
  return cached(hit, [] {
    return make_dtype({{"distance", "<f4", offsetof(boreas_hit, distance)},
                       {"point", "(3,)<f4", offsetof(boreas_hit, point)},
                       {"normal", "(3,)<f4", offsetof(boreas_hit, normal)},
                       {"kind", "<i4", offsetof(boreas_hit, kind)},
                       {"object", "(3,)<u4", offsetof(boreas_hit, object)},
                       {"part", "<i4", offsetof(boreas_hit, part)}},
                      sizeof(boreas_hit));
  });
}

py::dtype lidar_point_dtype() {
  return cached(lidar_point, [] {
    return make_dtype({{"x", "<f4", offsetof(boreas_lidar_point, x)},
                       {"y", "<f4", offsetof(boreas_lidar_point, y)},
                       {"z", "<f4", offsetof(boreas_lidar_point, z)},
                       {"intensity", "<f4", offsetof(boreas_lidar_point, intensity)},
                       {"ring", "<u2", offsetof(boreas_lidar_point, ring)},
                       {"time", "<f4", offsetof(boreas_lidar_point, time)},
                       {"kind", "<i4", offsetof(boreas_lidar_point, kind)},
                       {"object", "(3,)<u4", offsetof(boreas_lidar_point, object)},
                       {"part", "<i4", offsetof(boreas_lidar_point, part)}},
                      sizeof(boreas_lidar_point));
  });
}

py::dtype pixel_label_dtype() {
  return cached(pixel_label, [] {
    return make_dtype({{"kind", "<i4", offsetof(boreas_pixel_label, kind)},
                       {"object", "(3,)<u4", offsetof(boreas_pixel_label, object)},
                       {"part", "<i4", offsetof(boreas_pixel_label, part)}},
                      sizeof(boreas_pixel_label));
  });
}

py::array_t<float> as_points(py::handle points, const char* what) {
  if (points.is_none())
    throw py::type_error(std::string(what) + " must be an array of shape (N, 3), not None");
  auto array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!array)
    throw py::type_error(std::string(what) + " must be an array-like of numbers, shape (N, 3)");
  // A float32 view at an odd byte offset is C-contiguous but not aligned: the library reads
  // floats, so such points are copied once into aligned memory.
  if (!(array.flags() & py::detail::npy_api::NPY_ARRAY_ALIGNED_))
    array = py::array_t<float, py::array::c_style | py::array::forcecast>(
        py::module_::import("numpy").attr("require")(array, "float32", py::make_tuple("C", "A")));
  if (array.ndim() != 2 || array.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < array.ndim(); ++i)
      shape += (i ? ", " : "") + std::to_string(array.shape(i));
    shape += array.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(what) + " must have shape (N, 3), not " + shape);
  }
  return array;
}

}  // namespace boreas_py
