// boreas: the C++ API, a thin move-only RAII layer over boreas.h. Failures throw
// boreas::Error carrying the status and boreas_last_error()'s message.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "boreas/boreas.h"

// Ids compare as values and hash, so they can key std::unordered_map and sit in std::set
// order-free containers; the types are boreas.h's own, shared with C code.
#define BOREAS_ID_OPERATORS(kind)                                                               \
  inline bool operator==(boreas_##kind##_id a, boreas_##kind##_id b) {                          \
    return boreas_##kind##_id_equal(a, b) != 0;                                                 \
  }                                                                                             \
  inline bool operator!=(boreas_##kind##_id a, boreas_##kind##_id b) { return !(a == b); }      \
  template <>                                                                                   \
  struct std::hash<boreas_##kind##_id> {                                                        \
    size_t operator()(boreas_##kind##_id id) const noexcept {                                   \
      return std::hash<uint64_t>()((uint64_t(id.tag) << 40) ^ (uint64_t(id.generation) << 20) ^ \
                                   id.index);                                                   \
    }                                                                                           \
  };
BOREAS_ID_OPERATORS(tree)
BOREAS_ID_OPERATORS(mesh_tree)
BOREAS_ID_OPERATORS(blobtree)
BOREAS_ID_OPERATORS(meadow)
BOREAS_ID_OPERATORS(collider)
BOREAS_ID_OPERATORS(emitter)
BOREAS_ID_OPERATORS(primitive)
BOREAS_ID_OPERATORS(gust)
BOREAS_ID_OPERATORS(lidar)
#undef BOREAS_ID_OPERATORS

