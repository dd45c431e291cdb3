// Texture generator tests: normal maps from height fields (flat, ramps, periodic fields
// across the wrap).
#include "textures/height_normals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "textures/texture_error.h"

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_normal(const std::vector<float>& normals, size_t texel, double x, double y, double z,
                   double tolerance, const char* where) {
  EXPECT_NEAR(normals[texel * 3], x, tolerance) << where << " texel " << texel;
  EXPECT_NEAR(normals[texel * 3 + 1], y, tolerance) << where << " texel " << texel;
  EXPECT_NEAR(normals[texel * 3 + 2], z, tolerance) << where << " texel " << texel;
}

TEST(HeightNormals, FlatHeightPointsStraightOut) {
  for (HeightEdges edges : {HeightEdges::kClamp, HeightEdges::kWrap}) {
    std::vector<double> height(7 * 5, 3.25);
    std::vector<float> normals = normals_from_height(height, 7, 5, 0.1, 0.2, edges);
    ASSERT_EQ(normals.size(), 7u * 5u * 3u);
    for (size_t i = 0; i < 35; ++i) expect_normal(normals, i, 0.0, 0.0, 1.0, 0.0, "flat");
  }
}

TEST(HeightNormals, RampGivesItsAnalyticTiltEverywhere) {
  // h = a x + b y (mm), texels 0.5 mm across and 0.25 mm along: n = (-a, -b, 1) / |...|,
  // on the edges too (one-sided differences there).
  const int w = 9, h = 6;
  const double a = 0.3, b = -1.2, texel_x = 0.5, texel_y = 0.25;
  std::vector<double> height(w * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) height[y * w + x] = a * x * texel_x + b * y * texel_y + 2.0;
  }
  std::vector<float> normals =
      normals_from_height(height, w, h, texel_x, texel_y, HeightEdges::kClamp);
  double length = std::sqrt(a * a + b * b + 1.0);
  for (size_t i = 0; i < size_t(w * h); ++i) {
    expect_normal(normals, i, -a / length, -b / length, 1.0 / length, 1e-6, "ramp");
  }
}

TEST(HeightNormals, AreUnitLength) {
  const int w = 16, h = 12;
  std::vector<double> height(w * h);
  for (int i = 0; i < w * h; ++i) height[i] = std::sin(i * 0.7) * 3.0 + std::cos(i * 0.13);
  for (HeightEdges edges : {HeightEdges::kClamp, HeightEdges::kWrap}) {
    std::vector<float> n = normals_from_height(height, w, h, 0.3, 0.3, edges);
    for (int i = 0; i < w * h; ++i) {
      EXPECT_NEAR(std::sqrt(n[i * 3] * n[i * 3] + n[i * 3 + 1] * n[i * 3 + 1] +
                            n[i * 3 + 2] * n[i * 3 + 2]),
                  1.0, 1e-6);
      EXPECT_GT(n[i * 3 + 2], 0.0f);
    }
  }
}

TEST(HeightNormals, WrappedEdgesDifferenceAcrossTheSeam) {
  // One period of a sine across the texture: the central difference is exact,
  // (sin(k(x + t)) - sin(k(x - t))) / 2t = k cos(kx) sin(kt) / (kt), also at the edges.
  const int w = 12, h = 3;
  const double texel = 0.5, amplitude = 0.4, k = 2.0 * kPi / (w * texel);
  std::vector<double> height(w * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) height[y * w + x] = amplitude * std::sin(k * x * texel);
  }
  std::vector<float> normals = normals_from_height(height, w, h, texel, texel, HeightEdges::kWrap);
  for (int x : {0, 1, w / 2, w - 1}) {
    double slope = amplitude * k * std::cos(k * x * texel) * std::sin(k * texel) / (k * texel);
    double length = std::sqrt(slope * slope + 1.0);
    expect_normal(normals, size_t(w + x), -slope / length, 0.0, 1.0 / length, 1e-6, "sine");
  }
}

TEST(HeightNormals, RejectsAHeightFieldOfTheWrongSize) {
  std::vector<double> height(10, 0.0);
  EXPECT_THROW(normals_from_height(height, 4, 3, 1.0, 1.0, HeightEdges::kClamp), TextureError);
  EXPECT_THROW(
      normals_from_height(std::vector<double>(12, 0.0), 4, 3, 0.0, 1.0, HeightEdges::kClamp),
      TextureError);
}

}  // namespace
}  // namespace boreas::render
