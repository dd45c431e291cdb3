// boreas: the C API. Every entry point catches everything and turns it into a
// boreas_status and a per-thread message; no exception crosses the C ABI.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "api/c_api_guard.h"
#include "boreas/boreas.h"
#include "enum_as_int.h"
#include "errors.h"
#include "mesh_trees/wind_cache.h"
#include "runtime/device.h"
#include "trees/leaf_occlusion.h"
#include "trees/leaf_outline.h"
#include "trees/species.h"
#include "underbrush/component_species.h"
#include "validation.h"
#include "world.h"

std::string& boreas::api::last_error() {
  thread_local std::string message;
  return message;
}

namespace {

using boreas::api::copy_out;
using boreas::api::guarded;
using boreas::api::world_of;

void copy_string(char* dst, size_t cap, const std::string& src) {
  std::strncpy(dst, src.c_str(), cap - 1);
  dst[cap - 1] = '\0';
}

boreas_device_info to_info(const boreas::impl::Device& d) {
  boreas_device_info info{};
  info.platform_index = d.platform_index;
  info.device_index = d.device_index;
  copy_string(info.platform_name, sizeof info.platform_name, d.platform_name);
  copy_string(info.device_name, sizeof info.device_name, d.name);
  copy_string(info.device_version, sizeof info.device_version, d.version);
  copy_string(info.driver_version, sizeof info.driver_version, d.driver_version);
  info.is_gpu = d.is_gpu() ? 1 : 0;
  info.compute_units = d.compute_units;
  info.global_memory = d.global_memory;
  info.has_gl_sharing = d.has_extension("cl_khr_gl_sharing") ? 1 : 0;
  info.has_fp64 = d.has_extension("cl_khr_fp64") ? 1 : 0;
  info.uses_fast_math = d.uses_fast_math() ? 1 : 0;
  return info;
}

// What a tree's crown light sees: its species' calibration and the outline it is drawn with.
boreas::impl::CrownLight crown_light(const boreas::impl::TreeInstance& tree) {
  boreas::impl::CrownLight light;
  light.leaf_area_index = tree.model->leaf_area_index;
  light.clumping = tree.model->clumping;
  light.outline = tree.params.leaf_outline;
  return light;
}

}  // namespace

