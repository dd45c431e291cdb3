// boreas for Python: a tree's skin (boreas_tree_get_joints and its two bindings) as
// structured NumPy arrays over the C structs, the skeleton the glTF exporter and the
// Blender add-on share.
#include <pybind11/numpy.h>

#include <cstddef>
#include <string>
#include <vector>

#include "arrays.h"
#include "convert.h"
#include "world.h"

namespace py = pybind11;

namespace boreas_py {
namespace {

py::dtype joint_dtype() {
  static py::dtype* d = new py::dtype(py::dtype::from_args(py::dict(
      py::arg("names") = py::make_tuple("position", "rotation", "parent", "branch", "u"),
      py::arg("formats") = py::make_tuple("(3,)<f4", "(4,)<f4", "<i4", "<i4", "<f4"),
      py::arg("offsets") = py::make_tuple(offsetof(boreas_joint, position),
                                          offsetof(boreas_joint, rotation),
                                          offsetof(boreas_joint, parent),
                                          offsetof(boreas_joint, branch),
                                          offsetof(boreas_joint, u)),
      py::arg("itemsize") = sizeof(boreas_joint))));
  return *d;
}

py::dtype skin_weight_dtype() {
  static py::dtype* d = new py::dtype(py::dtype::from_args(py::dict(
      py::arg("names") = py::make_tuple("joints", "weights"),
      py::arg("formats") = py::make_tuple("(4,)<i4", "(4,)<f4"),
      py::arg("offsets") = py::make_tuple(offsetof(boreas_skin_weight, joints),
                                          offsetof(boreas_skin_weight, weights)),
      py::arg("itemsize") = sizeof(boreas_skin_weight))));
  return *d;
}

boreas_skin_def skin_def(int max_level, int segments) {
  boreas_skin_def d = boreas_default_skin_def();
  d.max_level = max_level;
  d.segments = segments;
  return d;
}

template <typename T, typename Call>
py::array skin_list(World& w, py::handle id, int max_level, int segments,
                    const py::dtype& dtype, Call call) {
  const auto tree = id_from<boreas_tree_id>(id);
  const boreas_skin_def def = skin_def(max_level, segments);
  std::vector<T> v = read_list<T>(w, [&](boreas_world cw, T* out, int capacity, int* count) {
    return call(cw, tree, &def, out, capacity, count);
  });
  const py::ssize_t n = py::ssize_t(v.size());
  return adopt(std::move(v), dtype, {n});
}

}  // namespace

void bind_skin(py::module_& m, py::class_<World>& cls) {
  m.attr("JOINT_DTYPE") = joint_dtype();
  m.attr("SKIN_WEIGHT_DTYPE") = skin_weight_dtype();
  const boreas_skin_def d = boreas_default_skin_def();
  cls.def(
      "tree_joints",
      [](World& w, py::handle id, int max_level, int segments) {
        return skin_list<boreas_joint>(w, id, max_level, segments, joint_dtype(),
                                       boreas_tree_get_joints);
      },
      py::arg("id"), py::arg("max_level") = d.max_level, py::arg("segments") = d.segments,
      "boreas_tree_get_joints: a structured array (JOINT_DTYPE).");
  cls.def(
      "tree_skin_weights",
      [](World& w, py::handle id, int max_level, int segments) {
        return skin_list<boreas_skin_weight>(w, id, max_level, segments, skin_weight_dtype(),
                                             boreas_tree_get_skin_weights);
      },
      py::arg("id"), py::arg("max_level") = d.max_level, py::arg("segments") = d.segments,
      "boreas_tree_get_skin_weights: one per mesh vertex (SKIN_WEIGHT_DTYPE).");
  cls.def(
      "tree_leaf_skin_weights",
      [](World& w, py::handle id, int max_level, int segments) {
        return skin_list<boreas_skin_weight>(w, id, max_level, segments, skin_weight_dtype(),
                                             boreas_tree_get_leaf_skin_weights);
      },
      py::arg("id"), py::arg("max_level") = d.max_level, py::arg("segments") = d.segments,
      "boreas_tree_get_leaf_skin_weights: one per leaf (SKIN_WEIGHT_DTYPE).");
  const boreas_animation_def a = boreas_default_animation_def();
  cls.def(
      "export_animation",
      [](World& w, py::iterable tree_ids, const std::string& path, int frames, float frame_time,
         int steps_per_frame, int max_level, int segments, bool leaves, py::iterable meadow_ids,
         py::iterable mesh_tree_ids, float morph_tolerance, int meadow_clumps, float clump_size,
         float warmup) {
        std::vector<boreas_tree_id> ids;
        for (py::handle id : tree_ids) ids.push_back(id_from<boreas_tree_id>(id));
        std::vector<boreas_meadow_id> meadows;
        for (py::handle id : meadow_ids) meadows.push_back(id_from<boreas_meadow_id>(id));
        std::vector<boreas_mesh_tree_id> mesh_trees;
        for (py::handle id : mesh_tree_ids) mesh_trees.push_back(id_from<boreas_mesh_tree_id>(id));
        boreas_animation_def def = boreas_default_animation_def();
        def.meadows = meadows.data();
        def.meadow_count = int(meadows.size());
        def.mesh_trees = mesh_trees.data();
        def.mesh_tree_count = int(mesh_trees.size());
        def.morph_tolerance = morph_tolerance;
        def.meadow_clumps = meadow_clumps;
        def.clump_size = clump_size;
        def.warmup = warmup;
        def.frames = frames;
        def.frame_time = frame_time;
        def.steps_per_frame = steps_per_frame;
        def.skin = skin_def(max_level, segments);
        def.leaves = leaves ? 1 : 0;
        w.call([&](boreas_world cw) {
          check(boreas_world_export_animation(cw, &def, ids.data(), int(ids.size()), path.c_str()));
        });
      },
      py::arg("trees"), py::arg("path"), py::arg("frames") = a.frames,
      py::arg("frame_time") = a.frame_time, py::arg("steps_per_frame") = a.steps_per_frame,
      py::arg("max_level") = a.skin.max_level, py::arg("segments") = a.skin.segments,
      py::arg("leaves") = true, py::arg("meadows") = py::tuple(), py::arg("mesh_trees") = py::tuple(),
      py::arg("morph_tolerance") = a.morph_tolerance, py::arg("meadow_clumps") = a.meadow_clumps,
      py::arg("clump_size") = a.clump_size, py::arg("warmup") = a.warmup,
      "boreas_world_export_animation: steps the world and writes an animated .glb (trees "
      "skinned; meadows and mesh_trees, lists of their ids, as morph targets; meadows as "
      "meadow_clumps looped clumps each, instanced over them, where meadow_clumps > 0; "
      "the first key after warmup seconds of steps).");
}

}  // namespace boreas_py
