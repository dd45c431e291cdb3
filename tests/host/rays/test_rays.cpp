// boreas_world_cast_rays: analytic cases first (a straight trunk, a gap between trees, a
// leaf and the notch beside it, a solid box, the ground), then what every hit must satisfy
// (its label names the object whose surface holds the point), the wind moving a blade's hit
// downwind, determinism, the enqueue form, bad input, and a structure that follows adds and
// removes. Embree's agreement over a windy forest is test_rays_embree.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "boreas/boreas_cl.h"
#include "mesh_trees/tube_trees.h"
#include "shared/leaf_outline.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace boreas {
namespace {

using Hits = std::vector<boreas_hit>;

boreas_world_def calm_def() {
  boreas_world_def def = boreas_default_world_def();
  def.wave_count = 0;
  return def;
}

// A species whose tree is one straight, untapered trunk (a prism of `sides` sides about
// its axis): no flare, lobes, curvature, leaves or branches.
std::string write_pole_species(const test::TempDir& dir) {
  const std::string path = (dir.path() / "pole.json").string();
  std::ofstream(path) << R"({"format": "boreas-species-1", "name": "pole", "params": {
    "Levels": 1, "Scale": 10, "ScaleV": 0, "Flare": 0, "Lobes": 0, "Leaves": 0,
    "0Taper": 0, "0Curve": 0, "0CurveV": 0, "0CurveBack": 0, "0SegSplits": 0}})";
  return path;
}

boreas_ray ray(double ox, double oy, double oz, double dx, double dy, double dz,
               float max_distance = std::numeric_limits<float>::infinity()) {
  return {{float(ox), float(oy), float(oz)}, {float(dx), float(dy), float(dz)}, max_distance};
}

double dot3(const float* a, const float* b) {
  return double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2];
}

TEST(Rays, AStraightTrunkIsHitAtItsSurfaceAtThatHeight) {
  test::TempDir dir;
  World world(calm_def());
  boreas_tree_def def = boreas_default_tree_def();
  const std::string species = write_pole_species(dir);
  def.species = species.c_str();
  def.position[0] = 2.0f;
  const TreeId tree = world.add_tree(def);
  const std::vector<boreas_branch> branches = world.tree_get_branches(tree);
  ASSERT_EQ(branches.size(), 1u);
  const boreas_branch& trunk = branches[0];
  // The premise: a vertical axis through (2, y, 0).
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(trunk.control_points[c][0], 2.0f, 1e-5f);
    EXPECT_NEAR(trunk.control_points[c][2], 0.0f, 1e-5f);
  }
  const int sides = def.levels[0].sides;
  // The deformer's frame: S = normalize(L x O), T = S x L with L = +y; a vertex at turn
  // k / sides lies along S sin + T cos, so the middle of face k along the turn (k + 1/2).
  const double l[3] = {0, 1, 0};
  const double* o = nullptr;
  double od[3] = {trunk.orientation[0], trunk.orientation[1], trunk.orientation[2]};
  o = od;
  double s[3] = {l[1] * o[2] - l[2] * o[1], l[2] * o[0] - l[0] * o[2], l[0] * o[1] - l[1] * o[0]};
  const double sn = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (double& x : s) x /= sn;
  const double t[3] = {s[1] * l[2] - s[2] * l[1], s[2] * l[0] - s[0] * l[2], s[0] * l[1] - s[1] * l[0]};
  const double height = trunk.control_points[3][1];
  const double r = trunk.radius, from = 5.0;
  std::vector<boreas_ray> rays;
  std::vector<double> expected;
  for (int k = 0; k < sides; ++k)
    for (double y : {0.1 * height, 0.5 * height, 0.9 * height}) {
      const double a = 2.0 * M_PI * (k + 0.5) / sides;
      const double u[3] = {s[0] * std::sin(a) + t[0] * std::cos(a), 0.0,
                           s[2] * std::sin(a) + t[2] * std::cos(a)};
      rays.push_back(ray(2.0 + from * u[0], y, from * u[2], -u[0], 0.0, -u[2]));
      expected.push_back(from - r * std::cos(M_PI / sides));  // to the face's middle
    }
  const Hits hits = world.cast_rays(rays);
  for (size_t i = 0; i < hits.size(); ++i) {
    EXPECT_EQ(hits[i].kind, BOREAS_HIT_BRANCH) << i;
    EXPECT_EQ(hits[i].part, 0) << i;
    EXPECT_NEAR(hits[i].distance, expected[i], 2e-5 * from) << i;
    // The face's normal points back along the ray.
    EXPECT_NEAR(dot3(hits[i].normal, rays[i].direction), -1.0, 1e-4) << i;
    EXPECT_TRUE(boreas_tree_id_equal(boreas_hit_tree(&hits[i]), tree)) << i;
  }
}

