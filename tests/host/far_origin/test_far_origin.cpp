// Far from the origin (issue 40): the same meadow, imported tree and tree grown from a
// species at the world's 0 and at (100 km, 0, -100 km), in the same wind, move the same —
// components' paths, strips' and imported trees' vertices, branches' control points and
// leaves, relative to where they stand, within 1e-4 m of each other over 600 steps.
// A float's spacing at 100 km is 8 mm, so a meadow whose state were kept in world
// coordinates would differ by millimetres (it did before the meadows got local origins).
// The positions are read back relative to each meadow's center (boreas_world_set_output_
// origin), which is what a renderer near either of them would ask for.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "host/mesh_trees/tube_trees.h"
// The kernels' wind math, compiled for the host (width 1) with the devices' polynomials.
#ifndef BOREAS_FAST_MATH
#define BOREAS_FAST_MATH 1
#endif
#include "shared/wind_sample.h"
#include "wind/plant_wind.h"
#include "wind/wind_sampling.h"
#include "support/temp_dir.h"
#include "support/test_support.h"

namespace boreas {
namespace {

constexpr int kSteps = 600;
constexpr float kDt = 1.0f / 60.0f;
constexpr double kTolerance = 1e-4;  // m
constexpr double kFar[3] = {1.0e5, 0.0, -1.0e5};

struct World {
  boreas_world w = nullptr;
  explicit World(const boreas_wave& wave) {
    boreas_world_def def = boreas_default_world_def();
    def.grid = test::calm_grid();  // idle: no primitive, no gust, no solid
    def.waves = &wave;
    def.wave_count = 1;
    EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_OK) << boreas_last_error();
  }
  ~World() { boreas_world_destroy(w); }
};

boreas_meadow_def meadow_at(double x, double y, double z) {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.center[0] = float(x);
  d.center[1] = float(y);
  d.center[2] = float(z);
  d.size[0] = d.size[1] = 1.5f;
  d.density = 200.0f;
  d.seed = 3;
  d.terrain_relief = 0.2f;  // rolling ground: the terrain too must not depend on the place
  return d;
}

// The meadow's components, positions relative to `origin`.
std::vector<boreas_component> components(boreas_world w, boreas_meadow_id m, const double* origin) {
  EXPECT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_meadow_get_components(w, m, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_component> out(static_cast<size_t>(count));
  EXPECT_EQ(boreas_meadow_get_components(w, m, out.data(), count, &count), BOREAS_OK)
      << boreas_last_error();
  return out;
}

std::vector<boreas_meadow_vertex> vertices(boreas_world w, boreas_meadow_id m, const double* origin) {
  EXPECT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_meadow_get_vertices(w, m, nullptr, nullptr, 0, &count, nullptr), BOREAS_OK);
  std::vector<boreas_meadow_vertex> out(static_cast<size_t>(count));
  EXPECT_EQ(boreas_meadow_get_vertices(w, m, nullptr, out.data(), count, &count, nullptr),
            BOREAS_OK)
      << boreas_last_error();
  return out;
}

double farthest(const float* a, const float* b) {
  double d = 0.0;
  for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(double(a[k]) - double(b[k])));
  return d;
}

// What the two meadows did: the largest difference of any component's base and center of
// mass and of any strip vertex, relative to each meadow's center, over the steps; and how
// far the near meadow's centers of mass moved from rest (so that the check means something).
struct Paths {
  double component = 0.0, vertex = 0.0, moved = 0.0;
  size_t components = 0;
};

Paths run_pair(const boreas_wave& wave) {
  World world(wave);
  const double near[3] = {0.0, 0.0, 0.0};
  const boreas_meadow_def defs[2] = {meadow_at(near[0], near[1], near[2]),
                                     meadow_at(kFar[0], kFar[1], kFar[2])};
  boreas_meadow_id ids[2];
  EXPECT_EQ(boreas_world_add_meadows(world.w, defs, 2, ids), BOREAS_OK) << boreas_last_error();
  Paths p;
  for (int s = 1; s <= kSteps; ++s) {
    EXPECT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK) << boreas_last_error();
    const std::vector<boreas_component> a = components(world.w, ids[0], near);
    const std::vector<boreas_component> b = components(world.w, ids[1], kFar);
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size()) return p;
    p.components = a.size();
    for (size_t i = 0; i < a.size(); ++i) {
      p.component = std::max({p.component, farthest(a[i].base, b[i].base),
                              farthest(a[i].center_of_mass, b[i].center_of_mass)});
      p.moved = std::max(p.moved, farthest(a[i].center_of_mass, a[i].rest_center_of_mass));
    }
    if (s % 50 == 0) {
      const std::vector<boreas_meadow_vertex> va = vertices(world.w, ids[0], near);
      const std::vector<boreas_meadow_vertex> vb = vertices(world.w, ids[1], kFar);
      for (size_t i = 0; i < va.size(); ++i)
        p.vertex = std::max(p.vertex, farthest(va[i].position, vb[i].position));
    }
  }
  std::printf("meadow: %zu components moved up to %.4f m; paths differ by up to %.2g m, strips "
              "by %.2g m\n",
              p.components, p.moved, p.component, p.vertex);
  return p;
}

