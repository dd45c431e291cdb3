// boreas tests: the device polygonizer of BlobTree trees — the binned field equals the
// naive one bit for bit and the double reference within float rounding; the meshes are
// the host marching cubes' on the same field, watertight and manifold, with outward
// gradient normals, vertices on the surface, a flat face where a cut was made, and
// blended texture coordinates; the C API keeps the world as it was on bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include "blobtree/blobtree_bins.h"
#include "blobtree/blobtree_model.h"
#include "blobtree/cube_cases.h"
#include "blobtree/polygonizer.h"
#include "boreas/boreas.h"
#include "reference/blobtree_reference.h"
#include "runtime/runtime.h"
#include "support/mesh_topology.h"
#include "support/test_support.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::test {
namespace {

using glm::dvec3;
using impl::BlobGrid;
using impl::BlobMesh;
using impl::BlobModel;
using impl::BlobTreeOptions;

class BlobTreePolygonizer : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { runtime_ = new impl::Runtime(nullptr, nullptr); }
  static void TearDownTestSuite() {
    delete runtime_;
    runtime_ = nullptr;
  }
  static impl::Runtime& rt() { return *runtime_; }
  static impl::Runtime* runtime_;
};
impl::Runtime* BlobTreePolygonizer::runtime_ = nullptr;

// An aspen with a cut trunk, a scar, bent laterals and PCM junctions: every kind of node.
// Branches down to 0.15 cells are kept (the product keeps half a cell and up), so that
// even a coarse grid holds PCM groups, bends and the scar; all at least 0.9 cells thick.
BlobModel aspen(int resolution, BlobGrid* grid, double trunk_cut = 0.0) {
  static const impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions o;
  o.bend_angle = 0.3;
  // A limb sawn off half way (or the trunk, for the test of the cut's face).
  if (trunk_cut > 0.0)
    o.cuts.push_back({0, trunk_cut});
  else
    o.cuts.push_back({tree.level_begin[1] + 20, 0.5});
  o.scars.push_back({tree.level_begin[1] + 14, 0.1, 0.6});
  BlobModel m = impl::build_blobtree(tree, dvec3(0.0), o);
  *grid = impl::blob_grid(m, resolution);
  o.min_radius = 0.15 * grid->cell;
  o.min_surface = 0.9 * grid->cell;
  m = impl::build_blobtree(tree, dvec3(0.0), o);
  *grid = impl::blob_grid(m, resolution);
  int pcm = 0, bent = 0, scars = 0;
  for (const impl::BlobPrimitive& p : m.primitives) {
    pcm += p.pcm ? 1 : 0;
    bent += p.bend_angle > 0.0 ? 1 : 0;
    scars += p.weight < 0.0 ? 1 : 0;
  }
  if (trunk_cut == 0.0) {
    EXPECT_GT(pcm, 10);
    EXPECT_GT(bent, 3);
  }
  EXPECT_EQ(scars, trunk_cut == 0.0 ? 1 : 0) << "the scarred limb grows above a trunk cut";
  EXPECT_EQ(m.cuts.size(), 1u);
  return m;
}

TEST_F(BlobTreePolygonizer, BinnedFieldIsTheNaiveFieldBitForBit) {
  BlobGrid grid;
  BlobModel m = aspen(96, &grid);
  std::vector<float> binned = impl::sample_blobtree_field(rt(), m, grid, false);
  std::vector<float> naive = impl::sample_blobtree_field(rt(), m, grid, true);
  ASSERT_EQ(binned.size(), naive.size());
  EXPECT_EQ(0, std::memcmp(binned.data(), naive.data(), binned.size() * sizeof(float)));
  size_t inside = 0;
  for (float f : binned) inside += f > 0.5f ? 1 : 0;
  EXPECT_GT(inside, 1000u);
}

