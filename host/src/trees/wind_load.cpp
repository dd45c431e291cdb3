// boreas: the drag load on a generated tree's branches and their bend as cantilevers.
#include "trees/wind_load.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "trees/leaf_area.h"
#include "trees/leaf_outline.h"

namespace boreas::impl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSlices = 16;
// No stem is thinner than a tenth of a millimetre for its stiffness (a grass's is thicker):
// this only keeps a beam with no load beyond some x from dividing by zero there.
constexpr double kThinnest = 1e-4;  // m

// A leaf's blade area, m^2, by the rule the light uses too (leaf_area.h), with the outline
// of the tree's species: a template is grown once for the trees of one species and seed,
// whatever outline their defs draw.
double leaf_area_of(const LeafModel& leaf, int outline) {
  return leaf_area(leaf.length, leaf.width, outline);
}

// The drawn radius at v (the deformer's taper and tip cap, without flare and lobes; the
// beads as their mean: a slice is longer than a bead, and a sample would fall on a waist or
// a crest by chance).
double drawn_radius(const BranchModel& b, double v) {
  // Most stems taper linearly (exponent 1): no pow for them, 16 slices of every branch.
  const double shape = b.taper_exponent == 1.0 ? v : std::pow(v, b.taper_exponent);
  return b.radius * std::max(0.0, 1.0 - b.taper_depth * shape) * bead_mean(b.bulge_depth) *
         tip_cap_factor(b.tip_cap, v);
}

// Loads on one branch, binned by the slice midpoints they lie beyond: a load at a acts on
// every midpoint x_k < a, that is on slices k < bin(a).
struct SliceLoads {
  std::array<double, kSlices + 1> drag{}, drag_at{}, leaf{};  // sums of P, P a, leaf area
};

int bin_of(double a, double length) {
  return std::clamp(int(std::floor(a / length * kSlices + 0.5)), 0, kSlices);
}

void add_load(SliceLoads& s, double a, double length, double drag_area, double leaf_area) {
  const int j = bin_of(a, length);
  s.drag[size_t(j)] += drag_area;
  s.drag_at[size_t(j)] += drag_area * a;
  s.leaf[size_t(j)] += leaf_area;
}

// The leaf area (m^2) each branch feeds: its own leaves' and all it carries. Children
// after parents (the generator's order, which the kernels rely on too): a branch is
// complete when its turn comes walking backwards, and hands itself on.
std::vector<double> carried_leaf_area(const TreeModel& m) {
  std::vector<double> leaf(m.branches.size(), 0.0);
  const int outline = species_leaf_outline(m.species);
  for (const LeafModel& l : m.leaves) leaf[size_t(l.parent)] += leaf_area_of(l, outline);
  for (size_t b = m.branches.size(); b-- > 0;)
    if (m.branches[b].parent >= 0) leaf[size_t(m.branches[b].parent)] += leaf[b];
  return leaf;
}

}  // namespace

double leaf_shelter(const TreeModel& m) {
  double leaves = 0.0;
  const int outline = species_leaf_outline(m.species);
  for (const LeafModel& leaf : m.leaves) leaves += kLeafDragCoefficient * leaf_area_of(leaf, outline);
  const double crown = kCrownDragCoefficient * m.crown_area;
  return leaves > crown && crown > 0.0 ? crown / leaves : 1.0;
}

