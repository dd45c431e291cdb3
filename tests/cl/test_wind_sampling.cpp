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
  boreas_grid_def g = centered_grid(24, 6, 20, 2.0f);
  g.wind_sampling = sampling;
  return g;
}

// Waves of every kind the bound treats: sharp (k >= 1), soft (0 < k < 1) and steady (0),
// with wavelengths from 4 to 40 cells, so some cells see a large error.
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
  world.wind().sample(xyz.data(), int(xyz.size() / 3), f.data(), as_plants);
  return f;
}

// The grid's states the slab must be current in: idle (no primitives: nothing but the
// slab runs for the plants), driven by a vortex, and driven while following a moving focus
// (the grid shifts between steps).
enum class GridState { kIdle, kActive, kFollowing };

void expect_bilinear_within_bound(GridState state) {
  SCOPED_TRACE(state == GridState::kIdle     ? "idle"
               : state == GridState::kActive ? "active"
                                             : "following");
  std::mt19937 rng(2027);
  boreas_grid_def def = sampling_grid(BOREAS_WIND_SAMPLING_INTERPOLATED);
  def.follow_focus = state == GridState::kFollowing ? 1 : 0;
  auto world = make_world(&def);
  const std::vector<boreas_wave> waves = mixed_waves(rng);
  world->wind().set_waves(waves.data(), int(waves.size()), 0.0f, world->time());
  if (state != GridState::kIdle) add_vortex(*world, 10.0f);
  const std::vector<impl::WaveParams> params =
      impl::checked_waves(waves.data(), int(waves.size()), "w", "count");
  const double h = def.cell_size;
  const double bound = impl::interpolation_error_bound(params, h);
  double amplitude_sum = 0.0;
  for (const auto& w : params) amplitude_sum += w.amplitude;

  double worst = 0.0;
  for (int round = 0; round < 4; ++round) {
    const float focus[3] = {-30.0f + 19.0f * float(round), 1.0f, 25.0f - 15.0f * float(round)};
    world->set_focus(focus, 1);
    world->step(0.37f + 0.5f * float(round));
    const boreas_grid_def g = world->wind().grid().def();  // where the grid stands now
    if (state == GridState::kFollowing && round > 0)
      EXPECT_NE(g.origin[0], def.origin[0]) << "the grid did not move";
    EXPECT_EQ(world->wind().grid().active(), state != GridState::kIdle);
    const double t = world->time();
    // Random points at least a cell inside the centers' rectangle (the outermost cell
    // hands over to the exact sum, WindSampling.InterpolatedHandsOverToExact...), and the
    // corners of that inner rectangle.
    const double x0 = g.origin[0] + 1.5 * h, x1 = g.origin[0] + (g.resolution[0] - 1.5) * h;
    const double z0 = g.origin[2] + 1.5 * h, z1 = g.origin[2] + (g.resolution[2] - 1.5) * h;
    std::uniform_real_distribution<double> ux(x0, x1), uz(z0, z1), y(0.0, 11.0);
    std::vector<float> xyz;
    for (int i = 0; i < 3000; ++i)
      xyz.insert(xyz.end(), {float(ux(rng)), float(y(rng)), float(uz(rng))});
    xyz.insert(xyz.end(), {float(x0), 1.0f, float(z0), float(x1), 1.0f, float(z1)});
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
      // The grid's part, the same in both samples: the exact sample less the exact sum.
      const auto s = impl::reference::sine_sum(params, px, pz, t);
      const double grid_x = exact[3 * p] - s[0], grid_z = exact[3 * p + 2] - s[1];
      // Float slab values: phases of up to w 47 m ~ 37 rad carry ~1e-5 rad, times the
      // terms' slopes of at most k / 2 <= 1.75 per rad, and the polynomials' ~2e-6; float
      // weights and sums add a few ulps of the amplitudes' sum; so does the exact sample
      // the grid's part is taken from. About 4x that.
      const double tolerance = 8e-5 * amplitude_sum;
      ASSERT_NEAR(got[3 * p] - grid_x, want[0], tolerance) << "point " << p;
      ASSERT_NEAR(got[3 * p + 2] - grid_z, want[1], tolerance) << "point " << p;
      ASSERT_EQ(got[3 * p + 1], exact[3 * p + 1]) << "the grid's part is sampled alike";
      // And the exact sum lies within the bound of it, as a vector.
      const double error = std::hypot(got[3 * p] - exact[3 * p], got[3 * p + 2] - exact[3 * p + 2]);
      ASSERT_LE(error, bound + tolerance) << "point " << p << " (" << px << ", " << pz << ")";
      worst = std::max(worst, error);
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_bound", testing::PrintToString(worst / bound));
  // Not vacuous: the interpolation does differ from the exact sum, and by a fair part of
  // the bound (which sums every wave's worst case at once).
  EXPECT_GT(worst, 0.05 * bound) << "worst " << worst << " bound " << bound;
}

TEST(WindSampling, InterpolatedIsBilinearInTheColumnCentersAndWithinTheBound) {
  for (GridState state : {GridState::kIdle, GridState::kActive, GridState::kFollowing})
    expect_bilinear_within_bound(state);
}

// Across the outermost cell of column centers the plants' wind goes from the bilinear sum
// to the exact one without a step: sampled every millimetre along lines through that cell
// (midway between centers along the edge, where the bilinear sum is furthest from the
// exact one), it changes between neighbours no more than the exact wind does, plus the
// hand-over's own slope (at most the bound times 1.5 per cell).
TEST(WindSampling, InterpolatedHandsOverToExactWithoutAStep) {
  std::mt19937 rng(3);
  const boreas_grid_def g = sampling_grid(BOREAS_WIND_SAMPLING_INTERPOLATED);
  auto world = make_world(&g);
  const std::vector<boreas_wave> waves = mixed_waves(rng);
  world->wind().set_waves(waves.data(), int(waves.size()), 0.0f, world->time());
  world->step(0.25f);
  const double bound = impl::interpolation_error_bound(
      impl::checked_waves(waves.data(), int(waves.size()), "w", "count"), g.cell_size);
  const double step = 1e-3;  // m
  // From half a cell beyond the rectangle of centers to 1.5 cells inside it: across the
  // -x edge at z = 4 (midway between the centers at 3 and 5 m), and across the +z edge.
  struct Line {
    float x0, z0, dx, dz;
  };
  for (const Line& line : {Line{-24.0f, 4.0f, 1.0f, 0.0f}, Line{-6.0f, 20.0f, 0.0f, -1.0f}}) {
    std::vector<float> xyz;
    for (int i = 0; i <= 4000; ++i) {
      const float d = float(i * step);
      xyz.insert(xyz.end(), {line.x0 + line.dx * d, 2.0f, line.z0 + line.dz * d});
    }
    const std::vector<float> got = sample(*world, xyz, true);
    const std::vector<float> exact = sample(*world, xyz, false);
    double jump = 0.0, exact_jump = 0.0, apart = 0.0;
    for (size_t p = 3; p < xyz.size(); p += 3) {
      jump = std::max(jump, double(std::hypot(got[p] - got[p - 3], got[p + 2] - got[p - 1])));
      exact_jump = std::max(
          exact_jump, double(std::hypot(exact[p] - exact[p - 3], exact[p + 2] - exact[p - 1])));
      apart = std::max(apart, double(std::hypot(got[p] - exact[p], got[p + 2] - exact[p + 2])));
    }
    const double allowed = 2.0 * exact_jump + 1.5 * bound * step / g.cell_size + 1e-5;
    EXPECT_LE(jump, allowed) << "line from (" << line.x0 << ", " << line.z0 << ")";
    RecordProperty("jump_over_allowed", testing::PrintToString(jump / allowed));
    RecordProperty("apart_over_allowed", testing::PrintToString(apart / allowed));
    // Not vacuous: inside, the two modes part by far more than any step allowed.
    EXPECT_GT(apart, 20.0 * allowed) << "line from (" << line.x0 << ", " << line.z0 << ")";
  }
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
    world->wind().set_waves(waves.data(), int(waves.size()), 0.0f, world->time());
    add_vortex(*world, 10.0f);
    const float lo[3] = {2.0f, 0.0f, 2.0f}, hi[3] = {6.0f, 4.0f, 6.0f};
    world->wind().add_solid_box(lo, hi);
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
