// boreas render: what the shaders need of an imported tree's surface that its animation does
// not change, derived once from the rest pose (boreas_mesh_tree_get_vertices before the
// first step): for the bark, the normal, the direction of the texture's +v on the surface
// and bark texture coordinates in repeats of boreas's bark texture; for the leaves, the +v
// direction, the texture coordinates and the light the crown lets through.
//
// The model's own texture coordinates are kept (its seams and orientation are the artist's)
// but rescaled, island by island (a connected run of triangles), to the bark texture's size:
// the model was textured for its own maps, which boreas does not load.
#pragma once

#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "gl/crown_light.h"

namespace boreas::render {

constexpr int kMeshBarkFloats = 8;  // normal (3), along (3), uv in repeats (2)
constexpr int kMeshLeafFloats = 6;  // along at rest (3), uv (2), occlusion (1)

// Per vertex kMeshBarkFloats. On each island u and v are scaled by the island's median
// metres per uv unit over tile_m, rounded so the island's uv extent spans whole repeats
// (a seam around a branch closes). An island without usable uvs (all equal, or degenerate
// triangles only) gets uv (0, 0) and +v along the projection of +Y.
std::vector<float> bark_attributes(const std::vector<boreas_vertex>& vertices,
                                   const std::vector<uint32_t>& indices, float tile_m);

// Per vertex kMeshLeafFloats. A leaf (island) whose vertices all share one uv gets uv
// (-1, -1): mesh_leaf.vert then samples the middle of the blade, so the leaf's own
// triangles are its shape. The occlusion is leaf_occlusion in crown.
std::vector<float> leaf_attributes(const std::vector<boreas_vertex>& vertices,
                                   const std::vector<uint32_t>& indices, const Bounds& crown);

// Per vertex, the island it belongs to (connected through shared vertices), numbered in
// order of first appearance; vertices no triangle uses are islands of their own.
std::vector<uint32_t> uv_islands(size_t vertex_count, const std::vector<uint32_t>& indices,
                                 uint32_t* island_count);

}  // namespace boreas::render