TEST(Rays, ARayBetweenTwoTreesHitsNothing) {
  test::TempDir dir;
  World world(calm_def());
  boreas_tree_def def = boreas_default_tree_def();
  const std::string species = write_pole_species(dir);
  def.species = species.c_str();
  def.position[0] = -1.0f;
  (void)world.add_tree(def);
  def.position[0] = 1.0f;
  (void)world.add_tree(def);
  const Hits hits = world.cast_rays({ray(0, 2, -20, 0, 0, 1), ray(-1, 2, -20, 0, 0, 1)});
  EXPECT_EQ(hits[0].kind, BOREAS_HIT_NONE);
  EXPECT_TRUE(std::isinf(hits[0].distance));
  EXPECT_EQ(hits[0].part, -1);
  EXPECT_TRUE(boreas_object_id_is_null(hits[0].object));
  EXPECT_EQ(hits[1].kind, BOREAS_HIT_BRANCH);  // the ray through the left trunk does hit
  EXPECT_LT(hits[1].distance, 20.0f);
}

// The world point of a leaf's texture coordinates (u, v): the renderer's quad.
void leaf_point(const boreas_leaf& leaf, float u, float v, double out[3]) {
  float along, across;
  boreas_leaf_offsets(u, v, leaf.length, leaf.width, &along, &across);
  const float* a = leaf.axis;
  const float* n = leaf.normal;
  const double side[3] = {double(a[1]) * n[2] - double(a[2]) * n[1],
                          double(a[2]) * n[0] - double(a[0]) * n[2],
                          double(a[0]) * n[1] - double(a[1]) * n[0]};
  for (int k = 0; k < 3; ++k) out[k] = leaf.position[k] + a[k] * double(along) + side[k] * double(across);
}

// A ray down onto a leaf's point (u, v) along its normal, from 1 cm above, 2 cm long.
boreas_ray onto_leaf(const boreas_leaf& leaf, float u, float v) {
  double p[3];
  leaf_point(leaf, u, v, p);
  const float* n = leaf.normal;
  return ray(p[0] + 0.01 * n[0], p[1] + 0.01 * n[1], p[2] + 0.01 * n[2], -n[0], -n[1], -n[2], 0.02f);
}

TEST(Rays, ARayHitsTheLeafItWasAimedAtAndMissesThroughTheNotchBesideIt) {
  World world(calm_def());
  boreas_tree_def def = boreas_default_tree_def();
  def.species = "ca_black_oak";
  const TreeId tree = world.add_tree(def);
  const std::vector<boreas_leaf> leaves = world.tree_get_leaves(tree);
  ASSERT_GT(leaves.size(), 1000u);
  // A sinus of the oak's outline: outside, with the blade on both sides of it along u.
  const int oak = BOREAS_LEAF_OUTLINE_OAK;
  float notch_u = -1.0f, notch_v = -1.0f;
  for (float v = 0.3f; v < 0.9f && notch_u < 0.0f; v += 0.01f)
    for (float u = 0.52f; u < 0.8f; u += 0.005f)
      if (!boreas_leaf_outline_inside(oak, u, v) && boreas_leaf_outline_inside(oak, u - 0.04f, v) &&
          boreas_leaf_outline_inside(oak, 0.5f, v) && boreas_leaf_outline_inside(oak, u + 0.04f, v) == 0 &&
          boreas_leaf_outline_inside(oak, 1.0f - u, v) == 0) {
        notch_u = u, notch_v = v;
        break;
      }
  ASSERT_GE(notch_u, 0.0f) << "no sinus found in the oak's outline";
  const float mid_v = 0.5f * (BOREAS_LEAF_BLADE_BASE_V + BOREAS_LEAF_BLADE_TIP_V);
  // Each ray from 1 cm above the leaf along its normal meets that leaf at 1 cm, unless a
  // twig or another leaf lies nearer (a crown's leaves sit on their twigs): never farther,
  // never another leaf at the same place. Through the notch it meets anything but the leaf.
  int aimed = 0, hit_aimed = 0, notch_hits_leaf = 0;
  for (size_t l = 0; l < leaves.size(); l += leaves.size() / 200) {
    const Hits hits = world.cast_rays({onto_leaf(leaves[l], 0.5f, mid_v), onto_leaf(leaves[l], notch_u, notch_v)});
    ++aimed;
    if (hits[0].kind == BOREAS_HIT_LEAF && hits[0].part == int(l)) {
      ++hit_aimed;
      EXPECT_NEAR(hits[0].distance, 0.01f, 2e-4f) << l;
    } else {
      EXPECT_NE(hits[0].kind, BOREAS_HIT_NONE) << l;
      EXPECT_LT(hits[0].distance, 0.01f - 1e-4f) << l << ": kind " << hits[0].kind;
    }
    if (hits[1].kind == BOREAS_HIT_LEAF && hits[1].part == int(l)) ++notch_hits_leaf;
  }
  EXPECT_GE(hit_aimed, aimed * 9 / 10);
  EXPECT_EQ(notch_hits_leaf, 0);
}

