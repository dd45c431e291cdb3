// boreas tests: the sine-sum kernel against the double-precision reference, and wave-set
// blending without jumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "reference/wind_reference.h"
#include "support/test_support.h"

namespace boreas::test {
namespace {

std::vector<boreas_wave> random_waves(std::mt19937& rng, int count) {
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
  std::uniform_real_distribution<float> amp(0.0f, 10.0f);
  std::uniform_real_distribution<float> len(1.0f, 100.0f);
  std::uniform_real_distribution<float> speed(-20.0f, 20.0f);
  std::uniform_real_distribution<float> sharp(1.0f, 8.0f);
  std::vector<boreas_wave> waves;
  for (int i = 0; i < count; ++i) {
    boreas_wave w{};
    float a = angle(rng);
    // Directions are not unit length on purpose: the library normalizes them.
    w.direction[0] = 3.0f * std::cos(a);
    w.direction[1] = 3.0f * std::sin(a);
    w.amplitude = amp(rng);
    w.wavelength = len(rng);
    w.speed = speed(rng);
    w.sharpness = i == 0 ? 0.0f : sharp(rng);  // one steady wave in every set
    waves.push_back(w);
  }
  return waves;
}

// Error bound of the float kernel at one point: the phase theta is computed in float, so
// it carries ~2 ulps of its magnitude; the term's slope in theta is at most A max(k,1)/2;
// the polynomials add ~1e-6 relative. Derived in the test rather than tuned.
double error_bound(const std::vector<impl::WaveParams>& waves, double x, double z) {
  double bound = 0.0;
  for (const impl::WaveParams& w : waves) {
    double theta_mag = std::fabs((w.dir_x * x + w.dir_z * z) * w.wavenumber()) + 2.0 * M_PI;
    double dtheta = 2.4e-7 * theta_mag + 4e-7;
    bound += w.amplitude * (0.5 * std::max(w.sharpness, 1.0) * dtheta + 2e-6);
  }
  return bound + 1e-6;
}

TEST(WindSineSum, KernelMatchesDoubleReferenceAtRandomPointsAndTimes) {
  std::mt19937 rng(2026);
  auto world = make_world();
  std::uniform_real_distribution<float> pos(-500.0f, 500.0f);
  std::uniform_real_distribution<float> dt(0.01f, 900.0f);
  double worst_ratio = 0.0;
  for (int round = 0; round < 6; ++round) {
    std::vector<boreas_wave> waves = random_waves(rng, 1 + round);
    world->wind().set_waves(waves.data(), static_cast<int>(waves.size()), 0.0f, world->time());
    world->step(dt(rng));
    std::vector<impl::WaveParams> params =
        impl::checked_waves(waves.data(), int(waves.size()), "w", "count");
    const int n = 4096;
    std::vector<float> xyz(3 * n), f(3 * n);
    for (int i = 0; i < n; ++i) {
      xyz[3 * i] = pos(rng);
      xyz[3 * i + 1] = pos(rng) * 0.01f + 5.0f;
      xyz[3 * i + 2] = pos(rng);
    }
    world->wind().sample(xyz.data(), n, f.data());
    for (int i = 0; i < n; ++i) {
      auto ref = impl::reference::sine_sum(params, xyz[3 * i], xyz[3 * i + 2], world->time());
      double err = std::hypot(f[3 * i] - ref[0], f[3 * i + 2] - ref[1]);
      double bound = error_bound(params, xyz[3 * i], xyz[3 * i + 2]);
      worst_ratio = std::max(worst_ratio, err / bound);
      ASSERT_EQ(f[3 * i + 1], 0.0f) << "the sine-sum wind is horizontal";
      ASSERT_LE(err, bound) << "round " << round << " point " << i << " t " << world->time();
    }
  }
  RecordProperty("worst_error_over_bound", testing::PrintToString(worst_ratio));
}

TEST(WindSineSum, SharpnessZeroIsSteadyWindOfAmplitudeAlongDirection) {
  auto world = make_world();
  boreas_wave w = steady_wave(3.0f, 4.0f, 7.5f);
  world->wind().set_waves(&w, 1, 0.0f, world->time());
  for (int s = 0; s < 3; ++s) {
    world->step(1.7f);
    std::vector<float> xyz = {0, 0, 0, 13.3f, 2, -41.0f, -300, 10, 250};
    std::vector<float> f(9);
    world->wind().sample(xyz.data(), 3, f.data());
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(f[3 * i], 7.5 * 0.6, 1e-5);
      EXPECT_EQ(f[3 * i + 1], 0.0f);
      EXPECT_NEAR(f[3 * i + 2], 7.5 * 0.8, 1e-5);
    }
  }
}

// Largest possible change of the wind over dt while set a blends out and set b blends in:
// d/dt of A((sin+1)/2)^k is at most A k |phi| / 2, and the smoothstep weights change at
// most 1.5 / blend per second on sets at most sum(A) strong.
double max_change(const std::vector<boreas_wave>& a, const std::vector<boreas_wave>& b, double dt,
                  double blend) {
  double rate = 0.0;
  for (const auto* set : {&a, &b}) {
    double total = 0.0;
    for (const boreas_wave& w : *set) {
      double phi = std::fabs(w.speed) * 2.0 * M_PI / w.wavelength;
      rate += w.amplitude * std::max(double(w.sharpness), 1.0) * phi / 2.0;
      total += w.amplitude;
    }
    if (blend > 0) rate += 1.5 / blend * total;
  }
  return rate * dt + 1e-4;
}

TEST(WindSineSum, NewWaveSetBlendsInWithoutAJump) {
  std::mt19937 rng(7);
  std::vector<boreas_wave> a = random_waves(rng, 3);
  std::vector<boreas_wave> b = random_waves(rng, 4);
  const float dt = 0.02f;
  std::vector<float> xyz;
  for (int i = 0; i < 64; ++i) xyz.insert(xyz.end(), {float(i * 7 % 50), 1.0f, float(i * 13 % 40)});
  auto biggest_step_change = [&](float blend) {
    auto world = make_world();
    world->wind().set_waves(a.data(), int(a.size()), 0.0f, world->time());
    std::vector<float> prev(xyz.size()), cur(xyz.size());
    world->wind().sample(xyz.data(), 64, prev.data());
    double worst = 0.0;
    for (int s = 1; s <= 300; ++s) {
      if (s == 50) world->wind().set_waves(b.data(), int(b.size()), blend, world->time());
      world->step(dt);
      world->wind().sample(xyz.data(), 64, cur.data());
      for (size_t i = 0; i < cur.size(); ++i) worst = std::max(worst, double(std::fabs(cur[i] - prev[i])));
      prev = cur;
    }
    return worst;
  };
  double blended = biggest_step_change(2.0f);
  EXPECT_LE(blended, max_change(a, b, dt, 2.0));
  // The same change with no blend does jump past that bound: the test can tell.
  double switched = biggest_step_change(0.0f);
  EXPECT_GT(switched, max_change(a, b, dt, 2.0));
}

TEST(WindSineSum, BlendEndsOnTheNewSetAlone) {
  auto world = make_world();
  boreas_wave a = steady_wave(1, 0, 4.0f);
  boreas_wave b = steady_wave(0, 1, 2.0f);
  world->wind().set_waves(&a, 1, 0.0f, world->time());
  world->wind().set_waves(&b, 1, 1.0f, world->time());
  float p[3] = {0, 0, 0}, f[3];
  world->wind().sample(p, 1, f);
  EXPECT_NEAR(f[0], 4.0f, 1e-6);  // at the moment of the change, still the old set
  EXPECT_NEAR(f[2], 0.0f, 1e-6);
  world->step(0.5f);
  world->wind().sample(p, 1, f);
  EXPECT_NEAR(f[0], 2.0f, 1e-5);  // halfway: smoothstep(1/2) = 1/2 of each
  EXPECT_NEAR(f[2], 1.0f, 1e-5);
  world->step(0.6f);
  world->wind().sample(p, 1, f);
  EXPECT_NEAR(f[0], 0.0f, 1e-6);
  EXPECT_NEAR(f[2], 2.0f, 1e-6);
  EXPECT_EQ(world->wind().wave_layers().layers().size(), 1u) << "faded sets are dropped";
}

}  // namespace
}  // namespace boreas::test

