// boreas textures: the built-in leaf kinds' outlines and optics.
#include "textures/leaf_kinds.h"

#include <filesystem>

#include "textures/thin_slab.h"

namespace boreas::render {
namespace {

// Optics of a 0.2 mm lamina measured (or here, chosen) as reflectance r and transmittance t
// per channel, linear RGB.
LeafOptics optics_of(const double (&r)[3], const double (&t)[3]) {
  LeafOptics optics;
  for (int c = 0; c < 3; ++c)
    optics.rgb[c] = slab_optics_from_measurement(r[c], t[c], kReferenceLaminaMm);
  return optics;
}

LeafKind aspen(const LeafTextureParams& base) {
  LeafKind k{"aspen", base};
  LeafShape& s = k.params.shape;
  s.base_exponent = 0.35;  // widest at 0.4 of the blade, a broad rounded base
  s.tip_exponent = 0.55;   // and a short tip
  s.notch_depth = 0.0;
  s.serration = 0.04;  // small, rounded-looking teeth
  s.teeth = 18;
  s.vein_pairs = 5;
  s.vein_angle_deg = 40.0;
  k.params.optics = optics_of({0.110, 0.185, 0.060}, {0.075, 0.160, 0.030});
  return k;
}

LeafKind oak(const LeafTextureParams& base) {
  LeafKind k{"oak", base};
  LeafShape& s = k.params.shape;
  s.base_exponent = 0.8;
  s.tip_exponent = 0.8;
  s.notch_depth = 0.0;
  s.lobes = 3.5;  // three a side and the terminal lobe
  s.lobe_depth = 0.55;
  s.sinus_width = 0.85;  // wide round sinuses leave the lobes pointed
  s.serration = 0.12;    // a few coarse, bristle-tipped teeth per lobe
  s.teeth = 14;
  s.vein_pairs = 4;
  s.vein_angle_deg = 45.0;
  k.params.optics = optics_of({0.080, 0.140, 0.050}, {0.050, 0.115, 0.018});
  return k;
}

LeafKind willow(const LeafTextureParams& base) {
  LeafKind k{"willow", base};
  LeafShape& s = k.params.shape;
  s.base_exponent = 1.0;  // a tapering base
  s.tip_exponent = 1.8;   // and a long, drawn-out tip
  s.notch_depth = 0.0;
  s.serration = 0.03;
  s.teeth = 40;
  s.vein_pairs = 12;
  s.vein_angle_deg = 62.0;
  k.params.optics = optics_of({0.100, 0.150, 0.075}, {0.060, 0.120, 0.030});
  return k;
}

LeafKind tupelo(const LeafTextureParams& base) {
  LeafKind k{"tupelo", base};
  LeafShape& s = k.params.shape;
  s.base_exponent = 1.2;  // widest past the middle: obovate
  s.tip_exponent = 0.9;
  s.notch_depth = 0.0;
  s.serration = 0.0;  // entire margin
  s.vein_pairs = 6;
  s.vein_angle_deg = 48.0;
  k.params.optics = optics_of({0.060, 0.110, 0.040}, {0.040, 0.090, 0.015});
  return k;
}

}  // namespace

std::vector<LeafKind> leaf_kinds(const LeafTextureParams& base) {
  return {LeafKind{"broadleaf", base}, aspen(base), oak(base), willow(base), tupelo(base)};
}

std::vector<std::string> leaf_kind_names() {
  std::vector<std::string> names;
  for (const LeafKind& k : leaf_kinds()) names.push_back(k.name);
  return names;
}

std::string default_leaf_kind(const std::string& species) {
  const std::string stem = std::filesystem::path(species).stem().string();
  if (stem == "quaking_aspen") return "aspen";
  if (stem == "ca_black_oak") return "oak";
  if (stem == "weeping_willow") return "willow";
  if (stem == "black_tupelo") return "tupelo";
  return "broadleaf";
}

}  // namespace boreas::render
