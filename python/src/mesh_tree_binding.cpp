// boreas for Python: the methods of boreas._boreas.World for trees made elsewhere —
// imported meshes swaying in the wind (mesh trees) and BlobTree surfaces over a world's
// trees, whose progress callback may be a Python callable.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <exception>
#include <string>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

py::tuple add_mesh_tree(World& w, py::handle def) {
  MeshTreeDef tree;
  mesh_tree_from(def, &tree);
  boreas_mesh_tree_id id{};
  w.call([&](boreas_world cw) { check(boreas_world_add_mesh_tree(cw, &tree.def, &id)); });
  return id_to_py(id);
}

py::array mesh_tree_vertices(World& w, py::handle id_obj, py::handle part_obj) {
  auto id = id_from<boreas_mesh_tree_id>(id_obj);
  boreas_mesh_part part = mesh_part_from(part_obj);
  std::vector<boreas_vertex> v = read_list<boreas_vertex>(
      w, [&](boreas_world cw, boreas_vertex* out, int capacity, int* count) {
        return boreas_mesh_tree_get_vertices(cw, id, part, out, capacity, count);
      });
  py::ssize_t n = py::ssize_t(v.size());
  return adopt(std::move(v), vertex_dtype(), {n});
}

py::array mesh_tree_indices(World& w, py::handle id_obj, py::handle part_obj) {
  auto id = id_from<boreas_mesh_tree_id>(id_obj);
  boreas_mesh_part part = mesh_part_from(part_obj);
  std::vector<uint32_t> v =
      read_list<uint32_t>(w, [&](boreas_world cw, uint32_t* out, int capacity, int* count) {
        return boreas_mesh_tree_get_indices(cw, id, part, out, capacity, count);
      });
  py::ssize_t triangles = py::ssize_t(v.size() / 3);
  return adopt(std::move(v), {triangles, py::ssize_t(3)});
}

// A Python progress callable called from boreas_world_add_blobtree, on the calling thread.
// The C call cannot be stopped, so the first exception the callable raises is kept, later
// reports are skipped, and the exception is raised once the call has returned.
struct Progress {
  py::handle callable;
  std::exception_ptr error;

  static void report(void* user, float fraction, const char* stage) {
    auto* self = static_cast<Progress*>(user);
    if (self->error) return;
    py::gil_scoped_acquire gil;
    try {
      self->callable(fraction, stage ? stage : "");
    } catch (...) {
      self->error = std::current_exception();
    }
  }
};

py::tuple add_blobtree(World& w, py::handle tree_obj, py::handle def, py::handle progress) {
  auto tree = id_from<boreas_tree_id>(tree_obj);
  BlobTreeDef blob;
  blobtree_from(def, &blob);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be callable(fraction, stage) or None");
  Progress report{progress, nullptr};
  boreas_blobtree_id id{};
  boreas_status status = BOREAS_OK;
  std::string message;
  w.call([&](boreas_world cw) {
    status = boreas_world_add_blobtree(
        cw, tree, &blob.def, progress.is_none() ? nullptr : &Progress::report, &report, &id);
    if (status != BOREAS_OK) message = boreas_last_error();
    // The callable failed: nothing is added after all.
    if (report.error && status == BOREAS_OK) boreas_world_remove_blobtree(cw, id);
  });
  if (report.error) std::rethrow_exception(report.error);
  if (status != BOREAS_OK) throw StatusError(status, message);
  return id_to_py(id);
}

py::tuple blobtree_mesh(World& w, py::handle id_obj) {
  auto id = id_from<boreas_blobtree_id>(id_obj);
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
  w.call([&](boreas_world cw) {
    int nv = 0, ni = 0;
    check(boreas_blobtree_get_mesh(cw, id, nullptr, 0, &nv, nullptr, 0, &ni));
    // Without both, the C call would only count (a NULL data() of an empty vector).
    if (nv == 0 || ni == 0) return;
    vertices.resize(size_t(nv));
    indices.resize(size_t(ni));
    check(boreas_blobtree_get_mesh(cw, id, vertices.data(), nv, &nv, indices.data(), ni, &ni));
  });
  py::ssize_t triangles = py::ssize_t(indices.size() / 3);
  py::ssize_t nv = py::ssize_t(vertices.size());
  return py::make_tuple(adopt(std::move(vertices), vertex_dtype(), {nv}),
                        adopt(std::move(indices), {triangles, py::ssize_t(3)}));
}

}  // namespace

void bind_mesh_trees(py::class_<World>& cls) {
  cls.def("add_mesh_tree", &add_mesh_tree, py::arg("mesh_tree"),
          "boreas_world_add_mesh_tree; the id.");
  cls.def(
      "remove_mesh_tree",
      [](World& w, py::handle id) {
        auto t = id_from<boreas_mesh_tree_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_mesh_tree(cw, t)); });
      },
      py::arg("id"), "boreas_world_remove_mesh_tree.");
  cls.def(
      "mesh_tree_info",
      [](World& w, py::handle id) {
        auto t = id_from<boreas_mesh_tree_id>(id);
        boreas_mesh_tree_info info{};
        w.call([&](boreas_world cw) { check(boreas_mesh_tree_get_info(cw, t, &info)); });
        return to_dict(info);
      },
      py::arg("id"), "boreas_mesh_tree_get_info, as a dict.");
  cls.def("mesh_tree_vertices", &mesh_tree_vertices, py::arg("id"), py::arg("part"),
          "boreas_mesh_tree_get_vertices: a structured array.");
  cls.def("mesh_tree_indices", &mesh_tree_indices, py::arg("id"), py::arg("part"),
          "boreas_mesh_tree_get_indices: (M, 3) uint32.");

  cls.def("add_blobtree", &add_blobtree, py::arg("tree"), py::arg("blobtree"),
          py::arg("progress") = py::none(), "boreas_world_add_blobtree; the id.");
  cls.def(
      "remove_blobtree",
      [](World& w, py::handle id) {
        auto b = id_from<boreas_blobtree_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_blobtree(cw, b)); });
      },
      py::arg("id"), "boreas_world_remove_blobtree.");
  cls.def(
      "blobtree_info",
      [](World& w, py::handle id) {
        auto b = id_from<boreas_blobtree_id>(id);
        boreas_blobtree_info info{};
        w.call([&](boreas_world cw) { check(boreas_blobtree_get_info(cw, b, &info)); });
        return to_dict(info);
      },
      py::arg("id"), "boreas_blobtree_get_info, as a dict.");
  cls.def("blobtree_mesh", &blobtree_mesh, py::arg("id"),
          "boreas_blobtree_get_mesh: (vertices, (M, 3) uint32 triangles).");
}

}  // namespace boreas_py
