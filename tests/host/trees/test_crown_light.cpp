// Crown light as real crowns have it (issue 40): each built-in species' mean sky light at
// its leaves (boreas_tree_get_leaf_occlusion, green, leaf transmittance 0.1) against what
// measured canopies give, a species file's LeafAreaIndex and Clumping reaching it, G from
// the leaves' normals against Ross's analytic cases, the grid placing leaves at their
// centres, and a leaf's area against its outline's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "support/small_world.h"
#include "trees/leaf_area.h"
#include "trees/leaf_occlusion.h"

namespace boreas {
namespace {

// The mean over a species' leaves (seed 1, default def) of the green sky light reaching
// them for leaves passing 0.1 of it; negative where the world or the tree fails.
double mean_sky_light(const char* species) {
  boreas_world world = nullptr;
  if (test::create_small_windy_world(&world, 0.0f) != BOREAS_OK) return -1.0;
  boreas_tree_def def = boreas_default_tree_def();
  def.species = species;
  boreas_tree_id tree{};
  double mean = -1.0;
  int n = 0;
  const float t[3] = {0.1f, 0.1f, 0.1f};
  if (boreas_world_add_tree(world, &def, &tree) == BOREAS_OK &&
      boreas_tree_get_leaf_occlusion(world, tree, t, nullptr, 0, &n) == BOREAS_OK && n > 0) {
    std::vector<float> rgb(size_t(n) * 3);
    if (boreas_tree_get_leaf_occlusion(world, tree, t, rgb.data(), n, &n) == BOREAS_OK) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rgb[3 * size_t(i) + 1];
      mean = sum / n;
      std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
      if (boreas_tree_get_leaves(world, tree, leaves.data(), n, &n) == BOREAS_OK) {
        double area = 0.0;
        const int outline = int(boreas_species_leaf_outline(species)) - 1;
        for (const boreas_leaf& l : leaves) area += impl::leaf_area(l.length, l.width, outline);
        std::printf("%-16s leaf area index as drawn %.2f\n", species,
                    area / impl::crown_projection(leaves));
      }
    }
  }
  boreas_world_destroy(world);
  return mean;
}

// The mean diffuse light over the leaves of a horizontal leaf layer of leaf area index
// `lai`, leaves spread evenly through its depth: a leaf under cumulative leaf area l sees
// the sky from direction mu = cos(zenith) through exp(-k l / mu), cosine-weighted over the
// hemisphere, k = (1 - t) Omega G. Midpoint rule, 400 x 400.
double layer_mean_light(double lai, double k) {
  const int n = 400;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double l = (i + 0.5) / n * lai;
    for (int j = 0; j < n; ++j) {
      const double mu = (j + 0.5) / n;
      sum += 2.0 * mu * std::exp(-k * l / mu) / n;
    }
  }
  return sum / n;
}

TEST(CrownLight, EveryBuiltInSpeciesIsLitAsMeasuredCrownsAre) {
  // No crown brighter than a sparse real one: a layer of leaf area index 1 (below every
  // biome's mean in Asner, Scurlock and Hicke's synthesis, the lowest deserts' 1.3) with spherical
  // leaves (G 0.5), clumped as broadleaves are (0.8) and passing 0.1: 0.76. A crown lit from its sides as well as
  // from above is brighter than the layer at the same leaf area, so this bounds a crown
  // that is no sparser than LAI ~1.
  const double bound = layer_mean_light(1.0, 0.9 * 0.8 * 0.5);
  for (int s = 0; boreas_builtin_species(s); ++s) {
    const char* name = boreas_builtin_species(s);
    const double light = mean_sky_light(name);
    std::printf("%-16s mean sky light %.3f (bound %.3f)\n", name, light, bound);
    EXPECT_GE(light, 0.25) << name;
    EXPECT_LE(light, bound) << name;
    if (std::string(name) == "quaking_aspen") {
      EXPECT_GE(light, 0.35);
      EXPECT_LE(light, 0.55);
    }
  }
}

