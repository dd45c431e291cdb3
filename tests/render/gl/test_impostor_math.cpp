// The impostors' math (render/gl/impostor_math.h) against double-precision references: an
// impostor record's matrix against the library's placement of a tree (host/src/trees/
// tree_layout.cpp: p -> position + R_y(rotation) (scale p)) plus the sway's shear, the
// hemi-octahedral map and the frames' cameras.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "gl/impostor_math.h"

namespace boreas::render {
namespace {

struct Vec3d {
  double x, y, z;
};

// The reference: placed as the library places a tree's rest points, then sheared.
Vec3d placed_reference(const ImpostorRecord& r, double tip_height, Vec3d p) {
  const double c = std::cos(double(r.rotation)), s = std::sin(double(r.rotation));
  const double k = r.scale;
  const double px = k * p.x, py = k * p.y, pz = k * p.z;
  const double shear = p.y / tip_height;
  return {r.position[0] + c * px + s * pz + r.sway[0] * shear, r.position[1] + py + r.sway[1] * shear,
          r.position[2] - s * px + c * pz + r.sway[2] * shear};
}

TEST(ImpostorMath, RecordMatrixPlacesAndShearsAsTheDoubleReference) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int trial = 0; trial < 200; ++trial) {
    ImpostorRecord r{};
    for (float& x : r.position) x = 100.0f * u(rng);
    r.scale = 1.0f + 0.5f * u(rng);
    r.rotation = 3.5f * u(rng);
    r.template_index = float(trial % 7);
    for (float& x : r.sway) x = 0.5f * u(rng);
    const float tip = 12.0f + 5.0f * u(rng);
    const glm::mat4 m = impostor_matrix(r, tip);
    for (int k = 0; k < 8; ++k) {
      const Vec3d p{4.0 * u(rng), 20.0 * (0.5 + 0.5 * u(rng)), 4.0 * u(rng)};
      const glm::vec4 got = m * glm::vec4(float(p.x), float(p.y), float(p.z), 1.0f);
      const Vec3d want = placed_reference(r, tip, p);
      // float32 of coordinates up to ~130 m: a few ulps of 128 m.
      EXPECT_NEAR(got.x, want.x, 5e-5) << "trial " << trial;
      EXPECT_NEAR(got.y, want.y, 5e-5) << "trial " << trial;
      EXPECT_NEAR(got.z, want.z, 5e-5) << "trial " << trial;
      EXPECT_FLOAT_EQ(got.w, 1.0f);
    }
    // Without sway the base stays, and the inverse placement undoes the placement.
    const glm::vec3 at(r.position[0], r.position[1], r.position[2]);
    const glm::mat4 round = tree_placement_inverse(at, r.rotation, r.scale) * tree_placement(at, r.rotation, r.scale);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(round[i][j], i == j ? 1.0f : 0.0f, 2e-5) << i << "," << j;
    const glm::vec4 base = m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    EXPECT_NEAR(glm::distance(glm::vec3(base), at), 0.0f, 1e-4);
  }
}

TEST(ImpostorMath, HemiOctahedralMapRoundTripsAndFoldsTheHorizonOntoTheBorder) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 2000; ++i) {
    double x = g(rng), y = std::abs(g(rng)), z = g(rng);
    const double n = std::sqrt(x * x + y * y + z * z);
    const glm::vec3 d(float(x / n), float(y / n), float(z / n));
    const glm::vec2 uv = hemi_octahedral_uv(d);
    ASSERT_GE(uv.x, 0.0f);
    ASSERT_LE(uv.x, 1.0f);
    ASSERT_GE(uv.y, 0.0f);
    ASSERT_LE(uv.y, 1.0f);
    const glm::vec3 back = hemi_octahedral_direction(uv);
    EXPECT_LT(glm::distance(back, d), 1e-5f) << x << " " << y << " " << z;
  }
  // Straight up is the centre; horizontal directions lie on the border (|u-0.5| or |v-0.5| = 0.5).
  EXPECT_LT(glm::distance(hemi_octahedral_uv({0.0f, 1.0f, 0.0f}), glm::vec2(0.5f)), 1e-6f);
  for (float a = 0.0f; a < 6.28f; a += 0.1f) {
    const glm::vec2 uv = hemi_octahedral_uv({std::cos(a), 0.0f, std::sin(a)});
    const float edge = std::max(std::abs(uv.x - 0.5f), std::abs(uv.y - 0.5f));
    // |x| + |z| = 1 maps onto the square's border: max(|u'|, |v'|) = 1 with u' = x + z, v' = x - z.
    EXPECT_NEAR(edge, 0.5f, 1e-5f) << a;
  }
}

// Every direction above the horizon has a frame within a bound, and the frame a direction
// falls in is the nearest one or close to it: what keeps the impostor's view error small.
TEST(ImpostorMath, FramesCoverTheHemisphereAndEachDirectionFindsItsFrame) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  double worst = 0.0;
  for (int i = 0; i < 5000; ++i) {
    glm::vec3 d(float(g(rng)), float(std::abs(g(rng))), float(g(rng)));
    d = glm::normalize(d);
    const glm::vec2 uv = hemi_octahedral_uv(d);
    const int ci = std::min(int(uv.x * kImpostorFrames), kImpostorFrames - 1);
    const int cj = std::min(int(uv.y * kImpostorFrames), kImpostorFrames - 1);
    const double angle = std::acos(std::min(1.0f, glm::dot(d, impostor_frame_direction(ci, cj))));
    worst = std::max(worst, angle);
  }
  // 8 x 8 frames: within 25 degrees everywhere (about 12 near the horizon).
  EXPECT_LT(worst * 180.0 / M_PI, 25.0);
  for (int i = 0; i < kImpostorFrames; ++i) {
    for (int j = 0; j < kImpostorFrames; ++j) {
      const glm::vec2 uv = hemi_octahedral_uv(impostor_frame_direction(i, j));
      EXPECT_EQ(int(uv.x * kImpostorFrames), i);
      EXPECT_EQ(int(uv.y * kImpostorFrames), j);
    }
  }
}

TEST(ImpostorMath, AFramesViewPutsTheSphereOnTheFrameFromItsDirection) {
  const glm::vec3 center(1.0f, 8.0f, -2.0f);
  const float radius = 9.0f;
  for (int i = 0; i < kImpostorFrames; ++i) {
    for (int j = 0; j < kImpostorFrames; ++j) {
      const glm::vec3 d = impostor_frame_direction(i, j);
      const glm::mat4 vp = impostor_frame_view_projection(d, center, radius);
      const glm::vec4 c = vp * glm::vec4(center, 1.0f);
      EXPECT_NEAR(c.x, 0.0f, 1e-5f);
      EXPECT_NEAR(c.y, 0.0f, 1e-5f);
      // The sphere's front and back stay inside the depth range; its rim on the frame's edge.
      EXPECT_GT((vp * glm::vec4(center + d * radius, 1.0f)).z, -1.0f - 1e-5f);
      EXPECT_LT((vp * glm::vec4(center - d * radius, 1.0f)).z, 1.0f + 1e-5f);
      const glm::vec3 up = glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) - d * d.y);
      EXPECT_NEAR((vp * glm::vec4(center + up * radius, 1.0f)).y, 1.0f, 1e-4f);
    }
  }
}

}  // namespace
}  // namespace boreas::render