namespace boreas::test {
namespace {

// Crests of a positive speed travel downwind, along the wave's direction, at that speed.
TEST(WindSineSum, CrestsTravelAlongTheDirectionAtTheSpeed) {
  auto world = make_world();
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 0.0f;
  w.direction[1] = 1.0f;  // along +z
  w.amplitude = 1.0f;
  w.wavelength = 40.0f;
  w.speed = 5.0f;
  w.sharpness = 8.0f;  // one narrow crest per wavelength
  world->wind().set_waves(&w, 1, 0.0f, world->time());
  auto crest_z = [&] {
    const int n = 400;  // z in [0, 40) every 0.1 m
    std::vector<float> xyz(3 * n), f(3 * n);
    for (int i = 0; i < n; ++i) xyz[3 * i + 2] = 0.1f * float(i);
    world->wind().sample(xyz.data(), n, f.data());
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (f[3 * i + 2] > f[3 * best + 2]) best = i;
    return 0.1 * best;
  };
  world->step(1.0f);
  double z0 = crest_z();
  world->step(0.6f);
  double moved = std::remainder(crest_z() - z0, 40.0);
  EXPECT_NEAR(moved, 3.0, 0.11) << "0.6 s at 5 m/s along +z";
}

}  // namespace
}  // namespace boreas::test

