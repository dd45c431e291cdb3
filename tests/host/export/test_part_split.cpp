// boreas tests: a skinned part cut into pieces (host/gltf/part_split.h): every piece within
// its vertex and joint limits, joint 0 first in each, and its triangles, piece after piece,
// the part's own (each corner's position, weights and joints, through the piece's joint
// map, those of the vertex it stood for).
#include <gtest/gtest.h>

#include <cmath>

#include "part_split.h"

namespace {

using boreas::gltf::SkinnedPart;
using boreas::gltf::SkinnedPiece;
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

void expect_same_triangles(const SkinnedPart& part, const std::vector<SkinnedPiece>& pieces,
                           size_t max_vertices, size_t max_joints) {
  size_t corner = 0;
  for (const SkinnedPiece& whole : pieces) {
    const SkinnedPart& piece = whole.part;
    ASSERT_LE(piece.vertex_count(), max_vertices);
    ASSERT_LE(whole.joint_map.size(), max_joints);
    ASSERT_EQ(whole.joint_map.at(0), 0) << "the root first";
    ASSERT_EQ(piece.joints.size(), 4 * piece.vertex_count());
    ASSERT_EQ(piece.uvs.size(), 2 * piece.vertex_count());
    for (uint32_t i : piece.indices) {
      ASSERT_LT(i, piece.vertex_count());
      ASSERT_LT(corner, part.indices.size());
      const uint32_t v = part.indices[corner++];
      for (size_t a = 0; a < 3; ++a) ASSERT_EQ(piece.positions[3 * i + a], part.positions[3 * v + a]);
      for (size_t k = 0; k < 4; ++k) {
        if (part.weights[4 * v + k] > 0)
          ASSERT_EQ(whole.joint_map.at(size_t(piece.joints[4 * i + k])), part.joints[4 * v + k]);
        ASSERT_EQ(piece.weights[4 * i + k], part.weights[4 * v + k]);
      }
      ASSERT_EQ(piece.uvs[2 * i], part.uvs[2 * v]);
    }
  }
  EXPECT_EQ(corner, part.indices.size());
}

TEST(PartSplit, PiecesHoldThePartsTrianglesInOrderWithinTheLimit) {
  const SkinnedPart part = grid(300, 300);  // 90,000 vertices: past 16 bits
  const std::vector<SkinnedPiece> pieces = split_part(part, 65535, 1 << 20);
  EXPECT_EQ(pieces.size(), 2u);
  expect_same_triangles(part, pieces, 65535, 1 << 20);
  const std::vector<SkinnedPiece> small = split_part(part, 1000, 1 << 20);
  expect_same_triangles(part, small, 1000, 1 << 20);
  // Copies only along the cuts: a cut through the grid shares at most two rows of it.
  size_t copied = 0;
  for (const SkinnedPiece& p : small) copied += p.part.vertex_count();
  EXPECT_LT(copied, part.vertex_count() + 2 * 300 * small.size());
}

TEST(PartSplit, PiecesHoldAtMost256Joints) {
  // Joints (row, column): 300 rows and 300 columns bind 600 joints in all.
  const SkinnedPart part = grid(300, 300);
  const std::vector<SkinnedPiece> pieces = split_part(part);
  EXPECT_GE(pieces.size(), 3u);
  expect_same_triangles(part, pieces, 65535, 256);
}

TEST(PartSplit, APartWithinTheLimitsStaysWhole) {
  const SkinnedPart part = grid(10, 10);
  const std::vector<SkinnedPiece> pieces = split_part(part);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].part.vertex_count(), part.vertex_count()) << "no copies";
  expect_same_triangles(part, pieces, 65535, 256);
}

}  // namespace
