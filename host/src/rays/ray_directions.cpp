// boreas: the map of the rays' directions (ray_directions.h).
#include "rays/ray_directions.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

namespace {

constexpr int kAz = kDirectionAzimuthCells, kEl = kDirectionElevationCells;

// The cell of an azimuth (radians, any) or an elevation (radians, [-pi/2, pi/2]), clamped:
// the same function places the rays and bounds the discs.
int azimuth_cell(double azimuth) {
  return std::clamp(int(std::floor((azimuth + M_PI) / (2.0 * M_PI) * kAz)), 0, kAz - 1);
}
int elevation_cell(double elevation) {
  return std::clamp(int(std::floor((elevation + 0.5 * M_PI) / M_PI * kEl)), 0, kEl - 1);
}

// Rays in cells [e0, e1] x [a0, a1] (inclusive, within the grid).
int32_t rays_in(const std::vector<int32_t>& s, int e0, int e1, int a0, int a1) {
  const size_t w = size_t(kAz) + 1;
  auto at = [&](int e, int a) { return s[size_t(e) * w + size_t(a)]; };
  return at(e1 + 1, a1 + 1) - at(e0, a1 + 1) - at(e1 + 1, a0) + at(e0, a0);
}

}  // namespace

DirectionMap direction_map(const boreas_ray* rays, int count) {
  DirectionMap map;
  if (count <= 0) return map;
  for (int a = 0; a < 3; ++a) map.apex[size_t(a)] = rays[0].origin[a];
  const size_t w = size_t(kAz) + 1;
  map.sums.assign(w * (size_t(kEl) + 1), 0);
  for (int i = 0; i < count; ++i) {
    const boreas_ray& r = rays[i];
    double off = 0.0, len = 0.0;
    for (int a = 0; a < 3; ++a) {
      off += std::pow(double(r.origin[a]) - map.apex[size_t(a)], 2);
      len += double(r.direction[a]) * r.direction[a];
    }
    map.spread = std::max(map.spread, std::sqrt(off));
    map.length = std::max(map.length, double(r.max_distance));
    len = std::sqrt(len);
    const double y = std::clamp(double(r.direction[1]) / len, -1.0, 1.0);
    const int e = elevation_cell(std::asin(y));
    const int a = azimuth_cell(std::atan2(double(r.direction[2]), double(r.direction[0])));
    ++map.sums[size_t(e + 1) * w + size_t(a + 1)];
  }
  for (size_t e = 1; e <= size_t(kEl); ++e)
    for (size_t a = 1; a <= size_t(kAz); ++a)
      map.sums[e * w + a] += map.sums[(e - 1) * w + a] + map.sums[e * w + a - 1] - map.sums[(e - 1) * w + a - 1];
  return map;
}

bool DirectionMap::meets(const std::array<double, 3>& center, double radius) const {
  if (sums.empty()) return false;
  const double r = radius + spread;
  const std::array<double, 3> v = {center[0] - apex[0], center[1] - apex[1], center[2] - apex[2]};
  const double d = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(d > r)) return true;  // the apex inside (or a NaN: keep it)
  if (d - r > length) return false;
  // The disc's angular radius, a hair wider for the rounding of these sums and of the rays'
  // own angles (1e-7 rad against cells of 8.7e-3: the cells a ray falls in by floor() are
  // then all among those the disc's range falls in).
  const double half = std::asin(r / d) + 1e-7;
  const double elevation = std::asin(std::clamp(v[1] / d, -1.0, 1.0));
  const double lo = elevation - half, hi = elevation + half;
  const int e0 = elevation_cell(lo), e1 = elevation_cell(hi);
  // The azimuths of a cap of angular radius `half` centred at that elevation lie within
  // asin(sin(half) / cos(elevation)) of its centre's; bounded here by the cap's largest
  // |elevation|, and every azimuth where the cap holds a pole.
  const double steepest = std::max(std::fabs(lo), std::fabs(hi));
  const double ratio = steepest < 0.5 * M_PI ? std::sin(half) / std::cos(steepest) : 2.0;
  if (ratio >= 1.0) return rays_in(sums, e0, e1, 0, kAz - 1) > 0;
  const double azimuth = std::atan2(v[2], v[0]), spread_az = std::asin(ratio) + 1e-7;
  const double a_lo = azimuth - spread_az, a_hi = azimuth + spread_az;
  // In cells (unclamped: wrapped about +-pi below).
  const int a0 = int(std::floor((a_lo + M_PI) / (2.0 * M_PI) * kAz));
  const int a1 = int(std::floor((a_hi + M_PI) / (2.0 * M_PI) * kAz));
  if (a1 - a0 + 1 >= kAz) return rays_in(sums, e0, e1, 0, kAz - 1) > 0;
  int32_t n = 0;
  if (a0 < 0) n += rays_in(sums, e0, e1, a0 + kAz, kAz - 1);
  if (a1 >= kAz) n += rays_in(sums, e0, e1, 0, a1 - kAz);
  n += rays_in(sums, e0, e1, std::max(a0, 0), std::min(a1, kAz - 1));
  return n > 0;
}

}  // namespace boreas::impl
