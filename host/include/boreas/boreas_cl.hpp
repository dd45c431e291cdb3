// boreas: the C++ form of boreas_cl.h (a world's OpenCL objects and the enqueue calls that
// write into a renderer's buffers), as free functions on a boreas::World, named as in
// boreas_cl.h without the boreas_ prefix.
#pragma once

#include <cstddef>

#include "boreas/boreas.hpp"
#include "boreas/boreas_cl.h"

namespace boreas {

[[nodiscard]] inline boreas_cl_objects get_cl(const World& world) {
  boreas_cl_objects objects{};
  check(boreas_world_get_cl(world.handle(), &objects));
  return objects;
}
inline void tree_enqueue_branch_records(World& world, boreas_tree_id tree, cl_mem out,
                                        size_t first_record) {
  check(boreas_tree_enqueue_branch_records(world.handle(), tree, out, first_record));
}
inline void tree_enqueue_leaf_records(World& world, boreas_tree_id tree, cl_mem out,
                                      size_t first_record) {
  check(boreas_tree_enqueue_leaf_records(world.handle(), tree, out, first_record));
}
[[nodiscard]] inline boreas_tree_view_def default_tree_view_def() {
  return boreas_default_tree_view_def();
}
// view's eye, planes and pixel_angle from a camera (boreas_set_tree_view_camera).
inline void set_tree_view_camera(boreas_tree_view_def& view, const float eye[3], const float forward[3],
                                 const float up[3], float vertical_fov, float aspect, float near_m,
                                 float far_m, int viewport_height) {
  check(boreas_set_tree_view_camera(&view, eye, forward, up, vertical_fov, aspect, near_m, far_m,
                                    viewport_height));
}
// The records of every tree the view sees, in one call (boreas_world_enqueue_tree_records).
inline void enqueue_tree_records(World& world, const boreas_tree_view_def& view,
                                 const boreas_tree_record_buffers& out) {
  check(boreas_world_enqueue_tree_records(world.handle(), &view, &out));
}
// camera: nullptr for full detail everywhere.
inline void meadow_enqueue_vertices(World& world, boreas_meadow_id meadow, const float* camera,
                                    cl_mem vertices, cl_mem strip_counts, size_t first_component) {
  check(boreas_meadow_enqueue_vertices(world.handle(), meadow, camera, vertices, strip_counts,
                                       first_component));
}
inline void mesh_tree_enqueue_vertices(World& world, boreas_mesh_tree_id tree,
                                       boreas_mesh_part part, cl_mem out, size_t first_vertex) {
  check(boreas_mesh_tree_enqueue_vertices(world.handle(), tree, part, out, first_vertex));
}
// Any list of meadows or imported trees in one launch (boreas_world_enqueue_meadow_vertices,
// boreas_world_enqueue_mesh_tree_vertices).
inline void enqueue_meadow_vertices(World& world, const boreas_meadow_id* meadows,
                                    const size_t* first_components, int count, const float* camera,
                                    cl_mem vertices, cl_mem strip_counts) {
  check(boreas_world_enqueue_meadow_vertices(world.handle(), meadows, first_components, count,
                                             camera, vertices, strip_counts));
}
inline void enqueue_mesh_tree_vertices(World& world, const boreas_mesh_tree_id* trees,
                                       const size_t* first_vertices, int count,
                                       boreas_mesh_part part, cl_mem out) {
  check(boreas_world_enqueue_mesh_tree_vertices(world.handle(), trees, first_vertices, count, part,
                                                out));
}

// Casts count rays from `rays` (from record first_ray) into `hits` (from record first_hit)
// on the world's queue (boreas_world_enqueue_cast_rays).
inline void enqueue_cast_rays(World& world, cl_mem rays, size_t first_ray, int count,
                                    cl_mem hits, size_t first_hit) {
  check(boreas_world_enqueue_cast_rays(world.handle(), rays, first_ray, count, hits, first_hit));
}

}  // namespace boreas