extern "C" {

const char* boreas_last_error(void) { return boreas::api::last_error().c_str(); }

const char* boreas_version(void) { return BOREAS_LIBRARY_VERSION; }

const char* boreas_status_name(boreas_status status) {
  switch (boreas::impl::enum_as_int(status)) {  // any int a C caller passes has a name
    case BOREAS_OK:
      return "BOREAS_OK";
    case BOREAS_ERROR_INVALID_ARGUMENT:
      return "BOREAS_ERROR_INVALID_ARGUMENT";
    case BOREAS_ERROR_NO_DEVICE:
      return "BOREAS_ERROR_NO_DEVICE";
    case BOREAS_ERROR_KERNEL_BUILD:
      return "BOREAS_ERROR_KERNEL_BUILD";
    case BOREAS_ERROR_OPENCL:
      return "BOREAS_ERROR_OPENCL";
    case BOREAS_ERROR_NOT_FOUND:
      return "BOREAS_ERROR_NOT_FOUND";
    case BOREAS_ERROR_OUT_OF_MEMORY:
      return "BOREAS_ERROR_OUT_OF_MEMORY";
    case BOREAS_ERROR_IO:
      return "BOREAS_ERROR_IO";
    case BOREAS_ERROR_INTERNAL:
      return "BOREAS_ERROR_INTERNAL";
  }
  return "BOREAS_ERROR_UNKNOWN";
}

boreas_status boreas_list_devices(boreas_device_info* out, int capacity, int* count) {
  return guarded(__func__, [&] {
    if (!count) boreas::impl::fail_argument("count is NULL");
    std::vector<boreas_device_info> infos;
    for (const auto& d : boreas::impl::list_devices()) infos.push_back(to_info(d));
    copy_out(infos, out, capacity, count);
  });
}

boreas_status boreas_choose_device(const char* request, int* list_index) {
  return guarded(__func__, [&] {
    if (!list_index) boreas::impl::fail_argument("list_index is NULL");
    auto devices = boreas::impl::list_devices();
    *list_index = boreas::impl::choose_device(devices, request ? request : "");
  });
}

boreas_grid_def boreas_default_grid_def(void) {
  boreas_grid_def g{};
  g.origin[0] = -64.0f;
  g.origin[1] = 0.0f;
  g.origin[2] = -64.0f;
  g.cell_size = 2.0f;
  g.resolution[0] = 64;
  g.resolution[1] = 16;
  g.resolution[2] = 64;
  g.diffusion = 0.5f;
  g.decay_rate = 0.2f;
  g.response_time = 0.5f;
  g.edge_fade = 2.0f;
  g.follow_focus = 0;
  g.wind_sampling = BOREAS_WIND_SAMPLING_EXACT;
  return g;
}

boreas_wave boreas_default_wave(void) {
  boreas_wave w{};
  w.direction[0] = 1.0f;
  w.direction[1] = 0.0f;
  w.amplitude = 3.0f;
  w.wavelength = 20.0f;
  w.speed = 4.0f;
  w.sharpness = 2.0f;
  return w;
}

boreas_world_def boreas_default_world_def(void) {
  boreas_world_def d{};
  d.device = nullptr;
  d.cache_dir = nullptr;
  d.grid = boreas_default_grid_def();
  d.waves = nullptr;
  d.wave_count = 0;
  return d;
}

boreas_status boreas_world_create(const boreas_world_def* def, boreas_world* out) {
  return guarded(__func__, [&] {
    if (!def) boreas::impl::fail_argument("def is NULL");
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = nullptr;
    *out = new boreas_world_s(*def);
  });
}

void boreas_world_destroy(boreas_world world) {
  if (!world) return;
  // From inside one of the world's own calls (its progress callback) the world is still in
  // use: left alone, with the reason in boreas_last_error, rather than freed under the call.
  // Otherwise the last error is left as it was.
  try {
    world->world.check_unlocked();
  } catch (const boreas::impl::Error& e) {
    boreas::api::last_error() = std::string(__func__) + ": " + e.what();
    return;
  }
  delete world;
}

boreas_status boreas_world_step(boreas_world world, float dt) {
  return guarded(__func__, [&] { world_of(world).step(dt); });
}

double boreas_world_get_time(boreas_world world) { return world ? world->world.time() : 0.0; }

boreas_status boreas_world_get_step_stats(boreas_world world, boreas_step_stats* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = world_of(world).step_stats();
  });
}

boreas_status boreas_world_get_memory(boreas_world world, boreas_memory_info* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    boreas::impl::Runtime& runtime = world_of(world).runtime();
    *out = boreas_memory_info{};
    out->device_bytes = runtime.memory_in_use();
    out->device_limit = runtime.memory_limit();
    out->kernel_variants = static_cast<int32_t>(runtime.kernel_variants());
  });
}

boreas_status boreas_world_get_state_hash(boreas_world world, uint64_t* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = world_of(world).state_hash();
  });
}

boreas_status boreas_world_get_device(boreas_world world, boreas_device_info* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = to_info(world_of(world).runtime().device());
  });
}

boreas_status boreas_wind_set_waves(boreas_world world, const boreas_wave* waves, int count,
                                    float blend_seconds) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    w.wind().set_waves(waves, count, blend_seconds, w.time());
  });
}

boreas_flow_primitive_def boreas_default_flow_primitive_def(void) {
  boreas_flow_primitive_def p{};
  p.type = BOREAS_FLOW_UNIFORM;
  p.direction[0] = 1.0f;
  p.strength = 1.0f;
  p.radius = 0.0f;
  p.lifetime = 0.0f;
  return p;
}

boreas_status boreas_wind_add_primitive(boreas_world world,
                                        const boreas_flow_primitive_def* primitive,
                                        boreas_primitive_id* out) {
  return guarded(__func__, [&] {
    if (!primitive) boreas::impl::fail_argument("primitive is NULL");
    boreas::impl::World& w = world_of(world);
    boreas_primitive_id id = w.wind().add_primitive(*primitive, w.time());
    if (out) *out = id;
  });
}

boreas_status boreas_wind_remove_primitive(boreas_world world, boreas_primitive_id primitive) {
  return guarded(__func__, [&] { world_of(world).wind().remove(primitive); });
}

boreas_gust_def boreas_default_gust_def(void) {
  boreas_gust_def g{};
  g.direction[0] = 1.0f;
  g.strength = 5.0f;
  g.delay = 0.0f;
  g.rise = 1.0f;
  g.hold = 1.0f;
  g.fall = 2.0f;
  g.radius = 0.0f;
  return g;
}

