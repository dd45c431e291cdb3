// The meadow, collider and emitter C API: planting, reading back, bad input, and the
// state of other meadows kept across adds and removes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "support/test_support.h"
#include "underbrush/meadow.h"
#include "underbrush_fixtures.h"

namespace boreas {
namespace {

struct CWorld {
  boreas_world w = nullptr;
  explicit CWorld(float wind = 0.0f) {
    boreas_world_def def = boreas_default_world_def();
    def.grid = test::calm_grid();
    boreas_wave wave = test::steady_wave(1.0f, 0.0f, wind);
    def.waves = wind > 0.0f ? &wave : nullptr;
    def.wave_count = wind > 0.0f ? 1 : 0;
    EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_OK) << boreas_last_error();
  }
  ~CWorld() { boreas_world_destroy(w); }
};

boreas_meadow_def small_meadow(float size = 2.0f, float density = 300.0f) {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.size[0] = d.size[1] = size;
  d.density = density;
  return d;
}

std::vector<boreas_component> components(boreas_world w, boreas_meadow_id m) {
  int n = 0;
  EXPECT_EQ(boreas_meadow_get_components(w, m, nullptr, 0, &n), BOREAS_OK) << boreas_last_error();
  std::vector<boreas_component> out(static_cast<size_t>(n));
  EXPECT_EQ(boreas_meadow_get_components(w, m, out.data(), n, &n), BOREAS_OK);
  return out;
}

TEST(MeadowApi, PlantsAboutTheRequestedDensityAtRest) {
  CWorld cw;
  boreas_meadow_def def = small_meadow(3.0f, 250.0f);
  def.center[0] = 1.0f;
  boreas_meadow_id m;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &def, &m), BOREAS_OK) << boreas_last_error();
  std::vector<boreas_component> c = components(cw.w, m);
  // Density is the target where the ground allows; the procedural ground allows most.
  EXPECT_GT(c.size(), 0.3 * 250 * 9);
  EXPECT_LT(c.size(), 1.2 * 250 * 9);
  int species_seen[3] = {0, 0, 0};
  int roots = 0, roots_above = 0;
  for (const boreas_component& x : c) {
    if (x.parent < 0) {  // rooted within a quarter spacing of a plant inside the rectangle
      EXPECT_GE(x.base[0], 1.0f - 1.5f - 0.05f);
      EXPECT_LE(x.base[0], 1.0f + 1.5f + 0.05f);
    }
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(x.center_of_mass[a], x.rest_center_of_mass[a]);
      EXPECT_EQ(x.velocity[a], 0.0f);
    }
    if (x.parent < 0) {
      ++roots;
      roots_above += x.center_of_mass[1] > x.base[1];
    }
    ASSERT_GE(x.species, 0);
    ASSERT_LT(x.species, 3);
    ++species_seen[x.species];
  }
  for (int s = 0; s < 3; ++s) EXPECT_GT(species_seen[s], 0) << "species " << s;
  // At rest, above the ground they grow from, but for the longest, most tilted blades: a
  // blade 1.3 times the mean's length (length_variation) bends 2.2 times as far under its
  // weight (the cantilever's L^3) and may droop past its base.
  EXPECT_GT(roots_above, 0.97 * roots) << roots_above << " of " << roots;
  std::printf("    %d of %d ground components hold their center of mass above their base\n", roots_above, roots);
  // Capacity smaller than the total: refused, naming the count needed.
  int n = 0;
  boreas_component one;
  EXPECT_EQ(boreas_meadow_get_components(cw.w, m, &one, 1, &n), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("below the " + std::to_string(c.size())),
            std::string::npos)
      << boreas_last_error();
}