namespace boreas {

using TreeId = boreas_tree_id;
using MeshTreeId = boreas_mesh_tree_id;
using BlobTreeId = boreas_blobtree_id;
using MeadowId = boreas_meadow_id;
using ColliderId = boreas_collider_id;
using EmitterId = boreas_emitter_id;
using PrimitiveId = boreas_primitive_id;
using GustId = boreas_gust_id;
using LidarId = boreas_lidar_id;

class Error : public std::runtime_error {
 public:
  Error(boreas_status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  boreas_status status() const noexcept { return status_; }

 private:
  boreas_status status_;
};

inline void check(boreas_status status) {
  if (status != BOREAS_OK) throw Error(status, boreas_last_error());
}

struct Vec3 {
  float x = 0.0f;
  float y = 0.0f;
  float z = 0.0f;
};

namespace detail {

// The API's list rule (boreas.h, "Output arrays"): one call for the count, one to fill.
template <typename T, typename Get>
std::vector<T> list(Get&& get) {
  int count = 0;
  check(get(static_cast<T*>(nullptr), 0, &count));
  std::vector<T> out(static_cast<size_t>(count));
  check(get(out.data(), count, &count));
  return out;
}

// The names a C enumerator (boreas_builtin_species and the like) gives, in order.
inline std::vector<std::string> names(const char* (*name)(int)) {
  std::vector<std::string> out;
  for (int i = 0; const char* n = name(i); ++i) out.emplace_back(n);
  return out;
}

}  // namespace detail

// Calls without a world, named as in boreas.h without the boreas_ prefix.
[[nodiscard]] inline const char* version() { return boreas_version(); }
[[nodiscard]] inline const char* status_name(boreas_status status) {
  return boreas_status_name(status);
}
[[nodiscard]] inline std::vector<boreas_device_info> list_devices() {
  return detail::list<boreas_device_info>([](boreas_device_info* out, int capacity, int* count) {
    return boreas_list_devices(out, capacity, count);
  });
}
// The entry of list_devices() a request picks (boreas_choose_device).
[[nodiscard]] inline int choose_device(const char* request = nullptr) {
  int index = 0;
  check(boreas_choose_device(request, &index));
  return index;
}
// The names of the built-in tree species.
[[nodiscard]] inline std::vector<std::string> builtin_species() {
  return detail::names(boreas_builtin_species);
}
// The leaf outline a tree of this species has by default (boreas_species_leaf_outline).
[[nodiscard]] inline boreas_leaf_outline species_leaf_outline(const char* species) {
  return boreas_species_leaf_outline(species);
}
// The names of the built-in underbrush species.
[[nodiscard]] inline std::vector<std::string> builtin_underbrush_species() {
  return detail::names(boreas_builtin_underbrush_species);
}
// Preprocesses a model without a world and writes it as a binary glTF
// (boreas_preprocess_mesh_tree).
inline boreas_mesh_tree_info preprocess_mesh_tree(const boreas_mesh_tree_def& def,
                                                  const std::string& out_path) {
  boreas_mesh_tree_info info{};
  check(boreas_preprocess_mesh_tree(&def, out_path.c_str(), &info));
  return info;
}
[[nodiscard]] inline boreas_grid_def default_grid_def() { return boreas_default_grid_def(); }
[[nodiscard]] inline boreas_wave default_wave() { return boreas_default_wave(); }
[[nodiscard]] inline boreas_world_def default_world_def() { return boreas_default_world_def(); }
[[nodiscard]] inline boreas_flow_primitive_def default_flow_primitive_def() {
  return boreas_default_flow_primitive_def();
}
[[nodiscard]] inline boreas_gust_def default_gust_def() { return boreas_default_gust_def(); }
[[nodiscard]] inline boreas_tree_def default_tree_def() { return boreas_default_tree_def(); }
[[nodiscard]] inline boreas_skin_def default_skin_def() { return boreas_default_skin_def(); }
[[nodiscard]] inline boreas_animation_def default_animation_def() {
  return boreas_default_animation_def();
}
[[nodiscard]] inline boreas_meadow_def default_meadow_def() { return boreas_default_meadow_def(); }
[[nodiscard]] inline boreas_collider_def default_collider_def() {
  return boreas_default_collider_def();
}
[[nodiscard]] inline boreas_emitter_def default_emitter_def() {
  return boreas_default_emitter_def();
}
[[nodiscard]] inline boreas_mesh_tree_def default_mesh_tree_def() {
  return boreas_default_mesh_tree_def();
}
[[nodiscard]] inline boreas_blobtree_def default_blobtree_def() {
  return boreas_default_blobtree_def();
}
[[nodiscard]] inline boreas_pose default_pose() { return boreas_default_pose(); }
[[nodiscard]] inline boreas_pose pose_between(const boreas_pose& a, const boreas_pose& b, float s) {
  boreas_pose out{};
  check(boreas_pose_between(&a, &b, s, &out));
  return out;
}
[[nodiscard]] inline boreas_lidar_def default_lidar_def() { return boreas_default_lidar_def(); }
[[nodiscard]] inline boreas_depth_camera_def default_depth_camera_def() {
  return boreas_default_depth_camera_def();
}
// A common unit's def by name ("VLP-16", "HDL-32E", "HDL-64E", "OS1-128").
[[nodiscard]] inline boreas_lidar_def lidar_preset(const char* name) {
  boreas_lidar_def def{};
  check(boreas_lidar_preset(name, &def));
  return def;
}
// Preset number index's name, or nullptr past the last.
[[nodiscard]] inline const char* lidar_preset_name(int index) {
  return boreas_lidar_preset_name(index);
}

// A world. Its methods are the C calls on a world, named as in boreas.h without the
// boreas_ prefix and, for the world's own calls, without world_: boreas_world_step is
// step, boreas_tree_get_branches is tree_get_branches (tests/host/test_api_surface.cpp
// checks that every call of boreas.h has its namesake here).
class World {
 public:
  explicit World(const boreas_world_def& def = boreas_default_world_def()) {
    check(boreas_world_create(&def, &world_));
  }
  ~World() { boreas_world_destroy(world_); }
  World(World&& other) noexcept : world_(std::exchange(other.world_, nullptr)) {}
  World& operator=(World&& other) noexcept {
    if (this != &other) {
      boreas_world_destroy(world_);
      world_ = std::exchange(other.world_, nullptr);
    }
    return *this;
  }
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // The C handle, for C code and for boreas_cl.hpp.
  [[nodiscard]] boreas_world handle() const { return world_; }

