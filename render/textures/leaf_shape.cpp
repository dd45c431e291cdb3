// boreas textures: the leaf outline (inside test and antialiased coverage) and its veins.
#include "textures/leaf_shape.h"

#include <algorithm>
#include <cmath>

#include "textures/hash_noise.h"

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Vein cross-section: 1 at the center line, 0 from one half-width out.
double bump(double distance, double half_width) {
  double r = distance / half_width;
  if (r >= 1.0) return 0.0;
  double s = 1.0 - r * r;
  return s * s;
}

// The outline's formula (cl/shared/leaf_outline.h), in double: the table's row promoted.
double blade_start_v(const LeafShape& s, double ax) {
  const BoreasLeafOutline& o = boreas_leaf_outlines[s.outline];
  double q = ax / o.notch_half_width;
  return kBladeBaseV - o.notch_depth * (1.0 - std::exp(-q * q));
}

// Half-width at blade parameter t in (0, 1), teeth and sinuses included.
double half_width(const LeafShape& s, double t) {
  if (t <= 0.0 || t >= 1.0) return 0.0;
  const BoreasLeafOutline& o = boreas_leaf_outlines[s.outline];
  double p = o.base_exponent, q = o.tip_exponent;
  double t_max = p / (p + q);
  double peak = std::pow(t_max, p) * std::pow(1.0 - t_max, q);
  double w = kBladeHalfWidth * std::pow(t, p) * std::pow(1.0 - t, q) / peak;
  // Distance (in lobe periods) to the nearest sinus; the cut's depth follows a raised
  // cosine across the sinus, so its bottom is round and its sides flare into the lobes.
  double phase = t * o.lobes;
  double d = std::abs(phase - std::round(phase));
  double half = 0.5 * o.sinus_width;
  if (d < half) w *= 1.0 - o.lobe_depth * 0.5 * (1.0 + std::cos(kPi * d / half));
  // Teeth point towards the tip: the margin rises slowly along t, then drops.
  double tooth_phase = t * o.teeth;
  double tooth = 1.0 - (tooth_phase - std::floor(tooth_phase));
  double fade = noise::smoothstep(0.08, 0.25, t) * (1.0 - noise::smoothstep(0.85, 0.97, t));
  return w * (1.0 - o.serration * tooth * fade);
}

double blade_t(const LeafShape& s, double ax, double v) {
  double start = blade_start_v(s, ax);
  return (v - start) / (kBladeTipV - start);
}

bool inside_petiole(double ax, double v) {
  if (v > kBladeBaseV + kPetioleHalfWidth || ax >= kPetioleHalfWidth) return false;
  // Rounded stem end.
  double below = kPetioleStartV + kPetioleHalfWidth - v;
  if (below <= 0.0) return true;
  return ax * ax + below * below < kPetioleHalfWidth * kPetioleHalfWidth;
}

}  // namespace

bool inside_leaf(const LeafShape& shape, double u, double v) {
  double ax = std::abs(u - 0.5);
  if (inside_petiole(ax, v)) return true;
  return ax < half_width(shape, blade_t(shape, ax, v));
}

std::vector<float> leaf_coverage(const LeafShape& shape, int width, int height) {
  // Inside tests at texel corners, shared between neighbours; a texel whose four corners
  // agree is taken as wholly in or out. A feature thinner than a texel that passes between
  // corners is lost: the petiole (0.016 wide) survives down to about 64 texels across.
  std::vector<unsigned char> corner(static_cast<size_t>(width + 1) * (height + 1));
  for (int j = 0; j <= height; ++j) {
    for (int i = 0; i <= width; ++i) {
      corner[size_t(j) * (width + 1) + i] =
          inside_leaf(shape, double(i) / width, double(j) / height);
    }
  }
  std::vector<float> coverage(static_cast<size_t>(width) * height);
  constexpr int kSub = 4;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      int in = corner[size_t(j) * (width + 1) + i] + corner[size_t(j) * (width + 1) + i + 1] +
               corner[size_t(j + 1) * (width + 1) + i] +
               corner[size_t(j + 1) * (width + 1) + i + 1];
      float c = 0.0f;
      if (in == 4) {
        c = 1.0f;
      } else if (in > 0) {
        int hits = 0;
        for (int b = 0; b < kSub; ++b) {
          for (int a = 0; a < kSub; ++a) {
            hits +=
                inside_leaf(shape, (i + (a + 0.5) / kSub) / width, (j + (b + 0.5) / kSub) / height);
          }
        }
        c = float(hits) / (kSub * kSub);
      }
      coverage[size_t(j) * width + i] = c;
    }
  }
  return coverage;
}

VeinWeights vein_weights(const LeafShape& s, double u, double v, uint32_t seed) {
  VeinWeights w;
  double x = u - 0.5;
  double ax = std::abs(x);

  // The petiole: a stalk that blends into the midrib over a short way into the blade. Its
  // profile is wider than its outline so that it stays thick (opaque) up to its edges.
  if (v >= kPetioleStartV) {
    double along = 1.0 - noise::smoothstep(kBladeBaseV, kBladeBaseV + 0.04, v);
    w.petiole = bump(ax, 1.6 * kPetioleHalfWidth) * along;
  }

  double t = blade_t(s, ax, v);
  if (t <= 0.0 || t >= 1.0) return w;
  double hw = half_width(s, t);
  w.margin = hw > 0.0 ? std::min(ax / hw, 1.0) : 1.0;

  double tm = std::clamp((v - kBladeBaseV) / (kBladeTipV - kBladeBaseV), 0.0, 1.0);
  w.midrib_taper = 1.0 - 0.6 * tm;
  if (v >= kBladeBaseV) w.midrib = bump(ax, s.midrib_half_width * w.midrib_taper);

  // Secondary veins: v = v0 + |x| cot(angle) + curvature |x|^2 from origins spread along the
  // midrib; the right side's origins sit a little higher (subopposite veins). The distance
  // to a vein is its vertical offset times the cosine of its slope. Low-frequency noise
  // bends them by up to about 0.004 either way, so they meander a little.
  double cot = 1.0 / std::tan(s.vein_angle_deg * kPi / 180.0);
  double meander = 0.008 * (noise::fbm(u, v, 8, 8, 2, seed) - 0.5);
  double rise = ax * cot + s.vein_curvature * ax * ax + meander;
  double slope = cot + 2.0 * s.vein_curvature * ax;
  double cos_slope = 1.0 / std::sqrt(1.0 + slope * slope);
  double length = kBladeTipV - kBladeBaseV;
  double side_offset = x > 0.0 ? 0.025 : 0.0;
  double nearest = 1e9;
  int n = std::max(s.vein_pairs, 1);
  for (int k = 0; k < n; ++k) {
    double t0 = n > 1 ? 0.06 + 0.72 * k / (n - 1) : 0.3;
    double v0 = kBladeBaseV + length * (t0 + side_offset);
    nearest = std::min(nearest, std::abs(v - v0 - rise) * cos_slope);
  }
  double vein_hw = s.vein_half_width * (1.0 - 0.5 * w.margin);
  w.secondary = bump(nearest, vein_hw) * (1.0 - noise::smoothstep(0.75, 0.97, w.margin));
  return w;
}

}  // namespace boreas::render
