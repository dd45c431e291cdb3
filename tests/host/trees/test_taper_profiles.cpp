// boreas tests: nTaper between 1 and 3 against Arbaro 1.9.9's radius function
// (StemImpl.stemRadius, transcribed below in double): the deformer's radius functions carry a
// stem's taper as one power of v and a sine (tree_generator.cpp, set_taper), Arbaro's profile
// ends in a hemisphere (1..2) or is a row of spherical beads (2..3). Measured here: the mean
// radius and the volume (mean r^2) over the stem, and the linear part of 1..2 point by point.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/tree_reference.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {
namespace {

// Arbaro's stemRadius(h) for a stem of length `length` and base radius `base`, z = h / length
// (no flare, lobes or 0Scale: a plain stem).
double arbaro_radius(double n_taper, double length, double base, double z) {
  double unit_taper = 0.0;
  if (n_taper <= 1.0) {
    unit_taper = n_taper;
  } else if (n_taper <= 2.0) {
    unit_taper = 2.0 - n_taper;
  }
  double radius = base * (1.0 - unit_taper * z);
  if (n_taper > 1.0) {
    const double z2 = (1.0 - z) * length;
    const double depth = (n_taper < 2.0 || z2 < radius) ? 1.0 : n_taper - 2.0;
    const double z3 =
        n_taper < 2.0 ? z2 : std::fabs(z2 - 2.0 * radius * double(int(z2 / 2.0 / radius + 0.5)));
    if (n_taper > 2.0 || z3 < radius)
      radius = (1.0 - depth) * radius +
               depth * std::sqrt(std::max(0.0, radius * radius - (z3 - radius) * (z3 - radius)));
  }
  return radius;
}

// A one-level species: a straight trunk 10 m long of base radius 10 m * ratio.
Species trunk_species(double n_taper, double ratio) {
  Species s;
  s.name = "taper";
  s.levels = 1;
  s.scale = 10.0;
  s.scale_v = 0.0;
  s.ratio = ratio;
  s.flare = 0.0;
  s.lobes = 0;
  s.lobe_depth = 0.0;
  s.leaves = 0;
  s.trunk_scale = 1.0;
  s.trunk_scale_v = 0.0;
  s.level[0].length = 1.0;
  s.level[0].length_v = 0.0;
  s.level[0].branches = 1;
  s.level[0].curve_res = 3;
  s.level[0].taper = n_taper;
  return s;
}

struct Means {
  double radius = 0.0, volume = 0.0;  // mean r and mean r^2 over the stem
};

TEST(TaperProfiles, MeanRadiusAndVolumeFollowArbaroBetweenOneAndThree) {
  constexpr int kSamples = 200000;
  for (double ratio : {0.02, 0.05}) {
    for (double n_taper : {1.03, 1.4, 1.7, 1.9, 2.0, 2.1, 2.5, 2.9}) {
      SCOPED_TRACE(testing::Message() << "nTaper " << n_taper << ", r / L " << ratio);
      const TreeModel t = grow_tree(trunk_species(n_taper, ratio), 1);
      ASSERT_EQ(t.branches.size(), 1u);
      const BranchModel& trunk = t.branches[0];
      const reference::BranchRadius p = reference::BranchRadius::of(trunk);
      const double length = trunk.length, base = length * ratio;
      ASSERT_DOUBLE_EQ(length, 10.0);
      Means ours, arbaro;
      for (int k = 0; k < kSamples; ++k) {
        const double z = (k + 0.5) / kSamples;
        const double r = reference::branch_radius(p, z, 0.0);
        const double a = arbaro_radius(n_taper, length, base, z);
        ours.radius += r / kSamples;
        ours.volume += r * r / kSamples;
        arbaro.radius += a / kSamples;
        arbaro.volume += a * a / kSamples;
        // 1..2: the linear taper is Arbaro's wherever its tip hemisphere has not begun.
        if (n_taper < 2.0 && (1.0 - z) * length > base) EXPECT_NEAR(r, a, 1e-12 * base) << z;
      }
      std::printf("    nTaper %.2f r/L %.2f: mean radius %+5.2f %%, volume %+5.2f %%\n", n_taper,
                  ratio, 100.0 * (ours.radius / arbaro.radius - 1.0),
                  100.0 * (ours.volume / arbaro.volume - 1.0));
      EXPECT_NEAR(ours.radius / arbaro.radius, 1.0, 0.015);
      EXPECT_NEAR(ours.volume / arbaro.volume, 1.0, 0.02);
    }
  }
}

// The old approximation (a profile 1 - v^p of the same mean) put up to 11 % more wood in a
// stem of nTaper 1.4 than Arbaro's; now the stem is Arbaro's cone, cut at (nTaper - 1) r.
TEST(TaperProfiles, BetweenOneAndTwoTheTipIsTheConesCut) {
  const TreeModel t = grow_tree(trunk_species(1.4, 0.02), 1);
  const reference::BranchRadius p = reference::BranchRadius::of(t.branches[0]);
  EXPECT_NEAR(reference::branch_radius(p, 1.0, 0.0), 0.4 * t.branches[0].radius, 1e-12);
  EXPECT_NEAR(reference::branch_radius(p, 0.5, 0.0), 0.7 * t.branches[0].radius, 1e-12);
}

}  // namespace
}  // namespace boreas::impl
