// Far from the origin, colliders against meadows and imported trees (issue 40): a sphere
// placed by its pose's origin in double 100 km out presses a meadow and an imported tree
// standing there as one near 0 presses the same stand, to 1e-6 m relative to each one's
// origin (to the bit, in practice): the batches take each collider's double position less
// the meadow's or the tree's origin (StepColliders::relative), so the kernels compare small
// numbers. The control places the far spheres at their float world positions (what a
// float world coordinate holds there, and what the kernels compared before: 4 mm off at
// 0.2537 m from 100 km) and shows the stand then moves measurably otherwise. Emitters
// likewise, placed by their def's origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/temp_dir.h"
#include "support/test_support.h"

namespace boreas {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr int kSteps = 60;
constexpr double kExact = 1e-6;  // m, relative to the meadow's or the tree's origin
constexpr double kFar[3] = {1.0e5, 0.0, -1.0e5};
// The imported tree stands this far from the meadow's center (m; whole metres: its float
// position is exact 100 km out as at 0, so the two trees are the same relative to it).
constexpr double kTreeOffset[3] = {-8.0, 0.0, 0.0};
// The spheres' centers, relative to the meadow's center and to the tree's position, off any
// float grid 100 km out, and their velocities (m/s): the meadow's rolls through a dense
// patch of seed 3's; the tree's (0.2 m) is driven into the top of its stem (0.13 m thick at
// 7.7 m) from just against it (started deeper, it throws the stem off, and they part).
constexpr float kInMeadow[3] = {-0.7463f, 0.25f, -0.4411f};
constexpr float kMeadowVelocity[3] = {0.0f, 0.0f, 0.3f};
constexpr float kInTree[3] = {0.3337f, 7.7011f, 0.0037f};
constexpr float kTreeVelocity[3] = {-0.5f, 0.0f, 0.0f};

enum class Placed { kNear, kFarInDouble, kFarInFloat };

struct Stand {
  std::vector<boreas_component> components;  // relative to the meadow's center
  std::vector<boreas_vertex> vertices;       // the tree's trunk then leaves, relative to it
  // Each step's contacts of the meadow's sphere and the tree's.
  std::vector<std::array<boreas_collider_contact, 2>> contacts;
};

// A calm world (no wave, an unforced grid): what moves, the spheres move.
boreas_world calm_world() {
  boreas_world_def def = boreas_default_world_def();
  def.grid = test::calm_grid();
  boreas_world w = nullptr;
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_OK) << boreas_last_error();
  return w;
}

boreas_meadow_def meadow_at(const double* at) {
  boreas_meadow_def d = boreas_default_meadow_def();
  for (int a = 0; a < 3; ++a) d.center[a] = float(at[a]);
  d.size[0] = d.size[1] = 2.0f;
  d.density = 300.0f;
  d.seed = 3;
  d.terrain_relief = 0.2f;
  return d;
}

// A sphere moving at `velocity`, `offset` from `origin`: in double (the pose's origin), or
// as a float world position (origin 0).
boreas_collider_def sphere(const double* origin, const float* offset, const float* velocity,
                           float radius, bool in_double) {
  boreas_collider_def c = boreas_default_collider_def();
  c.radius = radius;
  for (int a = 0; a < 3; ++a) {
    c.velocity[a] = velocity[a];
    c.pose.origin[a] = in_double ? origin[a] : 0.0;
    c.pose.position[a] = in_double ? offset[a] : float(origin[a] + double(offset[a]));
  }
  return c;
}

std::vector<boreas_vertex> tree_vertices(boreas_world w, boreas_mesh_tree_id t) {
  std::vector<boreas_vertex> all;
  for (boreas_mesh_part part : {BOREAS_MESH_TRUNK, BOREAS_MESH_LEAVES}) {
    int count = 0;
    EXPECT_EQ(boreas_mesh_tree_get_vertices(w, t, part, nullptr, 0, &count), BOREAS_OK);
    std::vector<boreas_vertex> v(static_cast<size_t>(count));
    EXPECT_EQ(boreas_mesh_tree_get_vertices(w, t, part, v.data(), count, &count), BOREAS_OK)
        << boreas_last_error();
    all.insert(all.end(), v.begin(), v.end());
  }
  return all;
}