TEST(FarOrigin, MeadowMovesAlikeAtTheOriginAndHundredKilometresOut) {
  // Steady and uniform (sharpness 0): the wind is the same at both meadows.
  const Paths p = run_pair(test::steady_wave(1.0f, 0.4f, 6.0f));
  ASSERT_GT(p.components, 100u);
  EXPECT_GT(p.moved, 0.01) << "the wind should bend the components";
  EXPECT_LE(p.component, kTolerance) << "component paths (base, center of mass), m";
  EXPECT_LE(p.vertex, kTolerance) << "strip vertices, m";
}

TEST(FarOrigin, GustyWaveKeepsItsPhaseHundredKilometresOut) {
  // A travelling wave whose wavelength divides the offset (100 km / 8 m = 12500 cycles,
  // along x only): both meadows stand at the same phase of it, so they must move alike.
  // In float, x = 1e5 m keeps a wave's phase to about 1e-3 cycle; the meadow's wind is
  // evaluated relative to its origin with the phase there computed in double.
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[1] = 0.0f;
  w.amplitude = 7.0f;
  w.wavelength = 8.0f;
  w.speed = 5.0f;
  w.sharpness = 2.0f;
  const Paths p = run_pair(w);
  ASSERT_GT(p.components, 100u);
  EXPECT_GT(p.moved, 0.01);
  EXPECT_LE(p.component, kTolerance);
  EXPECT_LE(p.vertex, kTolerance);
}

TEST(FarOrigin, OutputOriginIsCheckedAndWorldCoordinatesAreTheDefault) {
  World world(test::steady_wave(1.0f, 0.0f, 3.0f));
  const boreas_meadow_def def = meadow_at(kFar[0], kFar[1], kFar[2]);
  boreas_meadow_id id;
  ASSERT_EQ(boreas_world_add_meadow(world.w, &def, &id), BOREAS_OK) << boreas_last_error();
  const double bad[3] = {0.0, NAN, 0.0};
  EXPECT_EQ(boreas_world_set_output_origin(world.w, bad), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("origin[1]"), std::string::npos)
      << boreas_last_error();
  const double past[3] = {2.0 * BOREAS_WORLD_MAX_COORDINATE, 0.0, 0.0};
  EXPECT_EQ(boreas_world_set_output_origin(world.w, past), BOREAS_ERROR_INVALID_ARGUMENT);
  // NULL: world coordinates; the components stand within the meadow's rectangle there
  // (0.75 m each way), or on a stalk leaning a little past it.
  const std::vector<boreas_component> world_c = components(world.w, id, nullptr);
  const std::vector<boreas_component> local_c = components(world.w, id, kFar);
  ASSERT_FALSE(world_c.empty());
  for (size_t i = 0; i < world_c.size(); ++i) {
    EXPECT_NEAR(world_c[i].base[0], kFar[0], 1.0);
    EXPECT_NEAR(world_c[i].base[2], kFar[2], 1.0);
    // The same point, in float at 100 km (8 mm apart) and relative to the meadow.
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(double(world_c[i].base[a]), kFar[a] + double(local_c[i].base[a]), 8e-3);
  }
}

