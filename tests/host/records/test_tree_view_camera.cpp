// boreas tests: a records view from a camera (boreas_set_tree_view_camera). Points are
// inside its planes exactly where a double-precision GL projection (a look-at view matrix
// times a perspective matrix, clip space -w <= x, y, z <= w) puts them inside, for cameras
// turned every way; its pixel angle is the image centre's; bad arguments are refused by
// name and leave the view as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iterator>
#include <random>
#include <string>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "boreas/boreas_cl.hpp"

namespace boreas {
namespace {

using V3 = std::array<double, 3>;

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(const V3& a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

struct Camera {
  float eye[3], forward[3], up[3];
  float fov, aspect, near_m, far_m;
  int height;
};

// The point's clip coordinates under gluLookAt and gluPerspective's matrices, in double;
// returns how far inside it is, as the least of (w - |c|) / w over x, y, z (negative:
// outside, or behind the eye).
double clip_margin(const Camera& c, const V3& p) {
  const V3 e = {c.eye[0], c.eye[1], c.eye[2]};
  const V3 f = unit({c.forward[0], c.forward[1], c.forward[2]});
  const V3 s = unit(cross(f, {c.up[0], c.up[1], c.up[2]})), u = cross(s, f);
  const V3 d = sub(p, e);
  const double x = dot(s, d), y = dot(u, d), z = -dot(f, d);  // eye space, looking down -z
  const double t = 1.0 / std::tan(0.5 * double(c.fov)), n = c.near_m, fa = c.far_m;
  const double cx = t / double(c.aspect) * x, cy = t * y;
  const double cz = (fa + n) / (n - fa) * z + 2.0 * fa * n / (n - fa), w = -z;
  if (w <= 0.0) return -1.0;
  return std::min({(w - std::abs(cx)) / w, (w - std::abs(cy)) / w, (w - std::abs(cz)) / w});
}

bool inside_planes(const boreas_tree_view_def& v, const V3& p) {
  for (const auto& pl : v.planes)
    if (double(pl[0]) * p[0] + double(pl[1]) * p[1] + double(pl[2]) * p[2] + double(pl[3]) < 0.0) return false;
  return true;
}

TEST(TreeViewCamera, PlanesHoldWhatADoublePrecisionProjectionHolds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit_box(-1.0, 1.0);
  const Camera cameras[] = {
      {{0, 2, 10}, {0, 0, -1}, {0, 1, 0}, 0.9f, 16.0f / 9.0f, 0.1f, 200.0f, 720},
      {{-30, 1.8f, 30}, {30, 2.2f, -40}, {0, 1, 0}, 1.2f, 1.0f, 0.5f, 80.0f, 512},
      {{5, 40, -3}, {0.2f, -1, 0.1f}, {0, 0, -1}, 0.6f, 0.5f, 1.0f, 60.0f, 300},  // looking down
      {{100, 3, 100}, {-1, 0.3f, 0.5f}, {0.3f, 2, 0}, 2.5f, 2.4f, 0.05f, 40.0f, 1080}};
  for (size_t k = 0; k < std::size(cameras); ++k) {
    const Camera& c = cameras[k];
    boreas_tree_view_def v = boreas_default_tree_view_def();
    v.min_keep = 0.5f;
    ASSERT_EQ(boreas_set_tree_view_camera(&v, c.eye, c.forward, c.up, c.fov, c.aspect, c.near_m, c.far_m, c.height),
              BOREAS_OK)
        << boreas_last_error();
    EXPECT_EQ(v.min_keep, 0.5f) << "the other fields are kept";
    for (int a = 0; a < 3; ++a) EXPECT_EQ(v.eye[a], c.eye[a]);
    EXPECT_NEAR(double(v.pixel_angle), 2.0 * std::tan(0.5 * double(c.fov)) / c.height, 1e-7 * v.pixel_angle);
    int in = 0, out = 0;
    // Points about the frustum (in the camera's frame: depth from before the eye to past
    // the far plane, across half again its width and height there), so that both sides
    // of every plane are met.
    const V3 f = unit({c.forward[0], c.forward[1], c.forward[2]});
    const V3 rt = unit(cross(f, {c.up[0], c.up[1], c.up[2]})), up = cross(rt, f);
    const double ty = std::tan(0.5 * double(c.fov)), tx = ty * double(c.aspect);
    for (int i = 0; i < 20000; ++i) {
      const double z = c.far_m * (0.5 + 0.6 * unit_box(rng)), reach = std::max(std::abs(z), double(c.near_m));
      const double x = 1.5 * tx * reach * unit_box(rng), y = 1.5 * ty * reach * unit_box(rng);
      V3 p;
      for (int a = 0; a < 3; ++a) p[size_t(a)] = c.eye[a] + z * f[size_t(a)] + x * rt[size_t(a)] + y * up[size_t(a)];
      const double margin = clip_margin(c, p);
      if (std::abs(margin) < 1e-4) continue;  // on an edge: within float's rounding of it
      const bool expected = margin > 0.0;
      ASSERT_EQ(inside_planes(v, p), expected) << "camera " << k << " point " << p[0] << " " << p[1] << " " << p[2];
      (expected ? in : out) += 1;
    }
    EXPECT_GT(in, 100) << "camera " << k << ": the test would prove little";
    EXPECT_GT(out, 100) << "camera " << k;
  }
}

TEST(TreeViewCamera, TheCppNamesakeSetsTheSameView) {
  const float eye[3] = {1, 2, 3}, forward[3] = {0, 0, -1}, up[3] = {0, 1, 0};
  boreas_tree_view_def a = boreas_default_tree_view_def(), b = a;
  ASSERT_EQ(boreas_set_tree_view_camera(&a, eye, forward, up, 1.0f, 1.5f, 0.1f, 100.0f, 600), BOREAS_OK);
  set_tree_view_camera(b, eye, forward, up, 1.0f, 1.5f, 0.1f, 100.0f, 600);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
}

TEST(TreeViewCamera, BadArgumentsAreRefusedByNameAndTheViewIsKept) {
  const float eye[3] = {0, 2, 10}, forward[3] = {0, 0, -1}, up[3] = {0, 1, 0}, zero[3] = {0, 0, 0};
  const float nan = std::nanf("");
  const float bad_eye[3] = {0, nan, 0};
  struct Case {
    const float *e, *f, *u;
    float fov, aspect, n, fa;
    int h;
    const char* names;
  };
  const Case cases[] = {{nullptr, forward, up, 1, 1, 0.1f, 10, 100, "eye"},
                        {bad_eye, forward, up, 1, 1, 0.1f, 10, 100, "eye[1]"},
                        {eye, zero, up, 1, 1, 0.1f, 10, 100, "forward"},
                        {eye, forward, forward, 1, 1, 0.1f, 10, 100, "up is parallel to forward"},
                        {eye, forward, up, 0, 1, 0.1f, 10, 100, "vertical_fov"},
                        {eye, forward, up, 3.2f, 1, 0.1f, 10, 100, "vertical_fov"},
                        {eye, forward, up, 1, 0, 0.1f, 10, 100, "aspect"},
                        {eye, forward, up, 1, 1, 0, 10, 100, "near_m"},
                        {eye, forward, up, 1, 1, 10, 10, 100, "far_m"},
                        {eye, forward, up, 1, 1, 0.1f, nan, 100, "far_m"},
                        {eye, forward, up, 1, 1, 0.1f, 10, 0, "viewport_height"},
                        {eye, forward, up, 3.1f, 1, 0.1f, 10, 1, "viewport_height"}};
  for (const Case& c : cases) {
    boreas_tree_view_def v = boreas_default_tree_view_def();
    const boreas_tree_view_def before = v;
    EXPECT_EQ(boreas_set_tree_view_camera(&v, c.e, c.f, c.u, c.fov, c.aspect, c.n, c.fa, c.h),
              BOREAS_ERROR_INVALID_ARGUMENT)
        << c.names;
    EXPECT_NE(std::string(boreas_last_error()).find(c.names), std::string::npos) << boreas_last_error();
    EXPECT_EQ(std::memcmp(&v, &before, sizeof v), 0) << c.names << ": the view was written";
  }
  EXPECT_EQ(boreas_set_tree_view_camera(nullptr, eye, forward, up, 1, 1, 0.1f, 10, 100), BOREAS_ERROR_INVALID_ARGUMENT);
}

}  // namespace
}  // namespace boreas
