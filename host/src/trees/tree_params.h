// boreas: a tree definition from the C API, checked, with the per-branch physical
// constants that follow from it (bend compliance, natural frequency, step response).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "boreas/boreas.h"
#include "trees/tree_model.h"

namespace boreas::impl {

struct TreeLevelParams {
  double stiffness = 1.0;
  double damping_ratio = 0.15;
  double frequency_scale = 0.5;
  int rings = 6;
  int sides = 8;
};

// Simulation levels of detail, finest first (boreas_tree_def.lod_distances).
enum class TreeLod : uint8_t {
  kFull = 0,     // every level stepped
  kReduced = 1,  // the finest level carried rigidly by its parent
  kFar = 2,      // only the trunk and level 1 stepped
  kFrozen = 3,   // nothing stepped: the tree settles to rest, then is left alone
};
inline constexpr int kTreeLodCount = 4;
// A distance at or past this never changes level (floats cannot tell 1e9 m from 1e9 + 1).
inline constexpr double kLodNever = 1e9;

struct TreeParams {
  std::string species;
  std::array<double, 3> position{};
  double rotation = 0.0;  // rad about +y, counter-clockwise seen from above
  double scale = 1.0;     // applied to the template's lengths (the model is grown at 1)
  std::array<double, 3> lod_distances{kLodNever, kLodNever, kLodNever};
  uint64_t seed = 0;
  boreas_tree_mode mode = BOREAS_TREE_LAGGED;
  boreas_tree_response response = BOREAS_TREE_QUASI_STATIC;
  boreas_tree_load load = BOREAS_TREE_LOAD_DRAG;
  double bend_exponent = 1.8;
  std::array<TreeLevelParams, kMaxTreeLevels> levels{};
  // The leaves' outline kind, BOREAS_LEAF_OUTLINE_BROADLEAF.. of cl/shared/leaf_outline.h
  // (never "by species": resolved by trees/leaf_outline.h).
  int leaf_outline = 0;
};

// Every field checked; errors name the field ("tree_def.levels[2].stiffness ...").
TreeParams checked_tree_def(const boreas_tree_def& def);

// The level of detail at `distance` m from the nearest focus point.
TreeLod tree_lod_at(const TreeParams& params, double distance);

// A branch of a template as a tree of scale `scale` has it: every length times scale
// (control points, length, radius); the angles and the radius functions' shape stay.
BranchModel scaled_branch(const BranchModel& b, double scale);
// A whole template as a tree of that scale has it (branches as above; leaves' length, width
// and petiole too): for code that wants one tree's own model (BlobTree, references).
TreeModel scaled_model(const TreeModel& m, double scale);

// Linear load (BOREAS_TREE_LOAD_LINEAR, the paper's): the bend vector per unit wind (m per
// m/s) of a branch: its tip turns by about
// kBendAnglePerWind * sqrt(kBendReferenceRadius / radius) / stiffness radians per m/s,
// which for the bend of eq. 17 (a displacement added to a segment) means a displacement
// of that angle times the mean segment length. The square root is a choice: beam theory
// for a drag-loaded cantilever gives r^-3 at fixed length, which makes twigs wave like
// flags next to a rigid trunk; r^-1/2 keeps the whole tree visibly alive.
inline constexpr double kBendAnglePerWind = 0.01;    // rad / (m/s) at the reference radius
inline constexpr double kBendReferenceRadius = 0.1;  // m
double bend_compliance(const BranchModel& b, const TreeLevelParams& level);
// A tree of scale s bends with its template's compliance times sqrt(s): the formula above
// for a branch s times longer and thicker (the 1e-4 m floor on the radius is the
// template's), so trees of one template share their compliance planes (tree_layout.h).
double scaled_compliance(const BranchModel& template_branch, const TreeLevelParams& level,
                         double scale);

// First bending mode of a clamped-free cylinder (Euler-Bernoulli): omega = 1.875^2
// sqrt(E I / (rho A L^4)) = 3.516 (r / 2) / L^2 sqrt(E / rho), with E the species' wood
// modulus (Pa) and rho 800 kg/m^3 for green wood (sqrt(E / rho) = 3000 m/s at 7 GPa); rad/s.
double natural_frequency(const BranchModel& b, const TreeLevelParams& level, double wood_modulus);

// The exact step of x'' + 2 zeta omega x' + omega^2 x = 0 over dt as a 2x2 matrix
// {a, b, c, d}: (x, x') -> (a x + b x', c x + d x'). Closed forms for under-, critically
// and over-damped oscillators.
std::array<double, 4> oscillator_step(double omega, double zeta, double dt);

}  // namespace boreas::impl
