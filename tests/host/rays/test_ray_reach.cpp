// boreas tests: what a cast's rays reach (rays/ray_reach.h). The cones may only leave out a
// sphere no ray comes within its radius of (checked against each ray segment's exact
// distance to the sphere's center in double), and a LiDAR's slice of a sweep leaves out the
// plants beside it, which the box alone does not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rays/ray_checks.h"
#include "rays/ray_directions.h"
#include "rays/ray_reach.h"

namespace {

using boreas::impl::RayReach;
using V = std::array<double, 3>;

// The least distance from c to the segment of ray r (double).
double segment_distance(const boreas_ray& r, const V& c) {
  V d = {r.direction[0], r.direction[1], r.direction[2]};
  const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& x : d) x /= n;
  const V o = {r.origin[0], r.origin[1], r.origin[2]};
  double t = (c[0] - o[0]) * d[0] + (c[1] - o[1]) * d[1] + (c[2] - o[2]) * d[2];
  t = std::clamp(t, 0.0, double(r.max_distance));
  double s = 0.0;
  for (size_t a = 0; a < 3; ++a) s += std::pow(o[a] + t * d[a] - c[a], 2);
  return std::sqrt(s);
}

boreas::impl::Box sphere_box(const V& c, double r) {
  return {float(c[0] - r), float(c[1] - r), float(c[2] - r),
          float(c[0] + r), float(c[1] + r), float(c[2] + r)};
}

// Rays of every kind (shared origins and fans, scattered origins, opposite directions, long
// and short): no sphere a ray passes through is left out.
TEST(RayReach, ConesNeverLeaveOutASphereARayPassesThrough) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<boreas_ray> rays(size_t(50 + trial * 7));
    const V origin = {10 * u(rng), 2 * u(rng), 10 * u(rng)};
    const double scatter = trial % 3 == 0 ? 5.0 : trial % 3 == 1 ? 0.01 : 0.0;
    const double fan = trial % 4 == 0 ? 1.0 : 0.1;
    const V heading = {u(rng), 0.3 * u(rng), u(rng)};
    for (boreas_ray& r : rays) {
      for (int a = 0; a < 3; ++a) {
        r.origin[a] = float(origin[size_t(a)] + scatter * u(rng));
        r.direction[a] = float(heading[size_t(a)] + fan * u(rng));
      }
      r.max_distance = float(trial % 5 == 0 ? 1e30 : 30.0 * (1.0 + u(rng)));
    }
    std::vector<boreas_hit> hits(rays.size());
    const RayReach reach = boreas::impl::checked_rays(rays.data(), int(rays.size()), hits.data());
    ASSERT_FALSE(reach.cones.empty());
    int touched = 0, left_out = 0;
    for (int s = 0; s < 400; ++s) {
      const V c = {origin[0] + 40 * u(rng), origin[1] + 10 * u(rng), origin[2] + 40 * u(rng)};
      const double radius = 0.2 + 3.0 * (u(rng) + 1.0);
      double least = 1e300;
      for (const boreas_ray& r : rays) least = std::min(least, segment_distance(r, c));
      const bool meets = reach.meets(sphere_box(c, radius), c, radius);
      if (least <= radius) {
        ++touched;
        EXPECT_TRUE(meets) << "trial " << trial << " sphere " << s << ": a ray passes " << least
                           << " m from its center, radius " << radius;
      } else if (!meets) {
        ++left_out;
      }
    }
    EXPECT_GT(touched, 0) << trial;
    if (scatter == 0.0 && fan < 0.5) EXPECT_GT(left_out, 0) << trial;
  }
}

