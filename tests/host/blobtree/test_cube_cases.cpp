// boreas tests: the generated marching cubes table (every case on its own, every pair of
// cubes across a face, complements) and the host marching cubes on spheres, a torus and
// random fields, checked with mesh_topology, which is itself checked on small meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "blobtree/cube_cases.h"
#include "support/mesh_topology.h"

namespace boreas::test {
namespace {

using glm::dvec3;
using impl::GridMesh;

// The numbering of blobtree_types.h, typed in here so that the library's derivation of it is
// checked: edges 0-3 along x, 4-7 along y, 8-11 along z.
constexpr int kEdgeCorners[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                     {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

bool inside(int config, int corner) { return (config >> corner & 1) != 0; }

bool crossing(int config, int e) {
  return inside(config, kEdgeCorners[e][0]) != inside(config, kEdgeCorners[e][1]);
}

int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdgeCorners[e][0] == a && kEdgeCorners[e][1] == b) ||
        (kEdgeCorners[e][0] == b && kEdgeCorners[e][1] == a))
      return e;
  return -1;
}

// Does edge e lie on the face of the cube where coordinate `axis` is `side`?
bool on_face(int e, int axis, int side) {
  return (kEdgeCorners[e][0] >> axis & 1) == side && (kEdgeCorners[e][1] >> axis & 1) == side;
}

bool share_face(int e, int f) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      if (on_face(e, axis, side) && on_face(f, axis, side)) return true;
  return false;
}

// A case's triangles as a mesh whose vertices are the 12 edges.
std::vector<uint32_t> case_indices(int config) {
  const int8_t* row = impl::cube_case_table().data() + config * BOREAS_BT_CASE_ENTRIES;
  return std::vector<uint32_t>(row, row + 3 * impl::cube_case_triangles(config));
}

// The directed edges used by one triangle only: the polygons' outlines on the cube's faces.
std::set<std::pair<int, int>> outline(int config) {
  std::vector<uint32_t> idx = case_indices(config);
  std::set<std::pair<int, int>> directed;
  for (size_t i = 0; i < idx.size(); i += 3)
    for (int k = 0; k < 3; ++k) directed.insert({int(idx[i + k]), int(idx[i + (k + 1) % 3])});
  std::set<std::pair<int, int>> out;
  for (auto [a, b] : directed)
    if (!directed.count({b, a})) out.insert({a, b});
  return out;
}

std::set<std::pair<int, int>> outline_on_face(int config, int axis, int side) {
  std::set<std::pair<int, int>> out;
  for (auto [a, b] : outline(config))
    if (on_face(a, axis, side) && on_face(b, axis, side)) out.insert({a, b});
  return out;
}

// Inside corners diagonally opposite on the face, outside corners on the other diagonal.
bool ambiguous(int config, int axis, int side) {
  int in = 0, corners[4], n = 0;
  for (int c = 0; c < 8; ++c)
    if ((c >> axis & 1) == side) {
      corners[n++] = c;
      in += inside(config, c);
    }
  // corners[0] and corners[3] are diagonal (they differ in both other bits).
  return in == 2 && inside(config, corners[0]) == inside(config, corners[3]);
}

TEST(CubeCases, AllInsideAndAllOutsideAreEmpty) {
  EXPECT_EQ(impl::cube_case_triangles(0), 0);
  EXPECT_EQ(impl::cube_case_triangles(255), 0);
}

TEST(CubeCases, RowsFitTheTableAndEndWithMinusOne) {
  const auto& table = impl::cube_case_table();
  int most = 0;
  for (int config = 0; config < 256; ++config) {
    const int n = impl::cube_case_triangles(config);
    most = std::max(most, n);
    for (int k = 0; k < BOREAS_BT_CASE_ENTRIES; ++k) {
      const int e = table[config * BOREAS_BT_CASE_ENTRIES + k];
      if (k < 3 * n) {
        EXPECT_TRUE(e >= 0 && e < 12) << "case " << config;
      } else {
        EXPECT_EQ(e, -1) << "case " << config;
      }
    }
  }
  EXPECT_LE(most, BOREAS_BT_CASE_TRIANGLES);
}