TEST(MeadowApi, SameSeedSameMeadow) {
  CWorld a, b;
  boreas_meadow_def def = small_meadow();
  boreas_meadow_id ma, mb;
  ASSERT_EQ(boreas_world_add_meadow(a.w, &def, &ma), BOREAS_OK);
  ASSERT_EQ(boreas_world_add_meadow(b.w, &def, &mb), BOREAS_OK);
  std::vector<boreas_component> ca = components(a.w, ma), cb = components(b.w, mb);
  ASSERT_EQ(ca.size(), cb.size());
  EXPECT_EQ(std::memcmp(ca.data(), cb.data(), ca.size() * sizeof(boreas_component)), 0);
  def.seed = 2;
  boreas_meadow_id mc;
  ASSERT_EQ(boreas_world_add_meadow(b.w, &def, &mc), BOREAS_OK);
  std::vector<boreas_component> cc = components(b.w, mc);
  EXPECT_TRUE(cc.size() != ca.size() || std::memcmp(ca.data(), cc.data(), ca.size() * sizeof(boreas_component)) != 0);
}

TEST(MeadowApi, BadDefinitionsAreRefusedAndChangeNothing) {
  CWorld cw;
  boreas_meadow_id good;
  boreas_meadow_def def = small_meadow(1.0f, 100.0f);
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &def, &good), BOREAS_OK);
  std::vector<boreas_component> before = components(cw.w, good);

  struct Case {
    const char* expect;
    void (*edit)(boreas_meadow_def&);
  } cases[] = {
      {"meadow_def.center[1]", [](boreas_meadow_def& d) { d.center[1] = NAN; }},
      {"meadow_def.size[0]", [](boreas_meadow_def& d) { d.size[0] = -3.0f; }},
      {"meadow_def.density", [](boreas_meadow_def& d) { d.density = -1.0f; }},
      {"components; at most", [](boreas_meadow_def& d) { d.size[0] = d.size[1] = 1e4f; }},
      {"meadow_def.shape_angles", [](boreas_meadow_def& d) { d.shape_angles = 2; }},
      {"meadow_def.lod_distances", [](boreas_meadow_def& d) { d.lod_distances[1] = 1.0f; }},
      {"meadow_def.species is NULL", [](boreas_meadow_def& d) { d.species_count = 2; }},
  };
  for (const Case& c : cases) {
    boreas_meadow_def bad = small_meadow(1.0f, 100.0f);
    c.edit(bad);
    boreas_meadow_id id{7u, 7u, 7u};  // a sentinel: must stay as it is
    EXPECT_EQ(boreas_world_add_meadow(cw.w, &bad, &id), BOREAS_ERROR_INVALID_ARGUMENT) << c.expect;
    EXPECT_NE(std::string(boreas_last_error()).find(c.expect), std::string::npos) << boreas_last_error();
    EXPECT_EQ(id.index, 7u);
  }
  boreas_meadow_species unknown = {"no_such_grass", 1.0f};
  boreas_meadow_def bad = small_meadow(1.0f, 100.0f);
  bad.species = &unknown;
  bad.species_count = 1;
  boreas_meadow_id id;
  EXPECT_EQ(boreas_world_add_meadow(cw.w, &bad, &id), BOREAS_ERROR_IO);
  EXPECT_NE(std::string(boreas_last_error()).find("no_such_grass"), std::string::npos);
  const float heights[4] = {0.0f, 0.5f, std::nanf(""), 1.0f};
  bad = small_meadow(1.0f, 100.0f);
  bad.terrain = boreas_image{2, 2, 1, heights};
  EXPECT_EQ(boreas_world_add_meadow(cw.w, &bad, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error())
                .find("meadow_def.terrain: pixel (0, 1) channel 0 is not a finite number"),
            std::string::npos)
      << boreas_last_error();
  bad = small_meadow(1.0f, 100.0f);
  bad.nutrients = boreas_image{8, 8, 3, nullptr};
  EXPECT_EQ(boreas_world_add_meadow(cw.w, &bad, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("meadow_def.nutrients.pixels is NULL"),
            std::string::npos)
      << boreas_last_error();
  EXPECT_EQ(boreas_world_add_meadow(cw.w, nullptr, &id), BOREAS_ERROR_INVALID_ARGUMENT);

  // The world is as it was: the good meadow, alone, steps.
  EXPECT_EQ(boreas_world_step(cw.w, 0.02f), BOREAS_OK);
  std::vector<boreas_component> after = components(cw.w, good);
  ASSERT_EQ(after.size(), before.size());
  EXPECT_EQ(boreas_meadow_get_components(cw.w, boreas_meadow_id{good.index + 1, 1u, good.tag},
                                         nullptr, 0, &bad.seed_points),
            BOREAS_ERROR_NOT_FOUND);
}

