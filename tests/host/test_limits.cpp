// boreas tests: the limits in boreas.h ("Limits") are the library's own: each is accepted
// at the limit and refused just past it, and each is a constant expression of the type the
// header promises (int counts, double bounds). limits_from_c.c checks the same from C.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "boreas/boreas.h"
#include "support/expect_error.h"
#include "support/small_world.h"
#include "sensors/depth_camera.h"
#include "sensors/lidar_params.h"
#include "trees/tree_params.h"
#include "underbrush/component_species.h"
#include "underbrush/meadow.h"
#include "validation.h"
#include "wind/wind_params.h"

namespace {

using boreas::test::expect_error;
namespace impl = boreas::impl;

static_assert(std::is_same_v<decltype(BOREAS_WORLD_MAX_COORDINATE), double>);
static_assert(std::is_same_v<decltype(BOREAS_STEP_MAX_SECONDS), double>);
static_assert(std::is_same_v<decltype(BOREAS_WIND_MAX_SPEED), double>);
static_assert(std::is_same_v<decltype(BOREAS_MEADOW_MAX_DENSITY), double>);
static_assert(std::is_same_v<decltype(BOREAS_WIND_MAX_WAVES), int>);
static_assert(std::is_same_v<decltype(BOREAS_WIND_SAMPLE_MAX_POINTS), int>);
static_assert(std::is_same_v<decltype(BOREAS_GRID_MAX_RESOLUTION), int>);
static_assert(std::is_same_v<decltype(BOREAS_GRID_MAX_CELLS), int>);
static_assert(std::is_same_v<decltype(BOREAS_MEADOW_MAX_COMPONENTS), int>);
static_assert(std::is_same_v<decltype(BOREAS_MEADOW_MAX_SPECIES), int>);
static_assert(std::is_same_v<decltype(BOREAS_MEADOW_MAX_SEED_POINTS), int>);
static_assert(std::is_same_v<decltype(BOREAS_PLANT_MAX_COMPONENTS), int>);
static_assert(std::is_same_v<decltype(BOREAS_IMAGE_MAX_FLOATS), int>);
static_assert(std::is_same_v<decltype(BOREAS_LIDAR_MAX_CHANNELS), int>);
static_assert(std::is_same_v<decltype(BOREAS_LIDAR_MAX_RAYS_PER_TURN), int>);
static_assert(std::is_same_v<decltype(BOREAS_DEPTH_CAMERA_MAX_PIXELS), int>);
static_assert(std::is_same_v<decltype(BOREAS_SKIN_MAX_SEGMENTS), int>);
static_assert(std::is_same_v<decltype(BOREAS_ANIMATION_MAX_FRAMES), int>);
static_assert(std::is_same_v<decltype(BOREAS_ANIMATION_MAX_MORPH_FRAMES), int>);
// The bounds are whole numbers of their unit that a float holds exactly, so a float field
// can sit right on them.
static_assert(double(float(BOREAS_WORLD_MAX_COORDINATE)) == BOREAS_WORLD_MAX_COORDINATE);
static_assert(double(float(BOREAS_STEP_MAX_SECONDS)) == BOREAS_STEP_MAX_SECONDS);
static_assert(double(float(BOREAS_WIND_MAX_SPEED)) == BOREAS_WIND_MAX_SPEED);
static_assert(double(float(BOREAS_MEADOW_MAX_DENSITY)) == BOREAS_MEADOW_MAX_DENSITY);

// The float just past a bound, away from zero.
float past(double limit) { return std::nextafter(float(limit), 2.0f * float(limit)); }

TEST(Limits, WindSpeedBoundsWavesPrimitivesAndGusts) {
  const float v = float(BOREAS_WIND_MAX_SPEED);
  boreas_wave w = boreas_default_wave();
  w.amplitude = v;
  w.speed = -v;
  EXPECT_NO_THROW(impl::checked_wave(w, "w"));
  w.amplitude = past(BOREAS_WIND_MAX_SPEED);
  expect_error([&] { impl::checked_wave(w, "w"); }, BOREAS_ERROR_INVALID_ARGUMENT, {"w.amplitude"});
  w.amplitude = v;
  w.speed = -past(BOREAS_WIND_MAX_SPEED);
  expect_error([&] { impl::checked_wave(w, "w"); }, BOREAS_ERROR_INVALID_ARGUMENT, {"w.speed"});

  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.strength = v;
  EXPECT_NO_THROW(impl::checked_primitive(p, "p"));
  p.strength = past(BOREAS_WIND_MAX_SPEED);
  expect_error([&] { impl::checked_primitive(p, "p"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"p.strength"});
  boreas_gust_def g = boreas_default_gust_def();
  g.strength = -v;
  EXPECT_NO_THROW(impl::checked_gust(g, "g"));
  g.strength = -past(BOREAS_WIND_MAX_SPEED);
  expect_error([&] { impl::checked_gust(g, "g"); }, BOREAS_ERROR_INVALID_ARGUMENT, {"g.strength"});
}

TEST(Limits, LidarChannelsRaysPerTurnAndDepthPixels) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.channels = BOREAS_LIDAR_MAX_CHANNELS;
  d.points_per_turn = BOREAS_LIDAR_MAX_RAYS_PER_TURN / BOREAS_LIDAR_MAX_CHANNELS;
  EXPECT_NO_THROW(impl::checked_lidar_def(d));
  d.points_per_turn += 1;
  expect_error([&] { impl::checked_lidar_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"channels * points_per_turn", "2^22"});
  d.points_per_turn = 1;
  d.channels = BOREAS_LIDAR_MAX_CHANNELS + 1;
  expect_error([&] { impl::checked_lidar_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT, {"channels"});
  boreas_depth_camera_def c = boreas_default_depth_camera_def();
  c.width = 4096;
  c.height = BOREAS_DEPTH_CAMERA_MAX_PIXELS / 4096;
  EXPECT_NO_THROW(impl::checked_depth_camera_def(c));
  c.height += 1;
  expect_error([&] { impl::checked_depth_camera_def(c); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"width * height", "2^24"});
}

TEST(Limits, GridResolutionCellsAndOrigin) {
  boreas_grid_def g = boreas_default_grid_def();
  // The most cells in all, with the most along two axes.
  g.resolution[0] = g.resolution[2] = BOREAS_GRID_MAX_RESOLUTION;
  g.resolution[1] =
      BOREAS_GRID_MAX_CELLS / (BOREAS_GRID_MAX_RESOLUTION * BOREAS_GRID_MAX_RESOLUTION);
  g.origin[0] = -float(BOREAS_WORLD_MAX_COORDINATE);
  EXPECT_NO_THROW(impl::checked_grid(g, "grid"));
  g.resolution[1] += 1;
  expect_error([&] { impl::checked_grid(g, "grid"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"grid.resolution", "2^26"});
  g.resolution[1] = 2;
  g.resolution[0] = BOREAS_GRID_MAX_RESOLUTION + 1;
  expect_error([&] { impl::checked_grid(g, "grid"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"grid.resolution[0]"});
  g.resolution[0] = 2;
  g.origin[0] = -past(BOREAS_WORLD_MAX_COORDINATE);
  expect_error([&] { impl::checked_grid(g, "grid"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"grid.origin[0]"});
}

TEST(Limits, CoordinatesBoundTreesAndPositions) {
  boreas_tree_def t = boreas_default_tree_def();
  t.species = "quaking_aspen";
  t.position[2] = float(BOREAS_WORLD_MAX_COORDINATE);
  EXPECT_NO_THROW(impl::checked_tree_def(t));
  t.position[2] = past(BOREAS_WORLD_MAX_COORDINATE);
  expect_error([&] { impl::checked_tree_def(t); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"tree_def.position[2]"});
  float at[3] = {0.0f, -float(BOREAS_WORLD_MAX_COORDINATE), 0.0f};
  EXPECT_NO_THROW(impl::check_position(at, "center"));
  at[1] = -past(BOREAS_WORLD_MAX_COORDINATE);
  expect_error([&] { impl::check_position(at, "center"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"center[1]"});
}

TEST(Limits, MeadowDensityComponentsSpeciesAndSeedPoints) {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.size[0] = d.size[1] = 1.0f;
  d.density = float(BOREAS_MEADOW_MAX_DENSITY);
  d.seed_points = BOREAS_MEADOW_MAX_SEED_POINTS;
  EXPECT_NO_THROW(impl::checked_meadow_def(d));
  d.density = past(BOREAS_MEADOW_MAX_DENSITY);
  expect_error([&] { impl::checked_meadow_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"meadow_def.density"});
  d.density = 1.0f;
  d.seed_points = BOREAS_MEADOW_MAX_SEED_POINTS + 1;
  expect_error([&] { impl::checked_meadow_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"meadow_def.seed_points"});
  d.seed_points = 8;

  // A square meadow of exactly the most components, at one per square meter.
  const float side = std::sqrt(float(BOREAS_MEADOW_MAX_COMPONENTS));
  ASSERT_EQ(double(side) * side, double(BOREAS_MEADOW_MAX_COMPONENTS));
  d.size[0] = d.size[1] = side;
  EXPECT_NO_THROW(impl::checked_meadow_def(d));
  d.density = std::nextafter(1.0f, 2.0f);
  expect_error([&] { impl::checked_meadow_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"components; at most"});
  d.density = 1.0f;

  std::vector<boreas_meadow_species> mix(BOREAS_MEADOW_MAX_SPECIES + 1,
                                         boreas_meadow_species{"meadow_grass", 1.0f});
  d.species = mix.data();
  d.species_count = BOREAS_MEADOW_MAX_SPECIES;
  EXPECT_NO_THROW(impl::checked_meadow_def(d));
  d.species_count = BOREAS_MEADOW_MAX_SPECIES + 1;
  expect_error([&] { impl::checked_meadow_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"meadow_def.species_count"});
}

TEST(Limits, PlantComponentsOfAnUnderbrushSpecies) {
  // 64 blades with 3 leaves each: 256 components; one more part makes 257.
  static_assert(BOREAS_PLANT_MAX_COMPONENTS == 64 + 64 * 3, "the file below makes that many");
  const std::string head = R"({"format": "boreas-underbrush-1", "name": "x", "parts": [
      {"name": "blade", "count": 64}, {"name": "leaf", "parent": "blade", "count": 3})";
  EXPECT_NO_THROW(impl::parse_component_species(head + "]}", "most.json"));
  expect_error(
      [&] { impl::parse_component_species(head + R"(, {"name": "one_more"}]})", "more.json"); },
      BOREAS_ERROR_INVALID_ARGUMENT, {"more.json: parts make 257 components per plant"});
}

TEST(Limits, WavesStepAndSamplePointsOfAWorld) {
  boreas_world world = nullptr;
  ASSERT_EQ(boreas::test::create_small_windy_world(&world), BOREAS_OK) << boreas_last_error();
  std::vector<boreas_wave> waves(BOREAS_WIND_MAX_WAVES + 1, boreas_default_wave());
  EXPECT_EQ(boreas_wind_set_waves(world, waves.data(), BOREAS_WIND_MAX_WAVES + 1, 0.0f),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_wind_set_waves(world, waves.data(), BOREAS_WIND_MAX_WAVES, 0.0f), BOREAS_OK)
      << boreas_last_error();
  EXPECT_EQ(boreas_wind_set_waves(world, waves.data(), 1, 0.0f), BOREAS_OK);

  EXPECT_EQ(boreas_world_step(world, past(BOREAS_STEP_MAX_SECONDS)), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_world_step(world, float(BOREAS_STEP_MAX_SECONDS)), BOREAS_OK)
      << boreas_last_error();
  EXPECT_EQ(boreas_world_get_time(world), BOREAS_STEP_MAX_SECONDS);

  // Refused before any point is read: the buffers hold one point.
  float xyz[3] = {0.0f, 1.0f, 0.0f}, wind[3];
  EXPECT_EQ(boreas_wind_sample(world, xyz, BOREAS_WIND_SAMPLE_MAX_POINTS + 1, wind),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error())
                .find("count must be <= " + std::to_string(BOREAS_WIND_SAMPLE_MAX_POINTS)),
            std::string::npos)
      << boreas_last_error();
  boreas_world_destroy(world);
}

}  // namespace