boreas_status boreas_wind_add_gust(boreas_world world, const boreas_gust_def* gust,
                                   boreas_gust_id* out) {
  return guarded(__func__, [&] {
    if (!gust) boreas::impl::fail_argument("gust is NULL");
    boreas::impl::World& w = world_of(world);
    boreas_gust_id id = w.wind().add_gust(*gust, w.time());
    if (out) *out = id;
  });
}

boreas_status boreas_wind_remove_gust(boreas_world world, boreas_gust_id gust) {
  return guarded(__func__, [&] { world_of(world).wind().remove(gust); });
}

boreas_status boreas_wind_add_solid_box(boreas_world world, const float min[3],
                                        const float max[3]) {
  return guarded(__func__, [&] { world_of(world).wind().add_solid_box(min, max); });
}

boreas_status boreas_wind_set_solid_mask(boreas_world world, const uint8_t* mask, int64_t count) {
  return guarded(__func__, [&] { world_of(world).wind().set_solid_mask(mask, count); });
}

boreas_status boreas_wind_sample(boreas_world world, const float* xyz, int count,
                                 float* force_xyz) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (count > 0 && (!xyz || !force_xyz)) boreas::impl::fail_argument("xyz or force_xyz is NULL");
    w.wind().sample(xyz, count, force_xyz);
  });
}

boreas_status boreas_wind_get_grid(boreas_world world, boreas_grid_def* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = world_of(world).wind().grid().def();
  });
}

boreas_status boreas_wind_get_grid_values(boreas_world world, float* out, int64_t capacity) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!out) boreas::impl::fail_argument("out is NULL");
    boreas::impl::WindGrid& grid = w.wind().grid();
    int64_t need = grid.cell_count() * 4;
    if (capacity < need)
      boreas::impl::fail_argument("capacity " + std::to_string(capacity) + " is below the " +
                                  std::to_string(need) + " floats the grid needs");
    std::vector<float> cells = grid.read();
    std::memcpy(out, cells.data(), cells.size() * sizeof(float));
  });
}

const char* boreas_builtin_species(int index) {
  try {
    static const std::vector<std::string> names = boreas::impl::builtin_species_names();
    if (index < 0 || index >= static_cast<int>(names.size())) return nullptr;
    return names[static_cast<size_t>(index)].c_str();
  } catch (...) {
    return nullptr;
  }
}

boreas_leaf_outline boreas_species_leaf_outline(const char* species) {
  try {
    int kind = boreas::impl::species_leaf_outline(species != nullptr ? species : "");
    return static_cast<boreas_leaf_outline>(kind + 1);
  } catch (...) {
    return BOREAS_LEAF_BROADLEAF;
  }
}

boreas_tree_def boreas_default_tree_def(void) {
  boreas_tree_def d{};
  d.species = "quaking_aspen";
  d.rotation = 0.0f;
  d.scale = 1.0f;
  d.seed = 1;
  d.mode = BOREAS_TREE_LAGGED;
  d.response = BOREAS_TREE_QUASI_STATIC;
  d.load = BOREAS_TREE_LOAD_DRAG;
  d.bend_exponent = 1.8f;
  d.leaf_outline = BOREAS_LEAF_OUTLINE_SPECIES;
  const int rings[4] = {12, 6, 4, 3};
  const int sides[4] = {12, 8, 5, 4};
  for (int l = 0; l < 4; ++l) {
    d.levels[l].stiffness = 1.0f;
    d.levels[l].damping_ratio = 0.15f;
    d.levels[l].frequency_scale = 0.5f;
    d.levels[l].rings = rings[l];
    d.levels[l].sides = sides[l];
  }
  // Sized for an eye 1.8 m above the ground: a twig's sway is lost past ~30 m, a crown's
  // past ~80 m; past 250 m a tree is a few pixels of a 1080p frame.
  d.lod_distances[0] = 30.0f;
  d.lod_distances[1] = 80.0f;
  d.lod_distances[2] = 250.0f;
  return d;
}

boreas_status boreas_world_add_tree(boreas_world world, const boreas_tree_def* def,
                                    boreas_tree_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas_tree_id id = w.add_tree(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_tree(boreas_world world, boreas_tree_id tree) {
  return guarded(__func__, [&] { world_of(world).remove_tree(tree); });
}

boreas_status boreas_tree_heal(boreas_world world, boreas_tree_id tree) {
  return guarded(__func__, [&] { world_of(world).heal_tree(tree); });
}

boreas_status boreas_tree_get_template(boreas_world world, boreas_tree_id tree, int* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = w.tree_template(tree);
  });
}

