// boreas: checking colliders and emitters; the emitters' event schedule.
#include "underbrush/interaction.h"

#include <cmath>
#include <string>

#include "errors.h"
#include "trees/tree_random.h"
#include "validation.h"

namespace boreas::impl {

boreas_emitter_def checked_emitter_def(const boreas_emitter_def& def) {
  check_position(def.center, "emitter_def.center");
  for (int a = 0; a < 3; ++a)
    check_range(def.origin[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                "emitter_def.origin[" + std::to_string(a) + "]");
  check_range(def.area_radius, 0.0, 1e5, "emitter_def.area_radius");
  check_range(def.event_radius, 1e-4, 1e3, "emitter_def.event_radius");
  for (int a = 0; a < 3; ++a) check_range(def.impulse[a], -1e3, 1e3, "emitter_def.impulse[" + std::to_string(a) + "]");
  check_range(def.rate, 0.0, 1e6, "emitter_def.rate");
  check_range(def.lifetime, 0.0, 1e9, "emitter_def.lifetime");
  return def;
}

namespace {

// v as the float nearest it and the float nearest the rest (BoreasGpuImpulse). Not inlined:
// GCC 12.2 at -O3 SLP-vectorized the x and y splits inlined into the loop below and took
// double(float(v)) for v there, leaving the rest 0 (z, done apart, came out right).
__attribute__((noinline)) void split(double v, float* hi, float* lo) {
  const float h = static_cast<float>(v);
  *hi = h;
  *lo = static_cast<float>(v - static_cast<double>(h));
}

}  // namespace

std::vector<BoreasGpuImpulse> Emitter::events(double t0, double t1) {
  std::vector<BoreasGpuImpulse> out;
  // Events due by t1: all k with start + (k + 1/2)/rate <= t1 (one event at once for rate 0).
  uint64_t due;
  if (def.rate <= 0.0f) {
    due = 1;
  } else {
    double end = t1 - start;
    if (def.lifetime > 0.0f) end = std::min(end, double(def.lifetime));
    double n = std::floor(end * def.rate + 0.5);
    due = n > 0.0 ? static_cast<uint64_t>(n) : 0;
  }
  (void)t0;
  for (; fired < due; ++fired) {
    TreeRandom rng(def.seed, fired, 0xE5ULL);
    // Uniform in the disk: radius by the square root of a uniform number.
    double r = def.area_radius * std::sqrt(rng.uniform01());
    double a = 2.0 * M_PI * rng.uniform01();
    BoreasGpuImpulse e{};
    // In double from the origin, then split (BoreasGpuImpulse): exact far out as near 0.
    const double at[3] = {def.origin[0] + double(def.center[0]) + r * std::cos(a),
                          def.origin[1] + double(def.center[1]),
                          def.origin[2] + double(def.center[2]) + r * std::sin(a)};
    split(at[0], &e.x, &e.lx);
    split(at[1], &e.y, &e.ly);
    split(at[2], &e.z, &e.lz);
    e.radius = def.event_radius;
    e.jx = def.impulse[0];
    e.jy = def.impulse[1];
    e.jz = def.impulse[2];
    out.push_back(e);
  }
  return out;
}

bool Emitter::expired(double t) const {
  if (def.rate <= 0.0f) return fired >= 1 && (def.lifetime <= 0.0f || t - start >= def.lifetime);
  return def.lifetime > 0.0f && t - start >= def.lifetime;
}

}  // namespace boreas::impl
