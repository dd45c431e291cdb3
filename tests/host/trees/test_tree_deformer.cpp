// boreas tests: the branch deformer (cl/tree_deform.cl through TreeBatch::mesh, and the
// C++ compile of cl/shared/tree_math.h) against the double-precision swept surface of
// host/src/reference/tree_reference.h: radii, positions, normals, winding and counts.
//
// Trees are built by hand, in a World whose grid nothing forces (its wind is the sine sum
// alone), so these tests depend on the kernels only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#define BOREAS_FAST_MATH 1
#include "reference/tree_reference.h"
#include "shared/tree_math.h"
#include "support/test_support.h"
#include "host/trees/hand_built_trees.h"
#include "trees/tree_batch.h"

namespace boreas::test {
namespace {

namespace ref = impl::reference;
using glm::dvec3;
using impl::BranchModel;
using impl::TreeInstance;
using impl::TreeModel;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// ---- Hand-built trees (hand_built_trees.h) ---------------------------------------------

// Every radius function switched on: flare on the trunk, bulges (Arbaro's beads, their
// creased waists off the mesh's rings), lobes fading along.
void shape_radius(BranchModel& b, double flare, double bulges, double lobes) {
  b.flare = flare;
  b.bulge_count = bulges;
  b.bulge_depth = bulges > 0.0 ? 0.06 : 0.0;
  b.bulge_phase = 0.3;
  b.lobe_count = lobes;
  b.lobe_depth = lobes > 0.0 ? 0.12 : 0.0;
  b.lobe_taper = 0.6;
}

TreeModel tree_model(double bend) {
  TreeModel m;
  m.species = "hand";
  BranchModel trunk = hand_branch(0, -1, 6.0, 0.25, bend * 0.3, 0.4, 0.0, 0.0, 0.0, 0.85, 1.5);
  shape_radius(trunk, 0.6, 3.0, 5.0);
  m.branches.push_back(trunk);
  BranchModel a = hand_branch(1, 0, 2.5, 0.07, bend, 1.0, 0.5, 0.7, 1.0, 0.85, 1.5);
  shape_radius(a, 0.0, 2.0, 3.0);
  m.branches.push_back(a);
  BranchModel b = hand_branch(1, 0, 2.0, 0.06, -bend, -0.5, 0.75, 3.6, 0.8, 0.85, 1.5);
  shape_radius(b, 0.0, 0.0, 4.0);
  m.branches.push_back(b);
  BranchModel c = hand_branch(2, 1, 0.9, 0.02, bend, 0.3, 0.6, 2.0, 0.9, 0.85, 1.5);
  shape_radius(c, 0.0, 1.0, 0.0);
  m.branches.push_back(c);
  BranchModel d = hand_branch(3, 3, 0.4, 0.008, bend, 0.3, 0.7, 5.0, 0.7, 0.85, 1.5);
  m.branches.push_back(d);
  finish_levels(m);
  return m;
}

std::shared_ptr<TreeInstance> instance(TreeModel model) {
  auto t = std::make_shared<TreeInstance>();
  t->key = 1;
  t->model = std::make_shared<const TreeModel>(std::move(model));
  t->params.species = t->model->species;
  t->params.position = {2.0, 0.5, -3.0};
  t->params.mode = BOREAS_TREE_EXACT;
  const int rings[4] = {10, 7, 4, 3}, sides[4] = {12, 9, 5, 4};
  for (int l = 0; l < 4; ++l) {
    t->params.levels[l].rings = rings[l];
    t->params.levels[l].sides = sides[l];
  }
  return t;
}

std::unique_ptr<impl::World> calm_world(float gust_amplitude) {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = -20.0f;
  def.grid.origin[2] = -20.0f;
  def.grid.cell_size = 10.0f;
  def.grid.resolution[0] = 4;
  def.grid.resolution[1] = 2;
  def.grid.resolution[2] = 4;
  boreas_wave w[2] = {boreas_default_wave(), boreas_default_wave()};
  w[0].amplitude = gust_amplitude;
  w[0].direction[1] = 0.4f;
  w[1].amplitude = 0.5f * gust_amplitude;
  w[1].direction[0] = -0.3f;
  w[1].direction[1] = 1.0f;
  w[1].wavelength = 6.0f;
  def.waves = gust_amplitude > 0.0f ? w : nullptr;
  def.wave_count = gust_amplitude > 0.0f ? 2 : 0;
  return std::make_unique<impl::World>(def);
}

// ---- The mesh and where each vertex came from ---------------------------------------------

dvec3 d3(const float* v) { return dvec3(v[0], v[1], v[2]); }

struct Mesh {
  std::vector<boreas_vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<int> branch_of;  // per vertex
  std::vector<ref::Branch> state;
};

Mesh mesh_of(impl::World& world, const TreeInstance& tree) {
  impl::TreeBatch& batch = world.tree_batch(tree.params.mode);
  Mesh m;
  // Relative to the tree's base, as its state is kept (cl/shared/tree_origin.h): the
  // geometry without the float rounding of world positions 2-4 m out.
  const impl::TreeBatch::Origin base = tree.params.position;
  batch.mesh(tree.key, &m.vertices, &m.indices, base);
  for (const boreas_branch& b : batch.branches(tree.key, base)) {
    ref::Branch r;
    for (int k = 0; k < 4; ++k) r.curve.p[k] = d3(b.control_points[k]);
    r.o = d3(b.orientation);
    m.state.push_back(r);
  }
  for (size_t b = 0; b < tree.model->branches.size(); ++b) {
    const impl::TreeLevelParams& lp = tree.params.levels[tree.model->branches[b].level];
    m.branch_of.insert(m.branch_of.end(), size_t(lp.rings + 1) * (lp.sides + 1), static_cast<int>(b));
  }
  return m;
}

double angle(const dvec3& a, const dvec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

// The reference surface's normal by central differences (one-sided at v = 0 and 1).
// Whether v is within 1/50 of a radius of a bead's waist (boreas_beads), a crease: the
// surface has no normal there, and finite differences across it mean nothing.
bool near_waist(const ref::BranchRadius& r, double v) {
  const double x = 2.0 * (r.bulge_count * (1.0 - v) + r.bulge_phase);
  return r.bulge_depth > 0.0 && x > 0.98 && std::fabs(x - 2.0 * std::floor(0.5 * x + 0.5)) < 0.02;
}

dvec3 finite_difference_normal(const ref::Branch& b, const ref::BranchRadius& r, double v, double theta) {
  const double h = 1e-6;
  double v0 = std::max(v - h, 0.0), v1 = std::min(v + h, 1.0);
  dvec3 x_v = (ref::surface_position(b, r, v1, theta) - ref::surface_position(b, r, v0, theta)) / (v1 - v0);
  dvec3 x_t = (ref::surface_position(b, r, v, theta + h) - ref::surface_position(b, r, v, theta - h)) / (2.0 * h);
  return glm::normalize(glm::cross(x_t, x_v));
}

// ---- Counts ----------------------------------------------------------------------------------

TEST(TreeDeformer, VertexAndIndexCountsFollowTheLevels) {
  auto world = calm_world(0.0f);
  auto tree = instance(tree_model(0.3));
  world->tree_batch(tree->params.mode).add(tree);
  Mesh m = mesh_of(*world, *tree);
  size_t vertices = 0, indices = 0;
  for (const BranchModel& b : tree->model->branches) {
    const impl::TreeLevelParams& lp = tree->params.levels[b.level];
    vertices += size_t(lp.rings + 1) * (lp.sides + 1);
    indices += size_t(lp.rings) * lp.sides * 6;
  }
  EXPECT_EQ(m.vertices.size(), vertices);
  EXPECT_EQ(m.indices.size(), indices);
  EXPECT_EQ(m.branch_of.size(), vertices);
  // Every triangle within one branch's grid; every vertex used.
  std::vector<int> used(m.vertices.size(), 0);
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    ASSERT_LT(m.indices[i], m.vertices.size());
    ASSERT_LT(m.indices[i + 1], m.vertices.size());
    ASSERT_LT(m.indices[i + 2], m.vertices.size());
    EXPECT_EQ(m.branch_of[m.indices[i]], m.branch_of[m.indices[i + 1]]);
    EXPECT_EQ(m.branch_of[m.indices[i]], m.branch_of[m.indices[i + 2]]);
    for (int k = 0; k < 3; ++k) used[m.indices[i + k]] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  // The uv of each vertex is its grid position: u = side / sides, v = ring / rings.
  size_t k = 0;
  for (const BranchModel& b : tree->model->branches) {
    const impl::TreeLevelParams& lp = tree->params.levels[b.level];
    for (int ring = 0; ring <= lp.rings; ++ring)
      for (int side = 0; side <= lp.sides; ++side, ++k) {
        EXPECT_FLOAT_EQ(m.vertices[k].uv[0], float(side) / float(lp.sides));
        EXPECT_FLOAT_EQ(m.vertices[k].uv[1], float(ring) / float(lp.rings));
      }
  }
}

// ---- Straight branches: the radius functions ---------------------------------------------------

TEST(TreeDeformer, StraightBranchRadiusIsTheProductOfTheRadiusFunctions) {
  auto world = calm_world(0.0f);
  auto tree = instance(tree_model(0.0));
  world->tree_batch(tree->params.mode).add(tree);
  world->step(1.0f / 30.0f);  // calm: stays straight
  Mesh m = mesh_of(*world, *tree);
  double worst = 0.0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const boreas_vertex& vx = m.vertices[i];
    const int b = m.branch_of[i];
    const ref::Branch& br = m.state[b];
    dvec3 axis = glm::normalize(br.curve.p[3] - br.curve.p[0]);
    // Collinear control points: the frame's handles are one orthonormal pair all along
    // (to float's rounding of the points: a few units of 2^-24 of their size, over the
    // segment's length).
    const dvec3 segment = br.curve.p[2] - br.curve.p[1];
    const double rounding = 4.0 * 0x1p-24 *
                            (glm::length(br.curve.p[1]) + glm::length(br.curve.p[2])) / glm::length(segment);
    ASSERT_LT(glm::length(glm::cross(glm::normalize(segment), axis)), std::max(1e-6, rounding));
    const double v = vx.uv[1], theta = 2.0 * kPi * vx.uv[0];
    dvec3 rel = d3(vx.position) - br.curve.p[0];
    double along = glm::dot(rel, axis);
    double dist = glm::length(rel - along * axis);
    double want = ref::branch_radius(ref::BranchRadius::of(tree->model->branches[b]), v, theta);
    worst = std::max(worst, std::abs(dist - want) / want);
    ASSERT_NEAR(dist, want, 1e-4 * want + 1e-6) << "vertex " << i << " branch " << b << " v " << v << " turns "
                                                << vx.uv[0];
    // And at the curve's point for v along the axis.
    double want_along = glm::dot(ref::bezier_point(br.curve, v) - br.curve.p[0], axis);
    ASSERT_NEAR(along, want_along, 1e-5);
  }
  std::printf("    worst radius error %.3g relative\n", worst);
}

// ---- Positions, normals, outward, winding on bent branches -----------------------------------

void check_surface(impl::World& world, const TreeInstance& tree, bool expect_bent) {
  Mesh m = mesh_of(world, tree);
  double size = 0.0;
  for (const ref::Branch& b : m.state)
    for (const dvec3& p : b.curve.p) size = std::max(size, glm::length(p - m.state[0].curve.p[0]));
  double worst_angle = 0.0, worst_fd = 0.0, worst_position = 0.0, bent = 0.0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const boreas_vertex& vx = m.vertices[i];
    const int b = m.branch_of[i];
    const ref::Branch& br = m.state[b];
    const ref::BranchRadius r = ref::BranchRadius::of(tree.model->branches[b]);
    const double v = vx.uv[1], theta = 2.0 * kPi * vx.uv[0];
    ref::SurfacePoint s = ref::branch_surface(br, r, v, theta);
    dvec3 pos = d3(vx.position), n = d3(vx.normal);
    // Position on the reference surface (float rounding of coordinates up to ~8 m).
    worst_position = std::max(worst_position, glm::length(pos - s.position));
    ASSERT_LT(glm::length(pos - s.position), 1e-5 * size) << "vertex " << i;
    ASSERT_NEAR(glm::length(n), 1.0, 1e-5) << "vertex " << i;
    // Normal: the analytic one within a tenth of a degree, the finite-difference one of
    // the reference surface within one degree.
    double a = angle(n, s.normal);
    worst_angle = std::max(worst_angle, a);
    ASSERT_LT(a, 0.1 * kDegree) << "vertex " << i << " branch " << b;
    double fd = near_waist(r, v) ? 0.0 : angle(n, finite_difference_normal(br, r, v, theta));
    worst_fd = std::max(worst_fd, fd);
    ASSERT_LT(fd, 1.0 * kDegree) << "vertex " << i << " branch " << b << " v " << v;
    // Outward: along the direction from the axis to the vertex.
    dvec3 radial = pos - ref::bezier_point(br.curve, v);
    ASSERT_GT(glm::dot(n, radial), 0.0) << "vertex " << i;
    // How far the branch is from its chord (straight or bent).
    dvec3 chord = glm::normalize(br.curve.p[3] - br.curve.p[0]);
    dvec3 off = br.curve.p[2] - br.curve.p[0];
    bent = std::max(bent, glm::length(off - glm::dot(off, chord) * chord));
  }
  // Winding: counter-clockwise seen from outside, so the face normal from the index order
  // agrees with the vertex normals.
  int faces = 0;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    const boreas_vertex &a = m.vertices[m.indices[i]], &b = m.vertices[m.indices[i + 1]],
                        &c = m.vertices[m.indices[i + 2]];
    dvec3 face = glm::cross(d3(b.position) - d3(a.position), d3(c.position) - d3(a.position));
    dvec3 normals = d3(a.normal) + d3(b.normal) + d3(c.normal);
    ASSERT_GT(glm::length(face), 1e-12) << "degenerate triangle " << i / 3;
    ++faces;
    ASSERT_GT(glm::dot(face, normals), 0.0) << "triangle " << i / 3 << " turns clockwise seen from outside";
  }
  EXPECT_EQ(faces, static_cast<int>(m.indices.size() / 3));
  std::printf("    position error %.3g m, normal vs analytic %.3g deg, vs finite differences %.3g deg, bent %.3g m\n",
              worst_position, worst_angle / kDegree, worst_fd / kDegree, bent);
  if (expect_bent) {
    EXPECT_GT(bent, 0.05);
  }
}

