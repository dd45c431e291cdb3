// boreas tests: the force-field grid's behaviour — what primitives, obstacles and transport
// must do, stability under extreme input, and exact calm when nothing drives it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace boreas::test {
namespace {

// A vortex about the vertical through the origin and the default gust: a steady primitive
// (the forcing field) and a varying one (the step's own loop) at once.
void add_vortex_and_gust(impl::World& world) {
  add_vortex(world, 6.0f);
  world.wind().add_gust(boreas_default_gust_def(), world.time());
}

TEST(WindGrid, UniformPrimitiveFillsEmptyGridToTheAnalyticValue) {
  boreas_grid_def g = centered_grid(12, 4, 10, 2.0f);
  g.decay_rate = 0.3f;
  g.response_time = 0.5f;
  auto world = make_world(&g);
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.direction[0] = 3.0f;  // normalized by the library
  p.direction[1] = 0.0f;
  p.direction[2] = 4.0f;
  p.strength = 5.0f;
  world->wind().add_primitive(p, world->time());
  const double dt = 0.1;
  for (int s = 0; s < 300; ++s) world->step(float(dt));
  // Steady state of  v <- T + (v e^{-lambda dt} - T) e^{-dt/tau}:  v* = T (1-b) / (1-a b).
  double a = std::exp(-0.3 * dt), b = std::exp(-dt / 0.5);
  double magnitude = 5.0 * (1 - b) / (1 - a * b);
  std::vector<float> cells = world->wind().grid().read();
  for (size_t i = 0; i < cells.size() / 4; ++i) {
    ASSERT_NEAR(cells[4 * i + 0], 0.6 * magnitude, 1e-4) << "cell " << i;
    ASSERT_NEAR(cells[4 * i + 1], 0.0, 1e-6);
    ASSERT_NEAR(cells[4 * i + 2], 0.8 * magnitude, 1e-4);
  }
  // With no decay the grid reaches the primitive's velocity itself.
  boreas_grid_def g0 = g;
  g0.decay_rate = 0.0f;
  auto exact = make_world(&g0);
  exact->wind().add_primitive(p, exact->time());
  for (int s = 0; s < 300; ++s) exact->step(float(dt));
  float probe[3] = {1.0f, 3.0f, -2.0f}, f[3];
  exact->wind().sample(probe, 1, f);
  EXPECT_NEAR(f[0], 3.0f, 1e-4);
  EXPECT_NEAR(f[2], 4.0f, 1e-4);
}

TEST(WindGrid, VortexTurnsRightHandedAroundItsAxis) {
  boreas_grid_def g = centered_grid(24, 4, 24, 1.0f);
  g.diffusion = 0.0f;
  // The grid carries its own flow along (self-advection, no pressure term), which turns
  // the field by about omega * response_time before the primitive pulls it back: a small
  // radial part. A short response time keeps that lag small here.
  g.response_time = 0.1f;
  auto world = make_world(&g);
  boreas_flow_primitive_def v = boreas_default_flow_primitive_def();
  v.type = BOREAS_FLOW_VORTEX;
  v.position[1] = 2.0f;
  v.direction[0] = 0.0f;
  v.direction[1] = 1.0f;  // axis up: counter-clockwise seen from above
  v.strength = 3.0f;
  v.radius = 10.0f;
  world->wind().add_primitive(v, world->time());
  for (int s = 0; s < 40; ++s) world->step(0.1f);
  // On the +x side the flow goes to -z, on the +z side to +x (axis x r, right-handed).
  std::vector<float> xyz = {4, 2, 0, 0, 2, 4, -4, 2, 0, 0, 2, -4};
  std::vector<float> f(12);
  world->wind().sample(xyz.data(), 4, f.data());
  EXPECT_LT(f[2], -0.5f);
  EXPECT_GT(f[3], 0.5f);
  EXPECT_GT(f[8], 0.5f);
  EXPECT_LT(f[9], -0.5f);
  // Circulation around the axis is positive and the flow has no radial part to speak of.
  const int n = 64;
  std::vector<float> ring(3 * n), w(3 * n);
  for (int i = 0; i < n; ++i) {
    double a = 2 * M_PI * i / n;
    ring[3 * i] = float(5 * std::cos(a));
    ring[3 * i + 1] = 2.0f;
    ring[3 * i + 2] = float(5 * std::sin(a));
  }
  world->wind().sample(ring.data(), n, w.data());
  double circulation = 0.0, radial = 0.0;
  for (int i = 0; i < n; ++i) {
    double a = 2 * M_PI * i / n;
    // Tangent of (axis y) x (cos a, 0, sin a) = (sin a, 0, -cos a).
    circulation += w[3 * i] * std::sin(a) - w[3 * i + 2] * std::cos(a);
    radial += w[3 * i] * std::cos(a) + w[3 * i + 2] * std::sin(a);
  }
  EXPECT_GT(circulation / n, 1.0);
  EXPECT_LT(std::fabs(radial / n), 0.1 * circulation / n);
}

TEST(WindGrid, SourceAndSinkPointOutAndIn) {
  boreas_grid_def g = centered_grid(16, 8, 16, 1.0f);
  auto world = make_world(&g);
  boreas_flow_primitive_def s = boreas_default_flow_primitive_def();
  s.type = BOREAS_FLOW_SOURCE;
  s.position[0] = -4.0f;
  s.position[1] = 4.0f;
  s.strength = 2.0f;
  s.radius = 3.5f;
  boreas_flow_primitive_def k = s;
  k.type = BOREAS_FLOW_SINK;
  k.position[0] = 4.0f;
  world->wind().add_primitive(s, world->time());
  world->wind().add_primitive(k, world->time());
  for (int i = 0; i < 40; ++i) world->step(0.1f);
  std::vector<float> xyz = {-2.5f, 4.5f, 0.5f, 2.5f, 4.5f, 0.5f}, f(6);
  world->wind().sample(xyz.data(), 2, f.data());
  EXPECT_GT(f[0], 0.2f) << "away from the source at x = -4";
  EXPECT_GT(f[3], 0.2f) << "toward the sink at x = 4";
}

TEST(WindGrid, ObstacleHasZeroWindInsideAndNoFluxThroughItsFaces) {
  boreas_grid_def g = centered_grid(20, 8, 12, 1.0f);  // x in [-10, 10), z in [-6, 6)
  auto world = make_world(&g);
  boreas_wave wind = steady_wave(1.0f, 0.3f, 5.0f);  // into the wall's -x face and along z
  world->wind().set_waves(&wind, 1, 0.0f, world->time());
  float lo[3] = {-1.0f, 0.0f, -2.0f}, hi[3] = {1.0f, 4.0f, 2.0f};  // cells x -1..1 (2 cells)
  world->wind().add_solid_box(lo, hi);
  for (int s = 0; s < 60; ++s) world->step(0.1f);

  std::vector<float> inside = {-0.5f, 1.5f, 0.0f, 0.7f, 3.9f, -1.5f, 0.0f, 0.2f, 1.9f};
  std::vector<float> f(inside.size());
  world->wind().sample(inside.data(), 3, f.data());
  for (float v : f) EXPECT_EQ(v, 0.0f) << "the sampled wind is zero inside a solid";

  // Just outside each face, the component normal to that face vanishes (sine sum included).
  std::vector<float> outside;
  for (float y : {0.5f, 2.5f})
    for (float z : {-1.5f, 0.5f}) {
      outside.insert(outside.end(), {-1.0f - 1e-3f, y, z});  // upwind face, normal x
      outside.insert(outside.end(), {1.0f + 1e-3f, y, z});   // lee face, normal x
    }
  for (float x : {-0.5f, 0.5f}) {
    outside.insert(outside.end(), {x, 1.5f, -2.0f - 1e-3f});  // side faces, normal z
    outside.insert(outside.end(), {x, 1.5f, 2.0f + 1e-3f});
    outside.insert(outside.end(), {x, 4.0f + 1e-3f, 0.5f});   // roof, normal y
  }
  std::vector<float> w(outside.size());
  world->wind().sample(outside.data(), int(outside.size() / 3), w.data());
  for (size_t p = 0; p < outside.size() / 3; ++p) {
    int normal_axis = p < 8 ? 0 : ((p - 8) % 3 == 2 ? 1 : 2);
    EXPECT_NEAR(w[3 * p + normal_axis], 0.0f, 0.02f)
        << "point " << outside[3 * p] << "," << outside[3 * p + 1] << "," << outside[3 * p + 2];
  }
  // The tangential flow goes on along the upwind face: the wind is deflected, not stopped.
  EXPECT_GT(std::fabs(w[2]), 0.3f);
  // And the obstacle shelters its lee: behind it the wind is weaker than in the open.
  std::vector<float> lee = {3.0f, 1.5f, 0.0f, 3.0f, 6.5f, 0.0f}, lw(6);
  world->wind().sample(lee.data(), 2, lw.data());
  EXPECT_LT(std::hypot(lw[0], lw[2]), 0.8f * std::hypot(lw[3], lw[5]));
}

TEST(WindGrid, TransportMovesAPulseDownwindAtTheWindSpeed) {
  boreas_grid_def g = centered_grid(80, 4, 8, 1.0f);  // x in [-40, 40)
  g.diffusion = 0.0f;
  g.decay_rate = 0.0f;
  g.response_time = 0.05f;
  auto world = make_world(&g);
  boreas_wave wind = steady_wave(1.0f, 0.0f, 4.0f);
  world->wind().set_waves(&wind, 1, 0.0f, world->time());
  boreas_flow_primitive_def puff = boreas_default_flow_primitive_def();
  puff.direction[0] = 0.0f;
  puff.direction[2] = 1.0f;  // a crosswind puff, so its own speed does not carry it along x
  puff.strength = 0.5f;
  puff.radius = 4.0f;
  puff.position[0] = -25.0f;
  puff.position[1] = 2.0f;
  puff.lifetime = 0.2f;
  world->wind().add_primitive(puff, world->time());
  auto centroid_x = [&] {
    std::vector<float> c = world->wind().grid().read();
    double sum = 0.0, weight = 0.0;
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 80; ++i) {
          size_t idx = (size_t(k) * 4 + j) * 80 + i;
          double m = std::fabs(c[4 * idx + 2]);
          sum += m * (g.origin[0] + (i + 0.5) * g.cell_size);
          weight += m;
        }
    return sum / weight;
  };
  const float dt = 0.05f;
  for (int s = 0; s < 10; ++s) world->step(dt);  // puff made, primitive expired
  double t0 = world->time(), x0 = centroid_x();
  for (int s = 0; s < 200; ++s) world->step(dt);
  double speed = (centroid_x() - x0) / (world->time() - t0);
  EXPECT_NEAR(speed, 4.0, 0.08) << "centroid moved from " << x0;
}