TEST(MeadowApi, RemovingAMeadowKeepsTheOthersStateBitForBit) {
  CWorld cw(7.0f);
  boreas_meadow_def a = small_meadow(1.5f, 150.0f), b = small_meadow(1.5f, 150.0f);
  b.center[0] = 5.0f;
  b.seed = 9;
  boreas_meadow_id ma, mb;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &a, &ma), BOREAS_OK);
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &b, &mb), BOREAS_OK);
  for (int s = 0; s < 10; ++s) ASSERT_EQ(boreas_world_step(cw.w, 1.0f / 60.0f), BOREAS_OK);
  std::vector<boreas_component> before = components(cw.w, mb);
  ASSERT_EQ(boreas_world_remove_meadow(cw.w, ma), BOREAS_OK);
  std::vector<boreas_component> after = components(cw.w, mb);
  ASSERT_EQ(before.size(), after.size());
  EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(boreas_component)), 0);
  int n;
  EXPECT_EQ(boreas_meadow_get_components(cw.w, ma, nullptr, 0, &n), BOREAS_ERROR_NOT_FOUND);
  // And adding one back does not disturb it either.
  boreas_meadow_id mc;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &a, &mc), BOREAS_OK);
  after = components(cw.w, mb);
  EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(boreas_component)), 0);
}

TEST(MeadowApi, ColliderCallsCheckTheirArguments) {
  CWorld cw;
  boreas_collider_def ball = boreas_default_collider_def();
  EXPECT_FLOAT_EQ(ball.radius, 0.11f);
  boreas_collider_id id;
  ASSERT_EQ(boreas_world_add_collider(cw.w, &ball, &id), BOREAS_OK);
  float nan_center[3] = {0.0f, NAN, 0.0f};
  EXPECT_EQ(boreas_collider_set_position(cw.w, id, nan_center), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("center[1]"), std::string::npos);
  EXPECT_EQ(boreas_collider_set_position(cw.w, id, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  ball.radius = 0.0f;
  boreas_collider_id bad;
  EXPECT_EQ(boreas_world_add_collider(cw.w, &ball, &bad), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("collider_def.radius"), std::string::npos);
  ASSERT_EQ(boreas_world_remove_collider(cw.w, id), BOREAS_OK);
  float c[3] = {0, 0, 0};
  EXPECT_EQ(boreas_collider_set_position(cw.w, id, c), BOREAS_ERROR_NOT_FOUND);
  boreas_emitter_def e = boreas_default_emitter_def();
  e.event_radius = -1.0f;
  boreas_emitter_id bad_emitter;
  EXPECT_EQ(boreas_world_add_emitter(cw.w, &e, &bad_emitter), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("emitter_def.event_radius"), std::string::npos);
}

TEST(MeadowApi, VerticesCountsAndCapacity) {
  CWorld cw;
  boreas_meadow_def def = small_meadow(1.0f, 100.0f);
  boreas_meadow_id m;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &def, &m), BOREAS_OK);
  int components_n = int(components(cw.w, m).size());
  int n = 0;
  ASSERT_EQ(boreas_meadow_get_vertices(cw.w, m, nullptr, nullptr, 0, &n, nullptr), BOREAS_OK);
  EXPECT_EQ(n, components_n * BOREAS_MEADOW_VERTEX_STRIDE);
  std::vector<boreas_meadow_vertex> v(static_cast<size_t>(n));
  std::vector<int32_t> strips(static_cast<size_t>(components_n));
  EXPECT_EQ(boreas_meadow_get_vertices(cw.w, m, nullptr, v.data(), n - 1, &n, strips.data()),
            BOREAS_ERROR_INVALID_ARGUMENT);
  ASSERT_EQ(boreas_meadow_get_vertices(cw.w, m, nullptr, v.data(), int(v.size()), &n, strips.data()), BOREAS_OK);
  for (int32_t s : strips) {
    EXPECT_GE(s, 4);
    EXPECT_LE(s, BOREAS_MEADOW_VERTEX_STRIDE);
    EXPECT_EQ(s % 2, 0);
  }
  float cam[3] = {0.0f, 1.0f, 500.0f};  // beyond the cull distance
  ASSERT_EQ(boreas_meadow_get_vertices(cw.w, m, cam, v.data(), int(v.size()), &n, strips.data()), BOREAS_OK);
  for (int32_t s : strips) EXPECT_EQ(s, 0);
}