TEST(CubeCases, EveryCaseCutsExactlyItsSignChangingEdges) {
  for (int config = 0; config < 256; ++config) {
    std::vector<uint32_t> idx = case_indices(config);
    for (uint32_t e : idx) EXPECT_TRUE(crossing(config, int(e))) << "case " << config;
    for (int e = 0; e < 12; ++e)
      if (crossing(config, e)) {
        EXPECT_NE(std::find(idx.begin(), idx.end(), uint32_t(e)), idx.end())
            << "case " << config << " edge " << e;
      }
  }
}

// Each case is one or more discs (fanned polygons) whose outlines run over the cube's faces,
// once through every crossing point; no diagonal of a fan lies in a face, where the next
// cube could lay the same one.
TEST(CubeCases, EveryCaseIsDiscsOutlinedOnTheFaces) {
  for (int config = 1; config < 255; ++config) {
    std::vector<uint32_t> idx = case_indices(config);
    MeshTopology t = mesh_topology(idx, 12);
    int crossings = 0;
    for (int e = 0; e < 12; ++e) crossings += crossing(config, e);
    EXPECT_TRUE(t.manifold()) << "case " << config;
    EXPECT_EQ(t.boundary_edges, crossings) << "case " << config;
    EXPECT_EQ(t.euler, t.components) << "case " << config;
    EXPECT_EQ(t.triangles, crossings - 2 * t.components) << "case " << config;

    std::set<std::pair<int, int>> line = outline(config);
    for (auto [a, b] : line) EXPECT_TRUE(share_face(a, b)) << "case " << config;
    for (size_t i = 0; i < idx.size(); i += 3)
      for (int k = 0; k < 3; ++k) {
        const int a = int(idx[i + k]), b = int(idx[i + (k + 1) % 3]);
        if (!line.count({a, b})) {
          EXPECT_FALSE(share_face(a, b)) << "case " << config << " diagonal " << a << "-" << b;
        }
      }
  }
}

TEST(CubeCases, AmbiguousFacesCutEachInsideCornerOffOnItsOwn) {
  int seen = 0;
  for (int config = 0; config < 256; ++config)
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        if (!ambiguous(config, axis, side)) continue;
        ++seen;
        std::set<std::pair<int, int>> expected;
        for (auto [a, b] : outline_on_face(config, axis, side))
          expected.insert({std::min(a, b), std::max(a, b)});
        std::set<std::pair<int, int>> cut_off;
        for (int c = 0; c < 8; ++c) {
          if ((c >> axis & 1) != side || !inside(config, c)) continue;
          int around[2], n = 0;
          for (int e = 0; e < 12; ++e)
            if (on_face(e, axis, side) && (kEdgeCorners[e][0] == c || kEdgeCorners[e][1] == c))
              around[n++] = e;
          cut_off.insert({std::min(around[0], around[1]), std::max(around[0], around[1])});
        }
        EXPECT_EQ(expected, cut_off) << "case " << config << " face " << axis << side;
      }
  EXPECT_EQ(seen, 6 * 2 * 16);  // per face: 2 diagonal patterns times 16 for the far corners
}

// Cube A and the cube B beyond its face `axis` = 1 share that face's corners. Over every A
// and every B's far corners, B's outline on the shared face is A's reversed: the surface has
// no cracks and its orientation carries across. This covers every pair of neighbours.
TEST(CubeCases, NeighboursOutlineASharedFaceInReverse) {
  for (int axis = 0; axis < 3; ++axis) {
    const int bit = 1 << axis;
    for (int a = 0; a < 256; ++a)
      for (int far = 0; far < 16; ++far) {
        int b = 0, k = 0;
        for (int c = 0; c < 8; ++c) {
          const bool in = c & bit ? (far >> k++ & 1) != 0 : inside(a, c | bit);
          if (in) b |= 1 << c;
        }
        std::set<std::pair<int, int>> expected;
        for (auto [u, v] : outline_on_face(a, axis, 1)) {
          const int bu = edge_between(kEdgeCorners[u][0] & ~bit, kEdgeCorners[u][1] & ~bit);
          const int bv = edge_between(kEdgeCorners[v][0] & ~bit, kEdgeCorners[v][1] & ~bit);
          expected.insert({bv, bu});
        }
        ASSERT_EQ(outline_on_face(b, axis, 0), expected)
            << "axis " << axis << " A " << a << " B " << b;
      }
  }
}