  // The world.
  void step(float dt) { check(boreas_world_step(world_, dt)); }
  [[nodiscard]] double get_time() const { return boreas_world_get_time(world_); }
  [[nodiscard]] boreas_device_info get_device() const {
    boreas_device_info info{};
    check(boreas_world_get_device(world_, &info));
    return info;
  }
  [[nodiscard]] boreas_step_stats get_step_stats() const {
    boreas_step_stats stats{};
    check(boreas_world_get_step_stats(world_, &stats));
    return stats;
  }
  [[nodiscard]] boreas_memory_info get_memory() const {
    boreas_memory_info info{};
    check(boreas_world_get_memory(world_, &info));
    return info;
  }
  // The simulated state as one number: for determinism checks.
  [[nodiscard]] uint64_t get_state_hash() const {
    uint64_t hash = 0;
    check(boreas_world_get_state_hash(world_, &hash));
    return hash;
  }
  // Focus points for the simulation's level of detail (none: full detail everywhere).
  void set_focus(const std::vector<Vec3>& points) {
    check(boreas_world_set_focus(world_, reinterpret_cast<const float*>(points.data()),
                                 static_cast<int>(points.size())));
  }

  // Positions of meadows, imported trees and trees handed back relative to this point (m; the
  // world's 0 by default): camera-relative output far from the origin.
  void set_output_origin(const std::array<double, 3>& origin) {
    check(boreas_world_set_output_origin(world_, origin.data()));
  }

  // Wind.
  void wind_set_waves(const std::vector<boreas_wave>& waves, float blend_seconds = 0.0f) {
    check(
        boreas_wind_set_waves(world_, waves.data(), static_cast<int>(waves.size()), blend_seconds));
  }
  [[nodiscard]] boreas_primitive_id wind_add_primitive(const boreas_flow_primitive_def& primitive) {
    boreas_primitive_id id{};
    check(boreas_wind_add_primitive(world_, &primitive, &id));
    return id;
  }
  void wind_remove_primitive(boreas_primitive_id primitive) {
    check(boreas_wind_remove_primitive(world_, primitive));
  }
  [[nodiscard]] boreas_gust_id wind_add_gust(const boreas_gust_def& gust) {
    boreas_gust_id id{};
    check(boreas_wind_add_gust(world_, &gust, &id));
    return id;
  }
  void wind_remove_gust(boreas_gust_id gust) { check(boreas_wind_remove_gust(world_, gust)); }
  void wind_add_solid_box(Vec3 min, Vec3 max) {
    const float lo[3] = {min.x, min.y, min.z};
    const float hi[3] = {max.x, max.y, max.z};
    check(boreas_wind_add_solid_box(world_, lo, hi));
  }
  // One byte per grid cell, x fastest, then y, then z; empty clears every solid.
  void wind_set_solid_mask(const std::vector<uint8_t>& mask) {
    check(boreas_wind_set_solid_mask(world_, mask.empty() ? nullptr : mask.data(),
                                     static_cast<int64_t>(mask.size())));
  }
  // Wind (m/s) at each point.
  [[nodiscard]] std::vector<Vec3> wind_sample(const std::vector<Vec3>& points) const {
    static_assert(sizeof(Vec3) == 3 * sizeof(float), "Vec3 must be three packed floats");
    static_assert(BOREAS_WIND_SAMPLE_MAX_POINTS == 1 << 26, "the message spells it 2^26");
    if (points.size() > static_cast<size_t>(BOREAS_WIND_SAMPLE_MAX_POINTS))
      throw Error(BOREAS_ERROR_INVALID_ARGUMENT, "wind_sample: at most 2^26 points per call");
    std::vector<Vec3> out(points.size());
    check(boreas_wind_sample(world_, reinterpret_cast<const float*>(points.data()),
                             static_cast<int>(points.size()),
                             reinterpret_cast<float*>(out.data())));
    return out;
  }
  [[nodiscard]] Vec3 wind_sample(Vec3 point) const {
    return wind_sample(std::vector<Vec3>{point})[0];
  }
  [[nodiscard]] boreas_grid_def wind_get_grid() const {
    boreas_grid_def def{};
    check(boreas_wind_get_grid(world_, &def));
    return def;
  }
  // 4 floats per cell (x, y, z in m/s; 1 if solid), cells x fastest, then y, then z.
  [[nodiscard]] std::vector<float> wind_get_grid_values() const {
    const boreas_grid_def g = wind_get_grid();
    std::vector<float> out(static_cast<size_t>(g.resolution[0]) * size_t(g.resolution[1]) *
                           size_t(g.resolution[2]) * 4);
    check(boreas_wind_get_grid_values(world_, out.data(), static_cast<int64_t>(out.size())));
    return out;
  }

