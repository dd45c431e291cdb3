// boreas: the map of the rays' directions (ray_directions.h).
#include "rays/ray_directions.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

namespace {

constexpr int kAz = kDirectionAzimuthCells, kEl = kDirectionElevationCells;

// The map's coordinates, made with no trigonometry per ray (a cast's rays are hundreds of
// thousands): the elevation as its sine (y of the unit direction, cells of equal area) and
// the azimuth as the "diamond angle" of (x, z), a function of atan2(z, x) that rises with
// it from 0 at +x through 1, 2, 3 at +z, -x, -z to 4, with one division. Both rise with the
// angles they stand for, so a range of angles maps to the range between its ends' images.
double diamond(double x, double z) {
  if (z >= 0.0) return x >= 0.0 ? (x + z > 0.0 ? z / (x + z) : 0.0) : 1.0 - x / (z - x);
  return x < 0.0 ? 2.0 - z / (-x - z) : 3.0 + x / (x - z);
}
int azimuth_cell(double d) { return std::clamp(int(d * (kAz / 4.0)), 0, kAz - 1); }
int elevation_cell(double sine) { return std::clamp(int(std::floor((sine + 1.0) * (0.5 * kEl))), 0, kEl - 1); }

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
  double spread2 = 0.0;
  for (int i = 0; i < count; ++i) {
    double off = 0.0;
    for (int a = 0; a < 3; ++a)
      off += (double(rays[i].origin[a]) - map.apex[size_t(a)]) * (double(rays[i].origin[a]) - map.apex[size_t(a)]);
    spread2 = std::max(spread2, off);
  }
  map.spread = std::sqrt(spread2);
  if (map.spread > kDirectionMapSpread) return map;
  const size_t w = size_t(kAz) + 1;
  map.sums.assign(w * (size_t(kEl) + 1), 0);
  for (int i = 0; i < count; ++i) {
    const boreas_ray& r = rays[i];
    double len = 0.0;
    for (int a = 0; a < 3; ++a) len += double(r.direction[a]) * r.direction[a];
    map.length = std::max(map.length, double(r.max_distance));
    const int e = elevation_cell(std::clamp(double(r.direction[1]) / std::sqrt(len), -1.0, 1.0));
    const int a = azimuth_cell(diamond(r.direction[0], r.direction[2]));
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
  // Sines and cosines of the disc's angular radius h and of its centre's elevation e, and
  // the sines of e -+ h by the sum formulas (no trigonometry: a crown's thousands of
  // branches each ask). Every bound is widened by kHair for the rounding of these sums and
  // of the rays' own coordinates (1e-15 or so, against cells of 2e-3 or more in sine and
  // diamond angle): a ray's cell is then among the disc's.
  constexpr double kHair = 1e-7;
  const double sh = r / d, ch = std::sqrt(1.0 - sh * sh);
  const double se = std::clamp(v[1] / d, -1.0, 1.0), ce = std::sqrt(1.0 - se * se);
  // A pole within the disc (the angle from +-y under h): every azimuth, and that end.
  const bool north = se >= ch - kHair, south = -se >= ch - kHair;
  const int e0 = elevation_cell(south ? -1.0 : se * ch - ce * sh - kHair);
  const int e1 = elevation_cell(north ? 1.0 : se * ch + ce * sh + kHair);
  // No ray in the disc's band of elevations (above a LiDAR's top channel, say): done
  // without the azimuth.
  if (rays_in(sums, e0, e1, 0, kAz - 1) == 0) return false;
  if (north || south) return true;
  // The azimuths of a cap of angular radius h centred at elevation e lie within
  // asin(sin h / cos e) of its centre's; bounded here by the cap's steepest elevation
  // |e| + h (cos(|e| + h) = ce ch - |se| sh).
  const double steepest = ce * ch - std::fabs(se) * sh;
  if (!(steepest > 0.0)) return true;
  const double ratio = sh / steepest + kHair;  // the sine of the half-width
  if (ratio >= 1.0) return true;
  const double cw = std::sqrt(1.0 - ratio * ratio);
  // The centre's azimuth as a unit (x, z) turned by -+ the half-width (under pi / 2): the
  // range's ends, as diamond angles; the range crosses +x where its low end's exceeds its
  // high end's.
  const double h = std::hypot(v[0], v[2]);
  if (!(h > 0.0)) return true;
  const double x = v[0] / h, z = v[2] / h;
  const int a0 = azimuth_cell(diamond(x * cw + z * ratio, z * cw - x * ratio));
  const int a1 = azimuth_cell(diamond(x * cw - z * ratio, z * cw + x * ratio));
  if (a0 <= a1) return rays_in(sums, e0, e1, a0, a1) > 0;
  return rays_in(sums, e0, e1, a0, kAz - 1) + rays_in(sums, e0, e1, 0, a1) > 0;
}

}  // namespace boreas::impl
