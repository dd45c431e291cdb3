// The crown's ambient occlusion (trees/leaf_occlusion.h, cl/leaf_occlusion.cl): the device
// against the double-precision reference of the same method, the method against the
// closed form at the centre of a uniform ball of leaves (every ray crosses the radius, so
// the sky's share is exp(-(1 - t) Omega G L R): the mean of it over the directions for
// horizontal leaves, G = cos(zenith), and the value itself for leaves facing every way,
// G = 0.5), the calibration to a target leaf area index, and on a grown aspen:
// values in (0, 1], the core darker than the rim, the light inside greener than outside; the
// C API's checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "boreas/boreas.h"
#include "reference/leaf_occlusion_reference.h"
#include "runtime/runtime.h"
#include "support/small_world.h"
#include "support/test_support.h"
#include "trees/leaf_area.h"
#include "trees/leaf_occlusion.h"

namespace boreas {
namespace {

// The light of the tests of the method: the leaves' own area, no clumping, broadleaf.
impl::CrownLight own_area() {
  impl::CrownLight light;
  light.leaf_area_index = 0.0;
  light.clumping = 1.0;
  light.outline = BOREAS_LEAF_OUTLINE_BROADLEAF;
  return light;
}

// `count` leaves at uniformly random points of a ball of radius r around the origin (a
// fixed sequence), each of area L V / count (a uniform density L, m^2/m^3), and one more at
// the centre, returned first. Random, not on a lattice: lattice planes alias with the
// voxels' faces and stripe the grid. Their normals face every way (uniform on the sphere)
// or, with `horizontal`, up. The axis is zero, so a leaf's centre is its position.
std::vector<boreas_leaf> ball_of_leaves(double r, int count, double density,
                                        bool horizontal = false) {
  std::vector<boreas_leaf> leaves;
  const double volume = 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
  const double side =
      std::sqrt(density * volume / count / impl::leaf_fill(BOREAS_LEAF_OUTLINE_BROADLEAF));
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto uniform = [&] {  // splitmix64, [0, 1)
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
  };
  auto facing = [&](boreas_leaf& l) {
    if (horizontal) {
      l.normal[1] = 1.0f;
      return;
    }
    const double y = 2 * uniform() - 1, phi = 2 * 3.14159265358979323846 * uniform();
    const double s = std::sqrt(1 - y * y);
    l.normal[0] = float(s * std::cos(phi)), l.normal[1] = float(y), l.normal[2] = float(s * std::sin(phi));
  };
  boreas_leaf centre{};
  centre.length = centre.width = float(side);
  facing(centre);
  leaves.push_back(centre);
  while (int(leaves.size()) < count + 1) {
    double p[3] = {r * (2 * uniform() - 1), r * (2 * uniform() - 1), r * (2 * uniform() - 1)};
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > r * r) continue;
    boreas_leaf l{};
    for (int a = 0; a < 3; ++a) l.position[a] = float(p[a]);
    l.length = l.width = float(side);
    facing(l);
    leaves.push_back(l);
  }
  return leaves;
}

// A calm small world with the default tree (a quaking aspen), destroyed with the object.
struct AspenWorld {
  boreas_world world = nullptr;
  boreas_tree_id tree{};
  AspenWorld() {
    boreas_tree_def def = boreas_default_tree_def();
    if (test::create_small_windy_world(&world, 0.0f) != BOREAS_OK) return;
    if (boreas_world_add_tree(world, &def, &tree) != BOREAS_OK) {
      boreas_world_destroy(world);
      world = nullptr;
    }
  }
  ~AspenWorld() {
    if (world) boreas_world_destroy(world);
  }
  AspenWorld(const AspenWorld&) = delete;
  AspenWorld& operator=(const AspenWorld&) = delete;
};

TEST(LeafOcclusion, DirectionsAreUnitUpperAndCosineDistributed) {
  std::vector<float> d = impl::occlusion_directions(4096);
  double mean_cos = 0.0;
  for (size_t k = 0; k < d.size(); k += 3) {
    EXPECT_NEAR(std::hypot(d[k], d[k + 1], d[k + 2]), 1.0, 1e-6);
    EXPECT_GE(d[k + 1], 0.0f);
    mean_cos += d[k + 1];
  }
  // Under a cosine density the mean of cos(theta) is 2/3.
  EXPECT_NEAR(mean_cos / 4096.0, 2.0 / 3.0, 2e-3);
}

TEST(LeafOcclusion, DeviceMatchesTheDoubleReference) {
  impl::Runtime runtime(nullptr, nullptr);
  std::vector<boreas_leaf> leaves = ball_of_leaves(1.0, 20000, 2.0);
  const float t[3] = {0.06f, 0.13f, 0.02f};
  impl::CrownLight light = own_area();
  light.clumping = 0.7;
  std::vector<float> device = impl::leaf_occlusion(runtime, leaves, t, light);
  const double td[3] = {t[0], t[1], t[2]};
  const std::vector<float> directions = impl::occlusion_directions();
  std::vector<double> ref = impl::reference::leaf_occlusion(
      impl::leaf_density_grid(leaves, light), directions,
      impl::leaf_projection(leaves, directions, light.outline), light.clumping, td, leaves);
  ASSERT_EQ(device.size(), ref.size());
  double worst = 0.0, sum = 0.0;
  for (size_t i = 0; i < ref.size(); ++i) {
    double e = std::abs(double(device[i]) - ref[i]);
    worst = std::max(worst, e);
    sum += e;
  }
  // float32 marching: a sample landing on a voxel face can fall on either side of it.
  EXPECT_LT(worst, 5e-3);
  EXPECT_LT(sum / double(ref.size()), 1e-4);
}

TEST(LeafOcclusion, CentreOfAUniformBallSeesTheClosedForm) {
  impl::Runtime runtime(nullptr, nullptr);
  const double r = 2.0, density = 1.5;  // G L R = 1.5
  // About a hundred leaves per voxel (a tenth of the radius across).
  std::vector<boreas_leaf> leaves = ball_of_leaves(r, 420000, density);
  const size_t centre = 0;
  const float t[3] = {0.0f, 0.5f, 0.8f};
  std::vector<float> ao = impl::leaf_occlusion(runtime, leaves, t, own_area());
  for (int c = 0; c < 3; ++c) {
    const double tau = (1.0 - t[c]) * 0.5 * density * r;
    const double got = -std::log(double(ao[3 * centre + c]));
    // Voxels of a tenth of the radius, 32 directions, a hundred random leaves per voxel:
    // measured 1.497 against 1.5 (green 0.7496 against 0.75); the voxelized rim and the
    // leaves' scatter are allowed 3 %.
    EXPECT_NEAR(got, tau, 0.03 * tau) << "channel " << c;
  }
}

TEST(LeafOcclusion, HorizontalLeavesShadeByTheCosineOfTheZenith) {
  impl::Runtime runtime(nullptr, nullptr);
  const double r = 2.0, density = 1.5, clumping = 0.6;
  std::vector<boreas_leaf> leaves = ball_of_leaves(r, 420000, density, true);
  impl::CrownLight light = own_area();
  light.clumping = clumping;
  const float t[3] = {0.0f, 0.5f, 0.8f};
  std::vector<float> ao = impl::leaf_occlusion(runtime, leaves, t, light);
  // Every ray from the centre crosses the radius; toward mu = cos(zenith) horizontal leaves
  // present mu of their area, so the sky's share is the directions' mean of
  // exp(-(1 - t) Omega mu L R), in double.
  const std::vector<float> d = impl::occlusion_directions();
  for (int c = 0; c < 3; ++c) {
    double want = 0.0;
    for (size_t k = 0; k < d.size(); k += 3)
      want += std::exp(-(1.0 - t[c]) * clumping * d[k + 1] * density * r) / double(d.size() / 3);
    // As the ball of spherical leaves above: 3 % of the optical depth.
    EXPECT_NEAR(std::log(double(ao[c])), std::log(want), 0.03 * -std::log(want)) << "channel " << c;
  }
}

TEST(LeafOcclusion, LeafAreaIsScaledDownToTheTargetIndexNeverUp) {
  // 4 m^2 of leaves over a 2 m x 2 m square of centres: a projection of pi m^2.
  std::vector<boreas_leaf> leaves;
  for (int i = 0; i < 4; ++i) {
    boreas_leaf l{};
    l.position[0] = 2.0f * float(i % 2), l.position[2] = 2.0f * float(i / 2);
    l.length = l.width = float(std::sqrt(1.0 / impl::leaf_fill(BOREAS_LEAF_OUTLINE_OAK)));
    l.normal[1] = 1.0f;
    leaves.push_back(l);
  }
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(impl::crown_projection(leaves), pi, 1e-6);
  impl::CrownLight light = own_area();
  light.outline = BOREAS_LEAF_OUTLINE_OAK;
  EXPECT_EQ(impl::leaf_area_scale(leaves, light), 1.0);
  light.leaf_area_index = 0.5;  // 0.5 pi m^2 of 4
  EXPECT_NEAR(impl::leaf_area_scale(leaves, light), 0.5 * pi / 4.0, 1e-6);
  light.leaf_area_index = 2.0;  // above the leaves' own 4 / pi: as they are
  EXPECT_EQ(impl::leaf_area_scale(leaves, light), 1.0);
  // The grid holds the scaled area, each leaf in the voxel of its centre.
  light.leaf_area_index = 0.5;
  const impl::LeafDensityGrid g = impl::leaf_density_grid(leaves, light);
  double area = 0.0;
  for (float x : g.density) area += double(x) * g.cell * g.cell * g.cell;
  EXPECT_NEAR(area, 0.5 * pi, 1e-4);
}

TEST(LeafOcclusion, AnAspensCoreIsDarkerAndGreenerThanItsRim) {
  AspenWorld a;
  ASSERT_TRUE(a.world) << boreas_last_error();
  boreas_world world = a.world;
  boreas_tree_id tree = a.tree;
  int n = 0;
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_leaf> leaves(static_cast<size_t>(n));
  ASSERT_EQ(boreas_tree_get_leaves(world, tree, leaves.data(), n, &n), BOREAS_OK);
  const float t[3] = {0.06f, 0.13f, 0.02f};
  int count = 0;
  ASSERT_EQ(boreas_tree_get_leaf_occlusion(world, tree, t, nullptr, 0, &count), BOREAS_OK);
  ASSERT_EQ(count, n);
  std::vector<float> rgb(size_t(n) * 3);
  ASSERT_EQ(boreas_tree_get_leaf_occlusion(world, tree, t, rgb.data(), n, &count), BOREAS_OK);
  std::vector<float> again(size_t(n) * 3);
  ASSERT_EQ(boreas_tree_get_leaf_occlusion(world, tree, t, again.data(), n, &count), BOREAS_OK);
  EXPECT_EQ(rgb, again) << "same tree, same device: the same values";

  // The crown's centre and half-extent from its leaves.
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (const boreas_leaf& l : leaves)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], l.position[a]), hi[a] = std::max(hi[a], l.position[a]);
  double core = 0.0, rim = 0.0, greener = 0.0;
  // The tint, log(G/B) and log(G/R): light that crossed an optical depth tau in channel c
  // keeps exp(-(1 - t_c) tau), so the log-ratios grow as (t_G - t_c) tau, deeper in the
  // crown more. Over a leaf's many directions, -log of the mean of exp(-a tau) is concave
  // in a (a cumulant generating function), so each log-ratio is at most (t_G - t_c) /
  // (1 - t_G) times -log G, equal where every direction crosses the same depth; and the
  // blue's log-ratio at most (t_G - t_B) / (t_G - t_R) times the red's (a concave function's
  // mean slope falls over the longer interval).
  double core_gb = 0.0, rim_gb = 0.0, core_gr = 0.0, rim_gr = 0.0;
  int cores = 0, rims = 0;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      ASSERT_GT(rgb[3 * i + c], 0.0f);
      ASSERT_LE(rgb[3 * i + c], 1.0f + 1e-6f);
    }
    // Light that crossed leaves is tinted by them: green passes most, blue least.
    EXPECT_GE(rgb[3 * i + 1], rgb[3 * i]);
    EXPECT_GE(rgb[3 * i], rgb[3 * i + 2]);
    double q = 0.0;  // 0 at the crown's centre, 1 at its box's faces
    for (int a = 0; a < 3; ++a) {
      double h = 0.5 * (hi[a] - lo[a]);
      q = std::max(
          q, std::abs(leaves[size_t(i)].position[a] - 0.5 * (lo[a] + hi[a])) / std::max(h, 1e-6));
    }
    const double r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
    const double gb = std::log(g / b), gr = std::log(g / r), depth = -std::log(g) / (1.0 - t[1]);
    EXPECT_LE(gb, (t[1] - t[2]) * depth + 1e-5) << "leaf " << i;
    EXPECT_LE(gr, (t[1] - t[0]) * depth + 1e-5) << "leaf " << i;
    EXPECT_LE(gb, (t[1] - t[2]) / (t[1] - t[0]) * gr + 1e-5) << "leaf " << i;
    if (q < 0.3) core += g, core_gb += gb, core_gr += gr, ++cores;
    if (q > 0.8) rim += g, rim_gb += gb, rim_gr += gr, ++rims;
    greener += rgb[3 * i + 1] / std::max(rgb[3 * i + 2], 1e-6f);
  }
  ASSERT_GT(cores, 0);
  ASSERT_GT(rims, 0);
  EXPECT_LT(core / cores, 0.8 * (rim / rims)) << "core " << core / cores << ", rim " << rim / rims;
  // Greener: the core's mean tint above the rim's in both ratios.
  EXPECT_GT(core_gb / cores, rim_gb / rims) << "log(G/B)";
  EXPECT_GT(core_gr / cores, rim_gr / rims) << "log(G/R)";
  std::printf("core: G %.3f log(G/B) %.4f log(G/R) %.4f; rim: G %.3f log(G/B) %.4f log(G/R) %.4f\n",
              core / cores, core_gb / cores, core_gr / cores, rim / rims, rim_gb / rims, rim_gr / rims);
  EXPECT_GT(greener / n, 1.0);
}