// Swapping inside and outside keeps every unambiguous face's outline, reversed; an
// ambiguous face joins its crossings the other way, since the inside corners change.
TEST(CubeCases, ComplementReversesTheOutlineOfUnambiguousFaces) {
  for (int config = 0; config < 256; ++config) {
    const int complement = 255 - config;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        std::set<std::pair<int, int>> reversed;
        for (auto [a, b] : outline_on_face(config, axis, side)) reversed.insert({b, a});
        if (ambiguous(config, axis, side)) {
          EXPECT_NE(outline_on_face(complement, axis, side), reversed) << "case " << config;
        } else {
          EXPECT_EQ(outline_on_face(complement, axis, side), reversed) << "case " << config;
        }
      }
  }
}

// The rule is geometric: turning or mirroring the cube maps a case's outline onto the
// outline of the mapped case (reversed by a mirror, which turns counter-clockwise around).
// The fans may differ, since the apex follows the edge numbering.
TEST(CubeCases, SymmetriesOfTheCubeMapOutlinesOntoOutlines) {
  const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int order = 0; order < 6; ++order)
    for (int flips = 0; flips < 8; ++flips) {
      int map[8];
      for (int c = 0; c < 8; ++c) {
        map[c] = 0;
        for (int a = 0; a < 3; ++a) map[c] |= ((c >> orders[order][a] & 1) ^ (flips >> a & 1)) << a;
      }
      // A swap of two axes or a flip of one mirrors; two of them turn.
      const bool odd_flips = ((flips ^ flips >> 1 ^ flips >> 2) & 1) != 0;
      const bool mirror = (order >= 3) != odd_flips;
      for (int config = 0; config < 256; ++config) {
        int mapped = 0;
        for (int c = 0; c < 8; ++c)
          if (inside(config, c)) mapped |= 1 << map[c];
        std::set<std::pair<int, int>> expected;
        for (auto [a, b] : outline(config)) {
          const int ma = edge_between(map[kEdgeCorners[a][0]], map[kEdgeCorners[a][1]]);
          const int mb = edge_between(map[kEdgeCorners[b][0]], map[kEdgeCorners[b][1]]);
          expected.insert(mirror ? std::make_pair(mb, ma) : std::make_pair(ma, mb));
        }
        ASSERT_EQ(outline(mapped), expected) << "case " << config << " symmetry " << order << flips;
      }
    }
}

// Signed volume of a closed mesh: the inside's volume when the triangles face outwards.
double signed_volume(const GridMesh& m) {
  double v = 0.0;
  for (size_t i = 0; i < m.indices.size(); i += 3)
    v += glm::dot(m.positions[m.indices[i]],
                  glm::cross(m.positions[m.indices[i + 1]], m.positions[m.indices[i + 2]]));
  return v / 6.0;
}

dvec3 triangle_normal(const GridMesh& m, size_t i) {
  const dvec3& a = m.positions[m.indices[i]];
  return glm::cross(m.positions[m.indices[i + 1]] - a, m.positions[m.indices[i + 2]] - a);
}

struct Grid {
  int nx, ny, nz;
  dvec3 origin;
  double cell;
  std::vector<double> values;
};

Grid sample(int n, double extent, const std::function<double(const dvec3&)>& f) {
  Grid g{n, n, n, dvec3(-extent), 2.0 * extent / (n - 1), {}};
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) g.values.push_back(f(g.origin + g.cell * dvec3(x, y, z)));
  return g;
}

GridMesh extract(const Grid& g, double iso = 0.0) {
  return impl::marching_cubes(g.values, g.nx, g.ny, g.nz, g.origin, g.cell, iso);
}

void expect_closed_manifold(const GridMesh& m, int64_t components, int64_t euler) {
  MeshTopology t = mesh_topology(m.indices, int64_t(m.positions.size()));
  EXPECT_GT(t.triangles, 0);
  EXPECT_TRUE(t.watertight()) << t.boundary_edges << " boundary, " << t.nonmanifold_edges
                              << " non-manifold edges";
  EXPECT_TRUE(t.manifold()) << t.misoriented_edges << " misoriented edges, "
                            << t.nonmanifold_vertices << " non-manifold vertices";
  EXPECT_EQ(t.unused_vertices, 0);
  EXPECT_EQ(t.components, components);
  EXPECT_EQ(t.euler, euler);
}

