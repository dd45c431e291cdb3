// boreas: a LiDAR step's rays and, from their hits, its points. Pure functions of the
// LiDAR's params, so tests can check them on hits of their own.
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "sensors/lidar_params.h"
#include "sensors/lidar_sweep.h"
#include "pose.h"

namespace boreas::impl {

// Firing k's rays, channels per firing in ring order, firings in order: each from the pose
// between `from` (at t0) and `to` (at t1) at the firing's time, up to max_range.
std::vector<boreas_ray> lidar_rays(const LidarParams& p, const Pose& from, const Pose& to,
                                   double t0, double t1, double start, Firings firings);

// A ray's direction in the LiDAR's own axes (lidar_params.h; boreas.h, "Sensors").
Vec3d lidar_direction(double elevation, double azimuth);

// The points of the rays' hits (rays and hits as lidar_rays made them and a cast filled
// them): a hit nearer than min_range, a miss or a dropout gives no point; the others lie
// on their ray at the hit's distance plus the range noise.
// rays and hits hold firings.count() * channels entries, firing by firing.
std::vector<boreas_lidar_point> lidar_points(const LidarParams& p, Firings firings,
                                             const boreas_ray* rays, const boreas_hit* hits);

// The noise and dropout draws of ray (k, ring): uniform in [0, 1) and standard normal,
// a function of (seed, k, ring) alone, so slicing a sweep differently changes nothing.
struct RayDraws {
  double dropout;
  double noise;
};
RayDraws ray_draws(uint64_t seed, int64_t k, int ring);

}  // namespace boreas::impl
