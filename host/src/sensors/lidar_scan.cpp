// boreas: a LiDAR step's rays and points (lidar_scan.h).
#include "sensors/lidar_scan.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

namespace {

uint64_t mix(uint64_t z) {  // splitmix64's finalizer
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double unit(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }  // [0, 1)

}  // namespace

Vec3d lidar_direction(double elevation, double azimuth) {
  const double c = std::cos(elevation);
  return {c * std::cos(azimuth), std::sin(elevation), -c * std::sin(azimuth)};
}

std::vector<boreas_ray> lidar_rays(const LidarParams& p, const Pose& from, const Pose& to,
                                   double t0, double t1, double start, Firings firings) {
  std::vector<boreas_ray> rays;
  rays.reserve(size_t(firings.count()) * size_t(p.channels()));
  for (int64_t k = firings.first; k < firings.end; ++k) {
    const double s =
        t1 > t0 ? std::clamp((firing_time(k, start, p) - t0) / (t1 - t0), 0.0, 1.0) : 1.0;
    const Pose pose = between(from, to, s);
    const double azimuth = firing_azimuth(k, p);
    for (double elevation : p.elevations) {
      const Vec3d d = pose.turn(lidar_direction(elevation, azimuth));
      boreas_ray r{};
      for (size_t a = 0; a < 3; ++a) {
        r.origin[a] = float(pose.position[a]);
        r.direction[a] = float(d[a]);
      }
      r.max_distance = float(p.max_range);
      rays.push_back(r);
    }
  }
  return rays;
}

RayDraws ray_draws(uint64_t seed, int64_t k, int ring) {
  const uint64_t key = mix(mix(mix(seed) ^ uint64_t(k)) ^ uint64_t(uint32_t(ring)));
  const double u1 = 1.0 - unit(mix(key + 1)), u2 = unit(mix(key + 2));  // u1 in (0, 1]
  return {unit(mix(key)),
          std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2)};
}

std::vector<boreas_lidar_point> lidar_points(const LidarParams& p, Firings firings,
                                             const boreas_ray* rays, const boreas_hit* hits) {
  std::vector<boreas_lidar_point> points;
  const int channels = p.channels();
  for (int64_t k = firings.first; k < firings.end; ++k) {
    for (int ring = 0; ring < channels; ++ring) {
      const size_t i = size_t(k - firings.first) * size_t(channels) + size_t(ring);
      const boreas_hit& h = hits[i];
      if (h.kind == BOREAS_HIT_NONE || !(h.distance >= p.min_range)) continue;
      const RayDraws draw = ray_draws(p.seed, k, ring);
      if (draw.dropout < p.dropout) continue;
      const boreas_ray& r = rays[i];
      const double range = double(h.distance) + p.range_noise * draw.noise;
      double cosine = 0.0, norm2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        cosine += double(r.direction[a]) * h.normal[a];
        norm2 += double(r.direction[a]) * r.direction[a];
      }
      const double scale = range / std::sqrt(norm2);  // the cast measures along the unit ray
      boreas_lidar_point pt{};
      pt.x = float(r.origin[0] + scale * r.direction[0]);
      pt.y = float(r.origin[1] + scale * r.direction[1]);
      pt.z = float(r.origin[2] + scale * r.direction[2]);
      pt.intensity = float(p.reflectivity[boreas_lidar_surface_of(h.kind)] *
                           std::min(1.0, std::fabs(cosine) / std::sqrt(norm2)));
      pt.ring = uint16_t(ring);
      pt.time = float(time_in_sweep(k, p));
      pt.kind = h.kind;
      pt.object = h.object;
      pt.part = h.part;
      points.push_back(pt);
    }
  }
  return points;
}

}  // namespace boreas::impl