  // Trees.
  [[nodiscard]] boreas_tree_id add_tree(const boreas_tree_def& def) {
    boreas_tree_id id{};
    check(boreas_world_add_tree(world_, &def, &id));
    return id;
  }
  // Many trees in one call, all or none.
  [[nodiscard]] std::vector<boreas_tree_id> add_trees(const std::vector<boreas_tree_def>& defs) {
    std::vector<boreas_tree_id> ids(defs.size());
    check(boreas_world_add_trees(world_, defs.data(), static_cast<int>(defs.size()), ids.data()));
    return ids;
  }
  void remove_tree(boreas_tree_id tree) { check(boreas_world_remove_tree(world_, tree)); }
  void tree_heal(boreas_tree_id tree) { check(boreas_tree_heal(world_, tree)); }
  [[nodiscard]] int tree_get_template(boreas_tree_id tree) const {
    int index = 0;
    check(boreas_tree_get_template(world_, tree, &index));
    return index;
  }
  [[nodiscard]] std::vector<boreas_branch> tree_get_branches(boreas_tree_id tree) const {
    return detail::list<boreas_branch>([&](boreas_branch* out, int capacity, int* count) {
      return boreas_tree_get_branches(world_, tree, out, capacity, count);
    });
  }
  [[nodiscard]] std::vector<boreas_leaf> tree_get_leaves(boreas_tree_id tree) const {
    return detail::list<boreas_leaf>([&](boreas_leaf* out, int capacity, int* count) {
      return boreas_tree_get_leaves(world_, tree, out, capacity, count);
    });
  }
  // Per leaf, the fraction (r, g, b) of sky light reaching it through the crown: 3 floats
  // per leaf in the order of tree_get_leaves.
  [[nodiscard]] std::vector<float> tree_get_leaf_occlusion(boreas_tree_id tree,
                                                           Vec3 transmittance) const {
    const float t[3] = {transmittance.x, transmittance.y, transmittance.z};
    int count = 0;
    check(boreas_tree_get_leaf_occlusion(world_, tree, t, nullptr, 0, &count));
    std::vector<float> rgb(static_cast<size_t>(count) * 3);
    check(boreas_tree_get_leaf_occlusion(world_, tree, t, rgb.data(), count, &count));
    return rgb;
  }
  struct Mesh {
    std::vector<boreas_vertex> vertices;
    std::vector<uint32_t> indices;
  };
  [[nodiscard]] Mesh tree_get_mesh(boreas_tree_id tree) const {
    return mesh_of([&](boreas_vertex* v, int vc, int* vn, uint32_t* i, int ic, int* in) {
      return boreas_tree_get_mesh(world_, tree, v, vc, vn, i, ic, in);
    });
  }
  // The tree's skin (boreas_tree_get_joints): joints as of the last step, and the bindings
  // of tree_get_mesh's vertices and tree_get_leaves' leaves.
  [[nodiscard]] std::vector<boreas_joint> tree_get_joints(
      boreas_tree_id tree, const boreas_skin_def& def = boreas_default_skin_def()) const {
    return detail::list<boreas_joint>([&](boreas_joint* out, int capacity, int* count) {
      return boreas_tree_get_joints(world_, tree, &def, out, capacity, count);
    });
  }
  [[nodiscard]] std::vector<boreas_skin_weight> tree_get_skin_weights(
      boreas_tree_id tree, const boreas_skin_def& def = boreas_default_skin_def()) const {
    return detail::list<boreas_skin_weight>(
        [&](boreas_skin_weight* out, int capacity, int* count) {
          return boreas_tree_get_skin_weights(world_, tree, &def, out, capacity, count);
        });
  }
  [[nodiscard]] std::vector<boreas_skin_weight> tree_get_leaf_skin_weights(
      boreas_tree_id tree, const boreas_skin_def& def = boreas_default_skin_def()) const {
    return detail::list<boreas_skin_weight>(
        [&](boreas_skin_weight* out, int capacity, int* count) {
          return boreas_tree_get_leaf_skin_weights(world_, tree, &def, out, capacity, count);
        });
  }
  // An animated glTF file of these trees (boreas_world_export_animation): steps the world.
  void export_animation(const std::vector<boreas_tree_id>& trees, const std::string& path,
                        const boreas_animation_def& def = boreas_default_animation_def()) {
    check(boreas_world_export_animation(world_, &def, trees.data(), static_cast<int>(trees.size()),
                                        path.c_str()));
  }
  // ... with meadows and imported trees as morph targets (def's meadows and mesh_trees are
  // these vectors').
  void export_animation(const std::vector<boreas_tree_id>& trees,
                        const std::vector<boreas_meadow_id>& meadows,
                        const std::vector<boreas_mesh_tree_id>& mesh_trees, const std::string& path,
                        boreas_animation_def def = boreas_default_animation_def()) {
    def.meadows = meadows.data();
    def.meadow_count = static_cast<int>(meadows.size());
    def.mesh_trees = mesh_trees.data();
    def.mesh_tree_count = static_cast<int>(mesh_trees.size());
    export_animation(trees, path, def);
  }