TEST(WindGrid, NoNaNOrBlowUpAfter100kStepsOfExtremeInput) {
  // The limits of what the API accepts: the smallest cells and response time, the
  // largest diffusion, steps and speeds.
  boreas_grid_def g = centered_grid(6, 4, 6, 1e-3f);
  g.diffusion = 1e6f;
  g.decay_rate = 0.0f;
  g.response_time = 1e-4f;
  auto world = make_world(&g);
  boreas_wave waves[3] = {steady_wave(1, 0, 1000.0f), boreas_default_wave(), boreas_default_wave()};
  waves[1].amplitude = 1000.0f;
  waves[1].sharpness = 64.0f;
  waves[1].speed = 1000.0f;
  waves[1].wavelength = 1e-3f;
  waves[2].direction[0] = -1.0f;
  waves[2].amplitude = 1000.0f;
  waves[2].sharpness = 0.01f;
  world->wind().set_waves(waves, 3, 0.0f, world->time());
  boreas_flow_primitive_def v = boreas_default_flow_primitive_def();
  v.type = BOREAS_FLOW_VORTEX;
  v.direction[0] = 0.3f;
  v.direction[1] = 1.0f;
  v.strength = 1000.0f;
  v.radius = 1e-3f;
  world->wind().add_primitive(v, world->time());
  v.type = BOREAS_FLOW_SINK;
  v.radius = 2.0f;
  world->wind().add_primitive(v, world->time());
  boreas_gust_def gust = boreas_default_gust_def();
  gust.strength = -1000.0f;
  gust.hold = 1e9f;
  world->wind().add_gust(gust, world->time());
  float lo[3] = {-1e-3f, 0.0f, -1e-3f}, hi[3] = {1e-3f, 2e-3f, 1e-3f};
  world->wind().add_solid_box(lo, hi);
  const float dts[] = {3600.0f, 1e-6f, 0.5f, 60.0f};
  // Everything the grid holds is a convex mix of inputs bounded by these magnitudes.
  const float bound = 3 * 1000.0f + 3 * 1000.0f + 1.0f;
  for (int s = 0; s < 100000; ++s) {
    world->step(dts[s % 4]);
    if (s % 20000 == 19999) {
      std::vector<float> cells = world->wind().grid().read();
      for (float c : cells) {
        ASSERT_TRUE(std::isfinite(c)) << "step " << s;
        ASSERT_LE(std::fabs(c), bound) << "step " << s;
      }
    }
  }
}

