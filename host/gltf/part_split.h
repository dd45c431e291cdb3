// boreas gltf: a skinned part cut into pieces of at most 65,535 vertices, so that every
// piece's indices fit 16 bits (half the bytes of 32-bit ones). Triangles keep their order;
// a vertex used by triangles of two pieces is copied into both.
#pragma once

#include <vector>

#include "boreas_gltf/animation_gltf.h"

namespace boreas::gltf {

// The most vertices a piece holds: index 65535 stays unused (a strip's restart value).
constexpr size_t kPieceMaxVertices = 65535;

std::vector<SkinnedPart> split_part(const SkinnedPart& part, size_t max_vertices = kPieceMaxVertices);

}  // namespace boreas::gltf