TEST(Rays, ASolidBoxIsHitAtItsFace) {
  World world(calm_def());
  world.wind_add_solid_box({3, 0, -1}, {5, 2, 1});
  const Hits hits = world.cast_rays({ray(0, 1, 0.25, 1, 0, 0), ray(4, 10, 0.5, 0, -2, 0), ray(0, 3, 0, 1, 0, 0)});
  EXPECT_EQ(hits[0].kind, BOREAS_HIT_SOLID_BOX);
  EXPECT_FLOAT_EQ(hits[0].distance, 3.0f);
  EXPECT_EQ(hits[0].part, 0);
  EXPECT_FLOAT_EQ(hits[0].normal[0], -1.0f);
  EXPECT_EQ(hits[1].kind, BOREAS_HIT_SOLID_BOX);
  EXPECT_FLOAT_EQ(hits[1].distance, 8.0f);  // a direction of length 2 is normalized
  EXPECT_FLOAT_EQ(hits[1].normal[1], 1.0f);
  EXPECT_EQ(hits[2].kind, BOREAS_HIT_NONE);  // above it
}

boreas_meadow_def small_meadow(float density) {
  boreas_meadow_def m = boreas_default_meadow_def();
  m.size[0] = m.size[1] = 4.0f;
  m.density = density;
  return m;
}

TEST(Rays, TheGroundIsHitBelowTheGrassAndNamesItsMeadow) {
  World world(calm_def());
  boreas_meadow_def m = small_meadow(50.0f);
  m.terrain_relief = 0.0f;
  m.center[1] = 0.5f;
  const MeadowId meadow = world.add_meadow(m);
  std::vector<boreas_ray> rays;
  for (int i = 0; i < 400; ++i) rays.push_back(ray(-1.9 + 0.0095 * i, 3.0, 0.37, 0.0, -1.0, 0.0));
  const Hits hits = world.cast_rays(rays);
  int ground = 0, grass = 0;
  for (const boreas_hit& h : hits) {
    ASSERT_TRUE(h.kind == BOREAS_HIT_GROUND || h.kind == BOREAS_HIT_UNDERBRUSH) << h.kind;
    EXPECT_TRUE(boreas_meadow_id_equal(boreas_hit_meadow(&h), meadow));
    if (h.kind == BOREAS_HIT_GROUND) {
      ++ground;
      EXPECT_NEAR(h.distance, 2.5f, 1e-5f);
      EXPECT_NEAR(h.normal[1], 1.0f, 1e-6f);
    } else {
      ++grass;
      EXPECT_LT(h.distance, 2.5f);
    }
  }
  // Blades stand nearly upright: from above, most rays pass between them to the ground.
  EXPECT_GT(ground, 300);
}

TEST(Rays, SteadyWindMovesTheBladesHitsDownwind) {
  // Horizontal rays across a meadow, perpendicular to a steady wind along +x: the hits on
  // each component, measured from its base, move downwind once the wind has bent it.
  boreas_world_def def = calm_def();
  World world(def);
  const MeadowId meadow = world.add_meadow(small_meadow(40.0f));
  auto mean_offset = [&]() {
    const std::vector<boreas_component> comps = world.meadow_get_components(meadow);
    std::vector<boreas_ray> rays;
    for (int i = 0; i < 400; ++i)
      for (float y : {0.004f, 0.008f, 0.012f, 0.016f})
        rays.push_back(ray(-1.9 + 0.0095 * i, y, -3.0, 0.0, 0.0, 1.0, 6.0f));
    const Hits hits = world.cast_rays(rays);
    double sum = 0.0;
    int n = 0;
    for (const boreas_hit& h : hits)
      if (h.kind == BOREAS_HIT_UNDERBRUSH) {
        sum += h.point[0] - comps[size_t(h.part)].base[0];
        ++n;
      }
    EXPECT_GT(n, 50);
    return sum / n;
  };
  const double rest = mean_offset();
  boreas_wave steady = boreas_default_wave();
  steady.direction[0] = 1.0f;
  steady.direction[1] = 0.0f;
  steady.amplitude = 8.0f;
  steady.sharpness = 0.0f;
  world.wind_set_waves({steady});
  for (int i = 0; i < 60; ++i) world.step(1.0f / 30.0f);
  const double windy = mean_offset();
  EXPECT_NEAR(rest, 0.0, 0.01);
  EXPECT_GT(windy, rest + 0.01);
}