TEST(WindGrid, WithNothingToDriveItTheGridStaysExactlyZero) {
  boreas_grid_def g = centered_grid(10, 4, 10, 2.0f);
  auto world = make_world(&g);
  world->wind().grid().set_always_run(true);  // run the kernels although the grid is idle
  boreas_wave waves[2] = {boreas_default_wave(), steady_wave(0.2f, 1.0f, 3.0f)};
  world->wind().set_waves(waves, 2, 0.0f, world->time());
  for (int s = 0; s < 50; ++s) world->step(0.3f);
  for (float c : world->wind().grid().read()) ASSERT_EQ(c, 0.0f);
}

TEST(WindGrid, SameInputsGiveBitIdenticalResults) {
  auto run = [] {
    boreas_grid_def g = centered_grid(16, 6, 16, 1.0f);
    auto world = make_world(&g);
    boreas_wave w = boreas_default_wave();
    world->wind().set_waves(&w, 1, 0.0f, world->time());
    add_vortex_and_gust(*world);
    for (int s = 0; s < 40; ++s) world->step(0.05f);
    std::vector<float> c = world->wind().grid().read();
    unsigned long long h = 1469598103934665603ull;
    for (float x : c) {
      unsigned int bits;
      std::memcpy(&bits, &x, 4);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  };
  EXPECT_EQ(run(), run());
}

// The wind kernels written for a SIMD width (wind_sine_slab.cl, wind_sample_points.cl)
// run the same source at width 1 (GPUs) and at the CPU's width (cl/shared/simd_width.h):
// the grid the slab drives and the wind sampled at points must agree bit for bit, with a
// row length and a point count that leave partial last work-items, points beyond the
// grid and inside a solid, and waves of several sharpnesses (pow's exponent per wave).
TEST(WindGrid, EveryKernelWidthGivesTheSameWindBitForBit) {
  std::vector<float> points;
  unsigned state = 12345u;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (int i = 0; i < 1001; ++i) {
    points.push_back(-14.0f + 28.0f * next());
    points.push_back(-1.0f + 9.0f * next());
    points.push_back(-10.0f + 20.0f * next());
  }
  points.insert(points.end(), {0.0f, 1.0f, 0.0f, 0.5f, 2.5f, -0.5f});  // inside the solid
  const int count = int(points.size() / 3);
  auto run = [&](int width) {
    ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
    boreas_grid_def g = centered_grid(19, 6, 13, 1.0f);  // x in [-9.5, 9.5), z in [-6.5, 6.5)
    auto world = make_world(&g);
    EXPECT_EQ(world->runtime().simd_width(), width);
    boreas_wave waves[3] = {boreas_default_wave(), boreas_default_wave(), boreas_default_wave()};
    waves[1].direction[0] = 0.3f;
    waves[1].direction[1] = 0.9f;
    waves[1].sharpness = 2.5f;
    waves[1].wavelength = 7.0f;
    waves[2].sharpness = 0.0f;
    waves[2].wavelength = 31.0f;
    world->wind().set_waves(waves, 3, 0.0f, world->time());
    float lo[3] = {-1.0f, 0.0f, -2.0f}, hi[3] = {1.0f, 4.0f, 2.0f};
    world->wind().add_solid_box(lo, hi);
    add_vortex_and_gust(*world);
    for (int s = 0; s < 20; ++s) world->step(0.05f);
    std::vector<float> result = world->wind().grid().read();
    std::vector<float> f(points.size());
    world->wind().sample(points.data(), count, f.data());
    result.insert(result.end(), f.begin(), f.end());
    return result;
  };
  const std::vector<float> scalar = run(1);
  for (int width : {4, 8, 16}) {
    const std::vector<float> wide = run(width);
    ASSERT_EQ(wide.size(), scalar.size());
    size_t differing = 0;
    for (size_t i = 0; i < wide.size(); ++i)
      differing += std::memcmp(&wide[i], &scalar[i], sizeof(float)) != 0;
    EXPECT_EQ(differing, 0u) << "width " << width;
  }
  // Not vacuous: the sampled wind is non-zero outside the solid and zero inside it.
  EXPECT_NE(scalar[scalar.size() - 3 * count], 0.0f);
  for (int a = 0; a < 6; ++a) EXPECT_EQ(scalar[scalar.size() - 6 + a], 0.0f);
}

TEST(WindGrid, GustPushesThenFades) {
  boreas_grid_def g = centered_grid(8, 4, 8, 2.0f);
  auto world = make_world(&g);
  boreas_gust_def gust = boreas_default_gust_def();
  gust.direction[0] = 0.0f;
  gust.direction[2] = -1.0f;
  gust.strength = 6.0f;
  gust.delay = 0.5f;
  gust.rise = 0.5f;
  gust.hold = 2.0f;
  gust.fall = 0.5f;
  world->wind().add_gust(gust, world->time());
  float p[3] = {0.0f, 2.0f, 0.0f}, f[3];
  world->step(0.4f);
  world->wind().sample(p, 1, f);
  EXPECT_EQ(f[2], 0.0f) << "nothing before the delay";
  for (int s = 0; s < 20; ++s) world->step(0.1f);  // t = 2.4: holding
  world->wind().sample(p, 1, f);
  EXPECT_LT(f[2], -4.0f);
  for (int s = 0; s < 100; ++s) world->step(0.1f);  // t = 12.4, 8.9 s after the fall ended
  world->wind().sample(p, 1, f);
  // Left to itself the grid decays at decay_rate (0.2/s by default).
  double left = 6.0 * std::exp(-0.2 * (world->time() - 3.5));
  EXPECT_LT(f[2], 0.0f);
  EXPECT_GT(f[2], -left - 0.05);
}

}  // namespace
}  // namespace boreas::test