// The aspen's preset with its LeafAreaIndex and Clumping replaced, written to a file of its
// own; the file's path.
std::string aspen_with(const std::string& name, double leaf_area_index, double clumping) {
  namespace fs = std::filesystem;
  std::ifstream in(fs::path(BOREAS_TEST_DATA_DIR) / ".." / ".." / "host" / "species" /
                   "quaking_aspen.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string json = text.str();
  auto replace = [&](const std::string& key, double value) {
    const size_t at = json.find("\"" + key + "\": ");
    const size_t end = json.find_first_of(",\n", at);
    json.replace(at, end - at, "\"" + key + "\": " + std::to_string(value));
  };
  replace("LeafAreaIndex", leaf_area_index);
  replace("Clumping", clumping);
  const fs::path path = fs::temp_directory_path() / ("boreas_crown_light_" + name + ".json");
  std::ofstream(path) << json;
  return path.string();
}

TEST(CrownLight, TheSpeciesLeafAreaIndexAndClumpingReachTheLight) {
  // From a species file through boreas_tree_get_leaf_occlusion: less leaf area, or leaves
  // bunched tighter, let more light through (the aspen's own are 3.5 and 0.8).
  std::vector<std::string> files;
  auto light_of = [&](const std::string& name, double leaf_area_index, double clumping) {
    files.push_back(aspen_with(name, leaf_area_index, clumping));
    return mean_sky_light(files.back().c_str());
  };
  const double preset = mean_sky_light("quaking_aspen");
  const double sparse = light_of("sparse", 2.0, 0.8), dense = light_of("dense", 6.0, 0.8);
  const double clumped = light_of("clumped", 3.5, 0.5), same = light_of("same", 3.5, 0.8);
  for (const std::string& f : files) std::filesystem::remove(f);
  ASSERT_GT(dense, 0.0);
  EXPECT_GT(sparse, preset);
  EXPECT_LT(dense, preset);
  EXPECT_GT(clumped, preset);
  EXPECT_EQ(same, preset);
}

// A leaf at the origin facing `normal` (normalized here), 1 m x 1 m.
boreas_leaf facing(double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  boreas_leaf l{};
  l.normal[0] = float(x / n), l.normal[1] = float(y / n), l.normal[2] = float(z / n);
  l.length = l.width = 1.0f;
  return l;
}

TEST(CrownLight, ProjectionOfHorizontalLeavesIsTheZenithCosine) {
  // Faces up and down alike: a leaf's projection has no side.
  const std::vector<boreas_leaf> leaves = {facing(0, 1, 0), facing(0, -1, 0)};
  const std::vector<float> d = impl::occlusion_directions();
  const std::vector<float> g = impl::leaf_projection(leaves, d, BOREAS_LEAF_OUTLINE_ASPEN);
  ASSERT_EQ(g.size(), d.size() / 3);
  const std::vector<float> zenith = {0.0f, 1.0f, 0.0f};
  EXPECT_NEAR(impl::leaf_projection(leaves, zenith, 0)[0], 1.0, 1e-7);
  for (size_t k = 0; k < g.size(); ++k) EXPECT_NEAR(g[k], double(d[3 * k + 1]), 1e-6);
}

TEST(CrownLight, ProjectionOfASphericalDistributionIsOneHalf) {
  // Normals spread evenly over the sphere (a Fibonacci sphere of 100,000 points), two sizes
  // of leaf interleaved so that the area weights are exercised: G = 1/2 toward every
  // direction (Ross), against the double mean of |cos| over the sphere.
  std::vector<boreas_leaf> leaves;
  const int n = 100000;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double y = 1.0 - 2.0 * (k + 0.5) / n, s = std::sqrt(1.0 - y * y);
    boreas_leaf l = facing(s * std::cos(golden * k), y, s * std::sin(golden * k));
    l.length = l.width = k % 2 ? 0.05f : 0.1f;
    leaves.push_back(l);
  }
  const std::vector<float> d = {0, 1, 0, 1, 0, 0, 0.6f, 0.8f, 0, 0, 0.28f, 0.96f};
  const std::vector<float> g = impl::leaf_projection(leaves, d, BOREAS_LEAF_OUTLINE_OAK);
  for (float x : g) EXPECT_NEAR(x, 0.5, 2e-4);
}

TEST(CrownLight, ProjectionOfAnyLeavesAveragesOneHalfOverTheSky) {
  // Ross's normalization: whatever the leaves' angles, G averaged over the hemisphere's
  // directions (uniformly, not cosine-weighted) is 1/2 (a leaf's projection onto every plane
  // averages half its area). On the grown aspen's own leaves, over 20,000 directions spread
  // evenly over the upper hemisphere (a Fibonacci spiral uniform in height).
  boreas_world world = nullptr;
  ASSERT_EQ(test::create_small_windy_world(&world, 0.0f), BOREAS_OK) << boreas_last_error();
  boreas_tree_def def = boreas_default_tree_def();
  boreas_tree_id tree{};
  ASSERT_EQ(boreas_world_add_tree(world, &def, &tree), BOREAS_OK) << boreas_last_error();
  int n = 0;
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, leaves.data(), n, &n), BOREAS_OK);
  boreas_world_destroy(world);
  std::vector<float> d;
  const int m = 20000;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < m; ++k) {
    const double y = (k + 0.5) / m, s = std::sqrt(1.0 - y * y);
    d.insert(d.end(), {float(s * std::cos(golden * k)), float(y), float(s * std::sin(golden * k))});
  }
  const std::vector<float> g = impl::leaf_projection(leaves, d, BOREAS_LEAF_OUTLINE_ASPEN);
  double mean = 0.0;
  for (float x : g) mean += double(x) / m;
  EXPECT_NEAR(mean, 0.5, 1e-3);
  const std::vector<float> zh = impl::leaf_projection(leaves, {0, 1, 0, 1, 0, 0}, 0);
  std::printf("aspen G: zenith %.3f, horizon %.3f\n", zh[0], zh[1]);
}