// The sine sum as a plant 100 km out reads it (relative to its origin, with the waves'
// phases there from the host in double) against the double-precision sum at the same
// world points: within what the polynomial sine allows, where a float world position
// there loses about a thousandth of a cycle.
TEST(FarOrigin, SineSumRelativeToAnOriginKeepsItsPhase) {
  BoreasGpuWave wave{};
  wave.dir_x = 0.8f;
  wave.dir_z = 0.6f;
  wave.amplitude = 5.0f;
  wave.cycles_per_meter = float(1.0 / 7.3);
  wave.phase_cycles = 0.37f;
  wave.sharpness = 2.0f;
  const std::vector<BoreasGpuWave> waves = {wave};
  impl::PlantWind wind;
  wind.wave_count = 1;
  wind.host_waves = &waves;
  float phase = 0.0f;
  wind.phases_at(kFar[0], kFar[2], &phase);
  double local_error = 0.0, world_error = 0.0;
  for (int i = 0; i < 400; ++i) {
    const float lx = -1.0f + 0.005f * float(i), lz = 0.7f - 0.0035f * float(i);
    // The double sum at the world point kFar + l, with the wave's float constants.
    const double u = double(wave.phase_cycles) +
                     (double(wave.dir_x) * (kFar[0] + lx) + double(wave.dir_z) * (kFar[2] + lz)) *
                         double(wave.cycles_per_meter);
    const double b = 0.5 * (std::sin(2.0 * M_PI * (u - std::floor(u))) + 1.0);
    const double want = double(wave.amplitude) * b * b;
    float fx = 0.0f, fz = 0.0f;
    boreas_wind_sine_sum_phased(lx, lz, waves.data(), 1, &phase, 1, &fx, &fz);
    local_error = std::max(local_error, std::fabs(double(fx) - double(wave.dir_x) * want));
    boreas_wind_sine_sum(float(kFar[0] + lx), float(kFar[2] + lz), waves.data(), 1, &fx, &fz);
    world_error = std::max(world_error, std::fabs(double(fx) - double(wave.dir_x) * want));
  }
  std::printf("sine sum 100 km out: %.2g m/s off relative to the origin, %.2g m/s at float "
              "world positions\n",
              local_error, world_error);
  EXPECT_LT(local_error, 2e-4);
}

// The wind sampled at points near a grid 100 km out (boreas_wind_sample, and the plants'
// interpolated reading of the grid's slab) against the double sum at the same points: the
// sums are taken relative to the grid's corner with the phases there.
TEST(FarOrigin, WindNearAGridHundredKilometresOutKeepsItsPhase) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 0.8f;
  w.direction[1] = 0.6f;
  w.amplitude = 5.0f;
  w.wavelength = 30.0f;
  w.speed = 4.0f;
  w.sharpness = 2.0f;
  impl::WaveParams params;
  params.dir_x = 0.8;
  params.dir_z = 0.6;
  params.amplitude = 5.0;
  params.wavelength = 30.0;
  params.sharpness = 2.0;
  for (boreas_wind_sampling sampling :
       {BOREAS_WIND_SAMPLING_EXACT, BOREAS_WIND_SAMPLING_INTERPOLATED}) {
    boreas_world_def def = boreas_default_world_def();
    def.grid = test::centered_grid(16, 2, 16, 1.0f);
    def.grid.origin[0] += float(kFar[0]);
    def.grid.origin[2] += float(kFar[2]);
    def.grid.wind_sampling = sampling;
    def.waves = &w;
    def.wave_count = 1;
    impl::World world(def);
    for (int s = 0; s < 7; ++s) world.step(0.1f);
    const BoreasGpuWave wave = (*world.wind().plants().host_waves)[0];
    std::vector<float> xyz, force;
    for (int i = 0; i < 300; ++i) {
      xyz.push_back(float(kFar[0] - 6.0 + 0.04 * i));
      xyz.push_back(0.5f);
      xyz.push_back(float(kFar[2] + 6.0 - 0.037 * i));
    }
    force.resize(xyz.size());
    world.wind().sample(xyz.data(), 300, force.data(), true);
    double error = 0.0;
    for (size_t i = 0; i < 300; ++i) {
      const double u = double(wave.phase_cycles) +
                       (double(wave.dir_x) * xyz[3 * i] + double(wave.dir_z) * xyz[3 * i + 2]) *
                           double(wave.cycles_per_meter);
      const double b = 0.5 * (std::sin(2.0 * M_PI * (u - std::floor(u))) + 1.0);
      const double strength = double(wave.amplitude) * b * b;
      error = std::max({error, std::fabs(force[3 * i] - double(wave.dir_x) * strength),
                        std::fabs(double(force[3 * i + 1])),
                        std::fabs(force[3 * i + 2] - double(wave.dir_z) * strength)});
    }
    const double bound = sampling == BOREAS_WIND_SAMPLING_EXACT
                             ? 0.0
                             : impl::interpolation_error_bound({params}, 1.0);
    std::printf("wind near a grid 100 km out, %s: %.2g m/s off the double sum (bound %.2g + "
                "2e-4)\n",
                sampling == BOREAS_WIND_SAMPLING_EXACT ? "exact" : "interpolated", error, bound);
    EXPECT_LE(error, bound + 2e-4);
  }
}

