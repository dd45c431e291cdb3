// boreas: the checks of rays passed in (ray_checks.h).
#include "rays/ray_checks.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>
#include <string>

#include "errors.h"
#include "runtime/caller_buffers.h"
#include "runtime/launch.h"
#include "shared/ray_types.h"
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

RayReach checked_rays(const boreas_ray* rays, int count, const boreas_hit* hits) {
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
  RayReach out = reach_of(rays, count);
  out.box = reach;
  return out;
}

RayReach checked_device_rays(Runtime& runtime, const cl::Buffer& rays, size_t first_ray, int count,
                        const cl::Buffer& hits, size_t first_hit) {
  static_assert(sizeof(boreas_ray) == BOREAS_RAY_RAY_FLOATS * sizeof(float), "ray record");
  static_assert(sizeof(boreas_hit) == BOREAS_RAY_HIT_WORDS * 4, "hit record");
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  check_buffer_holds(rays, first_ray, size_t(count), sizeof(boreas_ray), "ray");
  check_buffer_holds(hits, first_hit, size_t(count), sizeof(boreas_hit), "hit");
  RayReach result;
  Box& reach = result.box;
  if (count == 0) return result;
  // Enough parts to keep a device busy on a large batch, few enough to read back at once.
  const int parts = std::min(count, 256);
  cl::Buffer out = runtime.buffer(CL_MEM_WRITE_ONLY, size_t(parts) * 8 * sizeof(float), "ray check");
  cl::Kernel& k = runtime.kernel("ray_refit.cl", "boreas_ray_check", "#define BOREAS_W 1\n");
  launch(runtime, k, Items(size_t(parts)), rays, int(first_ray), count, parts, out);
  std::vector<float> words(size_t(parts) * 8);
  runtime.read(out, 0, words.size() * sizeof(float), words.data());
  int bad = count;
  for (int p = 0; p < parts; ++p) {
    int b;
    std::memcpy(&b, &words[size_t(p) * 8], sizeof b);
    bad = std::min(bad, b);
    const float* box = &words[size_t(p) * 8 + 2];
    grow_box(reach, box);
    grow_box(reach, box + 3);
  }
  if (bad < count) {
    // The fault named from the ray itself, as the host's check names it.
    boreas_ray r;
    runtime.read(rays, (first_ray + size_t(bad)) * sizeof(boreas_ray), sizeof r, &r);
    check_ray(r, bad);
  }
  return result;
}

}  // namespace boreas::impl