// A world of every kind of surface a ray can hit: a tree, a meadow, a solid box, an
// imported tree (tubes with quad leaves) and a BlobTree (of a small tree added for it and
// removed), the last two inside the ring the rays start from.
struct Mixed {
  test::TempDir dir;
  World world{calm_def()};
  TreeId tree{};
  MeadowId meadow{};
  boreas_mesh_tree_id mesh_tree{};
  boreas_blobtree_id blobtree{};
  Mixed() {
    boreas_wave w = boreas_default_wave();
    world.wind_set_waves({w});
    boreas_tree_def def = boreas_default_tree_def();
    tree = world.add_tree(def);
    meadow = world.add_meadow(small_meadow(100.0f));
    world.wind_add_solid_box({6, 0, -2}, {7, 3, 2});
    const std::string model = test::write_tube_tree_obj(dir.path());
    boreas_mesh_tree_def m = boreas_default_mesh_tree_def();
    m.model = model.c_str();
    m.position[0] = -5.0f;
    m.cache = 0;
    mesh_tree = world.add_mesh_tree(m);
    boreas_tree_def small = boreas_default_tree_def();
    small.scale = 0.4f;
    small.position[2] = 5.5f;
    const TreeId for_blob = world.add_tree(small);
    boreas_blobtree_def b = boreas_default_blobtree_def();
    b.resolution = 64;
    blobtree = world.add_blobtree(for_blob, b);
    world.remove_tree(for_blob);
    for (int i = 0; i < 5; ++i) world.step(1.0f / 30.0f);
  }
  // Rays from a ring around the tree toward points of its crown and the ground.
  std::vector<boreas_ray> rays(int n) const {
    std::vector<boreas_ray> out;
    for (int i = 0; i < n; ++i) {
      const double a = 2.399963 * i, h = 0.2 + 14.0 * ((i * 7919) % 1000) / 1000.0;
      out.push_back(ray(9.0 * std::cos(a), h, 9.0 * std::sin(a), -std::cos(a) + 0.1 * std::sin(3.0 * i),
                        -0.3 * ((i % 7) / 7.0), -std::sin(a)));
    }
    return out;
  }
};

// A mesh's vertices and triangles.
struct Triangles {
  std::vector<boreas_vertex> positions;
  std::vector<uint32_t> indices;
};

// The distance (m) from p to the triangle (a, b, c), in double (Ericson, "Real-Time
// Collision Detection", the closest point on a triangle by its Voronoi regions).
double triangle_distance(const float p[3], const float a[3], const float b[3], const float c[3]) {
  double ab[3], ac[3], ap[3];
  for (int k = 0; k < 3; ++k) {
    ab[k] = double(b[k]) - a[k];
    ac[k] = double(c[k]) - a[k];
    ap[k] = double(p[k]) - a[k];
  }
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  auto at = [&](double v, double w) {  // the distance to a + v ab + w ac
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double q = a[k] + v * ab[k] + w * ac[k] - p[k];
      d2 += q * q;
    }
    return std::sqrt(d2);
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return at(0.0, 0.0);
  double bp[3], cp[3];
  for (int k = 0; k < 3; ++k) {
    bp[k] = double(p[k]) - b[k];
    cp[k] = double(p[k]) - c[k];
  }
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return at(1.0, 0.0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return at(d1 / (d1 - d3), 0.0);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return at(0.0, 1.0);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return at(0.0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1.0 - w, w);
  }
  const double denom = 1.0 / (va + vb + vc);
  return at(vb * denom, vc * denom);
}