// The imported tree's vertices (trunk, then leaves), relative to `origin`.
std::vector<boreas_vertex> mesh_vertices(boreas_world w, boreas_mesh_tree_id t, const double* origin) {
  EXPECT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
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

double mesh_tree_paths(const boreas_wave& wave, double* moved) {
  World world(wave);
  test::TempDir dir;
  const std::string path = test::write_tube_tree_obj(dir.path());
  const double near[3] = {0.0, 0.0, 0.0};
  boreas_mesh_tree_id ids[2];
  for (int k = 0; k < 2; ++k) {
    boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
    def.model = path.c_str();
    def.cache = 0;
    for (int a = 0; a < 3; ++a) def.position[a] = float(k == 0 ? near[a] : kFar[a]);
    EXPECT_EQ(boreas_world_add_mesh_tree(world.w, &def, &ids[k]), BOREAS_OK) << boreas_last_error();
  }
  const std::vector<boreas_vertex> rest = mesh_vertices(world.w, ids[0], near);
  double largest = 0.0;
  *moved = 0.0;
  for (int s = 1; s <= kSteps; ++s) {
    EXPECT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK) << boreas_last_error();
    const std::vector<boreas_vertex> a = mesh_vertices(world.w, ids[0], near);
    const std::vector<boreas_vertex> b = mesh_vertices(world.w, ids[1], kFar);
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size() || a.size() != rest.size()) return INFINITY;
    for (size_t i = 0; i < a.size(); ++i) {
      largest = std::max(largest, farthest(a[i].position, b[i].position));
      *moved = std::max(*moved, farthest(a[i].position, rest[i].position));
    }
  }
  std::printf("imported tree: moved up to %.4f m; vertex paths differ by up to %.2g m\n", *moved,
              largest);
  return largest;
}

TEST(FarOrigin, ImportedTreeMovesAlikeAtTheOriginAndHundredKilometresOut) {
  double moved = 0.0;
  const double largest = mesh_tree_paths(test::steady_wave(1.0f, 0.4f, 8.0f), &moved);
  EXPECT_GT(moved, 0.01) << "the wind should sway the tree, m";
  EXPECT_LE(largest, kTolerance) << "vertex paths, m";
}

TEST(FarOrigin, ImportedTreeKeepsAGustyWavesPhaseHundredKilometresOut) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[1] = 0.0f;
  w.amplitude = 9.0f;
  w.wavelength = 8.0f;  // 12500 cycles in 100 km: the same phase at both trees
  w.speed = 5.0f;
  w.sharpness = 2.0f;
  double moved = 0.0;
  const double largest = mesh_tree_paths(w, &moved);
  EXPECT_GT(moved, 0.01);
  EXPECT_LE(largest, kTolerance);
}

// Trees grown from species keep their state relative to their base (cl/shared/tree_origin.h)
// and sample the wind there with the waves' phases at the base: the same tree at 0 and 100
// km out moves alike. Every branch's control points and every leaf, read relative to each
// tree's base (boreas_world_set_output_origin), within 1e-4 m over 600 steps; on float
// world coordinates the trunk tip alone strayed 6 mm.
struct TreePaths {
  double branch = 0.0, leaf = 0.0, moved = 0.0;
  size_t branches = 0, leaves = 0;
};

