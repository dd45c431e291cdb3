// boreas tests: what a cast's rays reach (rays/ray_reach.h). The cones may only leave out a
// sphere no ray comes within its radius of (checked against each ray segment's exact
// distance to the sphere's center in double), and a LiDAR's slice of a sweep leaves out the
// plants beside it, which the box alone does not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "rays/ray_checks.h"
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

}  // namespace
