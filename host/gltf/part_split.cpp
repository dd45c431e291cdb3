// boreas gltf: a skinned part cut into 16-bit-indexable pieces (part_split.h).
#include "part_split.h"

#include <cstdint>

namespace boreas::gltf {
namespace {

// Vertex v of part appended to piece (every attribute it has).
void copy_vertex(const SkinnedPart& part, size_t v, SkinnedPart* piece) {
  auto copy = [v](const std::vector<float>& from, size_t n, std::vector<float>* to) {
    if (!from.empty()) to->insert(to->end(), from.begin() + long(n * v), from.begin() + long(n * v + n));
  };
  copy(part.positions, 3, &piece->positions);
  copy(part.normals, 3, &piece->normals);
  copy(part.uvs, 2, &piece->uvs);
  copy(part.weights, 4, &piece->weights);
  piece->joints.insert(piece->joints.end(), part.joints.begin() + long(4 * v),
                       part.joints.begin() + long(4 * v + 4));
}

}  // namespace

std::vector<SkinnedPart> split_part(const SkinnedPart& part, size_t max_vertices) {
  const size_t n = part.vertex_count();
  if (n <= max_vertices) return {part};
  std::vector<SkinnedPart> pieces(1);
  // local[v]: v's index in the piece that last took it; owner[v]: that piece + 1.
  std::vector<uint32_t> local(n, 0), owner(n, 0);
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    const uint32_t* tri = &part.indices[t];
    uint32_t piece = uint32_t(pieces.size());
    size_t fresh = 0;
    for (int k = 0; k < 3; ++k) fresh += owner[tri[k]] != piece && (k == 0 || tri[k] != tri[0]) &&
                                         (k < 2 || tri[2] != tri[1]);
    if (pieces.back().vertex_count() + fresh > max_vertices) {
      pieces.emplace_back();
      piece = uint32_t(pieces.size());
    }
    SkinnedPart& p = pieces.back();
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = tri[k];
      if (owner[v] != piece) {
        owner[v] = piece;
        local[v] = uint32_t(p.vertex_count());
        copy_vertex(part, v, &p);
      }
      p.indices.push_back(local[v]);
    }
  }
  return pieces;
}

}  // namespace boreas::gltf