TEST(TreeDeformer, StraightBranchNormalsOutwardAndCounterClockwise) {
  auto world = calm_world(0.0f);
  auto tree = instance(tree_model(0.0));
  world->tree_batch(tree->params.mode).add(tree);
  check_surface(*world, *tree, false);
}

TEST(TreeDeformer, BentBranchSurfaceNormalsAndWindingMatchReference) {
  auto world = calm_world(10.0f);
  auto tree = instance(tree_model(0.35));
  world->tree_batch(tree->params.mode).add(tree);
  for (int s = 0; s < 20; ++s) world->step(1.0f / 30.0f);
  check_surface(*world, *tree, true);
}

// The deformer makes BOREAS_W vertices per work-item (cl/shared/simd_width.h): every
// width gives the mesh of width 1 bit for bit (vertex counts per branch that are not a
// multiple of the width, so work-items straddle branches and the last one is partial).
TEST(TreeDeformer, EverySimdWidthGivesTheSameMeshBitForBit) {
  auto run = [](int width) {
    test::ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    auto world = calm_world(10.0f);
    EXPECT_EQ(world->runtime().simd_width(), width);
    auto tree = instance(tree_model(0.35));
    world->tree_batch(tree->params.mode).add(tree);
    for (int s = 0; s < 10; ++s) world->step(1.0f / 30.0f);
    Mesh m = mesh_of(*world, *tree);
    std::vector<unsigned char> bytes(m.vertices.size() * sizeof(boreas_vertex));
    std::memcpy(bytes.data(), m.vertices.data(), bytes.size());
    return bytes;
  };
  const std::vector<unsigned char> scalar = run(1);
  ASSERT_FALSE(scalar.empty());
  for (int width : {8, 16}) EXPECT_TRUE(run(width) == scalar) << "width " << width;
}

