// boreas for Python: the plant methods of boreas._boreas.World — Weber-Penn trees (one or a
// batch), meadows of underbrush, and the colliders and emitters that push it. Lists come
// back as structured NumPy arrays over the C structs (arrays.h), without a copy.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <memory>
#include <string>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

py::tuple add_tree(World& w, py::handle def) {
  TreeDef tree;
  tree_from(def, &tree, "tree");
  boreas_tree_id id{};
  w.call([&](boreas_world cw) { check(boreas_world_add_tree(cw, &tree.def, &id)); });
  return id_to_py(id);
}

py::list add_trees(World& w, py::handle defs) {
  std::vector<std::unique_ptr<TreeDef>> storage;
  std::vector<boreas_tree_def> list;
  for (py::handle item : py::iter(defs)) {
    storage.push_back(std::make_unique<TreeDef>());
    tree_from(item, storage.back().get(), "trees[" + std::to_string(storage.size() - 1) + "]");
    list.push_back(storage.back()->def);
  }
  std::vector<boreas_tree_id> ids(list.size());
  if (!list.empty())
    w.call([&](boreas_world cw) {
      check(boreas_world_add_trees(cw, list.data(), int(list.size()), ids.data()));
    });
  py::list out;
  for (const boreas_tree_id& id : ids) out.append(id_to_py(id));
  return out;
}

py::tuple tree_mesh(World& w, py::handle id_obj) {
  auto id = id_from<boreas_tree_id>(id_obj);
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
  w.call([&](boreas_world cw) {
    int nv = 0, ni = 0;
    check(boreas_tree_get_mesh(cw, id, nullptr, 0, &nv, nullptr, 0, &ni));
    // Without both, the C call would only count (a NULL data() of an empty vector).
    if (nv == 0 || ni == 0) return;
    vertices.resize(size_t(nv));
    indices.resize(size_t(ni));
    check(boreas_tree_get_mesh(cw, id, vertices.data(), nv, &nv, indices.data(), ni, &ni));
  });
  py::ssize_t triangles = py::ssize_t(indices.size() / 3);
  py::ssize_t nv = py::ssize_t(vertices.size());
  return py::make_tuple(adopt(std::move(vertices), vertex_dtype(), {nv}),
                        adopt(std::move(indices), {triangles, py::ssize_t(3)}));
}

py::tuple add_meadow(World& w, py::handle def) {
  MeadowDef meadow;
  meadow_from(def, &meadow, "meadow");
  boreas_meadow_id id{};
  w.call([&](boreas_world cw) { check(boreas_world_add_meadow(cw, &meadow.def, &id)); });
  return id_to_py(id);
}

py::list add_meadows(World& w, py::handle defs) {
  std::vector<std::unique_ptr<MeadowDef>> storage;
  std::vector<boreas_meadow_def> list;
  for (py::handle item : py::iter(defs)) {
    storage.push_back(std::make_unique<MeadowDef>());
    meadow_from(item, storage.back().get(), "meadows[" + std::to_string(storage.size() - 1) + "]");
    list.push_back(storage.back()->def);
  }
  std::vector<boreas_meadow_id> ids(list.size());
  if (!list.empty())
    w.call([&](boreas_world cw) {
      check(boreas_world_add_meadows(cw, list.data(), int(list.size()), ids.data()));
    });
  py::list out;
  for (const boreas_meadow_id& id : ids) out.append(id_to_py(id));
  return out;
}

// Vertices as (components, BOREAS_MEADOW_VERTEX_STRIDE): row i is component i's strip, of
// which strip_counts[i] vertices are drawn.
py::tuple meadow_vertices(World& w, py::handle id_obj, py::handle camera) {
  auto id = id_from<boreas_meadow_id>(id_obj);
  float eye[3];
  if (!camera.is_none()) vec3_from(camera, eye, "camera");
  const float* eye_ptr = camera.is_none() ? nullptr : eye;
  std::vector<boreas_meadow_vertex> vertices;
  std::vector<int32_t> strips;
  w.call([&](boreas_world cw) {
    int nv = 0;
    check(boreas_meadow_get_vertices(cw, id, eye_ptr, nullptr, 0, &nv, nullptr));
    vertices.resize(size_t(nv));
    strips.resize(size_t(nv / BOREAS_MEADOW_VERTEX_STRIDE));
    if (nv > 0)
      check(boreas_meadow_get_vertices(cw, id, eye_ptr, vertices.data(), nv, &nv, strips.data()));
  });
  py::ssize_t components = py::ssize_t(strips.size());
  return py::make_tuple(adopt(std::move(vertices), meadow_vertex_dtype(),
                              {components, py::ssize_t(BOREAS_MEADOW_VERTEX_STRIDE)}),
                        adopt(std::move(strips), {components}));
}

}  // namespace