TEST(Rays, EveryHitsLabelNamesTheObjectWhoseSurfaceHoldsThePoint) {
  Mixed m;
  const std::vector<boreas_leaf> leaves = m.world.tree_get_leaves(m.tree);
  const std::vector<boreas_branch> branches = m.world.tree_get_branches(m.tree);
  const World::Strips strips = m.world.meadow_get_vertices(m.meadow);
  const Triangles trunk{m.world.mesh_tree_get_vertices(m.mesh_tree, BOREAS_MESH_TRUNK),
                        m.world.mesh_tree_get_indices(m.mesh_tree, BOREAS_MESH_TRUNK)};
  const Triangles crown{m.world.mesh_tree_get_vertices(m.mesh_tree, BOREAS_MESH_LEAVES),
                        m.world.mesh_tree_get_indices(m.mesh_tree, BOREAS_MESH_LEAVES)};
  const World::Mesh blob_mesh = m.world.blobtree_get_mesh(m.blobtree);
  const Triangles blob{blob_mesh.vertices, blob_mesh.indices};
  // The ring's rays, then rays from 2 m off at the middles of the other kinds' triangles.
  std::vector<boreas_ray> rays = m.rays(3000);
  auto aim = [&](const float* a, const float* b, const float* c, int i) {
    const double off[3] = {std::sin(1.3 * i), 1.0 + 0.5 * std::cos(0.7 * i), std::cos(1.3 * i)};
    double p[3];
    for (int k = 0; k < 3; ++k) p[k] = (double(a[k]) + b[k] + c[k]) / 3.0;
    rays.push_back(ray(p[0] + 2.0 * off[0], p[1] + 2.0 * off[1], p[2] + 2.0 * off[2], -off[0],
                       -off[1], -off[2]));
  };
  for (const Triangles* t : {&trunk, &crown, &blob}) {
    const size_t n = t->indices.size() / 3;
    for (size_t j = 0; j < 300 && n > 0; ++j) {
      const uint32_t* tri = &t->indices[3 * (j * 7919 % n)];
      aim(t->positions[tri[0]].position, t->positions[tri[1]].position,
          t->positions[tri[2]].position, int(rays.size()));
    }
  }
  for (size_t c = 0; c < strips.counts.size() && c < 300; ++c) {
    const boreas_meadow_vertex* v = &strips.vertices[c * BOREAS_MEADOW_VERTEX_STRIDE];
    aim(v[0].position, v[1].position, v[2].position, int(rays.size()));
  }
  const Hits hits = m.world.cast_rays(rays);
  int kinds[9] = {};
  for (size_t i = 0; i < hits.size(); ++i) {
    const boreas_hit& h = hits[i];
    ++kinds[h.kind];
    // The point is on the ray at the distance.
    const float len = std::sqrt(float(dot3(rays[i].direction, rays[i].direction)));
    if (h.kind != BOREAS_HIT_NONE)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(h.point[k], rays[i].origin[k] + rays[i].direction[k] / len * h.distance, 1e-4f);
    if (h.kind == BOREAS_HIT_LEAF) {
      ASSERT_TRUE(boreas_tree_id_equal(boreas_hit_tree(&h), m.tree));
      const boreas_leaf& leaf = leaves[size_t(h.part)];
      const float rel[3] = {h.point[0] - leaf.position[0], h.point[1] - leaf.position[1],
                            h.point[2] - leaf.position[2]};
      EXPECT_NEAR(dot3(rel, leaf.normal), 0.0, 2e-4) << i;  // in the leaf's plane
      EXPECT_LT(std::sqrt(dot3(rel, rel)), 2.0 * (leaf.length + leaf.width)) << i;
    } else if (h.kind == BOREAS_HIT_BRANCH) {
      ASSERT_TRUE(boreas_tree_id_equal(boreas_hit_tree(&h), m.tree));
      // Within its radius (and the deformer's bounds) of its curve's control polygon hull.
      const boreas_branch& b = branches[size_t(h.part)];
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        lo[k] = hi[k] = b.control_points[0][k];
        for (int c = 1; c < 4; ++c) {
          lo[k] = std::min(lo[k], double(b.control_points[c][k]));
          hi[k] = std::max(hi[k], double(b.control_points[c][k]));
        }
        const double pad = 3.0 * b.radius + 1e-4;
        EXPECT_GE(h.point[k], lo[k] - pad) << i;
        EXPECT_LE(h.point[k], hi[k] + pad) << i;
      }
    } else if (h.kind == BOREAS_HIT_UNDERBRUSH) {
      // On the named component's own strip (full detail), not a neighbour's.
      ASSERT_TRUE(boreas_meadow_id_equal(boreas_hit_meadow(&h), m.meadow));
      ASSERT_LT(size_t(h.part), strips.counts.size());
      const boreas_meadow_vertex* v = &strips.vertices[size_t(h.part) * BOREAS_MEADOW_VERTEX_STRIDE];
      double nearest = INFINITY;
      for (int k = 0; k + 2 < strips.counts[size_t(h.part)]; ++k)
        nearest = std::min(nearest, triangle_distance(h.point, v[k].position, v[k + 1].position,
                                                      v[k + 2].position));
      EXPECT_LT(nearest, 1e-4) << i << ": component " << h.part;
    } else if (h.kind == BOREAS_HIT_MESH_TRUNK || h.kind == BOREAS_HIT_MESH_LEAF ||
               h.kind == BOREAS_HIT_BLOBTREE) {
      // On the named triangle of the imported tree's part or of the BlobTree's mesh.
      const Triangles& t = h.kind == BOREAS_HIT_MESH_TRUNK ? trunk
                           : h.kind == BOREAS_HIT_MESH_LEAF ? crown
                                                            : blob;
      if (h.kind == BOREAS_HIT_BLOBTREE)
        ASSERT_TRUE(boreas_blobtree_id_equal(boreas_hit_blobtree(&h), m.blobtree));
      else
        ASSERT_TRUE(boreas_mesh_tree_id_equal(boreas_hit_mesh_tree(&h), m.mesh_tree));
      ASSERT_LT(3 * size_t(h.part) + 2, t.indices.size()) << i;
      const uint32_t* tri = &t.indices[3 * size_t(h.part)];
      EXPECT_LT(triangle_distance(h.point, t.positions[tri[0]].position,
                                  t.positions[tri[1]].position, t.positions[tri[2]].position),
                1e-4)
          << i << ": kind " << h.kind << " triangle " << h.part;
    } else if (h.kind == BOREAS_HIT_SOLID_BOX) {
      EXPECT_TRUE(boreas_object_id_is_null(h.object));
      EXPECT_EQ(h.part, 0);
      // On a face of the box [6, 7] x [0, 3] x [-2, 2].
      const float lo[3] = {6, 0, -2}, hi[3] = {7, 3, 2};
      float off = 1e9f;
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(h.point[k], lo[k] - 1e-4f);
        EXPECT_LE(h.point[k], hi[k] + 1e-4f);
        off = std::min(off, std::min(std::fabs(h.point[k] - lo[k]), std::fabs(h.point[k] - hi[k])));
      }
      EXPECT_LT(off, 1e-4f) << i;
    } else if (h.kind == BOREAS_HIT_GROUND) {
      EXPECT_TRUE(boreas_meadow_id_equal(boreas_hit_meadow(&h), m.meadow));
    }
  }
  EXPECT_GT(kinds[BOREAS_HIT_LEAF], 100);
  EXPECT_GT(kinds[BOREAS_HIT_BRANCH], 10);
  for (int k : {BOREAS_HIT_UNDERBRUSH, BOREAS_HIT_MESH_TRUNK, BOREAS_HIT_MESH_LEAF,
                BOREAS_HIT_BLOBTREE, BOREAS_HIT_GROUND, BOREAS_HIT_SOLID_BOX})
    EXPECT_GT(kinds[k], 5) << "kind " << k;
}

