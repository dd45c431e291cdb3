// boreas gltf: a skinned part cut into pieces of at most 65,535 vertices, so that every
// piece's indices fit 16 bits (half the bytes of 32-bit ones), and of at most 256 joints
// (joint 0, the root, in each), so that its JOINTS_0 fit 8 bits: each piece names the
// joints it uses (joint_map) and is skinned by a skin of its own over them. Triangles keep
// their order; a vertex used by triangles of two pieces is copied into both.
#pragma once

#include <vector>

#include "boreas_gltf/animation_gltf.h"

namespace boreas::gltf {

// The most vertices a piece holds: index 65535 stays unused (a strip's restart value).
constexpr size_t kPieceMaxVertices = 65535;
// The most joints a piece's skin holds: 8-bit joint indices.
constexpr size_t kPieceMaxJoints = 256;

struct SkinnedPiece {
  SkinnedPart part;                // joints: indices into joint_map
  std::vector<int32_t> joint_map;  // the part's joint numbers; joint_map[0] is 0 (the root)
};

std::vector<SkinnedPiece> split_part(const SkinnedPart& part, size_t max_vertices = kPieceMaxVertices,
                                     size_t max_joints = kPieceMaxJoints);

}  // namespace boreas::gltf
