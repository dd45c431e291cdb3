// boreas: one part of a tree model built from a file's triangles: one vertex per distinct
// (position, normal, uv) of the file, face normals where the file has none.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh_trees/model_import_internal.h"
#include "mesh_trees/part_selection.h"
#include "mesh_trees/tree_model.h"

namespace boreas::impl::model_import {

// The file's vertex data that triangles refer to. glTF positions and normals are already in
// model space (the node transforms applied); normals are not yet unit.
struct SourcePools {
  std::vector<Vec3> positions;  // m
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
};

// Where a triangle corner's data is in the pools; -1: the file gives none.
struct Corner {
  int64_t position = -1;
  int64_t normal = -1;
  int64_t uv = -1;
  bool operator==(const Corner& o) const {
    return position == o.position && normal == o.normal && uv == o.uv;
  }
};

struct CornerHash {
  size_t operator()(const Corner& c) const {
    uint64_t h = uint64_t(c.position) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(c.normal) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= uint64_t(c.uv) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return size_t(h);
  }
};

class PartBuilder {
 public:
  explicit PartBuilder(const SourcePools& pools) : pools_(pools) {}

  void add_triangle(const Corner& a, const Corner& b, const Corner& c) {
    indices_.push_back(vertex_for(a));
    indices_.push_back(vertex_for(b));
    indices_.push_back(vertex_for(c));
  }

  // The part: its vertices and, as given, its triangles.
  MeshPart finish() const;

 private:
  // The area-weighted sum of the normals of the faces around one position.
  struct FaceNormals {
    Vec3 sum{};
    double magnitude = 0.0;  // sum of the faces' |cross|, to tell cancellation from zero
    Vec3 first{};            // the first non-degenerate face's, for when the sum cancels
    bool has_first = false;

    Vec3 unit() const;
  };

  static bool unit(const Vec3& v, Vec3* out);
  uint32_t vertex_for(const Corner& c);
  std::unordered_map<int64_t, FaceNormals> accumulate_face_normals() const;

  const SourcePools& pools_;
  std::unordered_map<Corner, uint32_t, CornerHash> vertex_of_;
  std::vector<Corner> vertices_;
  std::vector<uint32_t> indices_;
};

struct PartBuilders {
  explicit PartBuilders(const SourcePools& pools) : trunk(pools), leaves(pools) {}
  PartBuilder& operator[](Part part) { return part == Part::kTrunk ? trunk : leaves; }
  PartBuilder trunk;
  PartBuilder leaves;
};

// Both parts, the trunk checked for triangles (fail_no_trunk).
MeshModel finish(const std::string& path, const PartSelector& selector,
                 const PartBuilders& builders, const TrunkSearch& search);

}  // namespace boreas::impl::model_import