boreas_status boreas_world_add_trees(boreas_world world, const boreas_tree_def* defs, int count,
                                     boreas_tree_id* ids) {
  return guarded(__func__, [&] {
    std::vector<boreas_tree_id> added = world_of(world).add_trees(defs, count);
    if (ids) std::copy(added.begin(), added.end(), ids);
  });
}

boreas_status boreas_world_set_focus(boreas_world world, const float* points, int count) {
  return guarded(__func__, [&] { world_of(world).set_focus(points, count); });
}

boreas_status boreas_world_set_output_origin(boreas_world world, const double origin[3]) {
  return guarded(__func__, [&] { world_of(world).set_output_origin(origin); });
}

boreas_status boreas_tree_get_branches(boreas_world world, boreas_tree_id tree, boreas_branch* out,
                                       int capacity, int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    copy_out(w.tree_branches(tree), out, capacity, count);
  });
}

boreas_status boreas_tree_get_leaves(boreas_world world, boreas_tree_id tree, boreas_leaf* out,
                                     int capacity, int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    // Leaves are made when read: a count alone makes none.
    if (!out) {
      *count = static_cast<int>(w.tree(tree).model->leaf_count());
      return;
    }
    copy_out(w.tree_leaves(tree), out, capacity, count);
  });
}

boreas_status boreas_tree_get_leaf_occlusion(boreas_world world, boreas_tree_id tree,
                                             const float transmittance[3], float* rgb, int capacity,
                                             int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    if (!transmittance) boreas::impl::fail_argument("transmittance is NULL");
    for (int c = 0; c < 3; ++c) {
      if (!(transmittance[c] >= 0.0f && transmittance[c] <= 1.0f)) {
        boreas::impl::fail_argument("transmittance[" + std::to_string(c) + "] = " +
                                    std::to_string(transmittance[c]) + " is not in [0, 1]");
      }
    }
    const int leaves = static_cast<int>(w.tree(tree).model->leaf_count());
    if (!rgb) {
      *count = leaves;
      return;
    }
    if (capacity < leaves) {
      boreas::impl::fail_argument("capacity " + std::to_string(capacity) + " is below the " +
                                  std::to_string(leaves) +
                                  " leaves to write (call with rgb NULL for the count)");
    }
    std::vector<float> out = boreas::impl::leaf_occlusion(
        w.runtime(), w.tree_leaves(tree), transmittance, crown_light(w.tree(tree)));
    std::copy(out.begin(), out.end(), rgb);
    *count = leaves;
  });
}

boreas_mesh_tree_def boreas_default_mesh_tree_def(void) {
  boreas_mesh_tree_def d{};
  d.scale = 1.0f;
  d.seed = 1;
  d.noise_beta = 2.0f;
  d.bend_exponent = 2.0f;
  const float bend[4] = {0.3f, 0.25f, 0.15f, 0.08f};
  const float sway[4] = {0.08f, 0.08f, 0.05f, 0.03f};
  const float frequency[4] = {0.25f, 0.5f, 1.0f, 2.0f};
  const float response[4] = {1.5f, 0.8f, 0.4f, 0.2f};
  for (int k = 0; k < 4; ++k) d.levels[k] = {bend[k], sway[k], frequency[k], response[k]};
  d.leaf_flutter = 0.04f;
  d.leaf_turn = 0.5f;
  d.flutter_wavelength = 8.0f;
  d.cache = 1;
  return d;
}

boreas_status boreas_world_add_mesh_tree(boreas_world world, const boreas_mesh_tree_def* def,
                                         boreas_mesh_tree_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas_mesh_tree_id id = w.add_mesh_tree(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_mesh_tree(boreas_world world, boreas_mesh_tree_id tree) {
  return guarded(__func__, [&] { world_of(world).remove_mesh_tree(tree); });
}

boreas_status boreas_mesh_tree_get_info(boreas_world world, boreas_mesh_tree_id tree,
                                        boreas_mesh_tree_info* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = w.mesh_tree_info(tree);
  });
}