// Each case alone: its inside corners are the middle 2x2x2 of a 4x4x4 grid whose border is
// outside. Vertices sit at edge midpoints, so every triangle should face from its inside
// corners to its outside ones.
TEST(CubeCases, EveryCaseAloneGivesAClosedOutwardSurface) {
  for (int config = 1; config < 256; ++config) {
    std::vector<double> values(64, -1.0);
    for (int c = 0; c < 8; ++c)
      if (inside(config, c))
        values[((1 + (c >> 2 & 1)) * 4 + 1 + (c >> 1 & 1)) * 4 + 1 + (c & 1)] = 1.0;
    GridMesh m = impl::marching_cubes(values, 4, 4, 4, dvec3(0.0), 1.0, 0.0);
    MeshTopology t = mesh_topology(m.indices, int64_t(m.positions.size()));
    EXPECT_TRUE(t.watertight() && t.manifold()) << "case " << config;
    EXPECT_GT(signed_volume(m), 0.0) << "case " << config;
    for (size_t i = 0; i < m.indices.size(); i += 3) {
      // Outward at a vertex: from the inside end of its grid edge to the outside end.
      dvec3 out(0.0);
      for (int k = 0; k < 3; ++k) {
        const dvec3 p = m.positions[m.indices[i + k]];
        const dvec3 frac = p - glm::floor(p);
        const dvec3 along(frac.x > 0.0, frac.y > 0.0, frac.z > 0.0);
        const dvec3 start = glm::floor(p);
        const int s = int(((start.z * 4) + start.y) * 4 + start.x);
        const int e = s + int(along.x + 4 * along.y + 16 * along.z);
        out += values[s] > 0.0 ? along : -along;
        EXPECT_NE(values[s] > 0.0, values[e] > 0.0);
      }
      EXPECT_GT(glm::dot(triangle_normal(m, i), out), 0.0) << "case " << config;
    }
  }
}

TEST(MarchingCubes, SphereIsOneClosedOutwardSurfaceOnTheSphere) {
  const dvec3 c(0.013, -0.021, 0.034);
  const double r = 0.7;
  Grid g = sample(24, 1.0, [&](const dvec3& p) { return r - glm::length(p - c); });
  GridMesh m = extract(g);
  expect_closed_manifold(m, 1, 2);
  // Linear interpolation of a distance that curves across a cell: off by ~cell^2 / (8 r).
  double worst = 0.0;
  for (const dvec3& p : m.positions) worst = std::max(worst, std::abs(glm::length(p - c) - r));
  EXPECT_LT(worst, 0.02 * g.cell);
  for (size_t i = 0; i < m.indices.size(); i += 3)
    EXPECT_GT(glm::dot(triangle_normal(m, i), m.positions[m.indices[i]] - c), 0.0);
  const double volume = 4.0 / 3.0 * 3.14159265358979324 * r * r * r;
  EXPECT_NEAR(signed_volume(m), volume, 0.01 * volume);
}

TEST(MarchingCubes, OverlappingSpheresMergeAndSeparateOnesDoNot) {
  auto two = [](double gap) {
    return [gap](const dvec3& p) {
      return std::max(0.45 - glm::length(p - dvec3(-gap, 0.02, 0.01)),
                      0.4 - glm::length(p - dvec3(gap, -0.03, 0.02)));
    };
  };
  expect_closed_manifold(extract(sample(28, 1.0, two(0.3))), 1, 2);
  expect_closed_manifold(extract(sample(28, 1.0, two(0.5))), 2, 4);
}

TEST(MarchingCubes, TorusHasEulerCharacteristicZero) {
  Grid g = sample(32, 1.0, [](const dvec3& p) {
    const double ring = std::sqrt(p.x * p.x + p.y * p.y) - 0.6;
    return 0.22 - std::sqrt(ring * ring + p.z * p.z);
  });
  GridMesh m = extract(g);
  expect_closed_manifold(m, 1, 0);
  EXPECT_GT(signed_volume(m), 0.0);
}