  // Mesh trees (imported tree meshes).
  [[nodiscard]] boreas_mesh_tree_id add_mesh_tree(const boreas_mesh_tree_def& def) {
    boreas_mesh_tree_id id{};
    check(boreas_world_add_mesh_tree(world_, &def, &id));
    return id;
  }
  void remove_mesh_tree(boreas_mesh_tree_id tree) {
    check(boreas_world_remove_mesh_tree(world_, tree));
  }
  [[nodiscard]] boreas_mesh_tree_info mesh_tree_get_info(boreas_mesh_tree_id tree) const {
    boreas_mesh_tree_info info{};
    check(boreas_mesh_tree_get_info(world_, tree, &info));
    return info;
  }
  [[nodiscard]] std::vector<boreas_vertex> mesh_tree_get_vertices(boreas_mesh_tree_id tree,
                                                                  boreas_mesh_part part) const {
    return detail::list<boreas_vertex>([&](boreas_vertex* out, int capacity, int* count) {
      return boreas_mesh_tree_get_vertices(world_, tree, part, out, capacity, count);
    });
  }
  [[nodiscard]] std::vector<uint32_t> mesh_tree_get_indices(boreas_mesh_tree_id tree,
                                                            boreas_mesh_part part) const {
    return detail::list<uint32_t>([&](uint32_t* out, int capacity, int* count) {
      return boreas_mesh_tree_get_indices(world_, tree, part, out, capacity, count);
    });
  }