TEST(LeafOcclusion, BadArgumentsAreRefusedAndNothingIsWritten) {
  AspenWorld a;
  ASSERT_TRUE(a.world) << boreas_last_error();
  boreas_world world = a.world;
  boreas_tree_id tree = a.tree;
  int n = 0;
  const float good[3] = {0.1f, 0.1f, 0.1f};
  ASSERT_EQ(boreas_tree_get_leaf_occlusion(world, tree, good, nullptr, 0, &n), BOREAS_OK);
  std::vector<float> rgb(size_t(n) * 3, -7.0f);
  int count = -1;
  const float bad[3] = {0.1f, 1.5f, 0.1f};
  EXPECT_EQ(boreas_tree_get_leaf_occlusion(world, tree, bad, rgb.data(), n, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("transmittance[1]"), std::string::npos)
      << boreas_last_error();
  const float nan[3] = {0.1f, 0.1f, std::nanf("")};
  EXPECT_EQ(boreas_tree_get_leaf_occlusion(world, tree, nan, rgb.data(), n, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_tree_get_leaf_occlusion(world, tree, nullptr, rgb.data(), n, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_tree_get_leaf_occlusion(world, tree, good, rgb.data(), n - 1, &count),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("capacity"), std::string::npos)
      << boreas_last_error();
  EXPECT_EQ(boreas_tree_get_leaf_occlusion(world, tree, good, rgb.data(), n, nullptr),
            BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(count, -1);
  EXPECT_TRUE(std::all_of(rgb.begin(), rgb.end(), [](float x) { return x == -7.0f; }));
}

}  // namespace
}  // namespace boreas