boreas_status boreas_mesh_tree_get_vertices(boreas_world world, boreas_mesh_tree_id tree,
                                            boreas_mesh_part part, boreas_vertex* out, int capacity,
                                            int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    copy_out(w.mesh_tree_vertices(tree, part), out, capacity, count);
  });
}

boreas_status boreas_mesh_tree_get_indices(boreas_world world, boreas_mesh_tree_id tree,
                                           boreas_mesh_part part, uint32_t* out, int capacity,
                                           int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    copy_out(w.mesh_tree_indices(tree, part), out, capacity, count);
  });
}

boreas_status boreas_preprocess_mesh_tree(const boreas_mesh_tree_def* def, const char* out_path,
                                          boreas_mesh_tree_info* info) {
  return guarded(__func__, [&] {
    if (!def) boreas::impl::fail_argument("def is NULL");
    if (!out_path || !*out_path) boreas::impl::fail_argument("out_path is empty");
    boreas::impl::MeshTreeParams p = boreas::impl::checked_mesh_tree_def(*def);
    bool from_cache = false;
    std::string note;
    boreas::impl::PreprocessedTree tree = boreas::impl::preprocess_tree(
        p.model, {p.trunk_part, p.leaves_part}, p.seed, false, &from_cache, &note);
    boreas::impl::write_preprocessed_glb(out_path, tree, tree.key);
    if (info) *info = boreas::impl::describe_mesh_tree(tree.model, tree.data, from_cache);
  });
}

boreas_status boreas_tree_get_mesh(boreas_world world, boreas_tree_id tree, boreas_vertex* vertices,
                                   int vertex_capacity, int* vertex_count, uint32_t* indices,
                                   int index_capacity, int* index_count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!vertex_count || !index_count)
      boreas::impl::fail_argument("vertex_count or index_count is NULL");
    std::vector<boreas_vertex> v;
    std::vector<uint32_t> i;
    w.tree_mesh(tree, &v, &i);
    if (v.size() > static_cast<size_t>(INT32_MAX) || i.size() > static_cast<size_t>(INT32_MAX))
      boreas::impl::fail_argument(
          "the mesh has more than 2^31 vertices or indices: lower the rings and sides");
    if (vertices && indices) {
      if (vertex_capacity < static_cast<int>(v.size()) ||
          index_capacity < static_cast<int>(i.size()))
        boreas::impl::fail_argument("capacities " + std::to_string(vertex_capacity) +
                                    " vertices and " + std::to_string(index_capacity) +
                                    " indices are below the mesh's " + std::to_string(v.size()) +
                                    " and " + std::to_string(i.size()));
      std::copy(v.begin(), v.end(), vertices);
      std::copy(i.begin(), i.end(), indices);
    }
    *vertex_count = static_cast<int>(v.size());
    *index_count = static_cast<int>(i.size());
  });
}

const char* boreas_builtin_underbrush_species(int index) {
  try {
    return boreas::impl::builtin_underbrush_species(index);
  } catch (...) {
    return nullptr;
  }
}

boreas_meadow_def boreas_default_meadow_def(void) {
  boreas_meadow_def d{};
  d.species = nullptr;
  d.species_count = 0;
  d.size[0] = d.size[1] = 10.0f;
  d.density = 400.0f;
  d.seed = 1;
  d.terrain_relief = 0.0f;
  d.seed_points = 8;
  d.shape_angles = 19;
  d.shape_norms = 24;
  d.lod_distances[0] = 15.0f;
  d.lod_distances[1] = 40.0f;
  d.lod_distances[2] = 120.0f;
  return d;
}

boreas_status boreas_world_add_meadow(boreas_world world, const boreas_meadow_def* def,
                                      boreas_meadow_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas_meadow_id id = w.add_meadow(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_add_meadows(boreas_world world, const boreas_meadow_def* defs, int count,
                                       boreas_meadow_id* ids) {
  return guarded(__func__, [&] {
    std::vector<boreas_meadow_id> added = world_of(world).add_meadows(defs, count);
    if (ids) std::copy(added.begin(), added.end(), ids);
  });
}

boreas_status boreas_world_remove_meadow(boreas_world world, boreas_meadow_id meadow) {
  return guarded(__func__, [&] { world_of(world).remove_meadow(meadow); });
}

boreas_status boreas_meadow_get_components(boreas_world world, boreas_meadow_id meadow,
                                           boreas_component* out, int capacity, int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    copy_out(w.meadow_components(meadow), out, capacity, count);
  });
}