// A nutrient map whose right half is rich and left half bare grows plants on the right only;
// the caller's array may go away once the call returns (it was copied).
TEST(MeadowApi, PlantsFollowTheNutrientPixels) {
  const int w = 64, h = 64;
  auto pixels = std::make_unique<std::vector<float>>(size_t(w) * h * 3, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = w / 2; x < w; ++x)
      for (int c = 0; c < 3; ++c) (*pixels)[(size_t(y) * w + x) * 3 + c] = 0.9f;

  CWorld cw;
  boreas_meadow_def def = small_meadow(4.0f, 200.0f);
  def.nutrients = boreas_image{w, h, 3, pixels->data()};
  boreas_meadow_id m;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &def, &m), BOREAS_OK) << boreas_last_error();
  pixels.reset();
  ASSERT_EQ(boreas_world_step(cw.w, 0.02f), BOREAS_OK);
  int left = 0, right = 0;
  for (const boreas_component& c : components(cw.w, m)) {
    if (c.parent >= 0) continue;
    (c.base[0] < -0.1f ? left : right) += c.base[0] < -0.1f || c.base[0] > 0.1f;
  }
  EXPECT_GT(right, 100);
  EXPECT_EQ(left, 0);
}

// A height map lifts every plant's base onto the ground it describes: a ramp along x.
TEST(MeadowApi, PlantsStandOnTheTerrainPixels) {
  const std::vector<float> ramp = {0.0f, 1.0f, 0.0f, 1.0f};  // 2 x 2: low at -x, high at +x
  CWorld cw;
  boreas_meadow_def def = small_meadow(4.0f, 50.0f);
  def.terrain = boreas_image{2, 2, 1, ramp.data()};
  def.terrain_relief = 2.0f;
  boreas_meadow_id m;
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &def, &m), BOREAS_OK) << boreas_last_error();
  // A plant's components share its root's height, a few cm from their own bases, so each
  // base is within the ramp's slope times that spread, and the fitted slope is the ramp's.
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  int checked = 0;
  for (const boreas_component& c : components(cw.w, m)) {
    if (c.parent >= 0) continue;
    // y = center_y + relief * (x - x0) / size_x, bilinear between the two columns.
    const double expected = def.center[1] + 2.0 * (c.base[0] - (def.center[0] - 2.0)) / 4.0;
    EXPECT_NEAR(c.base[1], expected, 0.03) << "at x " << c.base[0];
    n += 1;
    sx += c.base[0];
    sy += c.base[1];
    sxx += double(c.base[0]) * c.base[0];
    sxy += double(c.base[0]) * c.base[1];
    ++checked;
  }
  EXPECT_NEAR((n * sxy - sx * sy) / (n * sxx - sx * sx), 0.5, 0.01);
  EXPECT_GT(checked, 50);
}

// The pixels are copied from the def and become the ground's grids; a planted meadow, which
// keeps its params for life, keeps no copy of them (a 4096^2 height map would be 64 MB).
TEST(MeadowApi, APlantedMeadowKeepsNoCopyOfThePixels) {
  const std::vector<float> ramp(64 * 64 * 2, 0.5f);
  boreas_meadow_def def = small_meadow(2.0f, 50.0f);
  def.terrain = boreas_image{64, 64, 2, ramp.data()};
  def.nutrients = boreas_image{64, 64, 2, ramp.data()};
  impl::MeadowParams params = impl::checked_meadow_def(def);
  ASSERT_EQ(params.terrain.data.size(), ramp.size());
  ASSERT_EQ(params.nutrients.data.size(), ramp.size());
  const impl::Meadow meadow = impl::plant_meadow(std::move(params));
  EXPECT_GT(meadow.count, 0);
  EXPECT_EQ(meadow.params.terrain.data.capacity(), 0u);
  EXPECT_EQ(meadow.params.nutrients.data.capacity(), 0u);
}

