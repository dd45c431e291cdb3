// boreas textures: the leaf drawn on its texture: an ovate blade with a serrate margin and a
// heart-shaped notch at the base, a petiole, a midrib and pinnate secondary veins.
//
// Coordinates are texture units: u across the leaf (midrib at u = 0.5), v along it from the
// stem end of the quad (v = 0) to the tip (v = 1); the quad is square. Along the blade,
// t = (v - v_start(|x|)) / (tip_v - v_start(|x|)) runs from the base (0) to the tip (1),
// x = u - 0.5, and the blade is where |x| < half_width(t):
//   half_width(t) = max_half_width * t^p (1 - t)^q / max over t of the same   (ovate for
//                   p < q: widest at t = p / (p + q)), times the lobes' sinuses and the
//                   serration teeth;
//   v_start(|x|)  = blade_base_v - notch_depth (1 - exp(-(|x| / notch_half_width)^2)), so the
//                   basal lobes reach below the petiole's attachment point.
#pragma once

#include <cstdint>
#include <vector>

namespace boreas::render {

struct LeafShape {
  double petiole_start_v = 0.02;  // stem end of the petiole
  double blade_base_v = 0.15;     // where the petiole meets the blade, on the midrib
  double tip_v = 0.97;
  double max_half_width = 0.30;  // the widest point's distance from the midrib
  double base_exponent = 0.55;   // p: below 1 rounds the base
  double tip_exponent = 1.25;    // q: above 1 draws the tip out
  double notch_depth = 0.035;    // how far the basal lobes reach below blade_base_v
  double notch_half_width = 0.05;
  double petiole_half_width = 0.008;
  double serration = 0.025;           // depth of the margin's teeth, fraction of the half-width
  int teeth = 26;                     // per side, along t
  // Lobes (an oak's): the sinuses between them sit at t = k / lobes (k = 1, 2, ...), each a
  // raised-cosine cut sinus_width of a lobe's period wide and lobe_depth of the half-width
  // deep at its bottom. lobes = 3.5 gives three lobes a side and a terminal one. 0: an unlobed
  // blade.
  double lobes = 0.0;
  double lobe_depth = 0.0;            // 0..0.95
  double sinus_width = 0.6;           // 0..1
  int vein_pairs = 7;                 // secondary veins per side
  double vein_angle_deg = 50.0;       // between a secondary vein and the midrib where it leaves
  double vein_curvature = 1.5;        // 1/texture unit: the veins turn towards the tip outwards
  double midrib_half_width = 0.0065;  // at the base; it tapers to 40% of this at the tip
  double vein_half_width = 0.0035;    // secondary veins at the midrib; half of this at the margin
};

// Whether (u, v) lies on the blade or the petiole.
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