// The stand (meadow at `at`, imported tree beside it, a sphere pressed into each) after
// kSteps, read relative to each one's origin.
Stand press(const double* at, Placed placed, const std::string& obj) {
  Stand s;
  boreas_world w = calm_world();
  const boreas_meadow_def md = meadow_at(at);
  boreas_meadow_id meadow;
  EXPECT_EQ(boreas_world_add_meadow(w, &md, &meadow), BOREAS_OK) << boreas_last_error();
  double tree_at[3];
  for (int a = 0; a < 3; ++a) tree_at[a] = at[a] + kTreeOffset[a];
  boreas_mesh_tree_def td = boreas_default_mesh_tree_def();
  td.model = obj.c_str();
  td.cache = 0;
  for (int a = 0; a < 3; ++a) td.position[a] = float(tree_at[a]);
  boreas_mesh_tree_id tree;
  EXPECT_EQ(boreas_world_add_mesh_tree(w, &td, &tree), BOREAS_OK) << boreas_last_error();
  const bool in_double = placed != Placed::kFarInFloat;
  const boreas_collider_def cd[2] = {sphere(at, kInMeadow, kMeadowVelocity, 0.3f, in_double),
                                     sphere(tree_at, kInTree, kTreeVelocity, 0.2f, in_double)};
  boreas_collider_id colliders[2];
  for (int k = 0; k < 2; ++k)
    EXPECT_EQ(boreas_world_add_collider(w, &cd[k], &colliders[k]), BOREAS_OK) << boreas_last_error();
  for (int step = 0; step < kSteps; ++step) {
    EXPECT_EQ(boreas_world_step(w, kDt), BOREAS_OK) << boreas_last_error();
    s.contacts.emplace_back();
    for (int k = 0; k < 2; ++k)
      EXPECT_EQ(boreas_collider_get_contact(w, colliders[k], &s.contacts.back()[size_t(k)]),
                BOREAS_OK);
  }
  EXPECT_EQ(boreas_world_set_output_origin(w, at), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_meadow_get_components(w, meadow, nullptr, 0, &count), BOREAS_OK);
  s.components.resize(size_t(count));
  EXPECT_EQ(boreas_meadow_get_components(w, meadow, s.components.data(), count, &count), BOREAS_OK);
  EXPECT_EQ(boreas_world_set_output_origin(w, tree_at), BOREAS_OK) << boreas_last_error();
  s.vertices = tree_vertices(w, tree);
  boreas_world_destroy(w);
  return s;
}

double farthest(const float* a, const float* b) {
  double d = 0.0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(double(a[k]) - double(b[k])));
  return d;
}

// How far two stands differ: the meadow components' bases and centers of mass, the tree's
// vertices (m), the spheres' forces and torques in every step (relative to the first
// stand's, 1 N or N m at least), and in how many steps a sphere's contact count differs.
struct Difference {
  double meadow = 0.0, tree = 0.0, force = 0.0;
  int counts = 0;
};

double relative(float a, float b) {
  return std::fabs(double(a) - double(b)) / std::max(1.0, std::fabs(double(a)));
}

Difference compare(const Stand& a, const Stand& b) {
  Difference d;
  EXPECT_EQ(a.components.size(), b.components.size());
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  for (size_t i = 0; i < std::min(a.components.size(), b.components.size()); ++i)
    d.meadow = std::max({d.meadow, farthest(a.components[i].center_of_mass,
                                            b.components[i].center_of_mass),
                         farthest(a.components[i].base, b.components[i].base)});
  for (size_t i = 0; i < std::min(a.vertices.size(), b.vertices.size()); ++i)
    d.tree = std::max(d.tree, farthest(a.vertices[i].position, b.vertices[i].position));
  for (size_t step = 0; step < std::min(a.contacts.size(), b.contacts.size()); ++step)
    for (size_t k = 0; k < 2; ++k) {
      const boreas_collider_contact &p = a.contacts[step][k], &q = b.contacts[step][k];
      d.counts += p.contacts != q.contacts;
      for (int c = 0; c < 3; ++c)
        d.force = std::max({d.force, relative(p.force[c], q.force[c]),
                            relative(p.torque[c], q.torque[c])});
    }
  return d;
}

// How far the near stand's meadow moved from rest, and the steps in which each sphere
// touched: that the comparison means something.
double moved(const Stand& s) {
  double most = 0.0;
  for (const boreas_component& c : s.components)
    most = std::max(most, farthest(c.center_of_mass, c.rest_center_of_mass));
  return most;
}

int touching_steps(const Stand& s, size_t k) {
  int steps = 0;
  for (const auto& c : s.contacts) steps += c[k].contacts > 0;
  return steps;
}

TEST(FarColliders, ColliderPlacedInDoublePushesAMeadowAndAnImportedTreeFarOutAsAtTheOrigin) {
  test::TempDir dir;
  const std::string obj = test::write_tube_tree_obj(dir.path());
  const double near[3] = {0.0, 0.0, 0.0};
  // The far spheres' centers are no floats: a float world position is millimetres off.
  for (const float* offset : {kInMeadow, kInTree}) {
    const double x = kFar[0] + (offset == kInTree ? kTreeOffset[0] : 0.0) + double(offset[0]);
    EXPECT_GT(std::fabs(double(float(x)) - x), 1e-3);
  }
  const Stand a = press(near, Placed::kNear, obj);
  const Stand b = press(kFar, Placed::kFarInDouble, obj);
  const Difference d = compare(a, b);
  std::printf("spheres 100 km out placed in double: they touch the meadow in %d steps and the "
              "tree in %d (at 0: %d, %d), with contact counts differing in %d; components "
              "differ by up to %.2g m, tree vertices by %.2g m, forces and torques by %.2g "
              "(relative); the meadow moved up to %.3f m\n",
              touching_steps(b, 0), touching_steps(b, 1), touching_steps(a, 0),
              touching_steps(a, 1), d.counts, d.meadow, d.tree, d.force, moved(a));
  EXPECT_EQ(touching_steps(a, 0), kSteps) << "the sphere should press the meadow throughout";
  EXPECT_GT(touching_steps(a, 1), kSteps / 2) << "the sphere should press the tree";
  EXPECT_GT(moved(a), 0.01);
  EXPECT_EQ(d.counts, 0);
  EXPECT_LE(d.meadow, kExact);
  EXPECT_LE(d.tree, kExact);
  EXPECT_LE(d.force, kExact);

  // The control: the same spheres at their float world positions press otherwise.
  const Stand c = press(kFar, Placed::kFarInFloat, obj);
  const Difference e = compare(a, c);
  std::printf("the same spheres at float world positions: contact counts differ in %d steps, "
              "components by up to %.2g m, tree vertices by %.2g m, forces and torques by %.2g "
              "(relative)\n",
              e.counts, e.meadow, e.tree, e.force);
  EXPECT_GT(e.meadow, 1e-4);
  EXPECT_GT(e.tree, 1e-4);
}

