// boreas tests: wind_sampling interpolated (boreas.h): the plants' sine sum read bilinearly
// from the step's slab of column centers, against a double-precision bilinear reference and
// against the exact sum within the analytic bound (wind/wind_sampling.cpp); exact beyond
// the centers; the same bits at every SIMD width.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "reference/wind_reference.h"
#include "support/test_support.h"
#include "wind/wind_sampling.h"

namespace boreas::test {
namespace {

// 24 x 6 x 20 cells of 2 m: column centers from x = -23 to 23 and z = -19 to 19.
boreas_grid_def sampling_grid(boreas_wind_sampling sampling) {
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -24.0f;
  g.origin[1] = 0.0f;
  g.origin[2] = -20.0f;
  g.cell_size = 2.0f;
  g.resolution[0] = 24;
  g.resolution[1] = 6;
  g.resolution[2] = 20;
  g.wind_sampling = sampling;
  return g;
}

// Waves of every kind the bound treats: sharp (k >= 1), soft (0 < k < 1) and steady (0),
// with wavelengths from 3 to 5 cells up to 40 cells, so some cells see a large error.
std::vector<boreas_wave> mixed_waves(std::mt19937& rng) {
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
  const float sharpness[] = {0.0f, 0.6f, 1.0f, 2.0f, 3.5f};
  const float wavelength[] = {30.0f, 8.0f, 80.0f, 11.0f, 20.0f};
  const float amplitude[] = {1.5f, 2.0f, 3.0f, 2.5f, 1.0f};
  std::vector<boreas_wave> waves;
  for (int i = 0; i < 5; ++i) {
    boreas_wave w = boreas_default_wave();
    const float a = angle(rng);
    w.direction[0] = std::cos(a);
    w.direction[1] = std::sin(a);
    w.amplitude = amplitude[i];
    w.wavelength = wavelength[i];
    w.speed = 3.0f + float(i);
    w.sharpness = sharpness[i];
    waves.push_back(w);
  }
  return waves;
}

std::vector<float> sample(impl::World& world, const std::vector<float>& xyz, bool as_plants) {
  std::vector<float> f(xyz.size());
  world.sample(xyz.data(), int(xyz.size() / 3), f.data(), as_plants);
  return f;
}

TEST(WindSampling, InterpolatedIsBilinearInTheColumnCentersAndWithinTheBound) {
  std::mt19937 rng(2027);
  const boreas_grid_def g = sampling_grid(BOREAS_WIND_SAMPLING_INTERPOLATED);
  // No primitives: the grid is idle, and the slab must still be written for the plants.
  auto world = make_world(&g);
  const std::vector<boreas_wave> waves = mixed_waves(rng);
  world->set_waves(waves.data(), int(waves.size()), 0.0f);
  const std::vector<impl::WaveParams> params =
      impl::checked_waves(waves.data(), int(waves.size()), "w", "count");
  const double h = g.cell_size;
  const double bound = impl::interpolation_error_bound(params, h);
  double amplitude_sum = 0.0;
  for (const auto& w : params) amplitude_sum += w.amplitude;

  double worst = 0.0;
  for (int round = 0; round < 3; ++round) {
    world->step(0.37f + 0.5f * float(round));
    const double t = world->time();
    // Random points within the centers' rectangle, and the rectangle's corners.
    std::uniform_real_distribution<float> ux(-23.0f, 23.0f), uz(-19.0f, 19.0f), y(0.0f, 11.0f);
    std::vector<float> xyz;
    for (int i = 0; i < 4000; ++i) xyz.insert(xyz.end(), {ux(rng), y(rng), uz(rng)});
    xyz.insert(xyz.end(), {-23.0f, 1.0f, -19.0f, 23.0f, 1.0f, 19.0f, -23.0f, 1.0f, 19.0f});
    const std::vector<float> got = sample(*world, xyz, true);
    const std::vector<float> exact = sample(*world, xyz, false);
    for (size_t p = 0; p < xyz.size() / 3; ++p) {
      const double px = xyz[3 * p], pz = xyz[3 * p + 2];
      // The reference: the double sine sum at the four surrounding centers, bilinear.
      const double cx = (px - g.origin[0]) / h - 0.5, cz = (pz - g.origin[2]) / h - 0.5;
      const int i0 = std::min(int(std::floor(cx)), g.resolution[0] - 2);
      const int k0 = std::min(int(std::floor(cz)), g.resolution[2] - 2);
      const double fx = cx - i0, fz = cz - k0;
      double want[2] = {0.0, 0.0};
      for (int corner = 0; corner < 4; ++corner) {
        const int di = corner & 1, dk = corner >> 1;
        const double w = (di ? fx : 1.0 - fx) * (dk ? fz : 1.0 - fz);
        const auto s = impl::reference::sine_sum(params, g.origin[0] + (i0 + di + 0.5) * h,
                                                 g.origin[2] + (k0 + dk + 0.5) * h, t);
        want[0] += w * s[0];
        want[1] += w * s[1];
      }
      // Float slab values: phases of up to w 47 m ~ 37 rad carry ~1e-5 rad, times the
      // terms' slopes of at most k / 2 <= 1.75 per rad, and the polynomials' ~2e-6; float
      // weights and sums add a few ulps of the amplitudes' sum. About 4x that.
      const double tolerance = 8e-5 * amplitude_sum;
      ASSERT_NEAR(got[3 * p], want[0], tolerance) << "point " << p;
      ASSERT_NEAR(got[3 * p + 2], want[1], tolerance) << "point " << p;
      ASSERT_EQ(got[3 * p + 1], exact[3 * p + 1]) << "the grid's part is sampled alike";
      // And the exact sum lies within the bound of it, per component and as a vector.
      const auto s = impl::reference::sine_sum(params, px, pz, t);
      const double error = std::hypot(got[3 * p] - s[0], got[3 * p + 2] - s[1]);
      ASSERT_LE(error, bound + tolerance) << "point " << p << " (" << px << ", " << pz << ")";
      worst = std::max(worst, error);
    }
  }
  RecordProperty("worst_error_over_bound", testing::PrintToString(worst / bound));
  // Not vacuous: the interpolation does differ from the exact sum, and by a fair part of
  // the bound (which sums every wave's worst case at once).
  EXPECT_GT(worst, 0.05 * bound) << "worst " << worst << " bound " << bound;
}

// Beyond the rectangle of the column centers (and outside the grid, and far away) the
// plants read the exact sum: the same bits as boreas_wind_sample. Within it they differ
// only in the sine sum's x and z. At every SIMD width the same bits, with the grid active
// (a primitive drives it) and a solid box.
TEST(WindSampling, InterpolatedIsExactBeyondTheCentersAndTheSameAtEveryWidth) {
  std::mt19937 rng(11);
  const std::vector<boreas_wave> waves = mixed_waves(rng);
  std::vector<float> beyond, within;
  std::uniform_real_distribution<float> any(-60.0f, 60.0f), y(-2.0f, 14.0f);
  while (beyond.size() < 3 * 1000) {
    const float x = any(rng), z = any(rng);
    const bool inside = x >= -23.0f && x <= 23.0f && z >= -19.0f && z <= 19.0f;
    std::vector<float>& to = inside ? within : beyond;
    to.insert(to.end(), {x, y(rng), z});
  }
  // Just past each side, and far away.
  beyond.insert(beyond.end(), {-23.001f, 1.0f, 0.0f, 23.001f, 1.0f, 0.0f, 0.0f, 1.0f, -19.001f,
                               0.0f, 1.0f, 19.001f, 5e5f, 3.0f, -7e5f});
  auto run = [&](int width) {
    ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    const boreas_grid_def g = sampling_grid(BOREAS_WIND_SAMPLING_INTERPOLATED);
    auto world = make_world(&g);
    EXPECT_EQ(world->runtime().simd_width(), width);
    world->set_waves(waves.data(), int(waves.size()), 0.0f);
    boreas_flow_primitive v = boreas_default_flow_primitive();
    v.type = BOREAS_FLOW_VORTEX;
    v.direction[1] = 1.0f;
    v.radius = 10.0f;
    v.strength = 4.0f;
    world->add_primitive(v);
    const float lo[3] = {2.0f, 0.0f, 2.0f}, hi[3] = {6.0f, 4.0f, 6.0f};
    world->add_solid_box(lo, hi);
    for (int s = 0; s < 10; ++s) world->step(0.05f);
    std::vector<float> out = sample(*world, beyond, true);
    const std::vector<float> exact_beyond = sample(*world, beyond, false);
    EXPECT_EQ(std::memcmp(out.data(), exact_beyond.data(), out.size() * sizeof(float)), 0)
        << "width " << width << ": beyond the centers the plants' wind is exact";
    const std::vector<float> in = sample(*world, within, true);
    const std::vector<float> exact_in = sample(*world, within, false);
    size_t differ = 0;
    for (size_t i = 0; i < in.size(); i += 3) {
      EXPECT_EQ(in[i + 1], exact_in[i + 1]);
      differ += in[i] != exact_in[i];
    }
    EXPECT_GT(differ, in.size() / 3 / 2) << "width " << width << ": within, interpolated";
    out.insert(out.end(), in.begin(), in.end());
    return out;
  };
  const std::vector<float> scalar = run(1);
  for (int width : {16}) {
    const std::vector<float> wide = run(width);
    ASSERT_EQ(wide.size(), scalar.size());
    EXPECT_EQ(std::memcmp(wide.data(), scalar.data(), wide.size() * sizeof(float)), 0)
        << "width " << width;
  }
}

// The bound's pieces (wind/wind_sampling.cpp): the second derivative of
// ((sin theta + 1) / 2)^k peaks at k / 2 for k >= 1, checked by finite differences; and the
// bound in boreas.h's example (h = L / 20, k = 1) is 0.6 % of the amplitude.
TEST(WindSampling, CurvatureOfAWaveTermPeaksAtHalfItsSharpness) {
  for (double k : {1.0, 1.3, 2.0, 3.5, 8.0, 40.0}) {
    double peak = 0.0;
    const double d = 1e-3;
    for (double theta = -M_PI; theta < M_PI; theta += 1e-4) {
      auto g = [k](double t) { return std::pow((std::sin(t) + 1.0) / 2.0, k); };
      peak = std::max(peak, std::fabs(g(theta + d) - 2.0 * g(theta) + g(theta - d)) / (d * d));
    }
    EXPECT_NEAR(peak, k / 2.0, 1e-3 * k) << "k " << k;
  }
  impl::WaveParams w;
  w.amplitude = 1.0;
  w.wavelength = 20.0;
  w.sharpness = 1.0;
  EXPECT_NEAR(impl::interpolation_error(w, 1.0), 0.00617, 1e-5);
  w.sharpness = 0.0;
  EXPECT_EQ(impl::interpolation_error(w, 1.0), 0.0);
}

}  // namespace
}  // namespace boreas::test
