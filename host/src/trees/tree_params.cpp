// boreas: checking a tree definition, and the branch constants that follow from it.
#include "trees/tree_params.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "enum_as_int.h"
#include "errors.h"
#include "trees/leaf_outline.h"
#include "trees/wind_load.h"
#include "validation.h"

namespace boreas::impl {

TreeParams checked_tree_def(const boreas_tree_def& def) {
  TreeParams p;
  if (def.species == nullptr || def.species[0] == '\0')
    fail_argument("tree_def.species is NULL or empty: give a built-in name or a species file path");
  p.species = def.species;
  for (int a = 0; a < 3; ++a) {
    check_range(def.position[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                "tree_def.position[" + std::to_string(a) + "]");
    p.position[a] = def.position[a];
  }
  check_range(def.rotation, -1e4, 1e4, "tree_def.rotation");
  p.rotation = def.rotation;
  if (!(def.scale > 0.0f) || !std::isfinite(def.scale) || def.scale > 1000.0f)
    fail_argument("tree_def.scale must be in (0, 1000] (got " + std::to_string(def.scale) + ")");
  p.scale = def.scale;
  for (int a = 0; a < 3; ++a) {
    const std::string name = "tree_def.lod_distances[" + std::to_string(a) + "]";
    // Finite like every other float of the API: "never" is spelled 1e9 or more.
    if (!std::isfinite(def.lod_distances[a]) || def.lod_distances[a] < 0.0f)
      fail_argument(name + " must be finite and >= 0 m, 1e9 or more for never (got " +
                    std::to_string(def.lod_distances[a]) + ")");
    if (a > 0 && def.lod_distances[a] < def.lod_distances[a - 1])
      fail_argument(name + " must not be below lod_distances[" + std::to_string(a - 1) + "] (got " +
                    std::to_string(def.lod_distances[a]) + " after " +
                    std::to_string(def.lod_distances[a - 1]) + ")");
    p.lod_distances[a] = std::min<double>(def.lod_distances[a], kLodNever);
  }
  p.seed = def.seed;
  const int mode = enum_as_int(def.mode);
  const int response = enum_as_int(def.response);
  if (mode != BOREAS_TREE_LAGGED && mode != BOREAS_TREE_EXACT)
    fail_argument("tree_def.mode must be BOREAS_TREE_LAGGED or BOREAS_TREE_EXACT (got " +
                  std::to_string(mode) + ")");
  p.mode = static_cast<boreas_tree_mode>(mode);
  if (response != BOREAS_TREE_QUASI_STATIC && response != BOREAS_TREE_DAMPED)
    fail_argument("tree_def.response must be BOREAS_TREE_QUASI_STATIC or BOREAS_TREE_DAMPED (got " +
                  std::to_string(response) + ")");
  p.response = static_cast<boreas_tree_response>(response);
  const int load = enum_as_int(def.load);
  if (load != BOREAS_TREE_LOAD_DRAG && load != BOREAS_TREE_LOAD_LINEAR)
    fail_argument("tree_def.load must be BOREAS_TREE_LOAD_DRAG or BOREAS_TREE_LOAD_LINEAR (got " +
                  std::to_string(load) + ")");
  p.load = static_cast<boreas_tree_load>(load);
  p.leaf_outline = resolved_leaf_outline(enum_as_int(def.leaf_outline), p.species);
  check_range(def.bend_exponent, 0.1, 10.0, "tree_def.bend_exponent");
  p.bend_exponent = def.bend_exponent;
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    const boreas_tree_level_def& in = def.levels[l];
    std::string name = "tree_def.levels[" + std::to_string(l) + "].";
    if (!(in.stiffness > 0.0f) || !std::isfinite(in.stiffness) || in.stiffness > 1e6f)
      fail_argument(name + "stiffness must be in (0, 1e6] (got " + std::to_string(in.stiffness) +
                    ")");
    check_range(in.damping_ratio, 0.01, 10.0, name + "damping_ratio");
    check_range(in.frequency_scale, 0.01, 100.0, name + "frequency_scale");
    check_int_range(in.rings, 1, 256, name + "rings");
    check_int_range(in.sides, 3, 256, name + "sides");
    p.levels[l] = {in.stiffness, in.damping_ratio, in.frequency_scale, in.rings, in.sides};
  }
  return p;
}

TreeLod tree_lod_at(const TreeParams& params, double distance) {
  int lod = 0;
  while (lod < 3 && params.lod_distances[size_t(lod)] < kLodNever &&
         distance >= params.lod_distances[size_t(lod)])
    ++lod;
  return static_cast<TreeLod>(lod);
}

BranchModel scaled_branch(const BranchModel& b, double scale) {
  BranchModel s = b;
  for (auto& point : s.local)
    for (double& x : point) x *= scale;
  s.length *= scale;
  s.radius *= scale;
  return s;
}

TreeModel scaled_model(const TreeModel& m, double scale) {
  if (m.packed)
    fail(BOREAS_ERROR_INTERNAL, "scaled_model of a packed model (grow it whole: whole_model)");
  TreeModel s = m;
  for (BranchModel& b : s.branches) b = scaled_branch(b, scale);
  s.crown_area *= scale * scale;
  for (LeafModel& l : s.leaves) {
    l.length *= scale;
    l.width *= scale;
    l.stem *= scale;
  }
  return s;
}

double bend_compliance(const BranchModel& b, const TreeLevelParams& level) {
  double radius = std::max(b.radius, 1e-4);
  return kBendAnglePerWind * (b.length / 3.0) * std::sqrt(kBendReferenceRadius / radius) /
         level.stiffness;
}

double scaled_compliance(const BranchModel& template_branch, const TreeLevelParams& level,
                         double scale) {
  return bend_compliance(template_branch, level) * std::sqrt(scale);
}

double natural_frequency(const BranchModel& b, const TreeLevelParams& level, double wood_modulus) {
  constexpr double kModeFactor = 3.516;                                   // 1.875^2
  const double wave_speed = std::sqrt(wood_modulus / kGreenWoodDensity);  // m/s
  double length = std::max(b.length, 1e-3);
  double radius = std::max(b.radius, 1e-5);
  return kModeFactor * (radius / 2.0) / (length * length) * wave_speed * level.frequency_scale;
}

std::array<double, 4> oscillator_step(double omega, double zeta, double dt) {
  double w = omega;
  if (std::abs(zeta - 1.0) < 1e-6) {
    double e = std::exp(-w * dt);
    return {e * (1.0 + w * dt), e * dt, -e * w * w * dt, e * (1.0 - w * dt)};
  }
  if (zeta < 1.0) {
    double wd = w * std::sqrt(1.0 - zeta * zeta);
    double e = std::exp(-zeta * w * dt);
    double c = std::cos(wd * dt), s = std::sin(wd * dt);
    return {e * (c + zeta * w / wd * s), e * s / wd, -e * w * w / wd * s,
            e * (c - zeta * w / wd * s)};
  }
  double root = std::sqrt(zeta * zeta - 1.0);
  double r1 = -w * (zeta - root), r2 = -w * (zeta + root);
  double e1 = std::exp(r1 * dt), e2 = std::exp(r2 * dt), span = r2 - r1;
  return {(r2 * e1 - r1 * e2) / span, (e2 - e1) / span, r1 * r2 * (e1 - e2) / span,
          (r2 * e2 - r1 * e1) / span};
}

}  // namespace boreas::impl
