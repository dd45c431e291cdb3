// boreas textures: the built-in leaf kinds' outlines and optics.
#include "textures/leaf_kinds.h"

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
  s.outline = BOREAS_LEAF_OUTLINE_ASPEN;
  s.vein_pairs = 5;
  s.vein_angle_deg = 40.0;
  k.params.optics = optics_of({0.110, 0.185, 0.060}, {0.075, 0.160, 0.030});
  return k;
}

LeafKind oak(const LeafTextureParams& base) {
  LeafKind k{"oak", base};
  LeafShape& s = k.params.shape;
  s.outline = BOREAS_LEAF_OUTLINE_OAK;
  s.vein_pairs = 4;
  s.vein_angle_deg = 45.0;
  k.params.optics = optics_of({0.080, 0.140, 0.050}, {0.050, 0.115, 0.018});
  return k;
}

LeafKind willow(const LeafTextureParams& base) {
  LeafKind k{"willow", base};
  LeafShape& s = k.params.shape;
  s.outline = BOREAS_LEAF_OUTLINE_WILLOW;
  s.vein_pairs = 12;
  s.vein_angle_deg = 62.0;
  k.params.optics = optics_of({0.100, 0.150, 0.075}, {0.060, 0.120, 0.030});
  return k;
}

LeafKind tupelo(const LeafTextureParams& base) {
  LeafKind k{"tupelo", base};
  LeafShape& s = k.params.shape;
  s.outline = BOREAS_LEAF_OUTLINE_TUPELO;
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

}  // namespace boreas::render