// The field kernel evaluates the device's SIMD width of points per work-item
// (cl/blobtree_field.cl), 8 along x by 2 along y at width 16, and the attributes kernel
// that many vertices, each lane walking its own bins' primitives (cl/blobtree_mesh.cl);
// the same source runs one point or vertex per work-item on GPUs. Every width gives width
// 1's field (binned and naive) and mesh (positions, normals, texture coordinates,
// triangles) bit for bit, on a tree with PCM groups, bends, a scar and a cut.
TEST_F(BlobTreePolygonizer, EverySimdWidthGivesTheSameFieldAndMeshBitForBit) {
  BlobGrid grid;
  BlobModel m = aspen(64, &grid);
  size_t vertices = 0;
  std::vector<uint32_t> triangles;
  auto fields = [&](int width) {
    ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    impl::Runtime at_width(nullptr, nullptr);
    EXPECT_EQ(at_width.simd_width(), width);
    std::vector<float> f = impl::sample_blobtree_field(at_width, m, grid, false);
    std::vector<float> naive = impl::sample_blobtree_field(at_width, m, grid, true);
    f.insert(f.end(), naive.begin(), naive.end());
    BlobMesh mesh = impl::polygonize_blobtree(at_width, m, grid);
    for (const std::vector<float>* a : {&mesh.positions, &mesh.normals, &mesh.uvs})
      f.insert(f.end(), a->begin(), a->end());
    if (width == 1) {
      vertices = mesh.vertex_count();
      triangles = mesh.indices;
    } else {
      EXPECT_EQ(mesh.indices, triangles) << "width " << width;
    }
    return f;
  };
  const std::vector<float> scalar = fields(1);
  // Not vacuous: wood, and a field around it, in the compared grid; a mesh of it.
  EXPECT_GT(vertices, 500u);
  size_t inside = 0, reached = 0;
  for (size_t i = 0; i < size_t(grid.points()); ++i) {
    inside += scalar[i] > 0.5f ? 1 : 0;
    reached += scalar[i] > 0.0f ? 1 : 0;
  }
  EXPECT_GT(inside, 200u);
  EXPECT_GT(reached, 1000u);
  for (int width : {2, 8, 16}) {
    const std::vector<float> wide = fields(width);
    ASSERT_EQ(wide.size(), scalar.size());
    size_t differing = 0;
    for (size_t i = 0; i < wide.size(); ++i)
      differing += std::memcmp(&wide[i], &scalar[i], sizeof(float)) != 0;
    EXPECT_EQ(differing, 0u) << "width " << width;
  }
}

// Stage 5's order: a permutation of the vertices, by bin (x fastest), in vertex order
// within a bin; points beyond the grid (or NaN) go to the nearest edge bin, never out of
// range.
TEST(BlobTreeVertexOrder, VerticesAreSortedByBinStably) {
  BlobGrid grid;
  grid.cell = 0.5;
  grid.nx = 16;
  grid.ny = 8;
  grid.nz = 16;  // bins 2 x 1 x 2, 4 m on a side
  impl::BlobBins bins;
  bins.bx = 2;
  bins.by = 1;
  bins.bz = 2;
  const float nan = std::nanf("");
  const std::vector<float> positions = {5.0f, 1.0f, 5.0f,   // bin 3
                                        1.0f, 1.0f, 1.0f,   // bin 0
                                        5.0f, 1.0f, 1.0f,   // bin 1
                                        1.0f, 1.0f, 5.0f,   // bin 2
                                        3.9f, 0.0f, 0.1f,   // bin 0
                                        99.f, -9.f, 99.f,   // beyond: bin 3
                                        nan,  nan,  nan,    // bin 0
                                        4.0f, 3.9f, 0.0f};  // bin 1 (4 m is the second bin's start)
  const std::vector<int32_t> order = impl::vertices_by_bin(positions, grid, bins);
  EXPECT_EQ(order, (std::vector<int32_t>{1, 4, 6, 2, 7, 3, 0, 5}));
}

TEST_F(BlobTreePolygonizer, FieldMatchesTheDoubleReference) {
  BlobGrid grid;
  BlobModel m = aspen(64, &grid);
  std::vector<float> field = impl::sample_blobtree_field(rt(), m, grid, false);
  double worst = 0.0;
  size_t checked = 0;
  for (int z = 0; z < grid.nz; ++z)
    for (int y = 0; y < grid.ny; ++y)
      for (int x = 0; x < grid.nx; ++x) {
        float f = field[(size_t(z) * grid.ny + y) * grid.nx + x];
        double ref = impl::reference::blob_field(m, grid.point(x, y, z));
        worst = std::max(worst, std::abs(f - ref));
        checked += ref > 0.0 ? 1 : 0;
      }
  EXPECT_GT(checked, 1000u);
  // Float positions a few metres from the origin and float distances: ~1e-6 relative.
  EXPECT_LT(worst, 2e-4);
}