TEST(Rays, RaysCastTwiceInOneStateGiveTheSameBits) {
  Mixed m;
  const std::vector<boreas_ray> rays = m.rays(2000);
  const Hits a = m.world.cast_rays(rays), b = m.world.cast_rays(rays);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(boreas_hit)), 0);
  // And a world built the same way casts the same bits (but the ids, which name their world).
  Mixed other;
  Hits c = other.world.cast_rays(rays);
  for (size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i].object.tag == 0, a[i].object.tag == 0) << i;
    c[i].object = a[i].object;
  }
  EXPECT_EQ(std::memcmp(a.data(), c.data(), a.size() * sizeof(boreas_hit)), 0);
}

TEST(Rays, TheEnqueueFormCastsWhatTheHostFormCasts) {
  Mixed m;
  const std::vector<boreas_ray> rays = m.rays(1500);
  const Hits expected = m.world.cast_rays(rays);
  boreas_cl_objects cl{};
  ASSERT_EQ(boreas_world_get_cl(m.world.handle(), &cl), BOREAS_OK);
  cl_int err = CL_SUCCESS;
  const size_t first = 7;
  cl_mem in = clCreateBuffer(cl.context, CL_MEM_READ_ONLY, (first + rays.size()) * sizeof(boreas_ray), nullptr, &err);
  ASSERT_EQ(err, CL_SUCCESS);
  cl_mem out = clCreateBuffer(cl.context, CL_MEM_READ_WRITE, (first + rays.size()) * sizeof(boreas_hit), nullptr, &err);
  ASSERT_EQ(err, CL_SUCCESS);
  ASSERT_EQ(clEnqueueWriteBuffer(cl.queue, in, CL_TRUE, first * sizeof(boreas_ray), rays.size() * sizeof(boreas_ray),
                                 rays.data(), 0, nullptr, nullptr), CL_SUCCESS);
  ASSERT_EQ(boreas_world_enqueue_cast_rays(m.world.handle(), in, first, int(rays.size()), out, first), BOREAS_OK)
      << boreas_last_error();
  Hits got(rays.size());
  ASSERT_EQ(clEnqueueReadBuffer(cl.queue, out, CL_TRUE, first * sizeof(boreas_hit), got.size() * sizeof(boreas_hit),
                                got.data(), 0, nullptr, nullptr), CL_SUCCESS);
  EXPECT_EQ(std::memcmp(got.data(), expected.data(), got.size() * sizeof(boreas_hit)), 0);
  // A bad ray in the buffer is refused naming it, and nothing is written.
  boreas_ray bad = rays[0];
  bad.direction[0] = bad.direction[1] = bad.direction[2] = 0.0f;
  ASSERT_EQ(clEnqueueWriteBuffer(cl.queue, in, CL_TRUE, (first + 1234) * sizeof(boreas_ray), sizeof bad, &bad, 0,
                                 nullptr, nullptr), CL_SUCCESS);
  const std::vector<char> zeros(got.size() * sizeof(boreas_hit), 0);
  ASSERT_EQ(clEnqueueWriteBuffer(cl.queue, out, CL_TRUE, first * sizeof(boreas_hit), zeros.size(), zeros.data(), 0,
                                 nullptr, nullptr), CL_SUCCESS);
  EXPECT_EQ(boreas_world_enqueue_cast_rays(m.world.handle(), in, first, int(rays.size()), out, first),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("rays[1234].direction must not be zero"), std::string::npos)
      << boreas_last_error();
  ASSERT_EQ(clEnqueueReadBuffer(cl.queue, out, CL_TRUE, first * sizeof(boreas_hit), got.size() * sizeof(boreas_hit),
                                got.data(), 0, nullptr, nullptr), CL_SUCCESS);
  EXPECT_EQ(std::memcmp(got.data(), zeros.data(), zeros.size()), 0);
  // A buffer too small for count rays is refused naming the sizes.
  EXPECT_EQ(boreas_world_enqueue_cast_rays(m.world.handle(), in, first + 1, int(rays.size()), out, first),
            BOREAS_ERROR_INVALID_ARGUMENT);
  clReleaseMemObject(in);
  clReleaseMemObject(out);
}

