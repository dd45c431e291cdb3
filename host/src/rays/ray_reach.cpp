// boreas: what a cast's rays can reach (ray_reach.h).
#include "rays/ray_reach.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

namespace {

using V = std::array<double, 3>;

double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double distance(const V& a, const V& b) {
  const V d = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return std::sqrt(dot(d, d));
}
// The axis of unit directions: their normalized sum (any unit vector where they cancel).
V mean_axis(const V& sum) {
  const double n = std::sqrt(dot(sum, sum));
  return n > 1e-12 ? V{sum[0] / n, sum[1] / n, sum[2] / n} : V{0.0, 1.0, 0.0};
}
void set_half_angle(ReachCone& c, double cos_half) {
  c.cos_half = std::clamp(cos_half, -1.0, 1.0);
  c.sin_half = std::sqrt(std::max(0.0, 1.0 - c.cos_half * c.cos_half));
}

// Whether the cone, grown by its spread, meets the sphere (conservative): the sphere grown
// by the spread against the cone from the apex, by the angle between the axis and the
// sphere's center against the half-angle plus the angle the sphere subtends.
bool cone_meets(const ReachCone& c, const V& center, double radius) {
  const double r = radius + c.spread;
  const V v = {center[0] - c.apex[0], center[1] - c.apex[1], center[2] - c.apex[2]};
  const double d = std::sqrt(dot(v, v));
  if (d <= r) return true;
  if (d - r > c.length) return false;
  if (c.cos_half <= -1.0) return true;
  const double sin_b = r / d, cos_b = std::sqrt(1.0 - sin_b * sin_b);
  // Half-angle plus subtended angle past pi: every direction.
  if (c.sin_half * cos_b + c.cos_half * sin_b < 0.0 && c.cos_half < 0.0) return true;
  const double cos_sum = c.cos_half * cos_b - c.sin_half * sin_b;  // cos(half + subtended)
  return dot(v, c.axis) / d >= cos_sum - 1e-12;
}

}  // namespace

ReachCone cone_over(const ReachCone* cones, int count) {
  ReachCone g;
  g.apex = cones[0].apex;
  V sum{};
  for (int i = 0; i < count; ++i)
    for (size_t a = 0; a < 3; ++a) sum[a] += cones[i].axis[a];
  g.axis = mean_axis(sum);
  double angle = 0.0;
  for (int i = 0; i < count; ++i) {
    const ReachCone& c = cones[i];
    const double off = distance(c.apex, g.apex);
    g.spread = std::max(g.spread, off + c.spread);
    g.length = std::max(g.length, c.length + off);
    const double between = std::acos(std::clamp(dot(c.axis, g.axis), -1.0, 1.0));
    angle = std::max(angle, between + std::acos(std::clamp(c.cos_half, -1.0, 1.0)));
  }
  set_half_angle(g, angle >= M_PI ? -1.0 : std::cos(angle));
  return g;
}

RayReach reach_of(const boreas_ray* rays, int count) {
  RayReach reach;
  for (int first = 0; first < count; first += kReachRun) {
    const int n = std::min(kReachRun, count - first);
    ReachCone c;
    for (size_t a = 0; a < 3; ++a) c.apex[a] = rays[first].origin[a];
    V sum{};
    std::array<V, kReachRun> dirs{};
    for (int i = 0; i < n; ++i) {
      const boreas_ray& r = rays[first + i];
      const V d = {r.direction[0], r.direction[1], r.direction[2]};
      const double len = std::sqrt(dot(d, d));
      dirs[size_t(i)] = {d[0] / len, d[1] / len, d[2] / len};
      for (size_t a = 0; a < 3; ++a) sum[a] += dirs[size_t(i)][a];
      c.spread = std::max(c.spread, distance({r.origin[0], r.origin[1], r.origin[2]}, c.apex));
      c.length = std::max(c.length, double(r.max_distance));
    }
    c.axis = mean_axis(sum);
    double cos_half = 1.0;
    for (int i = 0; i < n; ++i) cos_half = std::min(cos_half, dot(dirs[size_t(i)], c.axis));
    // A hair wider than the rays, so rounding never leaves a ray outside its cone.
    set_half_angle(c, std::cos(std::acos(std::clamp(cos_half, -1.0, 1.0)) + 1e-9));
    reach.cones.push_back(c);
  }
  for (size_t first = 0; first < reach.cones.size(); first += kReachGroup) {
    const int n = int(std::min<size_t>(kReachGroup, reach.cones.size() - first));
    reach.groups.push_back(cone_over(&reach.cones[first], n));
  }
  reach.directions = direction_map(rays, count);
  return reach;
}

bool RayReach::meets_part(const Box& bound, const std::array<double, 3>& center, double radius) const {
  for (int a = 0; a < 3; ++a)
    if (bound[size_t(a) + 3] < box[size_t(a)] || box[size_t(a) + 3] < bound[size_t(a)]) return false;
  return directions.sums.empty() || directions.meets(center, radius);
}

bool RayReach::meets(const Box& bound, const std::array<double, 3>& center, double radius) const {
  if (!meets_part(bound, center, radius)) return false;
  if (cones.empty()) return true;
  for (size_t g = 0; g < groups.size(); ++g) {
    if (!cone_meets(groups[g], center, radius)) continue;
    const size_t end = std::min(cones.size(), (g + 1) * size_t(kReachGroup));
    for (size_t i = g * size_t(kReachGroup); i < end; ++i)
      if (cone_meets(cones[i], center, radius)) return true;
  }
  return false;
}

}  // namespace boreas::impl