void bind_plants(py::class_<World>& cls) {
  cls.def("add_tree", &add_tree, py::arg("tree"), "boreas_world_add_tree; returns the id.");
  cls.def("add_trees", &add_trees, py::arg("trees"), "boreas_world_add_trees; returns the ids.");
  cls.def(
      "remove_tree",
      [](World& w, py::handle id) {
        auto tree = id_from<boreas_tree_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_tree(cw, tree)); });
      },
      py::arg("id"), "boreas_world_remove_tree.");
  cls.def(
      "heal_tree",
      [](World& w, py::handle id) {
        auto tree = id_from<boreas_tree_id>(id);
        w.call([&](boreas_world cw) { check(boreas_tree_heal(cw, tree)); });
      },
      py::arg("id"), "boreas_tree_heal: mends the broken branches, back at rest.");
  cls.def(
      "tree_branches",
      [](World& w, py::handle id) {
        auto tree = id_from<boreas_tree_id>(id);
        std::vector<boreas_branch> v = read_list<boreas_branch>(
            w, [&](boreas_world cw, boreas_branch* out, int capacity, int* count) {
              return boreas_tree_get_branches(cw, tree, out, capacity, count);
            });
        py::ssize_t n = py::ssize_t(v.size());
        return adopt(std::move(v), branch_dtype(), {n});
      },
      py::arg("id"), "boreas_tree_get_branches: a structured array.");
  cls.def(
      "tree_leaves",
      [](World& w, py::handle id) {
        auto tree = id_from<boreas_tree_id>(id);
        std::vector<boreas_leaf> v = read_list<boreas_leaf>(
            w, [&](boreas_world cw, boreas_leaf* out, int capacity, int* count) {
              return boreas_tree_get_leaves(cw, tree, out, capacity, count);
            });
        py::ssize_t n = py::ssize_t(v.size());
        return adopt(std::move(v), leaf_dtype(), {n});
      },
      py::arg("id"), "boreas_tree_get_leaves: a structured array.");
  cls.def(
      "tree_leaf_occlusion",
      [](World& w, py::handle id, std::array<float, 3> transmittance) {
        auto tree = id_from<boreas_tree_id>(id);
        std::vector<std::array<float, 3>> v = read_list<std::array<float, 3>>(
            w, [&](boreas_world cw, std::array<float, 3>* out, int capacity, int* count) {
              return boreas_tree_get_leaf_occlusion(cw, tree, transmittance.data(),
                                                    out ? out->data() : nullptr, capacity, count);
            });
        py::array_t<float> a({py::ssize_t(v.size()), py::ssize_t(3)});
        if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(v[0]));
        return a;
      },
      py::arg("id"), py::arg("transmittance"), "boreas_tree_get_leaf_occlusion: (L, 3) float32.");
  cls.def("tree_mesh", &tree_mesh, py::arg("id"),
          "boreas_tree_get_mesh: (vertices, (M, 3) uint32 triangles).");

  cls.def("add_meadow", &add_meadow, py::arg("meadow"), "boreas_world_add_meadow; the id.");
  cls.def("add_meadows", &add_meadows, py::arg("meadows"), "boreas_world_add_meadows; the ids.");
  cls.def(
      "remove_meadow",
      [](World& w, py::handle id) {
        auto meadow = id_from<boreas_meadow_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_meadow(cw, meadow)); });
      },
      py::arg("id"), "boreas_world_remove_meadow.");
  cls.def(
      "meadow_components",
      [](World& w, py::handle id) {
        auto meadow = id_from<boreas_meadow_id>(id);
        std::vector<boreas_component> v = read_list<boreas_component>(
            w, [&](boreas_world cw, boreas_component* out, int capacity, int* count) {
              return boreas_meadow_get_components(cw, meadow, out, capacity, count);
            });
        py::ssize_t n = py::ssize_t(v.size());
        return adopt(std::move(v), component_dtype(), {n});
      },
      py::arg("id"), "boreas_meadow_get_components: a structured array.");
  cls.def(
      "meadow_parts",
      [](World& w, py::handle id) {
        auto meadow = id_from<boreas_meadow_id>(id);
        std::vector<boreas_meadow_part> v = read_list<boreas_meadow_part>(
            w, [&](boreas_world cw, boreas_meadow_part* out, int capacity, int* count) {
              return boreas_meadow_get_parts(cw, meadow, out, capacity, count);
            });
        py::ssize_t n = py::ssize_t(v.size());
        return adopt(std::move(v), meadow_part_dtype(), {n});
      },
      py::arg("id"), "boreas_meadow_get_parts: a structured array.");
  cls.def("meadow_vertices", &meadow_vertices, py::arg("id"), py::arg("camera") = py::none(),
          "boreas_meadow_get_vertices: ((C, 18) vertices, (C,) int32 strip counts).");

  cls.def(
      "add_collider",
      [](World& w, py::handle def) {
        boreas_collider_def c = collider_from(def);
        boreas_collider_id id{};
        w.call([&](boreas_world cw) { check(boreas_world_add_collider(cw, &c, &id)); });
        return id_to_py(id);
      },
      py::arg("collider"), "boreas_world_add_collider; the id.");
  cls.def(
      "remove_collider",
      [](World& w, py::handle id) {
        auto c = id_from<boreas_collider_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_collider(cw, c)); });
      },
      py::arg("id"), "boreas_world_remove_collider.");
  cls.def(
      "collider_set_position",
      [](World& w, py::handle id, py::handle center) {
        auto c = id_from<boreas_collider_id>(id);
        float p[3];
        vec3_from(center, p, "position");
        w.call([&](boreas_world cw) { check(boreas_collider_set_position(cw, c, p)); });
      },
      py::arg("id"), py::arg("center"), "boreas_collider_set_position.");
  cls.def(
      "collider_set_pose",
      [](World& w, py::handle id, py::handle pose_obj) {
        auto c = id_from<boreas_collider_id>(id);
        const boreas_pose pose = pose_from(pose_obj, "pose");
        w.call([&](boreas_world cw) { check(boreas_collider_set_pose(cw, c, &pose)); });
      },
      py::arg("id"), py::arg("pose"), "boreas_collider_set_pose (pose a dict).");
  cls.def(
      "collider_set_velocity",
      [](World& w, py::handle id, py::handle velocity, py::handle angular_velocity) {
        auto c = id_from<boreas_collider_id>(id);
        float v[3], a[3];
        if (!velocity.is_none()) vec3_from(velocity, v, "velocity");
        if (!angular_velocity.is_none()) vec3_from(angular_velocity, a, "angular_velocity");
        w.call([&](boreas_world cw) {
          check(boreas_collider_set_velocity(cw, c, velocity.is_none() ? nullptr : v,
                                             angular_velocity.is_none() ? nullptr : a));
        });
      },
      py::arg("id"), py::arg("velocity") = py::none(), py::arg("angular_velocity") = py::none(),
      "boreas_collider_set_velocity (None keeps either).");
  cls.def(
      "collider_pose",
      [](World& w, py::handle id) {
        auto c = id_from<boreas_collider_id>(id);
        boreas_pose pose{};
        w.call([&](boreas_world cw) { check(boreas_collider_get_pose(cw, c, &pose)); });
        return to_dict(pose);
      },
      py::arg("id"), "boreas_collider_get_pose: {position, orientation}.");
  cls.def(
      "collider_contact",
      [](World& w, py::handle id) {
        auto c = id_from<boreas_collider_id>(id);
        boreas_collider_contact contact{};
        w.call([&](boreas_world cw) { check(boreas_collider_get_contact(cw, c, &contact)); });
        return to_dict(contact);
      },
      py::arg("id"), "boreas_collider_get_contact: {force, torque, contacts}.");
  cls.def(
      "add_emitter",
      [](World& w, py::handle def) {
        boreas_emitter_def e = emitter_from(def);
        boreas_emitter_id id{};
        w.call([&](boreas_world cw) { check(boreas_world_add_emitter(cw, &e, &id)); });
        return id_to_py(id);
      },
      py::arg("emitter"), "boreas_world_add_emitter; the id.");
  cls.def(
      "remove_emitter",
      [](World& w, py::handle id) {
        auto e = id_from<boreas_emitter_id>(id);
        w.call([&](boreas_world cw) { check(boreas_world_remove_emitter(cw, e)); });
      },
      py::arg("id"), "boreas_world_remove_emitter.");
  cls.def(
      "emitter_set_position",
      [](World& w, py::handle id, py::handle center) {
        auto e = id_from<boreas_emitter_id>(id);
        float p[3];
        vec3_from(center, p, "position");
        w.call([&](boreas_world cw) { check(boreas_emitter_set_position(cw, e, p)); });
      },
      py::arg("id"), py::arg("center"), "boreas_emitter_set_position.");
}

}  // namespace boreas_py