// A renderer finds each component's look through its species and part.
TEST(MeadowApi, PartsCarryTheSpeciesFilesLook) {
  CWorld cw;
  test::TempDir dir;
  const std::string path = dir.str() + "/poppy.json";
  std::ofstream(path) << R"({"format": "boreas-underbrush-1", "name": "poppy", "parts": [
      {"name": "stalk", "profile": "stalk", "length": 0.3, "width": 0.002, "thickness": 0.002, "tilt": [0, 10]},
      {"name": "petal", "parent": "stalk", "count": 4, "profile": "petal", "length": 0.03, "width": 0.02,
       "tilt": [60, 80], "color": [0.85, 0.1, 0.05], "translucency": 0.5}]})";
  boreas_meadow_species species[2] = {{"clover", 1.0f}, {path.c_str(), 1.0f}};
  boreas_meadow_def d = small_meadow(1.0f, 200.0f);
  d.species = species;
  d.species_count = 2;
  boreas_meadow_id m{};
  ASSERT_EQ(boreas_world_add_meadow(cw.w, &d, &m), BOREAS_OK) << boreas_last_error();
  int n = 0;
  ASSERT_EQ(boreas_meadow_get_parts(cw.w, m, nullptr, 0, &n), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(n, 4);  // clover: petiole, leaflet; poppy: stalk, petal
  std::vector<boreas_meadow_part> parts(static_cast<size_t>(n));
  ASSERT_EQ(boreas_meadow_get_parts(cw.w, m, parts.data(), n, &n), BOREAS_OK);
  EXPECT_EQ(parts[1].species, 0);
  EXPECT_EQ(parts[1].part, 1);
  EXPECT_STREQ(parts[1].name, "leaflet");
  EXPECT_EQ(parts[3].species, 1);
  EXPECT_STREQ(parts[3].name, "petal");
  EXPECT_FLOAT_EQ(parts[3].color[0], 0.85f);
  EXPECT_FLOAT_EQ(parts[3].translucency, 0.5f);
  EXPECT_GT(parts[2].color[1], parts[2].color[0]);  // the stalk: green by default
  // Every component's (species, part) is listed.
  for (const boreas_component& c : components(cw.w, m)) {
    bool found = false;
    for (const boreas_meadow_part& p : parts)
      found = found || (p.species == c.species && p.part == c.part);
    EXPECT_TRUE(found) << c.species << " " << c.part;
  }
}

TEST(MeadowApi, CppWrapperPlantsStepsAndDraws) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = test::calm_grid();
  boreas::World world(def);
  EXPECT_EQ(boreas::builtin_underbrush_species().size(), 4u);
  boreas_meadow_species grass = {"meadow_grass", 1.0f};
  boreas_meadow_def m = small_meadow(1.0f, 200.0f);
  m.species = &grass;
  m.species_count = 1;
  boreas_meadow_id meadow = world.add_meadow(m);
  boreas_collider_id ball = world.add_collider(boreas_default_collider_def());
  world.collider_set_position(ball, {0.2f, 0.11f, 0.0f});
  world.step(0.05f);
  std::vector<boreas_component> c = world.meadow_get_components(meadow);
  ASSERT_FALSE(c.empty());
  for (const boreas_component& x : c) EXPECT_EQ(x.species, 0);
  boreas::World::Strips s = world.meadow_get_vertices(meadow);
  EXPECT_EQ(s.counts.size(), c.size());
  EXPECT_EQ(s.vertices.size(), c.size() * BOREAS_MEADOW_VERTEX_STRIDE);
  EXPECT_THROW(world.collider_set_position(
                   boreas_collider_id{ball.index, ball.generation + 1, ball.tag}, {0, 0, 0}),
               std::exception);
}

}  // namespace
}  // namespace boreas