namespace boreas::test {
namespace {

// The steady forcing field is rebuilt when a primitive goes: afterwards the grid only
// decays. A uniform field is untouched by transport and diffusion, so it decays exactly
// as exp(-decay_rate t).
TEST(WindGrid, RemovedPrimitiveStopsDrivingAndTheGridDecays) {
  boreas_grid_def g = centered_grid(8, 4, 8, 2.0f);
  g.decay_rate = 0.5f;
  auto world = make_world(&g);
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.strength = 4.0f;
  boreas_primitive_id id = world->wind().add_primitive(p, world->time());
  for (int s = 0; s < 100; ++s) world->step(0.1f);
  float probe[3] = {0.0f, 3.0f, 0.0f}, before[3], after[3];
  world->wind().sample(probe, 1, before);
  ASSERT_GT(before[0], 1.0f);
  world->wind().remove(id);
  for (int s = 0; s < 20; ++s) world->step(0.1f);
  world->wind().sample(probe, 1, after);
  EXPECT_NEAR(after[0], before[0] * std::exp(-0.5 * 2.0), 1e-4);
  // A new primitive is picked up again.
  p.strength = -4.0f;
  world->wind().add_primitive(p, world->time());
  for (int s = 0; s < 100; ++s) world->step(0.1f);
  world->wind().sample(probe, 1, after);
  EXPECT_NEAR(after[0], -before[0], 1e-3);
}

}  // namespace
}  // namespace boreas::test