TEST_F(BlobTreePolygonizer, MeshIsTheHostMarchingCubesOfTheSameField) {
  BlobGrid grid;
  BlobModel m = aspen(64, &grid);
  std::vector<float> field = impl::sample_blobtree_field(rt(), m, grid, false);
  std::vector<double> values(field.begin(), field.end());
  impl::GridMesh host =
      impl::marching_cubes(values, grid.nx, grid.ny, grid.nz, grid.origin, grid.cell, 0.5);
  BlobMesh mesh = impl::polygonize_blobtree(rt(), m, grid);
  ASSERT_EQ(mesh.vertex_count(), host.positions.size());
  ASSERT_EQ(mesh.indices, host.indices);
  double worst = 0.0;
  for (size_t i = 0; i < host.positions.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(mesh.positions[3 * i + c] - host.positions[i][c]));
  EXPECT_LT(worst, 1e-5 * (1.0 + glm::length(grid.origin)) + 1e-4 * grid.cell);
}

TEST_F(BlobTreePolygonizer, TreeMeshIsWatertightManifoldWithOutwardNormalsOnTheSurface) {
  BlobGrid grid;
  BlobModel m = aspen(128, &grid);
  std::vector<double> progress;
  impl::PolygonizeOptions options;
  options.progress = [&](double f, const char*) { progress.push_back(f); };
  BlobMesh mesh = impl::polygonize_blobtree(rt(), m, grid, options);
  ASSERT_GT(mesh.triangle_count(), 5000u);
  MeshTopology t = mesh_topology(mesh.indices, int64_t(mesh.vertex_count()));
  EXPECT_TRUE(t.watertight()) << t.boundary_edges << " boundary, " << t.nonmanifold_edges
                              << " non-manifold edges";
  EXPECT_TRUE(t.manifold()) << t.misoriented_edges << " misoriented edges, "
                            << t.nonmanifold_vertices << " non-manifold vertices, "
                            << t.degenerate_triangles << " degenerate";
  EXPECT_EQ(t.unused_vertices, 0);
  EXPECT_EQ(t.euler % 2, 0);
  // One piece: the cut leaves no branch floating, the scar no bubble in the wood.
  EXPECT_EQ(t.components, 1);
  // Progress rises to 1.
  ASSERT_FALSE(progress.empty());
  for (size_t i = 1; i < progress.size(); ++i) EXPECT_GE(progress[i], progress[i - 1]);
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);

  // Normals: unit, outward (the winding's face normal and the gradient agree), and the
  // vertices lie on the reference's surface to a fraction of a cell.
  int agree = 0;
  for (size_t k = 0; k < mesh.triangle_count(); ++k) {
    dvec3 p[3], n(0.0);
    for (int j = 0; j < 3; ++j) {
      uint32_t v = mesh.indices[3 * k + j];
      p[j] = dvec3(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
      n += dvec3(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]);
    }
    agree += glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), n) > 0.0 ? 1 : 0;
  }
  EXPECT_GT(agree, int(0.99 * mesh.triangle_count()));
  std::vector<double> distances;
  for (size_t v = 0; v < mesh.vertex_count(); v += 7) {
    dvec3 p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    dvec3 n(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-4);
    dvec3 g = impl::reference::blob_gradient(m, p, 1e-4 * grid.cell);
    distances.push_back(std::abs(impl::reference::blob_field(m, p) - 0.5) /
                        std::max(glm::length(g), 1e-9));
  }
  // Linear interpolation along a cell's edge finds the surface to a fraction of a cell
  // (thin tubes, whose fall-off bends sharply within a cell, the least well); where the
  // field has a crease (PCM's union, a cut's edge) the first-order distance estimate
  // itself is rough, so the last percent is held to a whole cell.
  std::sort(distances.begin(), distances.end());
  EXPECT_LT(distances[distances.size() * 99 / 100], 0.35 * grid.cell);
  EXPECT_LT(distances.back(), grid.cell);
}

