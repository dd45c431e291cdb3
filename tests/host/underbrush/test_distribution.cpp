// boreas tests: the meadow's ground and where its plants grow (Endo et al. sec. 5.2) —
// bilinear grids, procedural and image terrain and nutrients, and the distribution's
// determinism, spacing, response to nutrients, competition, refusals and speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "errors.h"
#include "support/test_support.h"
#include "trees/tree_random.h"
#include "underbrush/distribution.h"
#include "underbrush/terrain.h"

namespace boreas::impl {
namespace {

GroundRect rect_of(double size_x, double size_z, double center_y = 0.0) {
  GroundRect r;
  r.center_x = 3.0;  // off the origin, so origin mistakes show
  r.center_y = center_y;
  r.center_z = -2.0;
  r.size_x = size_x;
  r.size_z = size_z;
  return r;
}

// One nutrient, `left` for x below the rectangle's middle and `right` from it on, with the
// step between two samples 0.05 m apart.
NutrientMaps half_nutrients(const GroundRect& r, float left, float right) {
  NutrientMaps m;
  m.grid.nx = int(std::lround(r.size_x / 0.05)) + 1;
  m.grid.nz = 2;
  m.grid.origin_x = r.center_x - 0.5 * r.size_x;
  m.grid.origin_z = r.center_z - 0.5 * r.size_z;
  m.grid.size_x = r.size_x;
  m.grid.size_z = r.size_z;
  m.channels = 1;
  for (int k = 0; k < m.grid.nz; ++k) {
    for (int i = 0; i < m.grid.nx; ++i) {
      m.values[0].push_back(2 * i < m.grid.nx - 1 ? left : right);
    }
  }
  return m;
}

NutrientMaps constant_nutrients(const GroundRect& r, float value) {
  return half_nutrients(r, value, value);
}

PlantNeeds kind(double spacing, double need0 = 0.0, double consumption0 = 0.0) {
  PlantNeeds k;
  k.spacing = spacing;
  k.need[0] = need0;
  k.consumption[0] = consumption0;
  return k;
}

DistributionParams params(int64_t target, uint64_t seed = 7) {
  DistributionParams p;
  p.target_count = target;
  p.seed = seed;
  return p;
}

// Pairs of plants closer than their spacing, found with a grid of `cell` m cells (at
// least the largest spacing), distances from the float positions in double.
int64_t spacing_violations(const std::vector<Planting>& plants,
                           const std::vector<PlantNeeds>& kinds, double cell) {
  std::unordered_map<int64_t, std::vector<size_t>> cells;
  const auto key = [](int64_t i, int64_t k) { return i * 1000003 + k; };
  for (size_t p = 0; p < plants.size(); ++p) {
    const auto i = int64_t(std::floor(plants[p].position[0] / cell));
    const auto k = int64_t(std::floor(plants[p].position[2] / cell));
    cells[key(i, k)].push_back(p);
  }
  int64_t violations = 0;
  for (size_t p = 0; p < plants.size(); ++p) {
    const auto i = int64_t(std::floor(plants[p].position[0] / cell));
    const auto k = int64_t(std::floor(plants[p].position[2] / cell));
    for (int64_t dk = -1; dk <= 1; ++dk) {
      for (int64_t di = -1; di <= 1; ++di) {
        auto it = cells.find(key(i + di, k + dk));
        if (it == cells.end()) continue;
        for (size_t q : it->second) {
          if (q <= p) continue;
          const double dx = double(plants[p].position[0]) - double(plants[q].position[0]);
          const double dz = double(plants[p].position[2]) - double(plants[q].position[2]);
          const double s = std::max(kinds[size_t(plants[p].kind)].spacing,
                                    kinds[size_t(plants[q].kind)].spacing);
          if (dx * dx + dz * dz < s * s) ++violations;
        }
      }
    }
  }
  return violations;
}

uint64_t hash_plantings(const std::vector<Planting>& plants) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a over the bytes
  for (const Planting& p : plants) {
    unsigned char bytes[sizeof(Planting)];
    std::memcpy(bytes, &p, sizeof(Planting));
    for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
  }
  return h;
}

template <typename F>
boreas_status status_of(F&& f, std::string* message = nullptr) {
  try {
    f();
  } catch (const Error& e) {
    if (message) *message = e.what();
    return e.status();
  }
  return BOREAS_OK;
}

// A caller's pixel array as the C API takes it.
GroundPixels pixels_of(int width, int height, int channels, const std::vector<float>& values) {
  return checked_ground_pixels(boreas_image{width, height, channels, values.data()}, "test");
}

// ---------------------------------------------------------------------------------------
// Terrain and nutrients

TEST(Terrain, GridSampleIsBilinearAndClampsOutside) {
  GroundGrid g;
  g.nx = 3;
  g.nz = 2;
  g.origin_x = 1.0;
  g.origin_z = -1.0;
  g.size_x = 4.0;  // samples at x = 1, 3, 5
  g.size_z = 2.0;  // and z = -1, 1
  const std::vector<float> v = {0, 2, 4, 10, 12, 14};
  EXPECT_DOUBLE_EQ(g.sample(v, 1.0, -1.0), 0.0);
  EXPECT_DOUBLE_EQ(g.sample(v, 5.0, 1.0), 14.0);
  EXPECT_DOUBLE_EQ(g.sample(v, 3.0, 0.0), 7.0);
  EXPECT_DOUBLE_EQ(g.sample(v, 4.0, 0.5), 10.5);    // 3 + 7.5, bilinear
  EXPECT_DOUBLE_EQ(g.sample(v, -10.0, -5.0), 0.0);  // clamped to the corner
  EXPECT_DOUBLE_EQ(g.sample(v, 20.0, 0.0), 9.0);    // clamped in x only
}

TEST(Terrain, FlatTerrainIsFlatWithUpNormal) {
  const GroundRect r = rect_of(30.0, 20.0, 1.5);
  const Terrain t = procedural_terrain(r, 0.0, 42);
  TreeRandom rng(1, 0, 0);
  for (int s = 0; s < 200; ++s) {
    const double x = r.center_x + 0.6 * r.size_x * rng.uniform_pm1();
    const double z = r.center_z + 0.6 * r.size_z * rng.uniform_pm1();
    EXPECT_EQ(t.height_at(x, z), 1.5);
    double n[3];
    t.normal_at(x, z, n);
    EXPECT_EQ(n[0], 0.0);
    EXPECT_EQ(n[1], 1.0);
    EXPECT_EQ(n[2], 0.0);
  }
}

TEST(Terrain, ProceduralHeightStaysWithinRelief) {
  const GroundRect r = rect_of(80.0, 60.0, -3.0);
  const double relief = 2.0;
  const Terrain t = procedural_terrain(r, relief, 9);
  double lo = 1e9, hi = -1e9;
  for (float h : t.height) {
    lo = std::min(lo, double(h));
    hi = std::max(hi, double(h));
  }
  EXPECT_GE(lo, -3.0 - relief - 1e-5);
  EXPECT_LE(hi, -3.0 + relief + 1e-5);
  EXPECT_GT(hi - lo, 0.5 * relief) << "the ground should roll, not lie flat";
  // Between samples the bilinear surface stays within its samples' range.
  TreeRandom rng(2, 0, 0);
  for (int s = 0; s < 1000; ++s) {
    const double h = t.height_at(r.center_x + 0.5 * r.size_x * rng.uniform_pm1(),
                                 r.center_z + 0.5 * r.size_z * rng.uniform_pm1());
    EXPECT_GE(h, lo - 1e-9);
    EXPECT_LE(h, hi + 1e-9);
  }
}

TEST(Terrain, ProceduralIsDeterministicPerSeed) {
  const GroundRect r = rect_of(20.0, 20.0);
  EXPECT_EQ(procedural_terrain(r, 1.0, 5).height, procedural_terrain(r, 1.0, 5).height);
  EXPECT_NE(procedural_terrain(r, 1.0, 5).height, procedural_terrain(r, 1.0, 6).height);
}

TEST(Terrain, NormalMatchesHeightGradient) {
  const GroundRect r = rect_of(40.0, 30.0);
  const Terrain t = procedural_terrain(r, 3.0, 11);
  const double dx = t.grid.size_x / (t.grid.nx - 1), dz = t.grid.size_z / (t.grid.nz - 1);
  const double h = 1e-5;  // m, central difference step
  TreeRandom rng(3, 0, 0);
  int checked = 0;
  for (int s = 0; s < 500; ++s) {
    const double x = r.center_x + 0.49 * r.size_x * rng.uniform_pm1();
    const double z = r.center_z + 0.49 * r.size_z * rng.uniform_pm1();
    // The bilinear surface's slope jumps across grid lines: stay off them.
    const double fx = std::fmod(x - t.grid.origin_x, dx), fz = std::fmod(z - t.grid.origin_z, dz);
    if (fx < 1e-3 || fx > dx - 1e-3 || fz < 1e-3 || fz > dz - 1e-3) continue;
    const double gx = (t.height_at(x + h, z) - t.height_at(x - h, z)) / (2 * h);
    const double gz = (t.height_at(x, z + h) - t.height_at(x, z - h)) / (2 * h);
    const double len = std::sqrt(gx * gx + 1 + gz * gz);
    double n[3];
    t.normal_at(x, z, n);
    EXPECT_NEAR(n[0], -gx / len, 1e-4);
    EXPECT_NEAR(n[1], 1 / len, 1e-4);
    EXPECT_NEAR(n[2], -gz / len, 1e-4);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
    EXPECT_GT(n[1], 0.0);
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(Terrain, PixelRampGivesHeightsAtCornersAndCenter) {
  // 5 x 3: value = (column / 4 + row / 2) / 2.
  const int w = 5, h = 3;
  std::vector<float> values;
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) values.push_back(0.5f * (col / 4.0f + row / 2.0f));
  }
  const GroundRect r = rect_of(10.0, 6.0, 1.0);
  const double relief = 4.0;
  const Terrain t = pixel_terrain(r, relief, pixels_of(w, h, 1, values));
  ASSERT_EQ(t.grid.nx, w);
  ASSERT_EQ(t.grid.nz, h);
  const double x0 = r.center_x - 5.0, x1 = r.center_x + 5.0;
  const double z0 = r.center_z - 3.0, z1 = r.center_z + 3.0;
  const double tol = 1e-6;
  EXPECT_NEAR(t.height_at(x0, z0), 1.0, tol);                 // row 0, column 0: 0
  EXPECT_NEAR(t.height_at(x1, z0), 1.0 + 0.5 * relief, tol);  // row 0, last column
  EXPECT_NEAR(t.height_at(x0, z1), 1.0 + 0.5 * relief, tol);  // last row: +z edge
  EXPECT_NEAR(t.height_at(x1, z1), 1.0 + relief, tol);        // 1
  EXPECT_NEAR(t.height_at(r.center_x, r.center_z), 1.0 + 0.5 * relief, tol);
  // The ramp's slope: 0.5 relief over 10 m along x, 0.5 relief over 6 m along z.
  double n[3];
  t.normal_at(r.center_x + 0.3, r.center_z + 0.2, n);
  EXPECT_NEAR(-n[0] / n[1], 0.5 * relief / 10.0, 1e-3);
  EXPECT_NEAR(-n[2] / n[1], 0.5 * relief / 6.0, 1e-3);
}

TEST(Terrain, HeightsInMetersWithReliefOne) {
  // A height map in meters (negative values too) is used as given with relief 1.
  const std::vector<float> values = {-2.5f, 0.0f, 3.25f, 7.0f};
  const GroundRect r = rect_of(2.0, 2.0, 10.0);
  const Terrain t = pixel_terrain(r, 1.0, pixels_of(2, 2, 1, values));
  EXPECT_NEAR(t.height_at(r.center_x - 1, r.center_z - 1), 7.5, 1e-6);
  EXPECT_NEAR(t.height_at(r.center_x + 1, r.center_z + 1), 17.0, 1e-6);
}

TEST(Terrain, BadPixelArraysAreRefusedNamingTheField) {
  const std::vector<float> four = {0.0f, 0.5f, 1.0f, 0.25f};
  std::vector<float> with_nan = four;
  with_nan[3] = std::nanf("");
  const float* none = nullptr;
  struct Case {
    boreas_image image;
    std::string expect;
  };
  const Case cases[] = {
      {{2, 2, 1, none}, "f.pixels is NULL but its size is 2 x 2 x 1"},
      {{0, 2, 1, four.data()}, "f must be at least 1 x 1 pixels (got 0 x 2)"},
      {{2, -1, 1, four.data()}, "f must be at least 1 x 1 pixels (got 2 x -1)"},
      {{2, 2, 0, four.data()}, "f.channels must be in 1..16 (got 0)"},
      {{2, 2, 17, four.data()}, "f.channels must be in 1..16 (got 17)"},
      {{1 << 15, 1 << 14, 1, four.data()}, "values is more than the 268435456"},
      {{2, 2, 1, with_nan.data()}, "f: pixel (1, 1) channel 0 is not a finite number"},
      {{1, 2, 2, with_nan.data()}, "f: pixel (0, 1) channel 1 is not a finite number"},
  };
  for (const Case& c : cases) {
    std::string message;
    EXPECT_EQ(status_of([&] { checked_ground_pixels(c.image, "f"); }, &message),
              BOREAS_ERROR_INVALID_ARGUMENT)
        << c.expect;
    EXPECT_NE(message.find(c.expect), std::string::npos) << message;
  }
  EXPECT_TRUE(checked_ground_pixels(boreas_image{0, 0, 0, nullptr}, "f").empty());
  // The copy is the caller's values, channel fastest.
  const GroundPixels p = checked_ground_pixels(boreas_image{2, 1, 2, four.data()}, "f");
  EXPECT_EQ(p.data, four);
  // A height out of any terrain's range (a wrong unit) names the pixel.
  std::string message;
  const std::vector<float> tall = {0.0f, 0.0f, 3e5f, 0.0f};
  EXPECT_EQ(
      status_of([&] { pixel_terrain(rect_of(4, 4), 1e4, pixels_of(2, 2, 1, tall)); }, &message),
      BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(message.find("meadow_def.terrain: pixel (0, 1)"), std::string::npos) << message;
}

TEST(Terrain, RgbPixelsGiveThreeNutrients) {
  const std::vector<float> values = {0.0f, 0.2f, 0.4f, 0.6f, 0.8f, 1.0f,   // row 0
                                     0.2f, 0.2f, 0.2f, 1.0f, 0.0f, 0.6f};  // row 1
  const GroundRect r = rect_of(8.0, 4.0);
  const NutrientMaps m = pixel_nutrients(r, pixels_of(2, 2, 3, values));
  ASSERT_EQ(m.channels, 3);
  const double x0 = r.center_x - 4, x1 = r.center_x + 4, z0 = r.center_z - 2, z1 = r.center_z + 2;
  const double corners[4][2] = {{x0, z0}, {x1, z0}, {x0, z1}, {x1, z1}};
  for (int c = 0; c < 4; ++c) {
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(m.at(ch, corners[c][0], corners[c][1]), values[size_t(c * 3 + ch)], 1e-6)
          << "corner " << c << " channel " << ch;
    }
  }
  EXPECT_NEAR(m.at(1, r.center_x, r.center_z), (0.2 + 0.8 + 0.2 + 0.0) / 4, 1e-6);
}

TEST(Terrain, OneChannelGivesOneNutrientAndValuesAreClamped) {
  const GroundRect r = rect_of(4.0, 4.0);
  const NutrientMaps m = pixel_nutrients(r, pixels_of(3, 1, 1, {0.2f, 0.6f, 1.0f}));
  ASSERT_EQ(m.channels, 1);
  EXPECT_NEAR(m.at(0, r.center_x - 2, r.center_z), 0.2, 1e-6);
  EXPECT_NEAR(m.at(0, r.center_x + 1, r.center_z + 1.9), 0.8, 1e-6);  // one row: no z change
  EXPECT_EQ(m.at(1, r.center_x, r.center_z), 0.0);                    // a channel it does not have
  // A concentration stays in 0..1 whatever the caller's floats.
  const NutrientMaps c = pixel_nutrients(r, pixels_of(2, 1, 1, {-3.0f, 7.0f}));
  EXPECT_EQ(c.at(0, r.center_x - 2, r.center_z), 0.0);
  EXPECT_EQ(c.at(0, r.center_x + 2, r.center_z), 1.0);
}

TEST(Terrain, ProceduralNutrientsAreSmoothPatchesInUnitRange) {
  const GroundRect r = rect_of(60.0, 60.0);
  const NutrientMaps m = procedural_nutrients(r, 3);
  ASSERT_EQ(m.channels, kMaxNutrients);
  for (int c = 0; c < kMaxNutrients; ++c) {
    const std::vector<float>& v = m.values[c];
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    EXPECT_GE(*lo, 0.0f);
    EXPECT_LE(*hi, 1.0f);
    EXPECT_GT(*hi - *lo, 0.6f) << "channel " << c << " should have poor and rich patches";
    // Smooth: 0.25 m apart differs little; patches a few meters across: 20 m apart is
    // another patch (on average far more different than 0.25 m apart).
    double near = 0.0, far = 0.0;
    TreeRandom rng(4, uint64_t(c), 0);
    for (int s = 0; s < 2000; ++s) {
      const double x = r.center_x + 20 * rng.uniform_pm1(), z = r.center_z + 20 * rng.uniform_pm1();
      near = std::max(near, std::abs(m.at(c, x + 0.25, z) - m.at(c, x, z)));
      far += std::abs(m.at(c, x + 20.0, z) - m.at(c, x, z)) / 2000;
    }
    EXPECT_LT(near, 0.2) << "channel " << c;
    EXPECT_GT(far, 0.1) << "channel " << c;
  }
  EXPECT_NE(m.values[0], m.values[1]);
  EXPECT_EQ(procedural_nutrients(r, 3).values[2], m.values[2]);
  EXPECT_NE(procedural_nutrients(r, 4).values[2], m.values[2]);
}

TEST(Terrain, BadRectOrReliefIsInvalidArgument) {
  std::string message;
  GroundRect r = rect_of(0.0, 4.0);
  EXPECT_EQ(status_of([&] { procedural_terrain(r, 1.0, 1); }, &message),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(message.find("size_x"), std::string::npos) << message;
  EXPECT_EQ(status_of([&] { procedural_nutrients(r, 1); }), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(status_of([&] { procedural_terrain(rect_of(4, 4), -1.0, 1); }, &message),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(message.find("relief"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------------------
// Distribution

struct Scene {
  GroundRect rect = rect_of(20.0, 16.0);
  Terrain terrain = procedural_terrain(rect, 1.0, 2);
  NutrientMaps nutrients = procedural_nutrients(rect, 2);
  std::vector<PlantNeeds> kinds;
  Scene() {
    PlantNeeds grass = kind(0.1, 0.3, 0.002);
    PlantNeeds clover = kind(0.15);
    clover.need[1] = 0.4;
    clover.consumption[1] = 0.004;
    clover.weight = 0.5;
    kinds = {grass, clover};
  }
};

TEST(Distribution, SameInputsGiveSameBits) {
  const Scene s;
  const auto a = distribute(s.terrain, s.nutrients, s.kinds, params(20000));
  const auto b = distribute(s.terrain, s.nutrients, s.kinds, params(20000));
  ASSERT_GT(a.size(), 1000u);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Planting)), 0);
  EXPECT_EQ(hash_plantings(a), hash_plantings(b));
}

TEST(Distribution, OtherSeedGivesOtherPlants) {
  const Scene s;
  const auto a = distribute(s.terrain, s.nutrients, s.kinds, params(5000, 1));
  const auto b = distribute(s.terrain, s.nutrients, s.kinds, params(5000, 2));
  EXPECT_NE(hash_plantings(a), hash_plantings(b));
}

TEST(Distribution, SpacingHoldsBetweenAllPlants) {
  const Scene s;
  const auto plants = distribute(s.terrain, s.nutrients, s.kinds, params(100000));
  ASSERT_GT(plants.size(), 1000u);
  EXPECT_EQ(spacing_violations(plants, s.kinds, 0.15), 0);
  // Both kinds grew: each has ground it can use in procedural nutrients.
  const auto clover =
      std::count_if(plants.begin(), plants.end(), [](const Planting& p) { return p.kind == 1; });
  EXPECT_GT(clover, 100);
  EXPECT_LT(clover, int64_t(plants.size()) - 100);
}

TEST(Distribution, PlantsStandOnTheTerrainInsideTheRect) {
  const Scene s;
  const auto plants = distribute(s.terrain, s.nutrients, s.kinds, params(20000));
  ASSERT_FALSE(plants.empty());
  const GroundGrid& g = s.terrain.grid;
  for (const Planting& p : plants) {
    const double x = p.position[0], z = p.position[2];
    ASSERT_GE(x, g.origin_x);
    ASSERT_LE(x, g.origin_x + g.size_x);
    ASSERT_GE(z, g.origin_z);
    ASSERT_LE(z, g.origin_z + g.size_z);
    ASSERT_EQ(p.position[1], float(s.terrain.height_at(x, z)));
    double n[3];
    s.terrain.normal_at(x, z, n);
    for (int i = 0; i < 3; ++i) ASSERT_EQ(p.normal[i], float(n[i]));
    ASSERT_TRUE(p.kind == 0 || p.kind == 1);
  }
}

// Plants per m^2 of the plants with x in [x_lo, x_hi).
double density(const std::vector<Planting>& plants, const GroundRect& r, double x_lo, double x_hi) {
  const auto n = std::count_if(plants.begin(), plants.end(), [&](const Planting& p) {
    return p.position[0] >= x_lo && p.position[0] < x_hi;
  });
  return double(n) / ((x_hi - x_lo) * r.size_z);
}

// 0.2 on the left, 0.9 on the right, need 0.1, consumption 0.01 per plant: the ground
// carries (0.2 - 0.1) / 0.01 = 10 plants per m^2 on the left and 80 on the right, well
// under what 5 cm spacing allows (~240). The planted densities must follow: each side
// between half and all of its budget, so their ratio is above 4 (the budgets' ratio is 8).
TEST(Distribution, DensityFollowsNutrients) {
  const GroundRect r = rect_of(40.0, 20.0);
  const Terrain t = procedural_terrain(r, 0.5, 1);
  const NutrientMaps m = half_nutrients(r, 0.2f, 0.9f);
  const std::vector<PlantNeeds> kinds = {kind(0.05, 0.1, 0.01)};
  const auto plants = distribute(t, m, kinds, params(10000000));
  // Away from the step, in whole ground cells (1 m, aligned with the rectangle's edge).
  const double left = density(plants, r, r.center_x - 19, r.center_x - 2);
  const double right = density(plants, r, r.center_x + 2, r.center_x + 19);
  std::printf("density: %.2f plants/m^2 on 0.2 ground, %.2f on 0.9 ground (%zu plants)\n", left,
              right, plants.size());
  EXPECT_GT(right, 4.0 * left);
  EXPECT_LE(left, 10.0 * 1.0001);
  EXPECT_LE(right, 80.0 * 1.0001);
  EXPECT_GT(left, 0.5 * 10.0) << "the poor side should fill most of its budget";
  EXPECT_GT(right, 0.5 * 80.0) << "the rich side should fill most of its budget";
}

TEST(Distribution, NothingGrowsBelowNeed) {
  const GroundRect r = rect_of(20.0, 10.0);
  const Terrain t = procedural_terrain(r, 0.0, 1);
  const NutrientMaps m = half_nutrients(r, 0.25f, 0.8f);
  const std::vector<PlantNeeds> kinds = {kind(0.1, 0.3)};  // consumes nothing
  const auto plants = distribute(t, m, kinds, params(1000000));
  ASSERT_GT(plants.size(), 1000u);
  for (const Planting& p : plants) {
    ASSERT_GE(m.at(0, p.position[0], p.position[2]), 0.3);
    ASSERT_GE(p.position[0], r.center_x - 0.05);
  }
  // A kind needing a nutrient the maps do not have grows nowhere.
  PlantNeeds needs_third = kind(0.1);
  needs_third.need[2] = 0.01;
  EXPECT_TRUE(distribute(t, m, {needs_third}, params(1000)).empty());
}

// Two kinds eat the same nutrient (0.6 everywhere, both need 0.2): together they may take
// at most (0.6 - 0.2) per m^2 of ground, so sum(count_k * consumption_k) <= 0.4 * area.
TEST(Distribution, CompetingKindsShareTheNutrients) {
  const GroundRect r = rect_of(20.0, 20.0);
  const Terrain t = procedural_terrain(r, 0.0, 1);
  const NutrientMaps m = constant_nutrients(r, 0.6f);
  const std::vector<PlantNeeds> both = {kind(0.05, 0.2, 0.02), kind(0.05, 0.2, 0.01)};
  const auto plants = distribute(t, m, both, params(10000000));
  int64_t count[2] = {0, 0};
  for (const Planting& p : plants) ++count[p.kind];
  const double budget = 0.4 * r.size_x * r.size_z;
  const double used = double(count[0]) * 0.02 + double(count[1]) * 0.01;
  std::printf("competing: %lld + %lld plants use %.2f of a budget of %.2f\n", (long long)count[0],
              (long long)count[1], used, budget);
  EXPECT_GT(count[0], 500);
  EXPECT_GT(count[1], 500);
  EXPECT_LE(used, budget * (1 + 1e-9));
  EXPECT_GT(used, 0.5 * budget) << "the ground should be mostly used up";
  // Alone, a kind gets more than it does beside the other.
  const auto alone = distribute(t, m, {both[0]}, params(10000000));
  EXPECT_GT(double(alone.size()), 1.3 * double(count[0]));
  EXPECT_LE(double(alone.size()) * 0.02, budget * (1 + 1e-9));
}

TEST(Distribution, WeightsShareThePlants) {
  const GroundRect r = rect_of(20.0, 20.0);
  const Terrain t = procedural_terrain(r, 0.0, 1);
  const NutrientMaps m = constant_nutrients(r, 1.0f);
  std::vector<PlantNeeds> kinds = {kind(0.1), kind(0.1)};
  kinds[0].weight = 3.0;
  const auto plants = distribute(t, m, kinds, params(8000));
  ASSERT_EQ(plants.size(), 8000u);
  const auto first =
      std::count_if(plants.begin(), plants.end(), [](const Planting& p) { return p.kind == 0; });
  EXPECT_NEAR(double(first), 6000.0, 10.0);
}

TEST(Distribution, TargetCountIsRespected) {
  const Scene s;
  for (int64_t target : {0, 1, 5, 1234}) {
    EXPECT_EQ(int64_t(distribute(s.terrain, s.nutrients, s.kinds, params(target)).size()), target);
  }
}

// With room for far more than the target, growth goes to the richer ground first.
TEST(Distribution, RichGroundIsPlantedFirst) {
  const GroundRect r = rect_of(40.0, 20.0);
  const Terrain t = procedural_terrain(r, 0.0, 1);
  const NutrientMaps m = half_nutrients(r, 0.4f, 0.9f);
  const auto plants = distribute(t, m, {kind(0.1, 0.1)}, params(3000));
  ASSERT_EQ(plants.size(), 3000u);
  const auto right = std::count_if(plants.begin(), plants.end(),
                                   [&](const Planting& p) { return p.position[0] >= r.center_x; });
  EXPECT_GT(right, 2700);
}

TEST(Distribution, ProgressIsReportedNowAndThen) {
  const Scene s;
  std::vector<double> seen;
  DistributionParams p = params(20000);
  p.progress = [&](double f) { seen.push_back(f); };
  distribute(s.terrain, s.nutrients, s.kinds, p);
  ASSERT_GE(seen.size(), 3u);
  EXPECT_LE(seen.size(), 100u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

TEST(Distribution, BadInputsAreInvalidArgumentNamingTheField) {
  const Scene s;
  const auto expect_refused = [&](std::vector<PlantNeeds> kinds, DistributionParams p,
                                  const std::string& field) {
    bool called = false;
    p.progress = [&](double) { called = true; };
    std::string message;
    EXPECT_EQ(status_of([&] { distribute(s.terrain, s.nutrients, kinds, p); }, &message),
              BOREAS_ERROR_INVALID_ARGUMENT)
        << field;
    EXPECT_NE(message.find(field), std::string::npos) << message;
    EXPECT_FALSE(called) << "refused before doing anything";
  };
  const PlantNeeds good = kind(0.1);
  PlantNeeds k = good;
  expect_refused({}, params(10), "kinds");
  k.weight = -1;
  expect_refused({good, k}, params(10), "kinds[1].weight must be > 0 and finite (got -1)");
  k = good;
  k.weight = 0;
  expect_refused({k}, params(10), "kinds[0].weight");
  k = good;
  k.need[2] = 1.5;
  expect_refused({k}, params(10), "kinds[0].need[2]");
  k = good;
  k.need[0] = -0.1;
  expect_refused({k}, params(10), "kinds[0].need[0]");
  k = good;
  k.need[1] = std::nan("");
  expect_refused({k}, params(10), "kinds[0].need[1]");
  k = good;
  k.consumption[1] = -0.5;
  expect_refused({good, k}, params(10), "kinds[1].consumption[1]");
  k = good;
  k.spacing = 0;
  expect_refused({k}, params(10), "kinds[0].spacing");
  k = good;
  k.spacing = INFINITY;
  expect_refused({k}, params(10), "kinds[0].spacing");
  expect_refused({good}, params(-1), "target_count");
  DistributionParams p = params(10);
  p.seed_points = 0;
  expect_refused({good}, p, "seed_points");
}

// A million plants on 150 m x 150 m at 10 cm spacing (about two thirds of the densest
// random packing). Only correctness is asserted; the time is printed.
TEST(Distribution, MillionPlants) {
  GroundRect r = rect_of(150.0, 150.0);
  const Terrain t = procedural_terrain(r, 2.0, 3);
  const NutrientMaps m = procedural_nutrients(r, 3);
  const std::vector<PlantNeeds> kinds = {kind(0.1), kind(0.1)};
  const auto start = std::chrono::steady_clock::now();
  const auto plants = distribute(t, m, kinds, params(1000000));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("distribute: %zu plants in %.3f s\n", plants.size(), seconds);
  ASSERT_EQ(plants.size(), 1000000u);
  EXPECT_EQ(spacing_violations(plants, kinds, 0.1), 0);
}

}  // namespace
}  // namespace boreas::impl