// The meadow at `at` after kSteps of drops from an emitter over a dense patch of it (placed
// in double by its origin, or at its float world center), relative to its center.
std::vector<boreas_component> rain_on(const double* at, bool in_double) {
  boreas_world w = calm_world();
  const boreas_meadow_def md = meadow_at(at);
  boreas_meadow_id meadow;
  EXPECT_EQ(boreas_world_add_meadow(w, &md, &meadow), BOREAS_OK) << boreas_last_error();
  boreas_emitter_def e = boreas_default_emitter_def();
  const float center[3] = {-0.7463f, 0.6f, -0.4411f};
  for (int a = 0; a < 3; ++a) {
    e.origin[a] = in_double ? at[a] : 0.0;
    e.center[a] = in_double ? center[a] : float(at[a] + double(center[a]));
  }
  e.area_radius = 0.3f;
  e.event_radius = 0.1f;
  e.impulse[1] = -2e-3f;  // a footstep's worth, so the meadow moves by centimetres
  e.rate = 600.0f;
  e.seed = 5;
  boreas_emitter_id id;
  EXPECT_EQ(boreas_world_add_emitter(w, &e, &id), BOREAS_OK) << boreas_last_error();
  for (int step = 0; step < kSteps; ++step)
    EXPECT_EQ(boreas_world_step(w, kDt), BOREAS_OK) << boreas_last_error();
  EXPECT_EQ(boreas_world_set_output_origin(w, at), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_meadow_get_components(w, meadow, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_component> out(static_cast<size_t>(count));
  EXPECT_EQ(boreas_meadow_get_components(w, meadow, out.data(), count, &count), BOREAS_OK);
  boreas_world_destroy(w);
  return out;
}

double largest_difference(const std::vector<boreas_component>& a,
                          const std::vector<boreas_component>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    d = std::max(d, farthest(a[i].center_of_mass, b[i].center_of_mass));
  return d;
}

// Rain from an emitter placed in double (its def's origin) 100 km out moves a meadow there
// as the same rain near 0 moves it; at its float world center (8 mm apart there) otherwise.
TEST(FarColliders, EmitterPlacedInDoubleRainsOnAMeadowFarOutAsAtTheOrigin) {
  const double near[3] = {0.0, 0.0, 0.0};
  EXPECT_GT(std::fabs(double(float(kFar[0] - 0.7463)) - (kFar[0] - 0.7463)), 1e-3);
  const std::vector<boreas_component> a = rain_on(near, true);
  const std::vector<boreas_component> b = rain_on(kFar, true);
  const std::vector<boreas_component> c = rain_on(kFar, false);
  double moved = 0.0;
  for (const boreas_component& p : a)
    moved = std::max(moved, farthest(p.center_of_mass, p.rest_center_of_mass));
  const double exact = largest_difference(a, b), off = largest_difference(a, c);
  std::printf("rain 100 km out: the meadow moved up to %.3f m; placed in double its components "
              "differ from those at 0 by up to %.2g m, at its float world center by %.2g m\n",
              moved, exact, off);
  EXPECT_GT(moved, 0.01);
  EXPECT_LE(exact, kExact);
  EXPECT_GT(off, 1e-4);
}

// An emitter's origin is checked like its center.
TEST(FarColliders, EmitterOriginIsChecked) {
  boreas_world w = calm_world();
  boreas_emitter_def e = boreas_default_emitter_def();
  e.origin[2] = NAN;
  boreas_emitter_id id;
  EXPECT_EQ(boreas_world_add_emitter(w, &e, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("emitter_def.origin[2]"), std::string::npos)
      << boreas_last_error();
  e.origin[2] = 2e7;
  EXPECT_EQ(boreas_world_add_emitter(w, &e, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  e.origin[2] = -1e5;
  EXPECT_EQ(boreas_world_add_emitter(w, &e, &id), BOREAS_OK) << boreas_last_error();
  boreas_world_destroy(w);
}

}  // namespace
}  // namespace boreas
