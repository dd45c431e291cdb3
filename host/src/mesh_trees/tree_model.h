// boreas: a tree mesh made elsewhere, as imported — its trunk-and-branches part and its
// leaves part, each an indexed triangle list in model space (m, Y up).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace boreas::impl {

struct MeshPart {
  std::vector<float> positions;   // xyz per vertex, m
  std::vector<float> normals;     // xyz per vertex, unit (from the faces when the file has none)
  std::vector<float> uvs;         // uv per vertex (zeros when the file has none)
  std::vector<uint32_t> indices;  // three per triangle

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
};

struct MeshModel {
  MeshPart trunk;   // trunk and branches: one connected run of triangles per branch
  MeshPart leaves;  // one connected run of triangles per leaf (may be empty)
};

// Which objects, groups or materials of a file make each part: comma-separated names,
// matched case-insensitively as substrings of the object/group name first, then of the
// material name. A run of triangles that matches neither is ignored.
struct ModelPartSelection {
  std::string trunk = "trunk,bark,branch,stem,wood";
  std::string leaves = "leaf,leaves,foliage,needle";
};

}  // namespace boreas::impl
