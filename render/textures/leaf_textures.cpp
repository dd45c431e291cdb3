// boreas textures: generating the leaf texture set (the steps are listed in leaf_textures.h).
#include "textures/leaf_textures.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "textures/hash_noise.h"
#include "textures/height_normals.h"
#include "textures/hl2_basis.h"
#include "textures/leaf_translucency.h"
#include "textures/texture_error.h"

namespace boreas::render {
namespace {

void require(bool ok, const char* name, const std::string& rule, double value) {
  require_param(ok, "LeafTextureParams", name, rule, value);
}

void check(const LeafTextureParams& p) {
  require(p.width >= 16 && p.width <= 8192, "width", "in 16..8192", p.width);
  require(p.height >= 16 && p.height <= 8192, "height", "in 16..8192", p.height);
  require(p.leaf_size_mm > 0.0, "leaf_size_mm", "> 0", p.leaf_size_mm);
  require(p.lamina_thickness_mm > 0.0, "lamina_thickness_mm", "> 0", p.lamina_thickness_mm);
  require(p.midrib_thickness_mm >= p.lamina_thickness_mm, "midrib_thickness_mm",
          ">= lamina_thickness_mm", p.midrib_thickness_mm);
  require(p.vein_thickness_mm >= p.lamina_thickness_mm, "vein_thickness_mm",
          ">= lamina_thickness_mm", p.vein_thickness_mm);
  require(p.petiole_thickness_mm >= p.lamina_thickness_mm, "petiole_thickness_mm",
          ">= lamina_thickness_mm", p.petiole_thickness_mm);
  require(p.tertiary_thickness_mm >= 0.0, "tertiary_thickness_mm", ">= 0", p.tertiary_thickness_mm);
  require(p.refractive_index >= 1.0 && p.refractive_index <= 3.0, "refractive_index", "in 1..3",
          p.refractive_index);
  require(p.hl2_rings >= 1 && p.hl2_rings <= 1024, "hl2_rings", "in 1..1024", p.hl2_rings);
  require(p.hl2_sectors >= 3 && p.hl2_sectors <= 1024, "hl2_sectors", "in 3..1024", p.hl2_sectors);
  require(p.shape.outline >= 0 && p.shape.outline < BOREAS_LEAF_OUTLINE_COUNT, "shape.outline",
          "in 0.." + std::to_string(BOREAS_LEAF_OUTLINE_COUNT - 1), p.shape.outline);
  require(p.optics.coefficient_channel >= 0 && p.optics.coefficient_channel < 3,
          "optics.coefficient_channel", "0, 1 or 2", p.optics.coefficient_channel);
}

// Linear RGB of vein tissue, which holds less chlorophyll than the lamina: a pale
// yellow-green.
constexpr double kVeinColor[3] = {0.20, 0.26, 0.075};

}  // namespace

LeafTextureSet generate_leaf_textures(const LeafTextureParams& p) {
  check(p);
  const int w = p.width, h = p.height;
  const size_t n = size_t(w) * h;
  const KubelkaMunkSlab slabs[3] = {KubelkaMunkSlab(p.optics.rgb[0]),
                                    KubelkaMunkSlab(p.optics.rgb[1]),
                                    KubelkaMunkSlab(p.optics.rgb[2])};

  LeafTextureSet set;
  set.width = w;
  set.height = h;
  set.albedo.resize(n * 4);
  set.thickness_mm.resize(n);
  set.translucency.resize(n * 3);
  set.hl2.resize(n * 3);

  std::vector<float> coverage = leaf_coverage(p.shape, w, h);
  std::vector<double> thickness(n);
  std::vector<double> height(n);
  const uint32_t seed = noise::hash(p.seed);

  for (int y = 0; y < h; ++y) {
    double v = (y + 0.5) / h;
    for (int x = 0; x < w; ++x) {
      double u = (x + 0.5) / w;
      size_t i = size_t(y) * w + x;
      VeinWeights vein = vein_weights(p.shape, u, v, seed + 3U);

      // Fine vein network: the borders of Worley cells about 2 mm across (at the default
      // size), fading out towards the margin.
      double border = noise::cell_border_distance(u, v, 36, 36, seed + 11U);
      double tertiary = (1.0 - noise::smoothstep(0.0, 0.1, border)) * (1.0 - vein.margin);

      double lamina = p.lamina_thickness_mm;
      double extra =
          std::max({(p.midrib_thickness_mm - lamina) * vein.midrib_taper * vein.midrib,
                    (p.vein_thickness_mm - lamina) * (1.0 - 0.5 * vein.margin) * vein.secondary,
                    (p.petiole_thickness_mm - lamina) * vein.petiole});
      double d = lamina + extra + p.tertiary_thickness_mm * tertiary;
      thickness[i] = d;

      // Upper surface: raised veins, the margin cupped up by cupping_mm, and bumps of
      // +-0.01 mm between the veins.
      double across = (u - 0.5) / kBladeHalfWidth;
      double bumps = 0.02 * (noise::fbm(u, v, 24, 24, 2, seed + 23U) - 0.5);
      height[i] = p.vein_raise * (d - lamina) + p.cupping_mm * across * across + bumps;

      // Mottling: brightness varies by up to 15% over patches a fifth of the quad across,
      // and red by up to 12% over larger ones (where the leaf is a little yellower).
      double mottle = noise::fbm(u, v, 5, 5, 4, seed + 31U);
      double yellowing = noise::fbm(u, v, 3, 3, 3, seed + 37U);
      double pale = 0.75 * std::max({vein.midrib, vein.secondary, vein.petiole}) + 0.2 * tertiary;
      pale = std::min(pale, 1.0);
      for (int c = 0; c < 3; ++c) {
        double r = slabs[c].reflectance(d);
        double a = (r + (kVeinColor[c] - r) * pale) * (0.85 + 0.3 * mottle);
        if (c == 0) a *= 0.9 + 0.25 * yellowing;
        set.albedo[i * 4 + c] = float(a);
        set.translucency[i * 3 + c] = float(slabs[c].transmittance(d));
      }
      set.albedo[i * 4 + 3] = coverage[i];
      set.thickness_mm[i] = float(d);
    }
  }

  set.normal = normals_from_height(height, w, h, p.leaf_size_mm / w, p.leaf_size_mm / h,
                                   HeightEdges::kClamp);

  const Hl2Fitter fitter(p.hl2_rings, p.hl2_sectors);
  const LeafTranslucency translucency(p.optics.rgb[p.optics.coefficient_channel],
                                      p.refractive_index);
  for (size_t i = 0; i < n; ++i) {
    glm::dvec3 normal =
        glm::normalize(glm::dvec3(set.normal[i * 3], set.normal[i * 3 + 1], set.normal[i * 3 + 2]));
    Hl2Coefficients c = translucency.coefficients(fitter, thickness[i], normal);
    for (int k = 0; k < 3; ++k) set.hl2[i * 3 + k] = float(c[k]);
  }
  return set;
}

}  // namespace boreas::render
