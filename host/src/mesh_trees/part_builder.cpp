// boreas: a tree model's part from the file's triangles (see part_builder.h).
#include "mesh_trees/part_builder.h"

#include <cmath>
#include <limits>

#include "errors.h"

namespace boreas::impl::model_import {

MeshPart PartBuilder::finish() const {
  std::unordered_map<int64_t, FaceNormals> face_normals = accumulate_face_normals();
  MeshPart part;
  part.positions.reserve(3 * vertices_.size());
  part.normals.reserve(3 * vertices_.size());
  part.uvs.reserve(2 * vertices_.size());
  for (const Corner& v : vertices_) {
    const Vec3& p = pools_.positions[size_t(v.position)];
    Vec3 n{};
    bool has_normal = v.normal >= 0 && unit(pools_.normals[size_t(v.normal)], &n);
    if (!has_normal) n = face_normals.at(v.position).unit();
    Vec2 uv = v.uv >= 0 ? pools_.uvs[size_t(v.uv)] : Vec2{0.0, 0.0};
    for (int k = 0; k < 3; ++k) part.positions.push_back(float(p[size_t(k)]));
    for (int k = 0; k < 3; ++k) part.normals.push_back(float(n[size_t(k)]));
    part.uvs.push_back(float(uv[0]));
    part.uvs.push_back(float(uv[1]));
  }
  part.indices = indices_;
  return part;
}

Vec3 PartBuilder::FaceNormals::unit() const {
  Vec3 n{};
  // Faces that cancel (a double-sided leaf card modelled as two opposite faces on the
  // same vertices) leave rounding noise, not a direction: then the first face decides.
  if (length(sum) > 1e-6 * magnitude && PartBuilder::unit(sum, &n)) return n;
  if (has_first && PartBuilder::unit(first, &n)) return n;
  // Only degenerate faces touch this position: any unit vector keeps later stages
  // finite, and up (Y) is the least surprising.
  return {0.0, 1.0, 0.0};
}

bool PartBuilder::unit(const Vec3& v, Vec3* out) {
  double len = length(v);
  if (!(len > 0.0) || !std::isfinite(len)) return false;
  *out = scale(v, 1.0 / len);
  return true;
}

uint32_t PartBuilder::vertex_for(const Corner& c) {
  auto found = vertex_of_.find(c);
  if (found != vertex_of_.end()) return found->second;
  if (vertices_.size() >= std::numeric_limits<uint32_t>::max()) {
    fail_argument("tree model part has more vertices than 32-bit indices can address");
  }
  uint32_t index = uint32_t(vertices_.size());
  vertices_.push_back(c);
  vertex_of_.emplace(c, index);
  return index;
}

std::unordered_map<int64_t, PartBuilder::FaceNormals> PartBuilder::accumulate_face_normals() const {
  std::unordered_map<int64_t, FaceNormals> sums;
  for (size_t t = 0; t + 2 < indices_.size(); t += 3) {
    const Corner* c[3] = {&vertices_[indices_[t]], &vertices_[indices_[t + 1]],
                          &vertices_[indices_[t + 2]]};
    const Vec3& a = pools_.positions[size_t(c[0]->position)];
    const Vec3& b = pools_.positions[size_t(c[1]->position)];
    const Vec3& d = pools_.positions[size_t(c[2]->position)];
    // |cross| is twice the triangle's area: the sum weights each face by its area.
    Vec3 n = cross(sub(b, a), sub(d, a));
    double len = length(n);
    for (const Corner* corner : c) {
      FaceNormals& s = sums[corner->position];
      s.sum = add(s.sum, n);
      s.magnitude += len;
      if (!s.has_first && len > 0.0) {
        s.first = n;
        s.has_first = true;
      }
    }
  }
  return sums;
}

MeshModel finish(const std::string& path, const PartSelector& selector,
                 const PartBuilders& builders, const TrunkSearch& search) {
  MeshModel model;
  model.trunk = builders.trunk.finish();
  if (model.trunk.indices.empty()) fail_no_trunk(path, selector, search);
  model.leaves = builders.leaves.finish();
  return model;
}

}  // namespace boreas::impl::model_import
