// boreas: a double-precision reference for the Weber-Penn generator's figures — the
// expected number of stems on each level, their mean length and mean base radius — written
// from the equations (Weber & Penn 1995 sec. 4, as Arbaro applies them: the rules in
// tests/data and the species README), independently of host/src/trees.
//
// It grows the expected tree, not a random one: every variation (nLengthV, ScaleV, ...)
// at its mean, each stem's children as a few weighted samples spread evenly over where
// they grow (a quadrature of the expectation over their offsets), and stem splits counted
// by Weber-Penn's error diffusion, walked stem after stem with the error carried on
// (every clone a stem of its stem's length and radius, the children the stem's to
// share). Pruning, curvature and direction are not modelled: they change where stems
// point, and pruning their lengths and so their children's numbers, which is why a pruned
// species is compared on fewer figures.
#pragma once

#include <array>

#include "trees/species.h"

namespace boreas::impl::reference {

struct WeberPennLevel {
  double stems = 0.0;        // expected stems (first pieces and clones)
  double mean_length = 0.0;  // m, over those stems (a clone has its stem's length)
  double mean_radius = 0.0;  // m, at the base
};

// The expected figures of a tree of `species` at its mean size, level by level (levels the
// species does not grow are zero).
std::array<WeberPennLevel, kMaxTreeLevels> weber_penn_expected(const Species& species);

// Weber-Penn's shape ratio, Shape 0..8 at r (Arbaro's conical r for Shape 0).
double reference_shape_ratio(const Species& species, int shape, double r);

}  // namespace boreas::impl::reference
