// boreas: the OpenCL side of a world (boreas_cl.h), for renderers that draw from device
// buffers. The C entry points only wrap the world's enqueue calls; the checks live there.
#include "boreas/boreas_cl.h"

#include "api/c_api_guard.h"
#include "world.h"

namespace {

// The caller's buffer, retained for as long as the wrapper lives (the enqueued write
// holds its own reference).
cl::Buffer wrap(cl_mem mem, const char* name) {
  if (mem == nullptr) boreas::impl::fail_argument(std::string(name) + " is NULL");
  return cl::Buffer(mem, true);
}

}  // namespace

boreas_status boreas_world_get_cl(boreas_world world, boreas_cl_objects* out) {
  return boreas::api::guarded(__func__, [&] {
    boreas::impl::World& w = boreas::api::world_of(world);
    if (!out) boreas::impl::fail_argument("out is NULL");
    out->context = w.runtime().context()();
    out->queue = w.runtime().queue()();
    out->device = w.runtime().device().device();
  });
}

boreas_status boreas_tree_enqueue_branch_records(boreas_world world, boreas_tree_id tree,
                                                 cl_mem out, size_t first_record) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_branch_records(tree, wrap(out, "out"), first_record);
  });
}

boreas_status boreas_tree_enqueue_leaf_records(boreas_world world, boreas_tree_id tree, cl_mem out,
                                               size_t first_record) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_leaf_records(tree, wrap(out, "out"), first_record);
  });
}

boreas_tree_view_def boreas_default_tree_view_def(void) {
  boreas_tree_view_def d{};
  for (auto& plane : d.planes) plane[3] = 1.0f;  // n = 0, d >= 0: no plane
  d.pixel_angle = 0.0f;
  d.resolved_pixels = 9.0f;
  d.min_keep = 0.05f;
  d.impostor_distance = 0.0f;
  d.vertices_per_branch = 0;
  d.vertices_per_leaf = 4;
  d.vertices_per_impostor = 4;
  return d;
}

boreas_status boreas_world_enqueue_tree_records(boreas_world world, const boreas_tree_view_def* view,
                                                const boreas_tree_record_buffers* out) {
  return boreas::api::guarded(__func__, [&] {
    boreas::impl::World& w = boreas::api::world_of(world);
    if (!view) boreas::impl::fail_argument("view is NULL");
    if (!out) boreas::impl::fail_argument("out is NULL");
    boreas::impl::TreeBatch::RecordOutputs o;
    o.branches = wrap(out->branches, "out->branches");
    o.leaves = wrap(out->leaves, "out->leaves");
    o.impostors = wrap(out->impostors, "out->impostors");
    o.ranges = wrap(out->ranges, "out->ranges");
    o.indirect = wrap(out->indirect, "out->indirect");
    w.enqueue_tree_records(*view, o);
  });
}

boreas_status boreas_meadow_enqueue_vertices(boreas_world world, boreas_meadow_id meadow,
                                             const float camera[3], cl_mem vertices,
                                             cl_mem strip_counts, size_t first_component) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_meadow_vertices(&meadow, &first_component, 1, camera,
                                                         wrap(vertices, "vertices"),
                                                         wrap(strip_counts, "strip_counts"), false);
  });
}

boreas_status boreas_world_enqueue_meadow_vertices(boreas_world world,
                                                   const boreas_meadow_id* meadows,
                                                   const size_t* first_components, int count,
                                                   const float camera[3], cl_mem vertices,
                                                   cl_mem strip_counts) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_meadow_vertices(meadows, first_components, count, camera,
                                                         wrap(vertices, "vertices"),
                                                         wrap(strip_counts, "strip_counts"), true);
  });
}

boreas_status boreas_mesh_tree_enqueue_vertices(boreas_world world, boreas_mesh_tree_id tree,
                                                boreas_mesh_part part, cl_mem out,
                                                size_t first_vertex) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_mesh_tree_vertices(&tree, &first_vertex, 1, part,
                                                            wrap(out, "out"), false);
  });
}

boreas_status boreas_world_enqueue_mesh_tree_vertices(boreas_world world,
                                                      const boreas_mesh_tree_id* trees,
                                                      const size_t* first_vertices, int count,
                                                      boreas_mesh_part part, cl_mem out) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_mesh_tree_vertices(trees, first_vertices, count, part,
                                                            wrap(out, "out"), true);
  });
}

boreas_status boreas_world_enqueue_cast_rays(boreas_world world, cl_mem rays, size_t first_ray,
                                             int count, cl_mem hits, size_t first_hit) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).enqueue_cast_rays(wrap(rays, "rays"), first_ray, count,
                                                   wrap(hits, "hits"), first_hit);
  });
}