  // BlobTree trees. progress(fraction, stage) may be empty; it is called on this thread.
  using Progress = std::function<void(float fraction, const char* stage)>;
  [[nodiscard]] boreas_blobtree_id add_blobtree(boreas_tree_id tree, const boreas_blobtree_def& def,
                                                const Progress& progress = {}) {
    boreas_blobtree_id id{};
    auto relay = [](void* user, float fraction, const char* stage) {
      (*static_cast<const Progress*>(user))(fraction, stage);
    };
    check(boreas_world_add_blobtree(world_, tree, &def, progress ? +relay : nullptr,
                                    const_cast<Progress*>(&progress), &id));
    return id;
  }
  void remove_blobtree(boreas_blobtree_id blobtree) {
    check(boreas_world_remove_blobtree(world_, blobtree));
  }
  [[nodiscard]] boreas_blobtree_info blobtree_get_info(boreas_blobtree_id blobtree) const {
    boreas_blobtree_info info{};
    check(boreas_blobtree_get_info(world_, blobtree, &info));
    return info;
  }
  [[nodiscard]] Mesh blobtree_get_mesh(boreas_blobtree_id blobtree) const {
    return mesh_of([&](boreas_vertex* v, int vc, int* vn, uint32_t* i, int ic, int* in) {
      return boreas_blobtree_get_mesh(world_, blobtree, v, vc, vn, i, ic, in);
    });
  }

  // Underbrush.
  [[nodiscard]] boreas_meadow_id add_meadow(const boreas_meadow_def& def) {
    boreas_meadow_id id{};
    check(boreas_world_add_meadow(world_, &def, &id));
    return id;
  }
  // Many meadows in one call, all or none.
  [[nodiscard]] std::vector<boreas_meadow_id> add_meadows(
      const std::vector<boreas_meadow_def>& defs) {
    std::vector<boreas_meadow_id> ids(defs.size());
    check(boreas_world_add_meadows(world_, defs.data(), static_cast<int>(defs.size()), ids.data()));
    return ids;
  }
  void remove_meadow(boreas_meadow_id meadow) { check(boreas_world_remove_meadow(world_, meadow)); }
  [[nodiscard]] std::vector<boreas_component> meadow_get_components(boreas_meadow_id meadow) const {
    return detail::list<boreas_component>([&](boreas_component* out, int capacity, int* count) {
      return boreas_meadow_get_components(world_, meadow, out, capacity, count);
    });
  }
  [[nodiscard]] std::vector<boreas_meadow_part> meadow_get_parts(boreas_meadow_id meadow) const {
    return detail::list<boreas_meadow_part>([&](boreas_meadow_part* out, int capacity, int* count) {
      return boreas_meadow_get_parts(world_, meadow, out, capacity, count);
    });
  }
  struct Strips {
    std::vector<boreas_meadow_vertex> vertices;  // BOREAS_MEADOW_VERTEX_STRIDE per component
    std::vector<int32_t> counts;                 // vertices of each component's strip
  };
  // camera: nullptr for full detail everywhere.
  [[nodiscard]] Strips meadow_get_vertices(boreas_meadow_id meadow,
                                           const float* camera = nullptr) const {
    int count = 0;
    check(boreas_meadow_get_vertices(world_, meadow, camera, nullptr, 0, &count, nullptr));
    Strips s;
    s.vertices.resize(static_cast<size_t>(count));
    s.counts.resize(static_cast<size_t>(count / BOREAS_MEADOW_VERTEX_STRIDE));
    check(boreas_meadow_get_vertices(world_, meadow, camera, s.vertices.data(), count, &count,
                                     s.counts.data()));
    return s;
  }
  // The nearest hit of each ray as of the last step (boreas_world_cast_rays).
  [[nodiscard]] std::vector<boreas_hit> cast_rays(const std::vector<boreas_ray>& rays) const {
    std::vector<boreas_hit> hits(rays.size());
    check(boreas_world_cast_rays(world_, rays.data(), static_cast<int>(rays.size()), hits.data()));
    return hits;
  }
  [[nodiscard]] boreas_collider_id add_collider(const boreas_collider_def& def) {
    boreas_collider_id id{};
    check(boreas_world_add_collider(world_, &def, &id));
    return id;
  }
  void remove_collider(boreas_collider_id collider) {
    check(boreas_world_remove_collider(world_, collider));
  }
  void collider_set_position(boreas_collider_id collider, Vec3 center) {
    const float c[3] = {center.x, center.y, center.z};
    check(boreas_collider_set_position(world_, collider, c));
  }
  void collider_set_pose(boreas_collider_id collider, const boreas_pose& pose) {
    check(boreas_collider_set_pose(world_, collider, &pose));
  }
  void collider_set_velocity(boreas_collider_id collider, Vec3 velocity, Vec3 angular_velocity) {
    const float v[3] = {velocity.x, velocity.y, velocity.z};
    const float w[3] = {angular_velocity.x, angular_velocity.y, angular_velocity.z};
    check(boreas_collider_set_velocity(world_, collider, v, w));
  }
  [[nodiscard]] boreas_pose collider_get_pose(boreas_collider_id collider) {
    boreas_pose p{};
    check(boreas_collider_get_pose(world_, collider, &p));
    return p;
  }
  [[nodiscard]] boreas_collider_contact collider_get_contact(boreas_collider_id collider) {
    boreas_collider_contact c{};
    check(boreas_collider_get_contact(world_, collider, &c));
    return c;
  }
  [[nodiscard]] boreas_emitter_id add_emitter(const boreas_emitter_def& def) {
    boreas_emitter_id id{};
    check(boreas_world_add_emitter(world_, &def, &id));
    return id;
  }
  void remove_emitter(boreas_emitter_id emitter) {
    check(boreas_world_remove_emitter(world_, emitter));
  }
  void emitter_set_position(boreas_emitter_id emitter, Vec3 center) {
    const float c[3] = {center.x, center.y, center.z};
    check(boreas_emitter_set_position(world_, emitter, c));
  }