TEST(CrownLight, DensityGridPlacesALeafAtItsCentre) {
  // A leaf 1 m long along +x from the origin, and one far away to size the grid: the first
  // one's area lies in the voxel holding (0.5, 0, 0), not the one holding its base.
  boreas_leaf a = facing(0, 1, 0), b = facing(0, 1, 0);
  a.axis[0] = 1.0f;
  b.position[0] = b.position[1] = b.position[2] = 10.0f;
  impl::CrownLight light;
  light.leaf_area_index = 0.0;
  const impl::LeafDensityGrid g = impl::leaf_density_grid({a, b}, light);
  auto voxel = [&](double x, double y, double z) {
    const int i = int((x - g.origin[0]) / g.cell), j = int((y - g.origin[1]) / g.cell),
              k = int((z - g.origin[2]) / g.cell);
    return g.density[(size_t(k) * g.size[1] + size_t(j)) * g.size[0] + size_t(i)];
  };
  EXPECT_NEAR(double(voxel(0.5, 0.0, 0.0)) * g.cell * g.cell * g.cell,
              impl::leaf_area(1.0, 1.0, light.outline), 1e-6);
  EXPECT_EQ(voxel(0.0, 0.0, 0.0), 0.0f);
}

// An outline row with no notch, lobes or teeth: the blade t^p (1 - t)^q over its peak.
BoreasLeafOutline smooth_outline(float p, float q) {
  BoreasLeafOutline o = boreas_leaf_outlines[BOREAS_LEAF_OUTLINE_BROADLEAF];
  o.base_exponent = p, o.tip_exponent = q;
  o.notch_depth = 0.0f, o.serration = 0.0f, o.lobes = 0.0f;
  return o;
}

TEST(CrownLight, AnEllipticBladeFillsAQuarterPiOfItsBox) {
  // p = q = 1/2 is the ellipse: its half-width sqrt(t (1 - t)) / (1/2).
  EXPECT_NEAR(impl::outline_fill(smooth_outline(0.5f, 0.5f)), 3.14159265358979323846 / 4.0, 1e-4);
}

TEST(CrownLight, ASmoothBladeFillsItsBetaIntegral) {
  // The integral of t^p (1 - t)^q is Euler's B(p + 1, q + 1); over the peak's value.
  const double cases[][2] = {{0.35, 0.55}, {1.0, 1.8}, {1.2, 0.9}};
  for (const auto& c : cases) {
    const double p = c[0], q = c[1], t = p / (p + q);
    const double peak = std::pow(t, p) * std::pow(1 - t, q);
    EXPECT_NEAR(impl::outline_fill(smooth_outline(float(p), float(q))),
                std::beta(p + 1, q + 1) / peak, 1e-3)
        << "p " << p << " q " << q;
  }
}

TEST(CrownLight, EachKindsLeafAreaIsItsOutlinesArea) {
  // For the kinds without a notched base, the blade's area is the integral along it of twice
  // its half-width (the teeth and the oak's sinuses included): a 1-D midpoint rule on
  // 100,000 slices, against the 2-D sampling of leaf_area.
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) {
    const BoreasLeafOutline& o = boreas_leaf_outlines[k];
    const double fill = impl::leaf_area(0.2, 0.1, k) / (0.2 * 0.1);
    EXPECT_GT(fill, 0.4) << "kind " << k;
    EXPECT_LT(fill, 3.14159265358979323846 / 4.0) << "kind " << k;
    if (o.notch_depth != 0.0f) continue;
    const int n = 100000;
    double area = 0.0;
    for (int i = 0; i < n; ++i)
      area += 2.0 * double(boreas_leaf_half_width(&o, float((i + 0.5) / n))) / n;
    area /= 2.0 * double(BOREAS_LEAF_BLADE_HALF_WIDTH);  // texture width to the leaf's width
    std::printf("kind %d: fill %.4f, along the blade %.4f\n", k, fill, area);
    EXPECT_NEAR(fill, area, 2e-3) << "kind " << k;
  }
}

}  // namespace
}  // namespace boreas
