// boreas render tests: an imported tree's static shading attributes (render/gl/
// mesh_tree_surface.h) on meshes whose answer is known: a cylinder mapped in turns and
// lengths gets whole bark repeats around and its axis as +v, islands keep their own scale,
// a model without texture coordinates still gets a usable frame, and leaves without them
// are flagged for the blade's middle.
#include "gl/mesh_tree_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Mesh {
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
};

// A cylinder along +Y from base (radius r, length l), `sides` x `rings` quads, u = turns
// around (0..1, the seam duplicated), v = 0..1 along; uvs scaled by uv_scale (0: none).
void add_cylinder(Mesh& m, glm::vec3 base, float r, float l, float uv_scale, int sides = 12,
                  int rings = 4) {
  const uint32_t first = uint32_t(m.vertices.size());
  for (int i = 0; i <= rings; ++i) {
    for (int j = 0; j <= sides; ++j) {
      double a = 2.0 * kPi * j / sides;
      boreas_vertex v{};
      glm::vec3 n(std::cos(a), 0.0, std::sin(a));
      glm::vec3 p = base + r * n + glm::vec3(0.0f, l * float(i) / float(rings), 0.0f);
      for (int k = 0; k < 3; ++k) v.position[k] = p[k], v.normal[k] = n[k];
      v.uv[0] = uv_scale * float(j) / float(sides);
      v.uv[1] = uv_scale * float(i) / float(rings);
      m.vertices.push_back(v);
    }
  }
  const uint32_t row = uint32_t(sides + 1);
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      uint32_t a = first + uint32_t(i) * row + uint32_t(j), b = a + 1, c = a + row + 1, d = a + row;
      m.indices.insert(m.indices.end(), {a, d, c, a, c, b});
    }
  }
}

const float* at(const std::vector<float>& a, size_t vertex, int floats) {
  return &a[vertex * size_t(floats)];
}

TEST(MeshTreeSurface, CylinderGetsWholeBarkRepeatsAroundAndItsAxisAlong) {
  Mesh m;
  add_cylinder(m, glm::vec3(0.0f), 0.15f, 2.0f, 1.0f);
  const float tile = 0.2f;
  std::vector<float> a = bark_attributes(m.vertices, m.indices, tile);
  ASSERT_EQ(a.size(), m.vertices.size() * kMeshBarkFloats);
  // Around: the median chord of 12 sides is a little under 2 pi r; 0.94 m / 0.2 m rounds
  // to 5 whole repeats so the seam closes. Along: 2 m is 10 repeats.
  const double chord = 12 * 2 * 0.15 * std::sin(kPi / 12);
  const double around = std::round(chord / tile), along = 2.0 / tile;
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    const float* x = at(a, v, kMeshBarkFloats);
    EXPECT_NEAR(x[6], m.vertices[v].uv[0] * around, 1e-4) << v;
    EXPECT_NEAR(x[7], m.vertices[v].uv[1] * along, 1e-4) << v;
    EXPECT_NEAR(x[3], 0.0, 1e-5);  // +v runs up the axis
    EXPECT_NEAR(x[4], 1.0, 1e-5);
    EXPECT_NEAR(x[5], 0.0, 1e-5);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(x[k], m.vertices[v].normal[k]);
  }
}

