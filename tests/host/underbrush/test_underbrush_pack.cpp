// The packed rest data of a meadow component (cl/shared/underbrush_pack.h, encoded by
// host/src/underbrush/frame_pack.h): round trips against the exact values in double
// within stated bounds, the decoded pair orthonormal, the link's fields exact, and what
// does not fit refused with a message naming it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "errors.h"
#include "underbrush/frame_pack.h"

namespace boreas::impl {
namespace {

struct D3 {
  double v[3];
};

D3 unit(double x, double y, double z) {
  const double l = std::sqrt(x * x + y * y + z * z);
  return {{x / l, y / l, z / l}};
}

double angle_to(BoreasV3 a, const D3& b) {
  // From the chord (acos loses precision near 1), a normalized in double.
  const double la = std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
  const double dx = a.x / la - b.v[0], dy = a.y / la - b.v[1], dz = a.z / la - b.v[2];
  return 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz)));
}

// Unit vectors: random on the sphere, and the hard places (poles, the octahedron's edges
// and the basis's seam at z = 0, in both halves).
std::vector<D3> directions() {
  std::vector<D3> out;
  for (int a = 0; a < 3; ++a)
    for (double s : {-1.0, 1.0}) {
      double v[3] = {0, 0, 0};
      v[a] = s;
      out.push_back(unit(v[0], v[1], v[2]));
    }
  for (double e : {0.0, 1e-7, -1e-7, 1e-3, -1e-3}) {
    out.push_back(unit(0.6, e, 0.8));
    out.push_back(unit(0.6, 0.8, e));
    out.push_back(unit(-0.3, -0.9, e));
    out.push_back(unit(e, -1.0, e));
  }
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  for (int k = 0; k < 20000; ++k) out.push_back(unit(g(rng), g(rng), g(rng)));
  return out;
}

// A unit vector perpendicular to d, turned by t about it.
D3 perpendicular(const D3& d, double t) {
  const D3 h = std::fabs(d.v[1]) < 0.9 ? D3{{0, 1, 0}} : D3{{1, 0, 0}};
  D3 a = unit(h.v[1] * d.v[2] - h.v[2] * d.v[1], h.v[2] * d.v[0] - h.v[0] * d.v[2],
              h.v[0] * d.v[1] - h.v[1] * d.v[0]);
  D3 b = {{d.v[1] * a.v[2] - d.v[2] * a.v[1], d.v[2] * a.v[0] - d.v[0] * a.v[2],
           d.v[0] * a.v[1] - d.v[1] * a.v[0]}};
  return unit(std::cos(t) * a.v[0] + std::sin(t) * b.v[0], std::cos(t) * a.v[1] + std::sin(t) * b.v[1],
              std::cos(t) * a.v[2] + std::sin(t) * b.v[2]);
}

// The axis within 5.5e-5 rad: a step of 1/32767 in one coordinate of the square moves the
// octahedron's point by at most sqrt(2)/32767, at least 1/sqrt(3) from the center, so by
// at most sqrt(6)/32767 = 7.5e-5 rad; the nearest of a cell's corners is within about
// half its diagonal, 5.3e-5 rad (measured: 4.3e-5).
TEST(UnderbrushPack, AxisRoundTripWithinBound) {
  double worst = 0.0;
  for (const D3& d : directions()) {
    const BoreasV3 e = boreas_ub_unpack_axis(pack_axis(d.v));
    worst = std::max(worst, angle_to(e, d));
    EXPECT_NEAR(double(e.x) * e.x + double(e.y) * e.y + double(e.z) * e.z, 1.0, 1e-6);
  }
  EXPECT_LT(worst, 5.5e-5);
  EXPECT_GT(worst, 1e-7);  // it is a quantization: the bound is measured, not vacuous
}

// The side within 1.5e-4 rad of the exact side's part perpendicular to the decoded axis,
// and the pair orthonormal to float precision, for sides all round each axis.
TEST(UnderbrushPack, SideOrthonormalAndWithinBound) {
  double worst = 0.0, worst_dot = 0.0, worst_len = 0.0;
  int k = 0;
  for (const D3& d : directions()) {
    const double t = 0.37 * k++;
    const D3 w = perpendicular(d, t);
    const int32_t axis = pack_axis(d.v);
    const int32_t turn = pack_turn(axis, w.v, 1.0, "test");
    const int32_t index[3] = {0, axis, turn};
    const UnpackedFrame f = unpack_frame(index, 1, 0);
    const double dot = double(f.axis.x) * f.side.x + double(f.axis.y) * f.side.y +
                       double(f.axis.z) * f.side.z;
    const double len = double(f.side.x) * f.side.x + double(f.side.y) * f.side.y +
                       double(f.side.z) * f.side.z;
    worst_dot = std::max(worst_dot, std::fabs(dot));
    worst_len = std::max(worst_len, std::fabs(len - 1.0));
    worst = std::max(worst, angle_to(f.side, w));
  }
  EXPECT_LT(worst_dot, 1e-6);
  EXPECT_LT(worst_len, 1e-6);
  // The side's own quantization (1.2e-4) plus the axis's (4e-5) tilting the plane.
  EXPECT_LT(worst, 1.6e-4);
  EXPECT_GT(worst, 1e-7);
}

// The scale within a relative 2^-11 (the nearest half: 10 bits past the leading one),
// exact where it is a half.
TEST(UnderbrushPack, ScaleRoundTripWithinBound) {
  const double up[3] = {0, 1, 0}, east[3] = {1, 0, 0};
  const int32_t axis = pack_axis(up);
  double worst = 0.0;
  for (int k = 0; k <= 10000; ++k) {
    const double s = 0.5 + k * 1e-4;
    const float got = boreas_ub_unpack_scale(pack_turn(axis, east, s, "test"));
    worst = std::max(worst, std::fabs(double(got) - s) / s);
  }
  EXPECT_LE(worst, std::ldexp(1.0, -11));
  EXPECT_GT(worst, 0.0);
  for (double s : {0.5, 1.0, 1.5, 0.75, BOREAS_UB_SCALE_MIN, BOREAS_UB_SCALE_MAX})
    EXPECT_EQ(double(boreas_ub_unpack_scale(pack_turn(axis, east, s, "test"))), s);
}

TEST(UnderbrushPack, LinkFieldsExact) {
  for (int part : {0, 1, 255, 4095, BOREAS_UB_LINK_PART_MASK})
    for (int back : {0, 1, 7, BOREAS_PLANT_MAX_COMPONENTS - 1, BOREAS_UB_LINK_PART_MASK}) {
      const int32_t index[1] = {pack_link(part, back, "test")};
      EXPECT_EQ(part_of(index, 1, 0), part);
      EXPECT_EQ(parent_of(index, 1, 0), -back);  // c = 0: its parent is back before it
    }
}

std::string refusal(void (*f)()) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    return e.what();
  }
  return "";
}

TEST(UnderbrushPack, RefusesWhatDoesNotFit) {
  EXPECT_NE(refusal([] { pack_link(BOREAS_UB_LINK_PART_MASK + 1, 0, "meadow x"); }).find("meadow x: part"),
            std::string::npos);
  EXPECT_NE(refusal([] { pack_link(0, -1, "meadow x"); }).find("meadow x: parent"), std::string::npos);
  EXPECT_NE(refusal([] {
              const double up[3] = {0, 1, 0};
              pack_turn(pack_axis(up), up, 1e5, "meadow y");
            }).find("meadow y: scale"),
            std::string::npos);
}

}  // namespace
}  // namespace boreas::impl