// A 32-channel LiDAR's slice of one 60 Hz step (a sixth of a 10 Hz turn) in the middle of a
// ring of trees: the cones leave out the trees outside the slice's wedge; the slice's box,
// a quadrant, holds more.
TEST(RayReach, ALidarSliceLeavesOutThePlantsBesideIt) {
  std::vector<boreas_ray> rays;
  const int columns = 2048 / 6;
  for (int col = 0; col < columns; ++col) {
    const double azimuth = 2 * M_PI * col / 2048.0;
    for (int ch = 0; ch < 32; ++ch) {
      const double elevation = (-30.67 + 41.34 * ch / 31.0) * M_PI / 180.0;
      boreas_ray r{};
      r.origin[1] = 1.8f;
      r.direction[0] = float(std::cos(elevation) * std::cos(azimuth));
      r.direction[1] = float(std::sin(elevation));
      r.direction[2] = float(-std::cos(elevation) * std::sin(azimuth));
      r.max_distance = 100.0f;
      rays.push_back(r);
    }
  }
  std::vector<boreas_hit> hits(rays.size());
  const RayReach reach = boreas::impl::checked_rays(rays.data(), int(rays.size()), hits.data());
  RayReach box_only;
  box_only.box = reach.box;
  int in_cones = 0, in_box = 0, trees = 0;
  for (int ring = 1; ring <= 4; ++ring) {
    for (int k = 0; k < 36; ++k) {
      const double a = 2 * M_PI * (k + 0.5) / 36;
      const V c = {15.0 * ring * std::cos(a), 6.0, -15.0 * ring * std::sin(a)};
      const double radius = 7.0;
      ++trees;
      in_cones += reach.meets(sphere_box(c, radius), c, radius);
      in_box += box_only.meets(sphere_box(c, radius), c, radius);
    }
  }
  // The slice is 60 degrees: with the trees' own size about a quarter of the ring.
  EXPECT_LT(in_cones, trees * 0.3) << in_cones << " of " << trees;
  EXPECT_GT(in_cones, trees * 60 / 360) << in_cones;
  EXPECT_GT(in_box, in_cones * 6 / 5) << in_box;
}

// The map of directions (ray_directions.h) alone, on the same kinds of rays: it may only
// leave out a sphere no ray segment comes within its radius of, near the poles and across
// the azimuth's seam too.
TEST(RayReach, TheDirectionMapNeverLeavesOutASphereARayPassesThrough) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int left_out_total = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<boreas_ray> rays(size_t(30 + trial * 5));
    const V origin = {10 * u(rng), 2 * u(rng), 10 * u(rng)};
    // Origins up to 1.7 m from the first ray's (the map is made within 4 m), or 0.01, or 0.
    const double scatter = trial % 3 == 0 ? 1.0 : trial % 3 == 1 ? 0.01 : 0.0;
    const double fan = trial % 4 == 0 ? 1.0 : 0.05;
    // Headings toward the poles (y), across the azimuth's seam (+x, where the map's azimuth
    // wraps), across -x, and anywhere.
    const V heading = trial % 6 == 0 ? V{0.02 * u(rng), 1.0, 0.02 * u(rng)}
                      : trial % 6 == 1 ? V{1.0, 0.1 * u(rng), 0.01 * u(rng)}
                      : trial % 6 == 2 ? V{-1.0, 0.1 * u(rng), 0.01 * u(rng)}
                                       : V{u(rng), 0.3 * u(rng), u(rng)};
    for (boreas_ray& r : rays) {
      for (int a = 0; a < 3; ++a) {
        r.origin[a] = float(origin[size_t(a)] + scatter * u(rng));
        r.direction[a] = float(heading[size_t(a)] + fan * u(rng));
      }
      r.max_distance = float(trial % 7 == 0 ? 1e30 : 30.0 * (1.0 + u(rng)));
    }
    const boreas::impl::DirectionMap map = boreas::impl::direction_map(rays.data(), int(rays.size()));
    ASSERT_FALSE(map.sums.empty()) << trial;
    int touched = 0;
    for (int s = 0; s < 400; ++s) {
      // Spheres along the rays (some of them touched) and anywhere about.
      const boreas_ray& along = rays[size_t(s) % rays.size()];
      const double t = 40.0 * (u(rng) + 1.0) * 0.5;
      V c = {origin[0] + 40 * u(rng), origin[1] + 10 * u(rng), origin[2] + 40 * u(rng)};
      if (s % 2 == 0)
        for (size_t a = 0; a < 3; ++a) c[a] = along.origin[a] + t * along.direction[a] + 0.5 * u(rng);
      const double radius = 0.05 + 1.0 * (u(rng) + 1.0);
      double least = 1e300;
      for (const boreas_ray& r : rays) least = std::min(least, segment_distance(r, c));
      const bool meets = map.meets(c, radius);
      if (least <= radius) {
        ++touched;
        EXPECT_TRUE(meets) << "trial " << trial << " sphere " << s << ": a ray passes " << least
                           << " m from its center, radius " << radius;
      } else {
        left_out_total += !meets;
      }
    }
    EXPECT_GT(touched, 0) << trial;
  }
  EXPECT_GT(left_out_total, 1000);  // it does leave spheres out
  // Rays from places farther apart than kDirectionMapSpread: no map (the cones decide).
  std::vector<boreas_ray> apart = {{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 10.0f},
                                   {{0.0f, 0.0f, 4.5f}, {1.0f, 0.0f, 0.0f}, 10.0f}};
  EXPECT_TRUE(boreas::impl::direction_map(apart.data(), 2).sums.empty());
  std::vector<boreas_hit> hits(2);
  const RayReach reach = boreas::impl::checked_rays(apart.data(), 2, hits.data());
  const V near = {5.0, 0.0, 2.25};  // between the two rays, 2.25 m from each
  EXPECT_TRUE(reach.meets(sphere_box(near, 2.5), near, 2.5));
}

