// boreas: the C entry points of BlobTree trees (boreas.h), over World.
#include <algorithm>
#include <string>

#include "api/c_api_guard.h"
#include "blobtree/blobtree_model.h"
#include "boreas/boreas.h"

using boreas::api::guarded;
using boreas::api::world_of;

extern "C" {

boreas_blobtree_def boreas_default_blobtree_def(void) {
  // The model's own defaults (BlobTreeOptions), so the two cannot disagree.
  const boreas::impl::BlobTreeOptions model;
  boreas_blobtree_def d{};
  d.resolution = 256;
  d.cubic = 0;
  d.max_level = model.max_level;
  d.min_radius = 0.0f;  // automatic: half a grid cell
  d.junctions = model.pcm ? BOREAS_BLOBTREE_PCM : BOREAS_BLOBTREE_BLEND;
  d.offsets = model.offsets ? 1 : 0;
  d.ridge = float(model.pcm_peak);
  d.ridge_width = float(model.pcm_width);
  d.bend = float(model.bend_angle);
  return d;
}

boreas_status boreas_world_add_blobtree(boreas_world world, boreas_tree_id tree,
                                        const boreas_blobtree_def* def, boreas_progress_fn progress,
                                        void* user, boreas_blobtree_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) boreas::impl::fail_argument("def is NULL");
    boreas::impl::BlobProgress report;
    if (progress)
      report = [progress, user](double fraction, const char* stage) {
        progress(user, float(fraction), stage);
      };
    boreas_blobtree_id id = w.add_blobtree(tree, *def, report);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_blobtree(boreas_world world, boreas_blobtree_id blobtree) {
  return guarded(__func__, [&] { world_of(world).remove_blobtree(blobtree); });
}

boreas_status boreas_blobtree_get_info(boreas_world world, boreas_blobtree_id blobtree,
                                       boreas_blobtree_info* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!out) boreas::impl::fail_argument("out is NULL");
    *out = w.blobtree(blobtree).info;
  });
}

boreas_status boreas_blobtree_get_mesh(boreas_world world, boreas_blobtree_id blobtree,
                                       boreas_vertex* vertices, int vertex_capacity,
                                       int* vertex_count, uint32_t* indices, int index_capacity,
                                       int* index_count) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!vertex_count || !index_count)
      boreas::impl::fail_argument("vertex_count or index_count is NULL");
    const boreas::impl::BlobMesh& mesh = w.blobtree(blobtree).mesh;
    const int nv = static_cast<int>(mesh.vertex_count());
    const int ni = static_cast<int>(mesh.indices.size());
    if (vertices && indices) {
      if (vertex_capacity < nv || index_capacity < ni)
        boreas::impl::fail_argument("capacities " + std::to_string(vertex_capacity) +
                                    " vertices and " + std::to_string(index_capacity) +
                                    " indices are below the mesh's " + std::to_string(nv) +
                                    " and " + std::to_string(ni));
      for (int i = 0; i < nv; ++i) {
        for (int c = 0; c < 3; ++c) {
          vertices[i].position[c] = mesh.positions[3 * size_t(i) + c];
          vertices[i].normal[c] = mesh.normals[3 * size_t(i) + c];
        }
        vertices[i].uv[0] = mesh.uvs[2 * size_t(i)];
        vertices[i].uv[1] = mesh.uvs[2 * size_t(i) + 1];
      }
      std::copy(mesh.indices.begin(), mesh.indices.end(), indices);
    }
    *vertex_count = nv;
    *index_count = ni;
  });
}

}  // extern "C"