// Random values, outside on the border layer: every case and its neighbours in every
// combination the rule allows, so a table inconsistent across faces shows up as holes.
TEST(MarchingCubes, RandomFieldsGiveClosedManifolds) {
  std::set<int> cases;
  for (uint32_t seed = 1; seed <= 500; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int nx = 6 + seed % 4, ny = 6 + seed / 4 % 4, nz = 6 + seed / 16 % 4;
    const double iso = 0.6 * u(rng);
    std::vector<double> values(size_t(nx) * ny * nz, -1.0);
    for (int z = 1; z + 1 < nz; ++z)
      for (int y = 1; y + 1 < ny; ++y)
        for (int x = 1; x + 1 < nx; ++x) values[(size_t(z) * ny + y) * nx + x] = u(rng);
    for (int z = 1; z + 2 < nz; ++z)
      for (int y = 1; y + 2 < ny; ++y)
        for (int x = 1; x + 2 < nx; ++x) {
          int config = 0;
          for (int c = 0; c < 8; ++c)
            if (values[(size_t(z + (c >> 2 & 1)) * ny + y + (c >> 1 & 1)) * nx + x + (c & 1)] > iso)
              config |= 1 << c;
          cases.insert(config);
        }
    GridMesh m = impl::marching_cubes(values, nx, ny, nz, dvec3(0.0), 1.0, iso);
    MeshTopology t = mesh_topology(m.indices, int64_t(m.positions.size()));
    ASSERT_TRUE(t.watertight() && t.manifold())
        << "seed " << seed << ": " << t.boundary_edges << " boundary, " << t.nonmanifold_edges
        << " non-manifold, " << t.misoriented_edges << " misoriented edges, "
        << t.nonmanifold_vertices << " non-manifold vertices";
    EXPECT_EQ(t.unused_vertices, 0);
    // Closed orientable surfaces: each has an even Euler characteristic of at most 2.
    EXPECT_EQ(t.euler % 2, 0);
    EXPECT_LE(t.euler, 2 * t.components);
    if (!m.indices.empty()) {
      EXPECT_GT(signed_volume(m), 0.0) << "seed " << seed;
    }
  }
  EXPECT_EQ(cases.size(), 256u);
}

// Vertices in (start point, axis) order and triangles in (cube, table) order, on a grid
// whose sides differ so that the linear index's x, y, z cannot be swapped unnoticed.
TEST(MarchingCubes, VerticesAndTrianglesFollowTheDocumentedOrder) {
  const int nx = 5, ny = 4, nz = 6;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> values(nx * ny * nz);
  for (double& v : values) v = u(rng);
  const dvec3 origin(0.5, -1.0, 2.0);
  const double cell = 0.25, iso = 0.1;
  GridMesh m = impl::marching_cubes(values, nx, ny, nz, origin, cell, iso);

  // Recover each vertex's (point, axis) from its position; keys must rise strictly.
  auto linear = [&](int x, int y, int z) { return (int64_t(z) * ny + y) * nx + x; };
  std::vector<int64_t> keys;
  for (const dvec3& p : m.positions) {
    const dvec3 q = (p - origin) / cell;
    const dvec3 start = glm::floor(q + 1e-9);
    int axis = -1;
    for (int a = 0; a < 3; ++a)
      if (q[a] - start[a] > 1e-6) axis = a;
    ASSERT_GE(axis, 0);
    keys.push_back(3 * linear(int(start.x), int(start.y), int(start.z)) + axis);
  }
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end());

  // Every sign-changing grid edge has its vertex, placed by linear interpolation.
  size_t expected_vertices = 0;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        for (int a = 0; a < 3; ++a) {
          const int p[3] = {x, y, z}, n[3] = {nx, ny, nz};
          if (p[a] + 1 >= n[a]) continue;
          const int64_t i = linear(x, y, z), j = i + (a == 0 ? 1 : a == 1 ? nx : nx * ny);
          if ((values[i] > iso) == (values[j] > iso)) continue;
          ++expected_vertices;
          const auto at = std::lower_bound(keys.begin(), keys.end(), 3 * i + a);
          ASSERT_TRUE(at != keys.end() && *at == 3 * i + a);
          dvec3 q(x, y, z);
          q[a] += (iso - values[i]) / (values[j] - values[i]);
          EXPECT_LT(glm::length(m.positions[at - keys.begin()] - (origin + cell * q)), 1e-12);
        }
  EXPECT_EQ(m.positions.size(), expected_vertices);

  std::vector<uint32_t> expected;
  for (int z = 0; z + 1 < nz; ++z)
    for (int y = 0; y + 1 < ny; ++y)
      for (int x = 0; x + 1 < nx; ++x) {
        int config = 0;
        for (int c = 0; c < 8; ++c)
          if (values[linear(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2 & 1))] > iso)
            config |= 1 << c;
        for (uint32_t e : case_indices(config)) {
          const int c = kEdgeCorners[e][0];
          const int64_t key =
              3 * linear(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2 & 1)) + int(e) / 4;
          expected.push_back(
              uint32_t(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin()));
        }
      }
  EXPECT_EQ(m.indices, expected);
}