TEST_F(BlobTreePolygonizer, CutLeavesAFlatFaceFacingAlongTheBranch) {
  BlobGrid grid;
  BlobModel m = aspen(128, &grid, 0.45);
  ASSERT_EQ(m.cuts.size(), 1u);
  const impl::BlobCut& cut = m.cuts[0];
  BlobMesh mesh = impl::polygonize_blobtree(rt(), m, grid);
  // Vertices whose gradient normal faces along the cut's normal, away from the rim (where
  // the face rounds into the bark), lie on the cut's plane; the ramp is the branch's radius
  // there.
  int on_face = 0;
  double farthest = 0.0, worst = 0.0;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    dvec3 p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    dvec3 n(mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]);
    if (glm::length(p - cut.point) > 0.75 * cut.ramp || glm::dot(n, cut.normal) < 0.99) continue;
    ++on_face;
    worst = std::max(worst, std::abs(glm::dot(p - cut.point, cut.normal)));
    farthest = std::max(farthest, glm::length(p - cut.point));
  }
  EXPECT_GT(on_face, 6);
  EXPECT_LT(worst, 1e-3 * grid.cell);
  // The face spans the trunk's cross-section there, not a point.
  EXPECT_GT(farthest, 0.5 * cut.ramp);
}

TEST_F(BlobTreePolygonizer, TextureCoordinatesAreTheReferencesBlend) {
  // One straight internode: u goes around it, v along it, as the reference blends them.
  std::vector<impl::BlobInternode> s(1);
  s[0].base = dvec3(0.3, 0.1, -0.2);
  s[0].top = dvec3(0.5, 1.6, 0.1);
  s[0].r_base = 0.2;
  s[0].r_top = 0.15;
  s[0].v_scale = 2.0;
  BlobModel m = impl::blob_model_of(s, {});
  BlobGrid grid = impl::blob_grid(m, 48);
  BlobMesh mesh = impl::polygonize_blobtree(rt(), m, grid);
  ASSERT_GT(mesh.vertex_count(), 100u);
  int checked = 0;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    dvec3 p(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
    glm::dvec2 ref = impl::reference::blob_uv(m, p);
    double du = std::abs(mesh.uvs[2 * v] - ref.x);
    du = std::min(du, 1.0 - du);  // the seam at u = 0 = 1
    EXPECT_LT(du, 2e-5) << "vertex " << v;
    EXPECT_NEAR(mesh.uvs[2 * v + 1], ref.y, 2e-5) << "vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST_F(BlobTreePolygonizer, SameInputsGiveTheSameBytes) {
  BlobGrid grid;
  BlobModel m = aspen(64, &grid);
  BlobMesh a = impl::polygonize_blobtree(rt(), m, grid);
  BlobMesh b = impl::polygonize_blobtree(rt(), m, grid);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(
      0, std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(a.uvs.data(), b.uvs.data(), a.uvs.size() * sizeof(float)));
}

// The kernels work in the grid's frame: a model 100 km out gives the mesh it gives at the
// origin (float world positions there are 8 mm apart, which would merge vertices and
// leave zero-area triangles), moved.
TEST_F(BlobTreePolygonizer, FarFromTheOriginTheMeshIsTheSameMoved) {
  const impl::TreeModel tree = impl::grow_tree(impl::load_species("quaking_aspen"), 1);
  BlobTreeOptions o;
  o.min_radius = 0.05;
  o.min_surface = 0.1;
  const dvec3 far(1e5, 0.0, -1e5);
  BlobModel near_model = impl::build_blobtree(tree, dvec3(0.0), o);
  // Moved in double (the generator itself places trees in float, as the kernels do).
  BlobModel far_model = near_model;
  for (impl::BlobPrimitive& p : far_model.primitives) p.base += far;
  far_model.update_bounds();
  BlobMesh a = impl::polygonize_blobtree(rt(), near_model, impl::blob_grid(near_model, 96));
  BlobMesh b = impl::polygonize_blobtree(rt(), far_model, impl::blob_grid(far_model, 96));
  ASSERT_GT(a.triangle_count(), 1000u);
  EXPECT_EQ(a.indices, b.indices);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  double worst = 0.0;
  for (size_t i = 0; i < a.positions.size(); ++i)
    worst = std::max(worst, std::abs(double(b.positions[i]) - far[i % 3] - a.positions[i]));
  EXPECT_LT(worst, 0.02);  // the float spacing at 1e5 m is 7.8 mm
  EXPECT_EQ(mesh_topology(b.indices, int64_t(b.vertex_count())).degenerate_triangles, 0);
}

// The C API: a world tree's BlobTree, its info and mesh, and refusals that add nothing.
TEST(BlobTreeApi, AddsAWorldTreesMeshAndRefusesBadDefsCleanly) {
  boreas_world world = nullptr;
  boreas_world_def wd = boreas_default_world_def();
  ASSERT_EQ(boreas_world_create(&wd, &world), BOREAS_OK) << boreas_last_error();
  std::unique_ptr<boreas_world_s, void (*)(boreas_world)> guard(world, boreas_world_destroy);
  boreas_tree_def td = boreas_default_tree_def();
  boreas_tree_id tree{};
  ASSERT_EQ(boreas_world_add_tree(world, &td, &tree), BOREAS_OK) << boreas_last_error();

  boreas_blobtree_def def = boreas_default_blobtree_def();
  def.resolution = 64;
  boreas_blobtree_cut bad_cut{100000, 0.5f};
  def.cuts = &bad_cut;
  def.cut_count = 1;
  boreas_blobtree_id blob{};
  EXPECT_EQ(boreas_world_add_blobtree(world, tree, &def, nullptr, nullptr, &blob),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("cuts[0].branch"), std::string::npos)
      << boreas_last_error();
  def.cut_count = 0;
  def.resolution = 5;
  EXPECT_EQ(boreas_world_add_blobtree(world, tree, &def, nullptr, nullptr, &blob),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("resolution"), std::string::npos)
      << boreas_last_error();
  def.resolution = 64;
  def.ridge = std::nanf("");
  EXPECT_EQ(boreas_world_add_blobtree(world, tree, &def, nullptr, nullptr, &blob),
            BOREAS_ERROR_INVALID_ARGUMENT);
  def.ridge = 0.2f;
  boreas_tree_id gone{};
  ASSERT_EQ(boreas_world_add_tree(world, &td, &gone), BOREAS_OK);
  ASSERT_EQ(boreas_world_remove_tree(world, gone), BOREAS_OK);
  EXPECT_EQ(boreas_world_add_blobtree(world, gone, &def, nullptr, nullptr, &blob),
            BOREAS_ERROR_NOT_FOUND);

  int calls = 0;
  auto progress = [](void* user, float, const char*) { ++*static_cast<int*>(user); };
  ASSERT_EQ(boreas_world_add_blobtree(world, tree, &def, progress, &calls, &blob), BOREAS_OK)
      << boreas_last_error();
  EXPECT_GT(calls, 2);
  boreas_blobtree_info info{};
  ASSERT_EQ(boreas_blobtree_get_info(world, blob, &info), BOREAS_OK);
  EXPECT_GT(info.triangles, 100);
  EXPECT_GE(info.branches, 1);
  EXPECT_EQ(std::max({info.grid[0], info.grid[1], info.grid[2]}), 64);
  int nv = 0, ni = 0;
  ASSERT_EQ(boreas_blobtree_get_mesh(world, blob, nullptr, 0, &nv, nullptr, 0, &ni), BOREAS_OK);
  EXPECT_EQ(nv, info.vertices);
  EXPECT_EQ(ni, 3 * info.triangles);
  std::vector<boreas_vertex> vertices(nv);
  std::vector<uint32_t> indices(ni);
  EXPECT_EQ(
      boreas_blobtree_get_mesh(world, blob, vertices.data(), nv - 1, &nv, indices.data(), ni, &ni),
      BOREAS_ERROR_INVALID_ARGUMENT);
  ASSERT_EQ(
      boreas_blobtree_get_mesh(world, blob, vertices.data(), nv, &nv, indices.data(), ni, &ni),
      BOREAS_OK);
  for (const boreas_vertex& v : vertices)
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(v.position[c], info.bounds_min[c]);
      EXPECT_LE(v.position[c], info.bounds_max[c]);
    }
  EXPECT_TRUE(mesh_topology(indices, nv).watertight());
  ASSERT_EQ(boreas_world_remove_blobtree(world, blob), BOREAS_OK);
  EXPECT_EQ(boreas_blobtree_get_info(world, blob, &info), BOREAS_ERROR_NOT_FOUND);
}

}  // namespace
}  // namespace boreas::test