namespace {

// Every branch's loads and what it carries, itself included: drag area C_d A (m^2), its own
// stem's part of it, and wood volume (m^3, for the weight a broken branch hangs by).
struct BranchLoads {
  std::vector<SliceLoads> slices;
  std::vector<double> drag, own_drag, wood;
};

BranchLoads branch_loads(const TreeModel& m) {
  const size_t n = m.branches.size();
  const double shelter = leaf_shelter(m);
  BranchLoads L;
  L.slices.resize(n);
  L.drag.assign(n, 0.0);
  L.own_drag.assign(n, 0.0);
  L.wood.assign(n, 0.0);
  const std::vector<double> carried_leaf = carried_leaf_area(m);
  const int outline = species_leaf_outline(m.species);
  for (const LeafModel& leaf : m.leaves) {
    const size_t b = size_t(leaf.parent);
    const double area = leaf_area_of(leaf, outline), drag = shelter * kLeafDragCoefficient * area;
    add_load(L.slices[b], leaf.v * m.branches[b].length, m.branches[b].length, drag, area);
    L.drag[b] += drag;
  }
  // Own wood, one point load per slice at its midpoint.
  for (size_t b = 0; b < n; ++b) {
    const BranchModel& br = m.branches[b];
    const double dx = br.length / kSlices;
    for (int k = 0; k < kSlices; ++k) {
      const double x = (k + 0.5) * dx, r = drawn_radius(br, x / br.length);
      const double drag = kWoodDragCoefficient * 2.0 * r * dx;
      add_load(L.slices[b], x, br.length, drag, 0.0);
      L.drag[b] += drag;
      L.own_drag[b] += drag;
      L.wood[b] += kPi * r * r * dx;
    }
  }
  // Each child hands its parent its whole load where it attaches (walking backwards, as
  // carried_leaf_area does).
  for (size_t b = n; b-- > 0;) {
    const BranchModel& br = m.branches[b];
    if (br.parent < 0) continue;
    const size_t p = size_t(br.parent);
    add_load(L.slices[p], br.v * m.branches[p].length, m.branches[p].length, L.drag[b],
             carried_leaf[b]);
    L.drag[p] += L.drag[b];
    L.wood[p] += L.wood[b];
  }
  return L;
}

// The beam's radius at x (m from the base) of a branch feeding `leaf` m^2 of leaves beyond
// x: the drawn one or the pipe model's, whichever is thicker.
double beam_radius(const BranchModel& br, double x, double length, double leaf) {
  const double pipe = std::sqrt(kHuberValue * leaf / kPi);
  return std::max({drawn_radius(br, x / length), pipe, kThinnest});
}

// E I of a round section of radius r, N m^2.
double bending_stiffness(double modulus, double r) { return modulus * kPi * r * r * r * r / 4.0; }

}  // namespace

std::vector<double> deflection_per_pressure(const TreeModel& m, const TreeParams& params) {
  const size_t n = m.branches.size();
  const std::vector<SliceLoads> loads = branch_loads(m).slices;
  std::vector<double> out(n, 0.0);
  for (size_t b = 0; b < n; ++b) {
    const BranchModel& br = m.branches[b];
    const double modulus = m.wood_modulus * params.levels[size_t(br.level)].stiffness;
    const double length = std::max(br.length, 1e-6), dx = length / kSlices;
    const SliceLoads& s = loads[b];
    // Sums over the loads beyond midpoint k: bins k + 1 .. kSlices.
    double drag = 0.0, drag_at = 0.0, leaf = 0.0, deflection = 0.0;
    for (int k = kSlices - 1; k >= 0; --k) {
      drag += s.drag[size_t(k) + 1];
      drag_at += s.drag_at[size_t(k) + 1];
      leaf += s.leaf[size_t(k) + 1];
      const double x = (k + 0.5) * dx;
      const double moment = drag_at - x * drag;  // sum of P (a - x)
      const double r = beam_radius(br, x, length, leaf);
      deflection += moment * (length - x) / bending_stiffness(modulus, r) * dx;
    }
    out[b] = deflection;
  }
  return out;
}

std::vector<double> tip_stiffness(const TreeModel& m, const TreeParams& params) {
  const size_t n = m.branches.size();
  const std::vector<SliceLoads> loads = branch_loads(m).slices;
  std::vector<double> out(n, 0.0);
  for (size_t b = 0; b < n; ++b) {
    const BranchModel& br = m.branches[b];
    const double modulus = m.wood_modulus * params.levels[size_t(br.level)].stiffness;
    const double length = std::max(br.length, 1e-6), dx = length / kSlices;
    // A unit load at the tip: M(x) = L - x, so the tip deflects by the integral of
    // (L - x)^2 / (E I(x)), on the same slices and radii as the wind's load.
    double leaf = 0.0, compliance = 0.0;
    for (int k = kSlices - 1; k >= 0; --k) {
      leaf += loads[b].leaf[size_t(k) + 1];
      const double x = (k + 0.5) * dx;
      const double r = beam_radius(br, x, length, leaf);
      compliance += (length - x) * (length - x) / bending_stiffness(modulus, r) * dx;
    }
    out[b] = 1.0 / compliance;
  }
  return out;
}