namespace boreas::test {
namespace {

// Changing the set every step, far faster than the sets fade, must never make the wind
// jump either: the fading sets fold into one at their present strength.
TEST(WindSineSum, ChangingSetsEveryStepNeverJumps) {
  auto world = make_world();
  const boreas_wave sets[2] = {steady_wave(1, 0, 10.0f), steady_wave(0, 1, 10.0f)};
  const float dt = 0.01f, blend = 100.0f;
  float p[3] = {3, 1, 4}, prev[3], cur[3];
  world->wind().set_waves(&sets[0], 1, 0.0f, world->time());
  world->wind().sample(p, 1, prev);
  double worst = 0.0;
  for (int s = 0; s < 60; ++s) {
    world->wind().set_waves(&sets[(s + 1) % 2], 1, blend, world->time());
    world->step(dt);
    world->wind().sample(p, 1, cur);
    for (int a = 0; a < 3; ++a) worst = std::max(worst, double(std::fabs(cur[a] - prev[a])));
    std::copy(cur, cur + 3, prev);
  }
  // Steady waves: only the weights move, at most 1.5 / blend per second on 2 x 10 m/s.
  EXPECT_LE(worst, dt * 1.5 / blend * 20.0 + 1e-5);
  EXPECT_LE(world->wind().wave_layers().layers().size(), 2u);
}

// The sine sum stays within [0, A] per wave for any point and wavelength: the phase is
// reduced to one cycle before the polynomial sine.
TEST(WindSineSum, StaysWithinAmplitudeForAnyPointAndWavelength) {
  auto world = make_world();
  for (float wavelength : {1e-4f, 0.01f, 1.0f, 1e4f}) {
    boreas_wave w = boreas_default_wave();
    w.direction[0] = 0.6f;
    w.direction[1] = 0.8f;
    w.amplitude = 1.0f;
    w.wavelength = wavelength;
    w.sharpness = 1.5f;
    world->wind().set_waves(&w, 1, 0.0f, world->time());
    world->step(123.4f);
    std::vector<float> xyz, f;
    for (float x : {0.0f, 1e3f, -1e5f, 1e7f, -1e9f, 3e20f, -1e30f})
      for (float z : {0.0f, 7.0f, -2e6f, 1e30f}) xyz.insert(xyz.end(), {x, 1.0f, z});
    f.resize(xyz.size());
    world->wind().sample(xyz.data(), int(xyz.size() / 3), f.data());
    for (size_t i = 0; i < xyz.size() / 3; ++i) {
      double along = 0.6 * f[3 * i] + 0.8 * f[3 * i + 2];
      ASSERT_TRUE(std::isfinite(along)) << "wavelength " << wavelength << " point " << i;
      ASSERT_GE(along, -1e-6);
      ASSERT_LE(along, 1.0 + 1e-5) << "wavelength " << wavelength << " point " << i;
    }
  }
}

}  // namespace
}  // namespace boreas::test
