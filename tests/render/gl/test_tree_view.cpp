// boreas render tests: the records' view from the camera (render/gl/tree_view.h) against
// planes built in double precision from the camera's own description (its eye, its basis
// and the half-angles of its field of view), and the widening toward the sun as the
// property it stands for: a point whose shadow lands in the camera's frustum is inside.
#include "gl/tree_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/type_precision.hpp>

namespace boreas::render {
namespace {

using dvec3 = glm::dvec3;

struct DPlane {
  dvec3 n;
  double d;
  double at(const dvec3& p) const { return glm::dot(n, p) + d; }
};

// Left, right, bottom, top, near, far, from the camera's basis in double.
std::array<DPlane, 6> reference_planes(const Camera& c, double aspect) {
  const dvec3 eye(c.eye), f = glm::normalize(dvec3(c.target) - eye);
  const dvec3 r = glm::normalize(glm::cross(f, dvec3(0, 1, 0))), u = glm::cross(r, f);
  const double tv = std::tan(double(c.fov_deg) * M_PI / 360.0), th = aspect * tv;
  auto side = [&](const dvec3& edge, const dvec3& along) {
    dvec3 n = glm::normalize(glm::cross(edge, along));
    if (glm::dot(n, f) < 0.0) n = -n;  // inward: the view's axis is inside
    return DPlane{n, -glm::dot(n, eye)};
  };
  return {side(f - r * th, u), side(f + r * th, u), side(f - u * tv, r), side(f + u * tv, r),
          DPlane{f, -glm::dot(f, eye) - double(c.near_m)}, DPlane{-f, glm::dot(f, eye) + double(c.far_m)}};
}

Camera test_camera() {
  Camera c;
  c.eye = {-30.0f, 1.8f, 30.0f};
  c.target = {0.0f, 4.0f, -10.0f};
  c.fov_deg = 55.0f;
  c.near_m = 0.1f;
  c.far_m = 3000.0f;
  return c;
}

TEST(TreeView, PlanesMatchTheCamerasFrustumInDouble) {
  const Camera c = test_camera();
  TreeViewInputs in;
  in.aspect = 1280.0f / 720.0f;
  const boreas_tree_view_def v = camera_tree_view(c, in);
  const std::array<DPlane, 6> ref = reference_planes(c, double(in.aspect));
  for (int i = 0; i < 6; ++i) {
    const dvec3 n(v.planes[i][0], v.planes[i][1], v.planes[i][2]);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-6) << "plane " << i;
    EXPECT_LT(glm::length(n - ref[size_t(i)].n), 1e-5) << "plane " << i;
    // d to float's precision of the largest (the far plane's 3 km).
    EXPECT_NEAR(double(v.planes[i][3]), ref[size_t(i)].d, 1e-6 * std::max(1.0, std::abs(ref[size_t(i)].d)))
        << "plane " << i;
  }
  for (int k = 0; k < 3; ++k) EXPECT_EQ(v.eye[k], (&c.eye.x)[k]);
  EXPECT_NEAR(double(v.pixel_angle), 2.0 * std::tan(55.0 * M_PI / 360.0) / 720.0, 1e-9);
  EXPECT_EQ(v.impostor_distance, 0.0f);
  EXPECT_EQ(boreas_default_tree_view_def().resolved_pixels, v.resolved_pixels);
  EXPECT_EQ(v.min_keep, kRecordsMinKeep);
}

TEST(TreeView, NoThinningMeansNoPixelAngle) {
  TreeViewInputs in;
  in.thinning = false;
  in.impostor_distance = 30.0f;
  const boreas_tree_view_def v = camera_tree_view(test_camera(), in);
  EXPECT_EQ(v.pixel_angle, 0.0f);
  EXPECT_EQ(v.impostor_distance, 30.0f);
}

TEST(TreeView, AnyPointWhoseShadowLandsInViewIsInsideTheWidenedPlanes) {
  const Camera c = test_camera();
  TreeViewInputs in;
  in.aspect = 1280.0f / 720.0f;
  in.toward_sun = glm::normalize(glm::vec3(-0.6f, 0.5f, 0.4f));
  in.shadow_height = 25.0f;
  const boreas_tree_view_def v = camera_tree_view(c, in);
  const std::array<DPlane, 6> ref = reference_planes(c, double(in.aspect));
  const dvec3 s(in.toward_sun);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> xz(-200.0, 200.0), h(0.0, 25.0);
  int outside_but_shadowing = 0, widened_out = 0;
  for (int i = 0; i < 20000; ++i) {
    const dvec3 p(xz(rng), h(rng), xz(rng));
    const dvec3 shadow = p - s * (p.y / s.y);  // on the ground, y = 0
    bool shadow_in = true, p_in = true, p_in_widened = true;
    for (int k = 0; k < 6; ++k) {
      shadow_in = shadow_in && ref[size_t(k)].at(shadow) >= 0.0;
      p_in = p_in && ref[size_t(k)].at(p) >= 0.0;
      const dvec3 n(v.planes[k][0], v.planes[k][1], v.planes[k][2]);
      p_in_widened = p_in_widened && glm::dot(n, p) + double(v.planes[k][3]) >= -1e-3;
    }
    if (shadow_in) {
      EXPECT_TRUE(p_in_widened) << p.x << " " << p.y << " " << p.z;
    }
    outside_but_shadowing += shadow_in && !p_in;
    widened_out += !p_in_widened;
  }
  // The case the widening is for occurs, and the widening still leaves most of the
  // square out (the planes are not simply dropped).
  EXPECT_GT(outside_but_shadowing, 50);
  EXPECT_GT(widened_out, 10000);
}

}  // namespace
}  // namespace boreas::render