  // Sensors.
  [[nodiscard]] boreas_lidar_id add_lidar(const boreas_lidar_def& def) {
    boreas_lidar_id id{};
    check(boreas_world_add_lidar(world_, &def, &id));
    return id;
  }
  void remove_lidar(boreas_lidar_id lidar) { check(boreas_world_remove_lidar(world_, lidar)); }
  void lidar_set_pose(boreas_lidar_id lidar, const boreas_pose& pose) {
    check(boreas_lidar_set_pose(world_, lidar, &pose));
  }
  [[nodiscard]] std::vector<boreas_lidar_point> lidar_get_points(
      boreas_lidar_id lidar, boreas_lidar_points which = BOREAS_LIDAR_LAST_SWEEP) const {
    return detail::list<boreas_lidar_point>([&](boreas_lidar_point* out, int capacity, int* count) {
      return boreas_lidar_get_points(world_, lidar, which, out, capacity, count);
    });
  }
  [[nodiscard]] boreas_lidar_info lidar_get_info(boreas_lidar_id lidar) const {
    boreas_lidar_info info{};
    check(boreas_lidar_get_info(world_, lidar, &info));
    return info;
  }
  struct DepthImage {
    std::vector<float> depth;                 // m along the optical axis; INFINITY: nothing
    std::vector<boreas_pixel_label> labels;   // what each pixel sees
  };
  // Row by row from the top, width * height pixels each.
  [[nodiscard]] DepthImage capture_depth(const boreas_depth_camera_def& camera) const {
    DepthImage image;
    const size_t pixels = camera.width > 0 && camera.height > 0
                              ? static_cast<size_t>(camera.width) * size_t(camera.height)
                              : 0;
    image.depth.resize(pixels);
    image.labels.resize(pixels);
    check(boreas_world_capture_depth(world_, &camera, image.depth.data(), image.labels.data()));
    return image;
  }

 private:
  // A mesh getter's two calls: the counts, then both arrays (boreas_tree_get_mesh's rule).
  template <typename Get>
  static Mesh mesh_of(Get&& get) {
    int vertex_count = 0, index_count = 0;
    check(get(nullptr, 0, &vertex_count, nullptr, 0, &index_count));
    Mesh m;
    m.vertices.resize(static_cast<size_t>(vertex_count));
    m.indices.resize(static_cast<size_t>(index_count));
    check(get(m.vertices.data(), vertex_count, &vertex_count, m.indices.data(), index_count,
              &index_count));
    return m;
  }

  boreas_world world_ = nullptr;
};

}  // namespace boreas
