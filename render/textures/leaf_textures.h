// boreas textures: the generated leaf texture set of the leaf shader (Kusternig sec. 3.2):
// albedo with the alpha mask, tangent-space normals, thickness, HL2 translucency
// coefficients and translucency color.
//
// No photographs or scans exist, so the set is drawn (leaf_shape.h) and derived, in this
// order, per texel:
//   1. coverage of the outline -> alpha;
//   2. veins -> thickness (lamina, thicker at the midrib, secondary and faint tertiary veins,
//      the petiole);
//   3. height of the upper surface = vein_raise x (thickness - lamina) + cupping towards the
//      margin + faint bumps -> normals by finite differences (height_normals.h);
//   4. thickness -> albedo = Kubelka-Munk reflectance per channel (thin_slab.h), paler on
//      veins (less chlorophyll) and mottled by hash noise;
//   5. thickness -> translucency color = Kubelka-Munk transmittance at normal incidence;
//   6. thickness and normal -> HL2 coefficients of the back-lit green intensity
//      (leaf_translucency.h).
// One set serves both sides of the leaf (the paper keeps one per side): the underside is
// shaded with the same maps, its normal mirrored to (n.x, n.y, -n.z), and
// leaf_translucency.h says how the HL2 coefficients are used from either side.
//
// Layout, for uploading as is: texel (x, y) is at index y * width + x, x along u (across),
// y along v (row 0 at v = 0, the stem end); u = (x + 0.5) / width, v = (y + 0.5) / height.
// Tangent space: +x along u, +y along v, +z out of the upper side.
#pragma once

#include <cstdint>
#include <vector>

#include "textures/leaf_shape.h"
#include "textures/thin_slab.h"

namespace boreas::render {

struct LeafTextureParams {
  int width = 512;   // texels, 16..8192
  int height = 512;  // texels, 16..8192
  uint32_t seed = 1;
  double leaf_size_mm = 80.0;           // side of the square quad the texture covers
  double lamina_thickness_mm = 0.2;     // the blade between veins
  double midrib_thickness_mm = 0.5;     // at the blade base, thinning with the midrib's width
  double vein_thickness_mm = 0.3;       // secondary veins where they leave the midrib
  double tertiary_thickness_mm = 0.03;  // extra thickness of the fine vein network
  double petiole_thickness_mm = 0.9;
  double vein_raise = 0.6;  // fraction of a vein's extra thickness that stands on the upper side
  double cupping_mm = 1.0;  // height of the margin above the midrib
  LeafShape shape;
  LeafOptics optics = default_leaf_optics();
  // Of the HL2 path model (leaf_translucency.h). 1.45, about that of cuticle and cell
  // walls: light refracts toward the normal on entering, so grazing light crosses less
  // tissue. With 1.0 (straight paths) the three-term fit is poor (relative RMS residual
  // 0.48 for the lamina) and passes 0.07 of straight-through light instead of 0.13; with
  // 1.45 the residual is 0.17 and it passes 0.10.
  double refractive_index = 1.45;
  // Hemisphere samples of the HL2 fit, rings x sectors (hl2_basis.h). The intensity is
  // steep in the polar angle and smooth in azimuth, so rings matter: 16 x 6 puts the
  // coefficients within 1% of a 64 x 128 fit for lamina and veins.
  int hl2_rings = 16;
  int hl2_sectors = 6;
};

struct LeafTextureSet {
  int width = 0;
  int height = 0;
  std::vector<float> albedo;        // RGBA: linear RGB diffuse reflectance, A = coverage (mask)
  std::vector<float> normal;        // xyz unit vectors, tangent space
  std::vector<float> thickness_mm;  // one per texel
  std::vector<float> hl2;           // c0, c1, c2 per texel (hl2_basis.h); may be negative
  std::vector<float> translucency;  // RGB transmittance at normal incidence, linear
};

// The set for params; throws TextureError naming a parameter out of range.
LeafTextureSet generate_leaf_textures(const LeafTextureParams& params = {});

}  // namespace boreas::render