// A 32-channel LiDAR's slice (the vertical spread of an HDL-32E, -30.67 .. +10.67 degrees,
// 1.8 m up): a branch's sphere between two channels' fans far off is met by the cones (a
// run of a firing's channels spans them) and left out by the map; one above the top
// channel is left out by both (the map does it in constant time, which is what lets the
// update ask it of every branch); one on a channel's fan or grazing the top one is met.
TEST(RayReach, TheDirectionMapLeavesOutWhatALidarsChannelsPassBy) {
  std::vector<boreas_ray> rays;
  for (int col = 0; col < 2048 / 6; ++col) {
    const double azimuth = 2 * M_PI * col / 2048.0;
    for (int ch = 0; ch < 32; ++ch) {
      const double elevation = (-30.67 + 41.34 * ch / 31.0) * M_PI / 180.0;
      boreas_ray r{};
      r.origin[1] = 1.8f;
      r.direction[0] = float(std::cos(elevation) * std::cos(azimuth));
      r.direction[1] = float(std::sin(elevation));
      r.direction[2] = float(-std::cos(elevation) * std::sin(azimuth));
      r.max_distance = 100.0f;
      rays.push_back(r);
    }
  }
  std::vector<boreas_hit> hits(rays.size());
  const RayReach reach = boreas::impl::checked_rays(rays.data(), int(rays.size()), hits.data());
  RayReach cones = reach;
  cones.directions = {};
  const double a = 30.0 * M_PI / 180.0;  // inside the slice's 60 degrees
  auto at = [&](double distance, double elevation_deg) {
    const double e = elevation_deg * M_PI / 180.0;
    return V{distance * std::cos(e) * std::cos(a), 1.8 + distance * std::sin(e), -distance * std::cos(e) * std::sin(a)};
  };
  const double step = 41.34 / 31.0;  // degrees between channels
  struct Case {
    V center;
    double radius;
    bool by_cones, by_map;
  };
  const Case cases[] = {
      {at(20.0, 10.67 + 4.0), 0.5, false, false},          // above the top channel
      {at(60.0, -30.67 + 5.5 * step), 0.1, true, false},   // between two channels, far
      {at(20.0, -30.67 + 5.0 * step), 0.3, true, true},    // on a channel's fan
      {at(20.0, 10.67 + 1.0), 0.5, true, true},            // grazing the top channel
  };
  for (const Case& c : cases) {
    const std::string where = std::to_string(c.center[0]) + " " + std::to_string(c.center[1]);
    EXPECT_EQ(cones.meets(sphere_box(c.center, c.radius), c.center, c.radius), c.by_cones) << where;
    EXPECT_EQ(reach.directions.meets(c.center, c.radius), c.by_map) << where;
    EXPECT_EQ(reach.meets(sphere_box(c.center, c.radius), c.center, c.radius), c.by_cones && c.by_map) << where;
  }
}

}  // namespace
