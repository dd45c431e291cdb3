// boreas for Python: NumPy views of the C structs. Each structured dtype takes its field
// offsets and item size from the C struct itself, so a list the library writes becomes an
// array without a copy and the layouts cannot drift.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <utility>
#include <vector>

namespace boreas_py {

// Structured dtypes of boreas_branch, boreas_leaf, boreas_vertex, boreas_component and
// boreas_meadow_vertex (made once; the GIL must be held).
pybind11::dtype branch_dtype();
pybind11::dtype leaf_dtype();
pybind11::dtype vertex_dtype();
pybind11::dtype component_dtype();
pybind11::dtype meadow_part_dtype();
pybind11::dtype meadow_vertex_dtype();
// boreas_hit, boreas_lidar_point (x, y, z, intensity, ring, time first: a ROS PointCloud2's
// fields) and boreas_pixel_label; ids as (3,) uint32 (index, generation, tag).
pybind11::dtype hit_dtype();
pybind11::dtype lidar_point_dtype();
pybind11::dtype pixel_label_dtype();

// Hands a vector to a NumPy array of the given dtype and shape without copying: the array
// owns the vector from now on. The GIL must be held.
template <typename T>
pybind11::array adopt(std::vector<T>&& values, const pybind11::dtype& dtype,
                      std::vector<pybind11::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  pybind11::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array(dtype, std::move(shape), {}, owned->data(), owner);
}

template <typename T>
pybind11::array adopt(std::vector<T>&& values, std::vector<pybind11::ssize_t> shape) {
  return adopt(std::move(values), pybind11::dtype::of<T>(), std::move(shape));
}

// points as a C-contiguous float32 (N, 3) array: the same object when it already is one,
// else one converted copy. ValueError or TypeError (what) for anything else.
pybind11::array_t<float> as_points(pybind11::handle points, const char* what);

}  // namespace boreas_py
