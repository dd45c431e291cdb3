// boreas tests: a skinned part cut into 16-bit-indexable pieces (host/gltf/part_split.h):
// every piece within its vertex limit, and its triangles, piece after piece, the part's
// own (each corner's position, joints and weights those of the vertex it stood for).
#include <gtest/gtest.h>

#include <cmath>

#include "part_split.h"

namespace {

using boreas::gltf::SkinnedPart;
using boreas::gltf::split_part;

// A rows x cols grid of vertices, two triangles a cell, each vertex's attributes its index.
SkinnedPart grid(uint32_t rows, uint32_t cols) {
  SkinnedPart p;
  for (uint32_t r = 0; r < rows; ++r)
    for (uint32_t c = 0; c < cols; ++c) {
      const float v = float(r * cols + c);
      p.positions.insert(p.positions.end(), {float(c), float(r), v});
      p.normals.insert(p.normals.end(), {0, 0, 1});
      p.uvs.insert(p.uvs.end(), {v, 0});
      p.joints.insert(p.joints.end(), {int32_t(r), int32_t(c), 0, 0});
      p.weights.insert(p.weights.end(), {0.25f, 0.75f, 0, 0});
    }
  for (uint32_t r = 0; r + 1 < rows; ++r)
    for (uint32_t c = 0; c + 1 < cols; ++c) {
      const uint32_t a = r * cols + c, b = a + 1, d = a + cols, e = d + 1;
      p.indices.insert(p.indices.end(), {a, b, e, a, e, d});
    }
  return p;
}

void expect_same_triangles(const SkinnedPart& part, const std::vector<SkinnedPart>& pieces,
                           size_t max_vertices) {
  size_t corner = 0;
  for (const SkinnedPart& piece : pieces) {
    ASSERT_LE(piece.vertex_count(), max_vertices);
    ASSERT_EQ(piece.joints.size(), 4 * piece.vertex_count());
    ASSERT_EQ(piece.uvs.size(), 2 * piece.vertex_count());
    for (uint32_t i : piece.indices) {
      ASSERT_LT(i, piece.vertex_count());
      ASSERT_LT(corner, part.indices.size());
      const uint32_t v = part.indices[corner++];
      for (size_t a = 0; a < 3; ++a) ASSERT_EQ(piece.positions[3 * i + a], part.positions[3 * v + a]);
      for (size_t k = 0; k < 4; ++k) {
        ASSERT_EQ(piece.joints[4 * i + k], part.joints[4 * v + k]);
        ASSERT_EQ(piece.weights[4 * i + k], part.weights[4 * v + k]);
      }
      ASSERT_EQ(piece.uvs[2 * i], part.uvs[2 * v]);
    }
  }
  EXPECT_EQ(corner, part.indices.size());
}

TEST(PartSplit, PiecesHoldThePartsTrianglesInOrderWithinTheLimit) {
  const SkinnedPart part = grid(300, 300);  // 90,000 vertices: past 16 bits
  const std::vector<SkinnedPart> pieces = split_part(part);
  EXPECT_EQ(pieces.size(), 2u);
  expect_same_triangles(part, pieces, 65535);
  const std::vector<SkinnedPart> small = split_part(part, 1000);
  expect_same_triangles(part, small, 1000);
  // Copies only along the cuts: a cut through the grid shares at most two rows of it.
  size_t copied = 0;
  for (const SkinnedPart& p : small) copied += p.vertex_count();
  EXPECT_LT(copied, part.vertex_count() + 2 * 300 * small.size());
}

TEST(PartSplit, APartWithinTheLimitStaysWhole) {
  const SkinnedPart part = grid(10, 10);
  const std::vector<SkinnedPart> pieces = split_part(part);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].indices, part.indices);
  EXPECT_EQ(pieces[0].positions, part.positions);
}

}  // namespace