TEST(MarchingCubes, ClampKeepsVerticesOffTheGridPoints) {
  // Corner 0 inside, the rest exactly at iso (outside): the crossings would land on
  // corners 1, 2 and 4 but stop 1e-4 of the edge short of them.
  std::vector<double> values(8, 0.0);
  values[0] = 1.0;
  GridMesh m = impl::marching_cubes(values, 2, 2, 2, dvec3(0.0), 2.0, 0.0);
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_NEAR(m.positions[0].x, 2.0 * (1.0 - 1e-4), 1e-12);
  EXPECT_NEAR(m.positions[1].y, 2.0 * (1.0 - 1e-4), 1e-12);
  EXPECT_NEAR(m.positions[2].z, 2.0 * (1.0 - 1e-4), 1e-12);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

// mesh_topology on small meshes. A tetrahedron with outward faces:
const std::vector<uint32_t> kTetrahedron = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};

TEST(MeshTopology, ClosedTetrahedronIsAManifoldSphere) {
  MeshTopology t = mesh_topology(kTetrahedron, 4);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.manifold());
  EXPECT_EQ(t.edges, 6);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.euler, 2);
}

TEST(MeshTopology, FindsTheHoleOfAnOpenTetrahedron) {
  std::vector<uint32_t> open(kTetrahedron.begin(), kTetrahedron.end() - 3);
  MeshTopology t = mesh_topology(open, 4);
  EXPECT_FALSE(t.watertight());
  EXPECT_EQ(t.boundary_edges, 3);
  EXPECT_TRUE(t.manifold());  // every vertex is one open fan
  EXPECT_EQ(t.euler, 1);
}

TEST(MeshTopology, FindsAnEdgeOfThreeTriangles) {
  MeshTopology t = mesh_topology({0, 1, 2, 1, 0, 3, 0, 1, 4}, 5);
  EXPECT_EQ(t.nonmanifold_edges, 1);
  EXPECT_FALSE(t.watertight());
  EXPECT_FALSE(t.manifold());
  EXPECT_EQ(t.nonmanifold_vertices, 2);  // edge 0-1's ends: their links fork
}

TEST(MeshTopology, FindsAFlippedTriangle) {
  std::vector<uint32_t> flipped = kTetrahedron;
  std::swap(flipped[10], flipped[11]);
  MeshTopology t = mesh_topology(flipped, 4);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.misoriented_edges, 3);
  EXPECT_FALSE(t.manifold());
}

TEST(MeshTopology, FindsTwoTetrahedraTouchingAtAVertex) {
  std::vector<uint32_t> bow_tie = kTetrahedron;
  for (uint32_t i : kTetrahedron) bow_tie.push_back(i == 0 ? 0 : i + 3);
  MeshTopology t = mesh_topology(bow_tie, 7);
  EXPECT_TRUE(t.watertight());
  EXPECT_EQ(t.nonmanifold_vertices, 1);
  EXPECT_FALSE(t.manifold());
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.euler, 7 - 12 + 8);
}

TEST(MeshTopology, CountsDegenerateTrianglesAndUnusedVertices) {
  std::vector<uint32_t> mesh = kTetrahedron;
  mesh.insert(mesh.end(), {1, 1, 2});
  MeshTopology t = mesh_topology(mesh, 6);
  EXPECT_EQ(t.degenerate_triangles, 1);
  EXPECT_EQ(t.unused_vertices, 2);
  EXPECT_TRUE(t.watertight());
  EXPECT_FALSE(t.manifold());
  EXPECT_EQ(t.euler, 2);
}

}  // namespace
}  // namespace boreas::test