TEST(MeshTreeSurface, EachIslandKeepsItsOwnScaleAndUnmappedOnesGetAFrame) {
  Mesh m;
  add_cylinder(m, glm::vec3(0.0f), 0.3f, 1.0f, 1.0f);  // thick, mapped in turns
  const size_t thin_first = m.vertices.size();
  add_cylinder(m, glm::vec3(2.0f, 0.0f, 0.0f), 0.01f, 1.0f, 1.0f);  // a twig: under half a repeat
  const size_t bare_first = m.vertices.size();
  add_cylinder(m, glm::vec3(4.0f, 0.0f, 0.0f), 0.1f, 1.0f, 0.0f);  // no uvs at all
  uint32_t islands = 0;
  std::vector<uint32_t> island = uv_islands(m.vertices.size() + 1, m.indices, &islands);
  EXPECT_EQ(islands, 4u);  // three cylinders and the unused vertex
  EXPECT_EQ(island[0], 0u);
  EXPECT_EQ(island[thin_first], 1u);
  EXPECT_EQ(island[bare_first], 2u);
  EXPECT_EQ(island.back(), 3u);

  std::vector<float> a = bark_attributes(m.vertices, m.indices, 0.2f);
  const size_t thick_seam = 12, thin_seam = thin_first + 12;  // u = 1 on the first ring
  EXPECT_NEAR(at(a, thick_seam, kMeshBarkFloats)[6],
              std::round(24 * 0.3 * std::sin(kPi / 12) / 0.2), 1e-4);
  // The twig's 0.06 m around is not rounded up to a whole repeat (that would stretch its
  // bark threefold): its scale is its own metres.
  EXPECT_NEAR(at(a, thin_seam, kMeshBarkFloats)[6], 24 * 0.01 * std::sin(kPi / 12) / 0.2, 1e-4);
  for (size_t v = bare_first; v < m.vertices.size(); ++v) {
    const float* x = at(a, v, kMeshBarkFloats);
    EXPECT_EQ(x[6], 0.0f);
    EXPECT_EQ(x[7], 0.0f);
    EXPECT_NEAR(x[4], 1.0, 1e-6) << "without uvs +v is +Y on the surface";
    EXPECT_NEAR(glm::dot(glm::vec3(x[3], x[4], x[5]), glm::vec3(x[0], x[1], x[2])), 0.0, 1e-6);
  }
}

TEST(MeshTreeSurface, LeavesKeepTheirUvsOrAreFlaggedAndTheCrownShadesItsMiddle) {
  // Two quads in the XZ plane, 1 m apart, facing up: one mapped (v along +X), one not.
  Mesh m;
  for (int q = 0; q < 2; ++q) {
    const uint32_t first = uint32_t(m.vertices.size());
    const float corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& c : corner) {
      boreas_vertex v{};
      v.position[0] = 0.1f * c[1];
      v.position[1] = 1.0f;
      v.position[2] = float(q) + 0.05f * c[0];
      v.normal[1] = 1.0f;
      v.uv[0] = q == 0 ? c[0] : 0.25f;
      v.uv[1] = q == 0 ? c[1] : 0.25f;
      m.vertices.push_back(v);
    }
    m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  Bounds crown;
  crown.add(glm::vec3(-1.0f, 0.0f, 0.0f));
  crown.add(glm::vec3(1.0f, 2.0f, 2.0f));  // the first quad near the middle's height
  std::vector<float> a = leaf_attributes(m.vertices, m.indices, crown);
  ASSERT_EQ(a.size(), m.vertices.size() * kMeshLeafFloats);
  for (size_t v = 0; v < 4; ++v) {
    const float* x = at(a, v, kMeshLeafFloats);
    EXPECT_EQ(x[3], m.vertices[v].uv[0]);
    EXPECT_EQ(x[4], m.vertices[v].uv[1]);
    EXPECT_NEAR(x[0], 1.0, 1e-5) << "+v runs along +X";
  }
  for (size_t v = 4; v < 8; ++v) {
    const float* x = at(a, v, kMeshLeafFloats);
    EXPECT_EQ(x[3], -1.0f);
    EXPECT_EQ(x[4], -1.0f);
  }
  for (size_t v = 0; v < 8; ++v) {
    float occlusion = at(a, v, kMeshLeafFloats)[5];
    EXPECT_FLOAT_EQ(occlusion,
                    leaf_occlusion(glm::vec3(m.vertices[v].position[0], m.vertices[v].position[1],
                                             m.vertices[v].position[2]),
                                   crown));
  }
  EXPECT_LT(leaf_occlusion(glm::vec3(0.0f, 1.0f, 1.0f), crown),
            leaf_occlusion(glm::vec3(1.0f, 2.0f, 2.0f), crown));
}

}  // namespace
}  // namespace boreas::render