std::vector<double> beam_base_radius(const TreeModel& m) {
  const std::vector<double> leaf = carried_leaf_area(m);
  std::vector<double> out(m.branches.size());
  for (size_t b = 0; b < out.size(); ++b)
    out[b] = std::max({m.branches[b].radius, std::sqrt(kHuberValue * leaf[b] / kPi), kThinnest});
  return out;
}

std::vector<double> base_moment_per_pressure(const TreeModel& m) {
  const std::vector<SliceLoads> loads = branch_loads(m).slices;
  std::vector<double> out(m.branches.size(), 0.0);
  // Every load lies beyond the base: the moment there is the sum of P a over all bins.
  for (size_t b = 0; b < out.size(); ++b)
    for (double at : loads[b].drag_at) out[b] += at;
  return out;
}

std::vector<double> base_stress_per_pressure(const TreeModel& m) {
  const std::vector<double> moment = base_moment_per_pressure(m), r = beam_base_radius(m);
  std::vector<double> out(moment.size());
  for (size_t b = 0; b < out.size(); ++b) out[b] = 4.0 * moment[b] / (kPi * r[b] * r[b] * r[b]);
  return out;
}

std::vector<double> peak_stress_per_pressure(const TreeModel& m) {
  const std::vector<SliceLoads> loads = branch_loads(m).slices;
  std::vector<double> out = base_stress_per_pressure(m);
  for (size_t b = 0; b < out.size(); ++b) {
    const BranchModel& br = m.branches[b];
    const double length = std::max(br.length, 1e-6), dx = length / kSlices;
    const SliceLoads& s = loads[b];
    // The beam of deflection_per_pressure, slice by slice: its moment and radius.
    double drag = 0.0, drag_at = 0.0, leaf = 0.0;
    for (int k = kSlices - 1; k >= 0; --k) {
      drag += s.drag[size_t(k) + 1];
      drag_at += s.drag_at[size_t(k) + 1];
      leaf += s.leaf[size_t(k) + 1];
      const double x = (k + 0.5) * dx, moment = drag_at - x * drag;
      const double r = beam_radius(br, x, length, leaf);
      out[b] = std::max(out[b], 4.0 * moment / (kPi * r * r * r));
    }
  }
  return out;
}

std::vector<double> reconfiguring_share(const TreeModel& m) {
  const BranchLoads L = branch_loads(m);
  std::vector<double> out(L.drag.size(), 0.0);
  for (size_t b = 0; b < out.size(); ++b)
    out[b] = L.drag[b] > 0.0 ? 1.0 - L.own_drag[b] / L.drag[b] : 0.0;
  return out;
}

std::vector<double> drag_per_weight(const TreeModel& m) {
  const BranchLoads L = branch_loads(m);
  std::vector<double> out(L.drag.size(), 0.0);
  for (size_t b = 0; b < out.size(); ++b)
    out[b] = 0.5 * kAirDensity * L.drag[b] / (kGreenWoodDensity * kGravity * std::max(L.wood[b], 1e-12));
  return out;
}

double reconfiguration(double speed, double exponent, double reference_speed) {
  return std::pow(std::max(speed, reference_speed) / reference_speed, exponent);
}

std::vector<double> break_bend(const TreeModel& m, const TreeParams& params) {
  const std::vector<double> k = drag_compliance(m, params), stress = peak_stress_per_pressure(m);
  const double w2 = std::pow(2.0 / 3.0, params.bend_exponent);
  std::vector<double> out(k.size());
  // F = K |u|^2 R and sigma = stress 1/2 rho |u|^2 R share the factor R: the bend at which
  // sigma reaches the modulus of rupture, unless the tip would move past kBreakReach of the
  // branch's length first (F (1 + w2) is the tip's deflection): there the small-deflection
  // beam the stress comes from no longer holds and a slender branch streamlines instead.
  for (size_t b = 0; b < out.size(); ++b) {
    out[b] = m.wood_rupture * k[b] / (stress[b] * 0.5 * kAirDensity);
    if (out[b] * (1.0 + w2) > kBreakReach * m.branches[b].length) out[b] = kNeverBreaks;
  }
  return out;
}

std::vector<double> drag_compliance(const TreeModel& m, const TreeParams& params) {
  const double w2 = std::pow(2.0 / 3.0, params.bend_exponent);
  std::vector<double> k = deflection_per_pressure(m, params);
  for (double& x : k) x *= 0.5 * kAirDensity / (1.0 + w2);
  return k;
}

}  // namespace boreas::impl
