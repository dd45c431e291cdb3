// boreas textures: the leaf drawn on its texture: the outline of its kind (the table and
// the formula of cl/shared/leaf_outline.h, which the rays use too, evaluated here in double),
// a petiole, a midrib and pinnate secondary veins.
//
// Coordinates are texture units: u across the leaf (midrib at u = 0.5), v along it from the
// stem end of the quad (v = 0) to the tip (v = 1); the quad is square. Every kind keeps one
// layout (kBladeBaseV, ... below), so one quad mapping serves all.
#pragma once

#include <cstdint>
#include <vector>

#include "shared/leaf_outline.h"

namespace boreas::render {

// The layout every kind shares (cl/shared/leaf_outline.h), texture units.
inline constexpr double kPetioleStartV = BOREAS_LEAF_PETIOLE_START_V;
inline constexpr double kBladeBaseV = BOREAS_LEAF_BLADE_BASE_V;
inline constexpr double kBladeTipV = BOREAS_LEAF_BLADE_TIP_V;
inline constexpr double kBladeHalfWidth = BOREAS_LEAF_BLADE_HALF_WIDTH;
inline constexpr double kPetioleHalfWidth = BOREAS_LEAF_PETIOLE_HALF_WIDTH;

struct LeafShape {
  // The outline's kind: a row of boreas_leaf_outlines (cl/shared/leaf_outline.h).
  int outline = BOREAS_LEAF_OUTLINE_BROADLEAF;
  int vein_pairs = 7;                 // secondary veins per side
  double vein_angle_deg = 50.0;       // between a secondary vein and the midrib where it leaves
  double vein_curvature = 1.5;        // 1/texture unit: the veins turn towards the tip outwards
  double midrib_half_width = 0.0065;  // at the base; it tapers to 40% of this at the tip
  double vein_half_width = 0.0035;    // secondary veins at the midrib; half of this at the margin
};

// Whether (u, v) lies on the blade or the petiole: boreas_leaf_outline_inside in double.
bool inside_leaf(const LeafShape& shape, double u, double v);

// Fraction of each texel covered by the leaf (width x height texels, row 0 at v = 0): 0 or 1
// away from the outline, and 4 x 4 supersampled in texels the outline crosses, so the edge is
// antialiased for alpha-to-coverage and mipmaps.
std::vector<float> leaf_coverage(const LeafShape& shape, int width, int height);

// How much of each vein lies at (u, v): 1 on a vein's center line, falling smoothly to 0 at
// its half-width (profile (1 - r^2)^2 with r = distance / half-width).
struct VeinWeights {
  double petiole = 0.0;
  double midrib = 0.0;
  double secondary = 0.0;
  double midrib_taper = 1.0;  // 1 at the blade base down to 0.4 at the tip
  double margin = 1.0;        // |x| / half_width: 0 on the midrib, 1 on the margin and outside
};
// seed picks the gentle meander of the secondary veins.
VeinWeights vein_weights(const LeafShape& shape, double u, double v, uint32_t seed);

}  // namespace boreas::render