boreas_status boreas_meadow_get_parts(boreas_world world, boreas_meadow_id meadow,
                                      boreas_meadow_part* out, int capacity, int* count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!count) boreas::impl::fail_argument("count is NULL");
    copy_out(w.meadow_parts(meadow), out, capacity, count);
  });
}

boreas_status boreas_meadow_get_vertices(boreas_world world, boreas_meadow_id meadow,
                                         const float camera[3], boreas_meadow_vertex* vertices,
                                         int vertex_capacity, int* vertex_count,
                                         int32_t* strip_counts) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!vertex_count) boreas::impl::fail_argument("vertex_count is NULL");
    // Checked on the count-only call too: a bad camera is refused however it is passed.
    if (camera) boreas::impl::check_position(camera, "camera");
    std::vector<float> v;
    std::vector<int32_t> counts;
    if (!vertices) {
      *vertex_count = w.meadow_component_count(meadow) * BOREAS_MEADOW_VERTEX_STRIDE;
      return;
    }
    w.meadow_vertices(meadow, camera, &v, &counts);
    size_t total = v.size() / 8;
    if (total > static_cast<size_t>(INT32_MAX))
      boreas::impl::fail_argument("the meadow has more than 2^31 vertices");
    if (vertex_capacity < static_cast<int>(total))
      boreas::impl::fail_argument("vertex_capacity " + std::to_string(vertex_capacity) +
                                  " is below the meadow's " + std::to_string(total) + " vertices");
    std::memcpy(vertices, v.data(), v.size() * sizeof(float));
    if (strip_counts) std::copy(counts.begin(), counts.end(), strip_counts);
    *vertex_count = static_cast<int>(total);
  });
}

boreas_collider_def boreas_default_collider_def(void) {
  boreas_collider_def d{};
  d.shape = BOREAS_COLLIDER_SPHERE;
  d.pose = boreas_default_pose();
  d.radius = 0.11f;  // a soccer ball
  d.pose.position[1] = 0.11f;
  d.half_height = 0.5f;
  for (float& h : d.half_extents) h = 0.5f;
  return d;
}

boreas_status boreas_world_add_collider(boreas_world world, const boreas_collider_def* def,
                                        boreas_collider_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas_collider_id id = w.add_collider(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_collider(boreas_world world, boreas_collider_id collider) {
  return guarded(__func__, [&] { world_of(world).remove_collider(collider); });
}

boreas_status boreas_collider_set_position(boreas_world world, boreas_collider_id collider,
                                           const float center[3]) {
  return guarded(__func__, [&] { world_of(world).set_collider_position(collider, center); });
}

boreas_status boreas_collider_set_pose(boreas_world world, boreas_collider_id collider,
                                       const boreas_pose* pose) {
  return guarded(__func__, [&] { world_of(world).set_collider_pose(collider, pose); });
}

boreas_status boreas_collider_set_velocity(boreas_world world, boreas_collider_id collider,
                                           const float velocity[3],
                                           const float angular_velocity[3]) {
  return guarded(__func__, [&] {
    world_of(world).set_collider_velocity(collider, velocity, angular_velocity);
  });
}

boreas_status boreas_collider_get_pose(boreas_world world, boreas_collider_id collider,
                                       boreas_pose* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = world_of(world).collider_pose(collider);
  });
}

boreas_status boreas_collider_get_contact(boreas_world world, boreas_collider_id collider,
                                          boreas_collider_contact* out) {
  return guarded(__func__, [&] {
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = world_of(world).collider_contact(collider);
  });
}

boreas_emitter_def boreas_default_emitter_def(void) {
  boreas_emitter_def d{};
  d.area_radius = 1.0f;
  d.event_radius = 0.05f;
  d.impulse[1] = -2e-4f;  // a 3 mm rain drop at 7 m/s
  d.rate = 50.0f;
  d.seed = 1;
  return d;
}

boreas_status boreas_world_add_emitter(boreas_world world, const boreas_emitter_def* def,
                                       boreas_emitter_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas_emitter_id id = w.add_emitter(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_emitter(boreas_world world, boreas_emitter_id emitter) {
  return guarded(__func__, [&] { world_of(world).remove_emitter(emitter); });
}

boreas_status boreas_emitter_set_position(boreas_world world, boreas_emitter_id emitter,
                                          const float center[3]) {
  return guarded(__func__, [&] { world_of(world).set_emitter_position(emitter, center); });
}

}  // extern "C"