std::vector<boreas_branch> tree_branches(boreas_world w, boreas_tree_id t, const double* origin) {
  EXPECT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_tree_get_branches(w, t, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_branch> b(static_cast<size_t>(count));
  EXPECT_EQ(boreas_tree_get_branches(w, t, b.data(), count, &count), BOREAS_OK) << boreas_last_error();
  return b;
}

std::vector<boreas_leaf> tree_leaves(boreas_world w, boreas_tree_id t, const double* origin) {
  EXPECT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
  int count = 0;
  EXPECT_EQ(boreas_tree_get_leaves(w, t, nullptr, 0, &count), BOREAS_OK);
  std::vector<boreas_leaf> l(static_cast<size_t>(count));
  EXPECT_EQ(boreas_tree_get_leaves(w, t, l.data(), count, &count), BOREAS_OK) << boreas_last_error();
  return l;
}

TreePaths tree_paths(const boreas_wave& wave, boreas_tree_mode mode,
                     boreas_tree_response response = BOREAS_TREE_QUASI_STATIC) {
  World world(wave);
  const double near[3] = {0.0, 0.0, 0.0};
  boreas_tree_id ids[2];
  for (int k = 0; k < 2; ++k) {
    boreas_tree_def def = boreas_default_tree_def();
    def.mode = mode;
    def.response = response;
    for (int a = 0; a < 3; ++a) def.position[a] = float(k == 0 ? near[a] : kFar[a]);
    EXPECT_EQ(boreas_world_add_tree(world.w, &def, &ids[k]), BOREAS_OK) << boreas_last_error();
  }
  TreePaths p;
  const std::vector<boreas_branch> rest = tree_branches(world.w, ids[0], near);
  for (int s = 1; s <= kSteps; ++s) {
    EXPECT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK) << boreas_last_error();
    const std::vector<boreas_branch> a = tree_branches(world.w, ids[0], near);
    const std::vector<boreas_branch> b = tree_branches(world.w, ids[1], kFar);
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size() || a.size() != rest.size()) return p;
    p.branches = a.size();
    for (size_t i = 0; i < a.size(); ++i) {
      for (int c = 0; c < 4; ++c)
        p.branch = std::max(p.branch, farthest(a[i].control_points[c], b[i].control_points[c]));
      p.moved = std::max(p.moved, farthest(a[i].control_points[3], rest[i].control_points[3]));
    }
    if (s % 100 == 0) {
      const std::vector<boreas_leaf> la = tree_leaves(world.w, ids[0], near);
      const std::vector<boreas_leaf> lb = tree_leaves(world.w, ids[1], kFar);
      EXPECT_EQ(la.size(), lb.size());
      p.leaves = std::min(la.size(), lb.size());
      for (size_t i = 0; i < p.leaves; ++i)
        p.leaf = std::max(p.leaf, farthest(la[i].position, lb[i].position));
    }
  }
  std::printf("tree (%s, %s): %zu branches, tips moved up to %.4f m; paths differ by up to %.2g m, "
              "%zu leaves by %.2g m\n",
              mode == BOREAS_TREE_EXACT ? "exact" : "lagged",
              response == BOREAS_TREE_DAMPED ? "damped" : "quasi-static", p.branches, p.moved, p.branch,
              p.leaves, p.leaf);
  return p;
}

// Both modes, each with both responses: the damped oscillator carries a velocity per branch
// from step to step, state that must be kept relative to the base like the bend.
TEST(FarOrigin, TreeMovesAlikeAtTheOriginAndHundredKilometresOut) {
  for (boreas_tree_mode mode : {BOREAS_TREE_LAGGED, BOREAS_TREE_EXACT})
  for (boreas_tree_response response : {BOREAS_TREE_QUASI_STATIC, BOREAS_TREE_DAMPED}) {
    SCOPED_TRACE(std::string(mode == BOREAS_TREE_EXACT ? "exact" : "lagged") +
                 (response == BOREAS_TREE_DAMPED ? ", damped" : ", quasi-static"));
    const TreePaths p = tree_paths(test::steady_wave(1.0f, 0.4f, 8.0f), mode, response);
    ASSERT_GT(p.branches, 10u);
    ASSERT_GT(p.leaves, 100u);
    EXPECT_GT(p.moved, 0.01) << "the wind should sway the branches, m";
    EXPECT_LE(p.branch, kTolerance) << "branch control points, m";
    EXPECT_LE(p.leaf, kTolerance) << "leaf positions, m";
  }
}

// A gusty wave whose wavelength divides the offset along x (12500 cycles in 100 km): both
// trees stand at the same phase of it, so they must move alike; in float world
// coordinates the wave's phase 100 km out is kept to about 1e-3 cycle.
TEST(FarOrigin, TreeKeepsAGustyWavesPhaseHundredKilometresOut) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[1] = 0.0f;
  w.amplitude = 9.0f;
  w.wavelength = 8.0f;
  w.speed = 5.0f;
  w.sharpness = 2.0f;
  const TreePaths p = tree_paths(w, BOREAS_TREE_LAGGED);
  EXPECT_GT(p.moved, 0.01);
  EXPECT_LE(p.branch, kTolerance);
  EXPECT_LE(p.leaf, kTolerance);
}

