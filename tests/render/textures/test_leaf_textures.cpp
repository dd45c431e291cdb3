// Texture generator tests: the default leaf set: its mask, normals, thickness, albedo,
// translucency and HL2 coefficients, and determinism for a seed.
#include "textures/leaf_textures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "textures/hl2_basis.h"
#include "textures/leaf_translucency.h"
#include "textures/texture_error.h"

namespace boreas::render {
namespace {

// Generated once: the default set takes a few tenths of a second.
const LeafTextureSet& default_leaf() {
  static const LeafTextureSet set = generate_leaf_textures();
  return set;
}

size_t texel_at(const LeafTextureSet& s, double u, double v) {
  return size_t(int(v * s.height)) * s.width + size_t(int(u * s.width));
}

glm::dvec3 normal_of(const LeafTextureSet& s, size_t i) {
  return {s.normal[i * 3], s.normal[i * 3 + 1], s.normal[i * 3 + 2]};
}

double straight_through(const LeafTextureSet& s, size_t i) {
  return hl2_evaluate({s.hl2[i * 3], s.hl2[i * 3 + 1], s.hl2[i * 3 + 2]}, {0.0, 0.0, 1.0});
}

TEST(LeafTextures, HasTheRequestedSizeAndLayout) {
  const LeafTextureSet& s = default_leaf();
  ASSERT_EQ(s.width, 512);
  ASSERT_EQ(s.height, 512);
  size_t n = 512u * 512u;
  EXPECT_EQ(s.albedo.size(), 4 * n);
  EXPECT_EQ(s.normal.size(), 3 * n);
  EXPECT_EQ(s.thickness_mm.size(), n);
  EXPECT_EQ(s.hl2.size(), 3 * n);
  EXPECT_EQ(s.translucency.size(), 3 * n);
}

TEST(LeafTextures, MaskCoversTheMiddleNotTheCorners) {
  const LeafTextureSet& s = default_leaf();
  auto alpha = [&](double u, double v) { return s.albedo[texel_at(s, u, v) * 4 + 3]; };
  EXPECT_EQ(alpha(0.5, 0.5), 1.0f);
  EXPECT_EQ(alpha(0.5, 0.9), 1.0f);    // towards the tip
  EXPECT_EQ(alpha(0.5, 0.08), 1.0f);   // the petiole
  EXPECT_EQ(alpha(0.45, 0.08), 0.0f);  // beside the petiole
  EXPECT_EQ(alpha(0.5, 0.995), 0.0f);  // beyond the tip
  for (double u : {0.0, 0.999}) {
    for (double v : {0.0, 0.999}) EXPECT_EQ(alpha(u, v), 0.0f) << u << " " << v;
  }
}

TEST(LeafTextures, MaskAreaIsThatOfAnOvateLeafWithASoftEdge) {
  // An ovate blade 0.6 wide and 0.82 long covers about a third of its quad (measured 0.329).
  const LeafTextureSet& s = default_leaf();
  double sum = 0.0;
  int partial = 0;
  for (size_t i = 0; i < s.thickness_mm.size(); ++i) {
    float a = s.albedo[i * 4 + 3];
    ASSERT_GE(a, 0.0f);
    ASSERT_LE(a, 1.0f);
    sum += a;
    partial += a > 0.0f && a < 1.0f;
  }
  double fraction = sum / s.thickness_mm.size();
  EXPECT_GT(fraction, 0.30);
  EXPECT_LT(fraction, 0.36);
  // The outline is antialiased: about two texels per outline row on each side are partial.
  EXPECT_GT(partial, 2 * s.height);
  EXPECT_LT(partial, 8 * s.height);
}

TEST(LeafTextures, NormalsAreUnitAndPointOutOfTheUpperSide) {
  const LeafTextureSet& s = default_leaf();
  double max_tilt = 0.0;
  for (size_t i = 0; i < s.thickness_mm.size(); ++i) {
    glm::dvec3 n = normal_of(s, i);
    ASSERT_NEAR(glm::length(n), 1.0, 1e-6) << i;
    ASSERT_GT(n.z, 0.0) << i;
    if (s.albedo[i * 4 + 3] > 0.0f) max_tilt = std::max(max_tilt, std::acos(n.z));
  }
  // Veins stand out: some texels on their flanks tilt by more than 20 degrees.
  EXPECT_GT(max_tilt, 20.0 * 3.14159265 / 180.0);
}

TEST(LeafTextures, ThicknessIsLaminaBetweenVeinsAndMoreOnThem) {
  const LeafTextureSet& s = default_leaf();
  float thinnest = 1e9f, thickest = 0.0f;
  for (float d : s.thickness_mm) {
    thinnest = std::min(thinnest, d);
    thickest = std::max(thickest, d);
  }
  EXPECT_NEAR(thinnest, 0.2f, 1e-6f);
  EXPECT_LE(thickest, 0.9f + 0.03f + 1e-6f);  // the petiole, plus the fine network at most
  // The midrib near the base is about 0.5 mm thick, and thins towards the tip.
  float base = 0.0f, tip = 0.0f;
  for (int x = 250; x < 262; ++x) {
    base = std::max(base, s.thickness_mm[size_t(int(0.2 * 512)) * 512 + x]);
    tip = std::max(tip, s.thickness_mm[size_t(int(0.85 * 512)) * 512 + x]);
  }
  EXPECT_NEAR(base, 0.5f, 0.04f);
  EXPECT_LT(tip, base - 0.1f);
}

TEST(LeafTextures, VeinsTransmitLessThanTheLamina) {
  const LeafTextureSet& s = default_leaf();
  double brightest_vein = 0.0, darkest_lamina = 1.0;
  for (size_t i = 0; i < s.thickness_mm.size(); ++i) {
    if (s.albedo[i * 4 + 3] < 1.0f) continue;
    double d = s.thickness_mm[i];
    if (d >= 0.35) {
      brightest_vein = std::max(brightest_vein, straight_through(s, i));
      ASSERT_LT(s.translucency[i * 3 + 1], 0.05f) << i;
    }
    if (d <= 0.21) darkest_lamina = std::min(darkest_lamina, straight_through(s, i));
  }
  EXPECT_GT(brightest_vein, 0.0);
  EXPECT_LT(brightest_vein, 0.5 * darkest_lamina);
}

TEST(LeafTextures, Hl2CoefficientsAreTheFitOfTheTexelsThicknessAndNormal) {
  const LeafTextureSet& s = default_leaf();
  LeafTextureParams p;
  Hl2Fitter fitter(p.hl2_rings, p.hl2_sectors);
  LeafTranslucency model(p.optics.rgb[1], p.refractive_index);
  for (auto [u, v] :
       {std::pair{0.5, 0.3}, std::pair{0.3, 0.4}, std::pair{0.507, 0.5}, std::pair{0.62, 0.77}}) {
    size_t i = texel_at(s, u, v);
    Hl2Coefficients c =
        model.coefficients(fitter, s.thickness_mm[i], glm::normalize(normal_of(s, i)));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.hl2[i * 3 + k], c[k], 1e-6 * std::abs(c[k]) + 1e-9);
  }
}

TEST(LeafTextures, AlbedoAndTranslucencyAreGreenWithPalerVeins) {
  const LeafTextureSet& s = default_leaf();
  auto luminance = [&](size_t i) {
    return 0.2126 * s.albedo[i * 4] + 0.7152 * s.albedo[i * 4 + 1] + 0.0722 * s.albedo[i * 4 + 2];
  };
  double lamina = 0.0;
  int count = 0;
  for (size_t i = 0; i < s.thickness_mm.size(); ++i) {
    if (s.albedo[i * 4 + 3] < 1.0f || s.thickness_mm[i] > 0.2001f) continue;
    EXPECT_GT(s.albedo[i * 4 + 1], s.albedo[i * 4]) << i;
    EXPECT_GT(s.albedo[i * 4 + 1], s.albedo[i * 4 + 2]) << i;
    EXPECT_GT(s.translucency[i * 3 + 1], s.translucency[i * 3]) << i;
    EXPECT_GT(s.translucency[i * 3], s.translucency[i * 3 + 2]) << i;
    lamina += luminance(i);
    ++count;
  }
  ASSERT_GT(count, 1000);
  lamina /= count;
  // Lamina albedo near the ColorChecker foliage patch (luminance 0.13).
  EXPECT_NEAR(lamina, 0.13, 0.03);
  double midrib = 0.0;
  for (int x = 250; x < 262; ++x) midrib = std::max(midrib, luminance(size_t(200) * 512 + x));
  EXPECT_GT(midrib, 1.3 * lamina);
}

TEST(LeafTextures, SameSeedGivesTheSameTexelsAndAnotherSeedDoesNot) {
  LeafTextureParams p;
  p.width = 64;
  p.height = 80;
  LeafTextureSet a = generate_leaf_textures(p), b = generate_leaf_textures(p);
  EXPECT_EQ(a.albedo, b.albedo);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.thickness_mm, b.thickness_mm);
  EXPECT_EQ(a.hl2, b.hl2);
  EXPECT_EQ(a.translucency, b.translucency);
  p.seed = 2;
  LeafTextureSet c = generate_leaf_textures(p);
  EXPECT_NE(a.albedo, c.albedo);
  EXPECT_NE(a.thickness_mm, c.thickness_mm);
}

TEST(LeafTextures, RejectsParametersOutOfRange) {
  LeafTextureParams p;
  p.width = 8;
  try {
    generate_leaf_textures(p);
    FAIL() << "no error for width 8";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("LeafTextureParams.width"), std::string::npos) << e.what();
  }
  p = {};
  p.midrib_thickness_mm = 0.1;
  EXPECT_THROW(generate_leaf_textures(p), TextureError);
  p = {};
  p.hl2_sectors = 2;
  EXPECT_THROW(generate_leaf_textures(p), TextureError);
}

}  // namespace
}  // namespace boreas::render