// A branch that tapers to a point (taper depth 1, as grown trees have): the tip ring has
// radius 0 and X_theta = 0 there, but the surface still has a limit normal (the cone's),
// and a renderer needs a unit normal at every vertex.
TEST(TreeDeformer, TipRingOfAFullyTaperedBranchHasUnitNormals) {
  auto world = calm_world(0.0f);
  TreeModel model = tree_model(0.2);
  for (BranchModel& b : model.branches) {
    b.taper_depth = 1.0;
    b.taper_exponent = 1.0;
  }
  auto tree = instance(model);
  world->tree_batch(tree->params.mode).add(tree);
  Mesh m = mesh_of(*world, *tree);
  int bad = 0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    double len = glm::length(d3(m.vertices[i].normal));
    if (!(std::abs(len - 1.0) < 1e-4)) ++bad;
    if (m.vertices[i].uv[1] == 1.0f && std::abs(len - 1.0) < 1e-4) {
      // The limit normal: the cone's, from the axis direction and the taper slope.
      const int b = m.branch_of[i];
      const ref::Branch& br = m.state[b];
      const ref::BranchRadius r = ref::BranchRadius::of(model.branches[b]);
      const double theta = 2.0 * kPi * m.vertices[i].uv[0];
      dvec3 want = ref::branch_surface(br, r, 1.0 - 1e-7, theta).normal;
      EXPECT_LT(angle(d3(m.vertices[i].normal), want), 1.0 * kDegree);
    }
  }
  EXPECT_EQ(bad, 0) << "of " << m.vertices.size() << " vertices have no unit normal";
}

