// boreas: the C++ API, a thin move-only RAII layer over boreas.h. Failures throw
// boreas::Error carrying the status and boreas_last_error()'s message.
#pragma once

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

// The names of the built-in underbrush species.
[[nodiscard]] inline std::vector<std::string> builtin_underbrush_species() {
  std::vector<std::string> names;
  for (int i = 0; const char* name = boreas_builtin_underbrush_species(i); ++i) names.emplace_back(name);
  return names;
}

// The names of the built-in tree species.
[[nodiscard]] inline std::vector<std::string> builtin_species() {
  std::vector<std::string> names;
  for (int i = 0; const char* name = boreas_builtin_species(i); ++i) names.emplace_back(name);
  return names;
}

[[nodiscard]] inline std::vector<boreas_device_info> list_devices() {
  int count = 0;
  check(boreas_list_devices(nullptr, 0, &count));
  std::vector<boreas_device_info> devices(static_cast<size_t>(count));
  check(boreas_list_devices(devices.data(), count, &count));
  return devices;
}

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

  void step(float dt) { check(boreas_world_step(world_, dt)); }
  [[nodiscard]] double time() const { return boreas_world_get_time(world_); }
  [[nodiscard]] boreas_device_info device() const {
    boreas_device_info info{};
    check(boreas_world_get_device(world_, &info));
    return info;
  }
  [[nodiscard]] boreas_step_stats step_stats() const {
    boreas_step_stats stats{};
    check(boreas_world_get_step_stats(world_, &stats));
    return stats;
  }
  [[nodiscard]] boreas_memory_info memory() const {
    boreas_memory_info info{};
    check(boreas_world_get_memory(world_, &info));
    return info;
  }
  // The simulated state as one number (boreas_world_get_state_hash): for determinism checks.
  [[nodiscard]] uint64_t state_hash() const {
    uint64_t hash = 0;
    check(boreas_world_get_state_hash(world_, &hash));
    return hash;
  }

  void set_waves(const std::vector<boreas_wave>& waves, float blend_seconds = 0.0f) {
    check(boreas_wind_set_waves(world_, waves.data(), static_cast<int>(waves.size()), blend_seconds));
  }
  [[nodiscard]] boreas_primitive_id add_primitive(const boreas_flow_primitive& primitive) {
    boreas_primitive_id id{};
    check(boreas_wind_add_primitive(world_, &primitive, &id));
    return id;
  }
  void remove_primitive(boreas_primitive_id primitive) {
    check(boreas_wind_remove_primitive(world_, primitive));
  }
  void remove_gust(boreas_gust_id gust) { check(boreas_wind_remove_gust(world_, gust)); }
  [[nodiscard]] boreas_gust_id add_gust(const boreas_gust& gust) {
    boreas_gust_id id{};
    check(boreas_wind_add_gust(world_, &gust, &id));
    return id;
  }
  void add_solid_box(Vec3 min, Vec3 max) {
    const float lo[3] = {min.x, min.y, min.z};
    const float hi[3] = {max.x, max.y, max.z};
    check(boreas_wind_add_solid_box(world_, lo, hi));
  }

  // Wind (m/s) at each point.
  [[nodiscard]] std::vector<Vec3> sample(const std::vector<Vec3>& points) const {
    static_assert(sizeof(Vec3) == 3 * sizeof(float), "Vec3 must be three packed floats");
    static_assert(BOREAS_WIND_SAMPLE_MAX_POINTS == 1 << 26, "the message spells it 2^26");
    if (points.size() > static_cast<size_t>(BOREAS_WIND_SAMPLE_MAX_POINTS))
      throw Error(BOREAS_ERROR_INVALID_ARGUMENT, "sample: at most 2^26 points per call");
    std::vector<Vec3> out(points.size());
    check(boreas_wind_sample(world_, reinterpret_cast<const float*>(points.data()),
                             static_cast<int>(points.size()), reinterpret_cast<float*>(out.data())));
    return out;
  }
  [[nodiscard]] Vec3 sample(Vec3 point) const { return sample(std::vector<Vec3>{point})[0]; }

  [[nodiscard]] boreas_grid_def grid() const {
    boreas_grid_def def{};
    check(boreas_wind_get_grid(world_, &def));
    return def;
  }

  // Trees.
  [[nodiscard]] boreas_tree_id add_tree(const boreas_tree_def& def) {
    boreas_tree_id id{};
    check(boreas_world_add_tree(world_, &def, &id));
    return id;
  }
  void remove_tree(boreas_tree_id tree) { check(boreas_world_remove_tree(world_, tree)); }
  // Many trees in one call, all or none (boreas_world_add_trees).
  [[nodiscard]] std::vector<boreas_tree_id> add_trees(const std::vector<boreas_tree_def>& defs) {
    std::vector<boreas_tree_id> ids(defs.size());
    check(boreas_world_add_trees(world_, defs.data(), static_cast<int>(defs.size()), ids.data()));
    return ids;
  }
  // Focus points for the simulation's level of detail (none: full detail everywhere).
  void set_focus(const std::vector<Vec3>& points) {
    check(boreas_world_set_focus(world_, reinterpret_cast<const float*>(points.data()),
                                 static_cast<int>(points.size())));
  }
  [[nodiscard]] std::vector<boreas_branch> branches(boreas_tree_id tree) const {
    int count = 0;
    check(boreas_tree_get_branches(world_, tree, nullptr, 0, &count));
    std::vector<boreas_branch> out(static_cast<size_t>(count));
    check(boreas_tree_get_branches(world_, tree, out.data(), count, &count));
    return out;
  }
  [[nodiscard]] std::vector<boreas_leaf> leaves(boreas_tree_id tree) const {
    int count = 0;
    check(boreas_tree_get_leaves(world_, tree, nullptr, 0, &count));
    std::vector<boreas_leaf> out(static_cast<size_t>(count));
    check(boreas_tree_get_leaves(world_, tree, out.data(), count, &count));
    return out;
  }
  struct Mesh {
    std::vector<boreas_vertex> vertices;
    std::vector<uint32_t> indices;
  };
  [[nodiscard]] Mesh mesh(boreas_tree_id tree) const {
    int vertex_count = 0, index_count = 0;
    check(boreas_tree_get_mesh(world_, tree, nullptr, 0, &vertex_count, nullptr, 0, &index_count));
    Mesh m;
    m.vertices.resize(static_cast<size_t>(vertex_count));
    m.indices.resize(static_cast<size_t>(index_count));
    check(boreas_tree_get_mesh(world_, tree, m.vertices.data(), vertex_count, &vertex_count, m.indices.data(),
                               index_count, &index_count));
    return m;
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
  [[nodiscard]] boreas_mesh_tree_info mesh_tree_info(boreas_mesh_tree_id tree) const {
    boreas_mesh_tree_info info{};
    check(boreas_mesh_tree_get_info(world_, tree, &info));
    return info;
  }
  [[nodiscard]] Mesh mesh_tree_part(boreas_mesh_tree_id tree, boreas_mesh_part part) const {
    Mesh m;
    int count = 0;
    check(boreas_mesh_tree_get_vertices(world_, tree, part, nullptr, 0, &count));
    m.vertices.resize(static_cast<size_t>(count));
    check(boreas_mesh_tree_get_vertices(world_, tree, part, m.vertices.data(), count, &count));
    check(boreas_mesh_tree_get_indices(world_, tree, part, nullptr, 0, &count));
    m.indices.resize(static_cast<size_t>(count));
    check(boreas_mesh_tree_get_indices(world_, tree, part, m.indices.data(), count, &count));
    return m;
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
  [[nodiscard]] boreas_blobtree_info blobtree_info(boreas_blobtree_id blobtree) const {
    boreas_blobtree_info info{};
    check(boreas_blobtree_get_info(world_, blobtree, &info));
    return info;
  }
  [[nodiscard]] Mesh blobtree_mesh(boreas_blobtree_id blobtree) const {
    int vertex_count = 0, index_count = 0;
    check(boreas_blobtree_get_mesh(world_, blobtree, nullptr, 0, &vertex_count, nullptr, 0, &index_count));
    Mesh m;
    m.vertices.resize(static_cast<size_t>(vertex_count));
    m.indices.resize(static_cast<size_t>(index_count));
    check(boreas_blobtree_get_mesh(world_, blobtree, m.vertices.data(), vertex_count, &vertex_count,
                                   m.indices.data(), index_count, &index_count));
    return m;
  }

  // Underbrush.
  // Many meadows in one call, all or none (boreas_world_add_meadows).
  [[nodiscard]] std::vector<boreas_meadow_id> add_meadows(
      const std::vector<boreas_meadow_def>& defs) {
    std::vector<boreas_meadow_id> ids(defs.size());
    check(boreas_world_add_meadows(world_, defs.data(), static_cast<int>(defs.size()), ids.data()));
    return ids;
  }
  [[nodiscard]] boreas_meadow_id add_meadow(const boreas_meadow_def& def) {
    boreas_meadow_id id{};
    check(boreas_world_add_meadow(world_, &def, &id));
    return id;
  }
  void remove_meadow(boreas_meadow_id meadow) { check(boreas_world_remove_meadow(world_, meadow)); }
  [[nodiscard]] std::vector<boreas_component> components(boreas_meadow_id meadow) const {
    int count = 0;
    check(boreas_meadow_get_components(world_, meadow, nullptr, 0, &count));
    std::vector<boreas_component> out(static_cast<size_t>(count));
    check(boreas_meadow_get_components(world_, meadow, out.data(), count, &count));
    return out;
  }
  struct Strips {
    std::vector<boreas_meadow_vertex> vertices;  // BOREAS_MEADOW_VERTEX_STRIDE per component
    std::vector<int32_t> counts;                 // vertices of each component's strip
  };
  // camera: nullptr for full detail everywhere.
  [[nodiscard]] Strips strips(boreas_meadow_id meadow, const float* camera = nullptr) const {
    int count = 0;
    check(boreas_meadow_get_vertices(world_, meadow, camera, nullptr, 0, &count, nullptr));
    Strips s;
    s.vertices.resize(static_cast<size_t>(count));
    s.counts.resize(static_cast<size_t>(count / BOREAS_MEADOW_VERTEX_STRIDE));
    check(boreas_meadow_get_vertices(world_, meadow, camera, s.vertices.data(), count, &count, s.counts.data()));
    return s;
  }
  [[nodiscard]] boreas_collider_id add_collider(const boreas_collider_def& def) {
    boreas_collider_id id{};
    check(boreas_world_add_collider(world_, &def, &id));
    return id;
  }
  void remove_collider(boreas_collider_id collider) {
    check(boreas_world_remove_collider(world_, collider));
  }
  void move_collider(boreas_collider_id collider, Vec3 center) {
    const float c[3] = {center.x, center.y, center.z};
    check(boreas_collider_set_position(world_, collider, c));
  }
  [[nodiscard]] boreas_emitter_id add_emitter(const boreas_emitter_def& def) {
    boreas_emitter_id id{};
    check(boreas_world_add_emitter(world_, &def, &id));
    return id;
  }
  void remove_emitter(boreas_emitter_id emitter) {
    check(boreas_world_remove_emitter(world_, emitter));
  }

  // The C handle, for calls the C++ layer does not wrap.
  [[nodiscard]] boreas_world handle() const { return world_; }

 private:
  boreas_world world_ = nullptr;
};

}  // namespace boreas
