// Texture generator tests: the bark texture tiles in u and v, its furrows run along the
// trunk, its normals are unit vectors, and a seed fixes it.
#include "textures/bark_textures.h"

#include <gtest/gtest.h>

#include <cmath>

#include "textures/texture_error.h"

namespace boreas::render {
namespace {

// Mean absolute difference of channel values between texel columns x0 and x1 (or rows,
// when along_u is false), over all channels.
double seam_step(const std::vector<float>& image, int w, int h, int channels, bool along_u, int a,
                 int b) {
  double sum = 0.0;
  int count = along_u ? h : w;
  for (int k = 0; k < count; ++k) {
    size_t ia = along_u ? size_t(k) * w + a : size_t(a) * w + k;
    size_t ib = along_u ? size_t(k) * w + b : size_t(b) * w + k;
    for (int c = 0; c < channels; ++c)
      sum += std::abs(image[ia * channels + c] - image[ib * channels + c]);
  }
  return sum / (count * channels);
}

// The mean step between neighbouring columns (rows) inside the texture.
double interior_step(const std::vector<float>& image, int w, int h, int channels, bool along_u) {
  int n = along_u ? w : h;
  double sum = 0.0;
  for (int i = 0; i + 1 < n; ++i) sum += seam_step(image, w, h, channels, along_u, i, i + 1);
  return sum / (n - 1);
}

TEST(BarkTextures, TilesInUAndV) {
  BarkTextureSet s = generate_bark_textures();
  ASSERT_EQ(s.width, 256);
  ASSERT_EQ(s.height, 256);
  for (bool along_u : {true, false}) {
    int last = (along_u ? s.width : s.height) - 1;
    for (auto [image, name] : {std::pair{&s.albedo, "albedo"}, std::pair{&s.normal, "normal"}}) {
      double seam = seam_step(*image, s.width, s.height, 3, along_u, last, 0);
      double typical = interior_step(*image, s.width, s.height, 3, along_u);
      EXPECT_LT(seam, 1.5 * typical) << name << (along_u ? " across u" : " across v");
      // Two unrelated rows or columns differ far more: what a seam would look like.
      double unrelated = seam_step(*image, s.width, s.height, 3, along_u, 0, last / 2);
      EXPECT_GT(unrelated, 3.0 * typical) << name;
    }
  }
}

TEST(BarkTextures, FurrowsRunAlongTheTrunk) {
  BarkTextureSet s = generate_bark_textures();
  // The surface slopes across the furrows (normal x) far more than along them (normal y).
  double across = 0.0, along = 0.0;
  for (size_t i = 0; i < s.normal.size() / 3; ++i) {
    across += s.normal[i * 3] * s.normal[i * 3];
    along += s.normal[i * 3 + 1] * s.normal[i * 3 + 1];
  }
  EXPECT_GT(across, 2.0 * along);
  // And albedo varies faster across them than along them.
  EXPECT_GT(interior_step(s.albedo, s.width, s.height, 3, true),
            1.5 * interior_step(s.albedo, s.width, s.height, 3, false));
}

TEST(BarkTextures, NormalsAreUnitAndAlbedoIsBarkColoured) {
  BarkTextureParams p;
  p.width = 96;
  p.height = 160;
  BarkTextureSet s = generate_bark_textures(p);
  ASSERT_EQ(s.albedo.size(), 96u * 160u * 3u);
  double mean[3] = {0.0, 0.0, 0.0};
  for (size_t i = 0; i < s.normal.size() / 3; ++i) {
    const float* n = &s.normal[i * 3];
    ASSERT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-6);
    ASSERT_GT(n[2], 0.0f);
    for (int c = 0; c < 3; ++c) {
      ASSERT_GE(s.albedo[i * 3 + c], 0.0f);
      ASSERT_LE(s.albedo[i * 3 + c], 1.0f);
      mean[c] += s.albedo[i * 3 + c];
    }
  }
  // Dark and brownish-grey on the whole: red above blue, nothing bright.
  EXPECT_GT(mean[0], mean[2]);
  EXPECT_LT(mean[1] / (s.normal.size() / 3), 0.2);
}

TEST(BarkTextures, SameSeedGivesTheSameTexelsAndAnotherSeedDoesNot) {
  BarkTextureParams p;
  p.width = 64;
  p.height = 64;
  BarkTextureSet a = generate_bark_textures(p), b = generate_bark_textures(p);
  EXPECT_EQ(a.albedo, b.albedo);
  EXPECT_EQ(a.normal, b.normal);
  p.seed = 99;
  EXPECT_NE(generate_bark_textures(p).albedo, a.albedo);
  p.furrows = 0;
  EXPECT_THROW(generate_bark_textures(p), TextureError);
}

}  // namespace
}  // namespace boreas::render