// ---- The C++ compile of the shared header ------------------------------------------------

BoreasV3 f3(const dvec3& v) { return boreas_v3(float(v.x), float(v.y), float(v.z)); }
dvec3 d3(const BoreasV3& v) { return dvec3(v.x, v.y, v.z); }

TEST(TreeDeformer, SharedHeaderSurfaceMatchesReference) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit01(0.0, 1.0);
  double worst_position = 0.0, worst_angle = 0.0;
  for (int curve = 0; curve < 50; ++curve) {
    // A bent curve: segments of 0.5..1.5 m turning by up to ~40 degrees each.
    ref::Branch b;
    dvec3 p(5.0 * u(rng), 5.0 * u(rng), 5.0 * u(rng));
    dvec3 dir = glm::normalize(dvec3(u(rng), 1.5, u(rng)));
    for (int k = 0; k < 4; ++k) {
      b.curve.p[k] = p;
      dir = glm::normalize(dir + 0.6 * dvec3(u(rng), u(rng), u(rng)));
      p += (0.5 + unit01(rng)) * dir;
    }
    dvec3 any(u(rng), u(rng), u(rng));
    dvec3 l0 = glm::normalize(b.curve.p[1] - b.curve.p[0]);
    b.o = glm::normalize(any - glm::dot(any, l0) * l0);
    BoreasBezier c;
    c.p0 = f3(b.curve.p[0]);
    c.p1 = f3(b.curve.p[1]);
    c.p2 = f3(b.curve.p[2]);
    c.p3 = f3(b.curve.p[3]);
    BoreasV3 o = f3(b.o);
    b.curve.p = {d3(c.p0), d3(c.p1), d3(c.p2), d3(c.p3)};
    b.o = d3(o);
    double size = 0.0;
    for (const dvec3& q : b.curve.p) size = std::max(size, glm::length(q - b.curve.p[0]));
    BoreasBranchRadius rp;
    rp.radius = float(0.05 + 0.2 * unit01(rng));
    rp.taper_depth = float(0.9 * unit01(rng));
    rp.taper_exponent = float(1.0 + 2.0 * unit01(rng));
    rp.flare = float(unit01(rng));
    rp.bulge_count = float(std::floor(5.0 * unit01(rng)));
    rp.bulge_depth = float(0.1 * unit01(rng));
    rp.lobe_count = float(std::floor(8.0 * unit01(rng)));
    rp.lobe_depth = float(0.2 * unit01(rng));
    rp.lobe_taper = float(unit01(rng));
    // Every other curve closes in a tip cap (Arbaro's hemisphere) over up to a fifth of v.
    rp.tip_cap = curve % 2 ? float(0.2 * unit01(rng)) : 0.0f;
    // The beads start anywhere in their period (a piece ending short of its stem's tip).
    rp.bulge_phase = float(2.0 * unit01(rng));
    ref::BranchRadius r;
    r.radius = rp.radius;
    r.taper_depth = rp.taper_depth;
    r.taper_exponent = rp.taper_exponent;
    r.flare = rp.flare;
    r.bulge_count = rp.bulge_count;
    r.bulge_depth = rp.bulge_depth;
    r.lobe_count = rp.lobe_count;
    r.lobe_depth = rp.lobe_depth;
    r.lobe_taper = rp.lobe_taper;
    r.tip_cap = rp.tip_cap;
    r.bulge_phase = rp.bulge_phase;
    BoreasSloanFrame f = boreas_sloan_frame(c, o);
    ref::SloanFrame rf = ref::sloan_frame(b.curve, b.o);
    for (int k = 0; k < 3; ++k) {
      const BoreasV3 s[3] = {f.s0, f.s1, f.s2}, t[3] = {f.t0, f.t1, f.t2};
      EXPECT_LT(glm::length(d3(s[k]) - rf.s[k]), 1e-5);
      EXPECT_LT(glm::length(d3(t[k]) - rf.t[k]), 1e-5);
    }
    for (int sample = 0; sample < 40; ++sample) {
      float v = float(unit01(rng));
      float turns = float(unit01(rng));
      double theta = 2.0 * kPi * double(turns);
      BoreasV3 pos, nrm;
      boreas_branch_surface(c, f, rp, v, turns, float(std::sin(theta)), float(std::cos(theta)), &pos, &nrm);
      ref::SurfacePoint s = ref::branch_surface(b, r, v, theta);
      double dp = glm::length(d3(pos) - s.position);
      double a = angle(d3(nrm), s.normal);
      worst_position = std::max(worst_position, dp / size);
      worst_angle = std::max(worst_angle, a);
      ASSERT_LT(dp, 1e-5 * size) << "curve " << curve << " v " << v << " turns " << turns;
      ASSERT_LT(a, 1.0 * kDegree) << "curve " << curve << " v " << v << " turns " << turns;
      // The reference's analytic normal against its own finite differences (off the creases).
      if (!near_waist(r, v))
        ASSERT_LT(angle(s.normal, finite_difference_normal(b, r, v, theta)), 0.01 * kDegree);
    }
  }
  std::printf("    shared header vs reference: position %.3g relative, normal %.3g deg\n", worst_position,
              worst_angle / kDegree);
}

}  // namespace
}  // namespace boreas::test
