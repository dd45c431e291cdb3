// boreas gltf: a skinned part cut into pieces of 16-bit indices and 8-bit joints
// (part_split.h).
#include "part_split.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace boreas::gltf {
namespace {

// The piece being filled: the part's vertices and joints it took so far.
struct Filling {
  SkinnedPiece piece;
  std::unordered_map<uint32_t, uint32_t> vertex;  // part vertex -> piece vertex
  std::unordered_map<int32_t, int32_t> joint;     // part joint -> piece joint
  Filling() { add_joint(0); }
  void add_joint(int32_t j) {
    if (joint.emplace(j, int32_t(piece.joint_map.size())).second) piece.joint_map.push_back(j);
  }
};

// The joints vertex v is weighted to (a zero weight binds nothing).
template <typename F>
void for_joints(const SkinnedPart& part, uint32_t v, F f) {
  for (size_t k = 0; k < 4; ++k)
    if (part.weights[4 * v + k] > 0) f(part.joints[4 * v + k]);
}

// Whether the triangle fits the piece: its new vertices and new joints within the limits.
bool fits(const Filling& f, const SkinnedPart& part, const uint32_t* tri, size_t max_vertices,
          size_t max_joints) {
  size_t vertices = f.piece.part.vertex_count(), joints = f.piece.joint_map.size();
  std::vector<int32_t> seen;
  for (int k = 0; k < 3; ++k) {
    if (f.vertex.count(tri[k]) || (k > 0 && tri[k] == tri[0]) || (k > 1 && tri[k] == tri[1])) continue;
    ++vertices;
    for_joints(part, tri[k], [&](int32_t j) {
      if (!f.joint.count(j) && std::find(seen.begin(), seen.end(), j) == seen.end()) seen.push_back(j);
    });
  }
  return vertices <= max_vertices && joints + seen.size() <= max_joints;
}

void take_vertex(const SkinnedPart& part, uint32_t v, Filling* f) {
  SkinnedPart& p = f->piece.part;
  auto copy = [v](const std::vector<float>& from, size_t n, std::vector<float>* to) {
    if (!from.empty()) to->insert(to->end(), from.begin() + long(n * v), from.begin() + long(n * v + n));
  };
  f->vertex.emplace(v, uint32_t(p.vertex_count()));
  copy(part.positions, 3, &p.positions);
  copy(part.normals, 3, &p.normals);
  copy(part.uvs, 2, &p.uvs);
  copy(part.weights, 4, &p.weights);
  for (size_t k = 0; k < 4; ++k) {
    const int32_t j = part.joints[4 * v + k];
    if (part.weights[4 * v + k] > 0) {
      f->add_joint(j);
      p.joints.push_back(f->joint.at(j));
    } else {
      p.joints.push_back(0);
    }
  }
}

}  // namespace

std::vector<SkinnedPiece> split_part(const SkinnedPart& part, size_t max_vertices, size_t max_joints) {
  std::vector<SkinnedPiece> pieces;
  Filling f;
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    const uint32_t* tri = &part.indices[t];
    if (!fits(f, part, tri, max_vertices, max_joints) && !f.piece.part.indices.empty()) {
      pieces.push_back(std::move(f.piece));
      f = Filling();
    }
    for (int k = 0; k < 3; ++k) {
      if (!f.vertex.count(tri[k])) take_vertex(part, tri[k], &f);
      f.piece.part.indices.push_back(f.vertex.at(tri[k]));
    }
  }
  if (!f.piece.part.indices.empty()) pieces.push_back(std::move(f.piece));
  return pieces;
}

}  // namespace boreas::gltf