TEST(Rays, BadRaysAreRefusedNamingTheRayAndNothingIsWritten) {
  Mixed m;
  std::vector<boreas_ray> rays = m.rays(10);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  struct Case {
    int index;
    void (*spoil)(boreas_ray&, float, float);
    const char* says;
  };
  const Case cases[] = {
      {3, [](boreas_ray& r, float n, float) { r.origin[1] = n; }, "rays[3].origin[1] must be finite"},
      {0, [](boreas_ray& r, float, float i) { r.direction[2] = i; }, "rays[0].direction[2] must be finite"},
      {9, [](boreas_ray& r, float, float) { r.direction[0] = r.direction[1] = r.direction[2] = 0.0f; },
       "rays[9].direction must not be zero"},
      {5, [](boreas_ray& r, float, float) { r.max_distance = -1.0f; }, "rays[5].max_distance must be >= 0"},
      {6, [](boreas_ray& r, float n, float) { r.max_distance = n; }, "rays[6].max_distance must be >= 0"},
  };
  for (const Case& c : cases) {
    std::vector<boreas_ray> spoiled = rays;
    c.spoil(spoiled[size_t(c.index)], nan, inf);
    Hits hits(rays.size());
    std::memset(hits.data(), 0x5a, hits.size() * sizeof(boreas_hit));
    const Hits before = hits;
    EXPECT_EQ(boreas_world_cast_rays(m.world.handle(), spoiled.data(), int(spoiled.size()), hits.data()),
              BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(boreas_last_error()).find(c.says), std::string::npos) << boreas_last_error();
    EXPECT_EQ(std::memcmp(hits.data(), before.data(), hits.size() * sizeof(boreas_hit)), 0) << c.says;
  }
  Hits hits(1);
  EXPECT_EQ(boreas_world_cast_rays(m.world.handle(), rays.data(), -1, hits.data()), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("count must be >= 0"), std::string::npos);
  EXPECT_EQ(boreas_world_cast_rays(m.world.handle(), nullptr, 2, hits.data()), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("rays is NULL"), std::string::npos);
  EXPECT_EQ(boreas_world_cast_rays(m.world.handle(), rays.data(), 1, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_world_cast_rays(m.world.handle(), nullptr, 0, nullptr), BOREAS_OK);  // nothing to do
  // An unbounded ray and a zero-length one are fine.
  std::vector<boreas_ray> edge = {rays[0], rays[1]};
  edge[0].max_distance = inf;
  edge[1].max_distance = 0.0f;
  const Hits e = m.world.cast_rays(edge);
  EXPECT_EQ(e[1].kind, BOREAS_HIT_NONE);
}

TEST(Rays, TheStructureFollowsTreesAddedAndRemovedAndEveryStep) {
  test::TempDir dir;
  World world(calm_def());
  const boreas_ray r = ray(3, 2, -10, 0, 0, 1);
  EXPECT_EQ(world.cast_rays({r})[0].kind, BOREAS_HIT_NONE);
  boreas_tree_def def = boreas_default_tree_def();
  const std::string species = write_pole_species(dir);
  def.species = species.c_str();
  def.position[0] = 3.0f;
  const TreeId tree = world.add_tree(def);
  const boreas_hit hit = world.cast_rays({r})[0];
  EXPECT_EQ(hit.kind, BOREAS_HIT_BRANCH);
  EXPECT_TRUE(boreas_tree_id_equal(boreas_hit_tree(&hit), tree));
  // A steady wind bends the pole: the same ray meets it elsewhere after steps.
  boreas_wave steady = boreas_default_wave();
  steady.direction[0] = 0.0f;
  steady.direction[1] = 1.0f;
  steady.amplitude = 20.0f;
  steady.sharpness = 0.0f;
  world.wind_set_waves({steady});
  const boreas_ray high = ray(3, 9, -10, 0, 0, 1);
  const float before = world.cast_rays({high})[0].distance;
  for (int i = 0; i < 30; ++i) world.step(1.0f / 30.0f);
  const boreas_hit bent = world.cast_rays({high})[0];
  // The wind blows along +z, as the ray goes: the pole's near face moves away from it.
  EXPECT_EQ(bent.kind, BOREAS_HIT_BRANCH);
  EXPECT_GT(bent.distance, before + 1e-4f);
  world.remove_tree(tree);
  EXPECT_EQ(world.cast_rays({r})[0].kind, BOREAS_HIT_NONE);
}

TEST(Rays, ABlobTreesSurfaceIsHitAndNamed) {
  World world(calm_def());
  boreas_tree_def def = boreas_default_tree_def();
  def.position[0] = 30.0f;  // the tree itself stands elsewhere: the BlobTree is built where
  const TreeId tree = world.add_tree(def);
  boreas_blobtree_def bdef = boreas_default_blobtree_def();
  bdef.resolution = 48;
  bdef.max_level = 1;
  boreas_blobtree_id blob{};
  ASSERT_EQ(boreas_world_add_blobtree(world.handle(), tree, &bdef, nullptr, nullptr, &blob), BOREAS_OK)
      << boreas_last_error();
  // The tree is removed: what stands is the BlobTree alone (its mesh stays in the world).
  world.remove_tree(tree);
  boreas_blobtree_info info{};
  ASSERT_EQ(boreas_blobtree_get_info(world.handle(), blob, &info), BOREAS_OK);
  const float cx = 0.5f * (info.bounds_min[0] + info.bounds_max[0]);
  const float cz = 0.5f * (info.bounds_min[2] + info.bounds_max[2]);
  const float y = info.bounds_min[1] + 0.5f;  // through the trunk near its base
  const Hits hits = world.cast_rays({ray(cx - 5.0f, y, cz, 1, 0, 0), ray(cx + 5.0f, y, cz, -1, 0, 0)});
  for (const boreas_hit& h : hits) {
    ASSERT_EQ(h.kind, BOREAS_HIT_BLOBTREE);
    EXPECT_TRUE(boreas_blobtree_id_equal(boreas_hit_blobtree(&h), blob));
    EXPECT_GE(h.part, 0);
    EXPECT_LT(h.part, info.triangles);
    // Inside the mesh's box, short of the trunk's axis.
    EXPECT_GT(h.point[0], info.bounds_min[0] - 1e-4f);
    EXPECT_LT(h.point[0], info.bounds_max[0] + 1e-4f);
    EXPECT_LT(h.distance, 5.0f);
  }
  // The two sides of the trunk: the hits are apart by about its diameter.
  EXPECT_GT(hits[1].point[0] - hits[0].point[0], 0.05f);
}

TEST(Rays, AWorldNobodyCastsIntoPaysNothingAndCastingChangesNoState) {
  auto memory = [](const World& w) {
    boreas_memory_info m{};
    EXPECT_EQ(boreas_world_get_memory(w.handle(), &m), BOREAS_OK);
    return m.device_bytes;
  };
  Mixed quiet, cast;
  EXPECT_EQ(memory(quiet.world), memory(cast.world));
  EXPECT_EQ(quiet.world.get_state_hash(), cast.world.get_state_hash());
  (void)cast.world.cast_rays(cast.rays(100));
  EXPECT_GT(memory(cast.world), memory(quiet.world));  // the structure exists once cast into
  for (World* w : {&quiet.world, &cast.world})
    for (int i = 0; i < 3; ++i) w->step(1.0f / 30.0f);
  (void)cast.world.cast_rays(cast.rays(100));
  EXPECT_EQ(quiet.world.get_state_hash(), cast.world.get_state_hash());
}

}  // namespace
}  // namespace boreas