// A tree meets a collider relative to its base (the collider's float position less the
// base, in double): a sphere pressed into the trunk at the same offset from each tree's
// base (an offset of 1/128 m steps, exact in float 100 km out) pushes both alike, and
// the two colliders feel the same push back.
TEST(FarOrigin, TreePushedByAColliderMovesAlikeHundredKilometresOut) {
  World world(test::steady_wave(1.0f, 0.4f, 8.0f));
  const double near[3] = {0.0, 0.0, 0.0};
  boreas_tree_id ids[2];
  boreas_collider_id colliders[2];
  for (int k = 0; k < 2; ++k) {
    const double* at = k == 0 ? near : kFar;
    boreas_tree_def def = boreas_default_tree_def();
    for (int a = 0; a < 3; ++a) def.position[a] = float(at[a]);
    ASSERT_EQ(boreas_world_add_tree(world.w, &def, &ids[k]), BOREAS_OK) << boreas_last_error();
    boreas_collider_def c = boreas_default_collider_def();
    c.radius = 0.25f;
    const double offset[3] = {0.25, 1.5, 0.0};  // into the trunk's side, 1.5 m up
    for (int a = 0; a < 3; ++a) c.pose.position[a] = float(at[a] + offset[a]);
    ASSERT_EQ(boreas_world_add_collider(world.w, &c, &colliders[k]), BOREAS_OK) << boreas_last_error();
  }
  double largest = 0.0, pushed = 0.0;
  for (int s = 1; s <= 120; ++s) {
    ASSERT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK) << boreas_last_error();
    const std::vector<boreas_branch> a = tree_branches(world.w, ids[0], near);
    const std::vector<boreas_branch> b = tree_branches(world.w, ids[1], kFar);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i)
      for (int c = 0; c < 4; ++c)
        largest = std::max(largest, farthest(a[i].control_points[c], b[i].control_points[c]));
    boreas_collider_contact ca{}, cb{};
    ASSERT_EQ(boreas_collider_get_contact(world.w, colliders[0], &ca), BOREAS_OK);
    ASSERT_EQ(boreas_collider_get_contact(world.w, colliders[1], &cb), BOREAS_OK);
    EXPECT_EQ(ca.contacts, cb.contacts) << "step " << s;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(ca.force[a], cb.force[a], 1e-3 * (1.0 + std::fabs(ca.force[a]))) << "step " << s;
      EXPECT_NEAR(ca.torque[a], cb.torque[a], 1e-3 * (1.0 + std::fabs(ca.torque[a]))) << "step " << s;
    }
    pushed = std::max(pushed, double(ca.contacts));
  }
  std::printf("tree and collider: %g contacts at most; paths differ by up to %.2g m\n", pushed,
              largest);
  EXPECT_GT(pushed, 0.0) << "the sphere should touch the tree";
  EXPECT_LE(largest, kTolerance);
}

// Without an output origin the trees' positions are world coordinates: the same points as
// relative to the base, to the float spacing there (8 mm at 100 km).
TEST(FarOrigin, TreeOutputsAreWorldCoordinatesByDefault) {
  World world(test::steady_wave(1.0f, 0.4f, 8.0f));
  boreas_tree_def def = boreas_default_tree_def();
  for (int a = 0; a < 3; ++a) def.position[a] = float(kFar[a]);
  boreas_tree_id id;
  ASSERT_EQ(boreas_world_add_tree(world.w, &def, &id), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 5; ++s) ASSERT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK);
  const std::vector<boreas_branch> world_b = tree_branches(world.w, id, nullptr);
  const std::vector<boreas_branch> local_b = tree_branches(world.w, id, kFar);
  ASSERT_EQ(world_b.size(), local_b.size());
  ASSERT_FALSE(world_b.empty());
  EXPECT_EQ(world_b[0].control_points[0][0], float(kFar[0])) << "the trunk stands at its base";
  for (size_t i = 0; i < world_b.size(); ++i)
    for (int c = 0; c < 4; ++c)
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(double(world_b[i].control_points[c][a]),
                    kFar[a] + double(local_b[i].control_points[c][a]), 8e-3);
  const std::vector<boreas_leaf> world_l = tree_leaves(world.w, id, nullptr);
  const std::vector<boreas_leaf> local_l = tree_leaves(world.w, id, kFar);
  ASSERT_EQ(world_l.size(), local_l.size());
  for (size_t i = 0; i < world_l.size(); ++i)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(double(world_l[i].position[a]), kFar[a] + double(local_l[i].position[a]), 8e-3);
}

}  // namespace
}  // namespace boreas
