// boreas: the checks of rays passed in (ray_checks.h).
#include "rays/ray_checks.h"

#include <cmath>
#include <string>

#include "errors.h"
#include "validation.h"

namespace boreas::impl {

namespace {

std::string ray_name(int i) { return "rays[" + std::to_string(i) + "]"; }

void check_ray(const boreas_ray& r, int i) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(r.origin[k]))
      fail_argument(ray_name(i) + ".origin[" + std::to_string(k) + "] must be finite (got " +
                    num(r.origin[k]) + ")");
  double length2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(r.direction[k]))
      fail_argument(ray_name(i) + ".direction[" + std::to_string(k) + "] must be finite (got " +
                    num(r.direction[k]) + ")");
    length2 += double(r.direction[k]) * r.direction[k];
  }
  // A direction whose square underflows in float cannot be normalized on the device.
  if (!(length2 > 1e-30))
    fail_argument(ray_name(i) + ".direction must not be zero (got " + num(r.direction[0]) + ", " +
                  num(r.direction[1]) + ", " + num(r.direction[2]) + ")");
  if (std::isnan(r.max_distance) || r.max_distance < 0.0f)
    fail_argument(ray_name(i) + ".max_distance must be >= 0 m (got " + num(r.max_distance) + ")");
}

}  // namespace

Box checked_rays(const boreas_ray* rays, int count, const boreas_hit* hits) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > 0 && rays == nullptr) fail_argument("rays is NULL with count " + std::to_string(count));
  if (count > 0 && hits == nullptr) fail_argument("hits is NULL with count " + std::to_string(count));
  Box reach = empty_box();
  for (int i = 0; i < count; ++i) {
    const boreas_ray& r = rays[i];
    check_ray(r, i);
    // The segment's ends (an unbounded ray reaches infinity along its direction's signs).
    const double len = std::sqrt(double(r.direction[0]) * r.direction[0] +
                                 double(r.direction[1]) * r.direction[1] +
                                 double(r.direction[2]) * r.direction[2]);
    float end[3];
    for (int k = 0; k < 3; ++k) {
      const double step = double(r.direction[k]) / len * double(r.max_distance);
      end[k] = std::isfinite(step) || r.direction[k] != 0.0f ? float(r.origin[k] + step) : r.origin[k];
    }
    grow_box(reach, r.origin);
    grow_box(reach, end);
  }
  return reach;
}

}  // namespace boreas::impl
