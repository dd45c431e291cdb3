// boreas tests: the double BlobTree reference against closed forms and brute force (cone
// distance, Barr's bend, PCM, cuts, scars, texture), so the float kernels have a sound twin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "blobtree/blobtree_model.h"
#include "reference/blobtree_reference.h"

namespace boreas::test {
namespace {

using impl::BlobCut;
using impl::BlobModel;
using impl::BlobPrimitive;
namespace ref = impl::reference;

constexpr double kPi = 3.14159265358979323846;

// Where a lone Wyvill fall-off is 1/2, as a fraction of R: sqrt(1 - (1/2)^(1/3)).
double iso_fraction() { return std::sqrt(1.0 - std::cbrt(0.5)); }

double wyvill(double d, double influence) {
  double x = 1.0 - d * d / (influence * influence);
  return d < influence ? x * x * x : 0.0;
}

// A unit vector perpendicular to unit a.
glm::dvec3 perpendicular(const glm::dvec3& a) {
  glm::dvec3 other = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(a, other));
}

BlobPrimitive cone(const glm::dvec3& base, const glm::dvec3& axis, double length,
                   double cone_radius, double iso) {
  BlobPrimitive p;
  p.base = base;
  p.axis = glm::normalize(axis);
  p.length = length;
  p.cone_radius = cone_radius;
  p.iso_distance = iso;
  p.influence = iso / iso_fraction();
  p.u_direction = perpendicular(p.axis);
  p.bend_direction = p.u_direction;
  return p;
}

BlobModel model_of(std::initializer_list<BlobPrimitive> prims) {
  BlobModel m;
  m.primitives = prims;
  return m;
}

// A point given in a straight primitive's frame: t along the axis, r out at `angle` from
// u_direction towards axis x u_direction.
glm::dvec3 at(const BlobPrimitive& p, double t, double r, double angle = 0.0) {
  glm::dvec3 w = glm::cross(p.axis, p.u_direction);
  return p.base + t * p.axis + r * (std::cos(angle) * p.u_direction + std::sin(angle) * w);
}

// u is an angle: compare on the circle.
double u_error(double u, double expected) {
  double e = std::abs(u - expected);
  return std::min(e, 1.0 - e);
}

double field_of(const BlobPrimitive& prim, const glm::dvec3& p, double* d = nullptr) {
  return ref::blob_primitive_field(prim, p, d);
}

TEST(BlobTreeReference, StraightConeFieldAtKnownPoints) {
  BlobPrimitive p = cone({0.2, -0.1, 0.3}, {1.0, 2.0, 0.5}, 2.0, 0.3, 0.2);
  const double R = p.influence;
  double d = -1.0;
  // On the axis and inside the skeleton cone: distance 0, field 1.
  EXPECT_EQ(field_of(p, at(p, 1.0, 0.0), &d), 1.0);
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(field_of(p, at(p, 0.5, 0.2, 1.0)), 1.0);  // 0.2 < 0.3 (1 - 0.5 / 2)
  EXPECT_EQ(field_of(p, at(p, 1.999, 0.0)), 1.0);
  // Beside the base's rim, behind the base disc, behind the rim.
  EXPECT_NEAR(field_of(p, at(p, 0.0, 0.4, 2.0), &d), wyvill(0.1, R), 1e-14);
  EXPECT_NEAR(d, 0.1, 1e-14);
  field_of(p, at(p, -0.15, 0.1, -1.0), &d);
  EXPECT_NEAR(d, 0.15, 1e-14);
  field_of(p, at(p, -0.1, 0.5, 3.0), &d);
  EXPECT_NEAR(d, std::hypot(0.1, 0.2), 1e-14);
  // Beyond the tip, on the axis and off it (nearest the apex).
  EXPECT_NEAR(field_of(p, at(p, 2.1, 0.0), &d), wyvill(0.1, R), 1e-14);
  EXPECT_NEAR(d, 0.1, 1e-14);
  field_of(p, at(p, 2.2, 0.01, 0.5), &d);
  EXPECT_NEAR(d, std::hypot(0.2, 0.01), 1e-14);
  // Out from the slanted side along its normal (r0, L) / |(r0, L)| in the (t, r) plane.
  const double norm = std::hypot(0.3, 2.0);
  const double nt = 0.3 / norm, nr = 2.0 / norm;
  for (double s : {0.1, 0.5, 0.9}) {
    double ft = 2.0 * s, fr = 0.3 * (1.0 - s);
    field_of(p, at(p, ft + 0.05 * nt, fr + 0.05 * nr, 0.7), &d);
    EXPECT_NEAR(d, 0.05, 1e-14);
    // At the iso distance the field is the iso-value.
    EXPECT_NEAR(field_of(p, at(p, ft + 0.2 * nt, fr + 0.2 * nr, 4.0)), 0.5, 1e-12);
  }
  EXPECT_NEAR(field_of(p, at(p, 1.0, 0.15 + 0.5 * R / nr, 0.0)), 0.421875, 1e-12);  // (3/4)^3
  // Nothing at and beyond R.
  EXPECT_EQ(field_of(p, at(p, 2.0 + R * 1.000001, 0.0)), 0.0);
  EXPECT_EQ(field_of(p, at(p, -R * 1.000001, 0.1)), 0.0);
  EXPECT_EQ(field_of(p, at(p, 1.0, 5.0)), 0.0);
}

// The smallest |q - surface(s, a)| over s in [0, 1] and every angle a: a coarse grid, then
// a pattern search from its best sample (so the brute force is exact to ~1e-12).
template <typename Surface>
double brute_distance(const glm::dvec3& q, Surface surface) {
  const int kGrid = 48;
  double best = 1e300, bs = 0.0, ba = 0.0;
  for (int i = 0; i <= kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      double s = double(i) / kGrid, a = 2.0 * kPi * j / kGrid;
      double d = glm::length(q - surface(s, a));
      if (d < best) best = d, bs = s, ba = a;
    }
  }
  double ds = 1.0 / kGrid, da = 2.0 * kPi / kGrid;
  while (ds > 1e-13) {
    bool moved = false;
    for (int di = -1; di <= 1; ++di) {
      for (int dj = -1; dj <= 1; ++dj) {
        double s = std::clamp(bs + di * ds, 0.0, 1.0), a = ba + dj * da;
        double d = glm::length(q - surface(s, a));
        if (d < best) best = d, bs = s, ba = a, moved = true;
      }
    }
    if (!moved) ds *= 0.5, da *= 0.5;
  }
  return best;
}

// The solid cone's distance against the nearest of its surface points found in 3D.
TEST(BlobTreeReference, ConeDistanceMatchesBruteForce) {
  std::mt19937 rng(20040602);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int outside = 0;
  for (int trial = 0; trial < 30; ++trial) {
    glm::dvec3 axis = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    double length = 1.0 + 0.5 * unit(rng), r0 = 0.3 + 0.2 * unit(rng);
    BlobPrimitive p = cone({unit(rng), unit(rng), unit(rng)}, axis, length, r0, 0.1);
    glm::dvec3 u = p.u_direction, w = glm::cross(axis, u);
    auto radial = [&](double a) { return std::cos(a) * u + std::sin(a) * w; };
    auto disc = [&](double s, double a) { return p.base + s * r0 * radial(a); };
    auto side = [&](double s, double a) {
      return p.base + s * length * axis + (1.0 - s) * r0 * radial(a);
    };
    for (int k = 0; k < 6; ++k) {
      glm::dvec3 q =
          p.base + 0.5 * length * axis + 1.5 * glm::dvec3(unit(rng), unit(rng), unit(rng));
      double d;
      field_of(p, q, &d);
      double t = glm::dot(q - p.base, axis);
      double r = glm::length(q - p.base - t * axis);
      if (t >= 0.0 && t <= length && r <= r0 * (1.0 - t / length)) {
        EXPECT_EQ(d, 0.0);
        continue;
      }
      ++outside;
      double brute = std::min(brute_distance(q, disc), brute_distance(q, side));
      EXPECT_NEAR(d, brute, 1e-10) << "trial " << trial << " point " << k;
    }
  }
  EXPECT_GT(outside, 100);
}

// A bent line skeleton (r0 = 0) of angle `angle` in a tilted frame.
BlobPrimitive bent_line(double angle) {
  BlobPrimitive p = cone({0.3, 0.1, -0.2}, {0.2, 1.0, -0.3}, 1.5, 0.0, 0.1);
  p.bend_angle = angle;
  p.bend_direction = perpendicular(p.axis);
  return p;
}

TEST(BlobTreeReference, BendKeepsTheEndpointsAndBulgesByTheSagitta) {
  for (double angle : {0.3, 1.2, 2.5}) {
    BlobPrimitive p = bent_line(angle);
    double rho = p.length / angle;
    double chord = 2.0 * rho * std::sin(0.5 * angle);
    EXPECT_NEAR(ref::blob_chord_length(p), chord, 1e-15);
    double d = -1.0;
    EXPECT_NEAR(field_of(p, p.base, &d), 1.0, 1e-12);
    EXPECT_LT(d, 1e-12);
    EXPECT_NEAR(field_of(p, p.base + chord * p.axis, &d), 1.0, 1e-12);
    EXPECT_LT(d, 1e-12);
    double sagitta = rho * (1.0 - std::cos(0.5 * angle));
    glm::dvec3 arc_mid = p.base + 0.5 * chord * p.axis + sagitta * p.bend_direction;
    EXPECT_NEAR(field_of(p, arc_mid, &d), 1.0, 1e-12);
    EXPECT_LT(d, 1e-12);
    EXPECT_LT(glm::length(ref::blob_skeleton_point(p, 0.5 * p.length) - arc_mid), 1e-14);
    // The chord's midpoint lies the sagitta inside the arc.
    field_of(p, p.base + 0.5 * chord * p.axis, &d);
    EXPECT_NEAR(d, sagitta, 1e-12);
    if (angle > 1.0) {
      EXPECT_LT(field_of(p, p.base + 0.5 * chord * p.axis), 0.5);
    }
    // Along the arc t grows with arc length and the skeleton stays at distance 0.
    for (double s = 0.0; s <= p.length; s += p.length / 16) {
      glm::dvec3 q = ref::blob_skeleton_point(p, s);
      EXPECT_NEAR(ref::blob_local(p, q).t, s, 1e-12);
      field_of(p, q, &d);
      EXPECT_LT(d, 1e-12);
    }
  }
}

// Beyond either end the end's frame goes on rigidly, and the field is continuous there.
TEST(BlobTreeReference, BendFrameContinuesBeyondTheEnds) {
  BlobPrimitive p = bent_line(1.2);
  p.cone_radius = 0.05;
  glm::dvec3 n = p.bend_direction, b = glm::cross(p.axis, n);
  double half = 0.6;
  glm::dvec3 t0 = std::cos(half) * p.axis + std::sin(half) * n;  // leaves towards the bulge
  glm::dvec3 t1 = std::cos(half) * p.axis - std::sin(half) * n;
  glm::dvec3 out0 = -std::sin(half) * p.axis + std::cos(half) * n;
  glm::dvec3 top = p.base + ref::blob_chord_length(p) * p.axis;
  double d;
  field_of(p, p.base - 0.07 * t0, &d);
  EXPECT_NEAR(d, 0.07, 1e-12);
  field_of(p, top + 0.07 * t1, &d);
  EXPECT_NEAR(d, 0.07, 1e-12);
  ref::BlobLocal l = ref::blob_local(p, p.base - 0.07 * t0 + 0.02 * out0 + 0.03 * b);
  EXPECT_NEAR(l.t, -0.07, 1e-12);
  EXPECT_NEAR(l.c0, 0.02, 1e-12);
  EXPECT_NEAR(l.c1, 0.03, 1e-12);
  l = ref::blob_local(p, top + 0.07 * t1);
  EXPECT_NEAR(l.t, p.length + 0.07, 1e-12);
  // Across the planes where the arc ends, on and off the skeleton cone.
  glm::dvec3 out1 = std::sin(half) * p.axis + std::cos(half) * n;
  for (glm::dvec2 c : {glm::dvec2(0.03, 0.01), glm::dvec2(-0.04, -0.02), glm::dvec2(0.1, -0.05)}) {
    for (double eps : {1e-9, 1e-7}) {
      glm::dvec3 q = p.base + c.x * out0 + c.y * b;
      EXPECT_NEAR(field_of(p, q - eps * t0), field_of(p, q + eps * t0), 100 * eps);
      glm::dvec3 r = top + c.x * out1 + c.y * b;
      EXPECT_NEAR(field_of(p, r - eps * t1), field_of(p, r + eps * t1), 100 * eps);
    }
  }
}

// For a line skeleton the unbent distance is the exact distance to the arc, also behind the
// arc's centre, where the two ends' frames meet.
TEST(BlobTreeReference, BentLineDistanceIsTheDistanceToTheArc) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double angle : {0.8, 2.0, 3.5}) {
    BlobPrimitive p = bent_line(angle);
    glm::dvec3 centre = p.base + 0.5 * ref::blob_chord_length(p) * p.axis -
                        (p.length / angle) * std::cos(0.5 * angle) * p.bend_direction;
    // The arc is blob_skeleton_point's (checked above), reached with a as a dummy angle.
    auto arc = [&](double s, double) { return ref::blob_skeleton_point(p, s * p.length); };
    for (int k = 0; k < 100; ++k) {
      glm::dvec3 q = centre + 1.2 * glm::dvec3(unit(rng), unit(rng), unit(rng));
      double d;
      field_of(p, q, &d);
      EXPECT_NEAR(d, brute_distance(q, arc), 1e-10) << "angle " << angle << " point " << k;
    }
  }
}

TEST(BlobTreeReference, TextureCoordinatesGoAroundTheAxis) {
  BlobPrimitive p = cone({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.0, 0.1, 0.2);
  p.u_direction = glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
  p.v0 = 0.25;
  p.v_scale = 0.5;
  BlobModel m = model_of({p});
  for (double quarter : {0.0, 1.0, 2.0, 3.0}) {
    glm::dvec2 uv = ref::blob_uv(m, at(p, 0.8, 0.12, quarter * 0.5 * kPi));
    EXPECT_LT(u_error(uv.x, quarter / 4.0), 1e-12);
    EXPECT_NEAR(uv.y, 0.25 + 0.5 * 0.8, 1e-12);
  }
  EXPECT_GE(ref::blob_uv(m, at(p, 0.8, 0.12, -1e-17)).x, 0.0);
  EXPECT_LT(ref::blob_uv(m, at(p, 0.8, 0.12, -1e-17)).x, 1.0);
  EXPECT_EQ(ref::blob_uv(m, at(p, 0.8, 5.0)), glm::dvec2(0.0));
  // Bent: u from the arc's outward normal towards axis x bend_direction; v by arc length.
  BlobPrimitive b = bent_line(1.0);
  b.v0 = 0.0;
  b.v_scale = 1.0;
  BlobModel mb = model_of({b});
  glm::dvec3 mid = ref::blob_skeleton_point(b, 0.5 * b.length);
  glm::dvec3 side = glm::cross(b.axis, b.bend_direction);
  EXPECT_LT(u_error(ref::blob_uv(mb, mid + 0.05 * b.bend_direction).x, 0.0), 1e-12);
  EXPECT_LT(u_error(ref::blob_uv(mb, mid + 0.05 * side).x, 0.25), 1e-12);
  EXPECT_NEAR(ref::blob_uv(mb, mid + 0.05 * side).y, 0.5 * b.length, 1e-12);
  // Two primitives blend their coordinates by their fields.
  BlobPrimitive q = p;
  q.v0 = 2.25;
  glm::dvec3 x = at(p, 0.8, 0.12, 0.0);
  double fp = field_of(p, x), fq = field_of(q, x);
  EXPECT_NEAR(ref::blob_uv(model_of({p, q}), x).y, (fp * 0.65 + fq * 2.65) / (fp + fq), 1e-12);
}

TEST(BlobTreeReference, GradientIsTheFalloffSlopeAlongTheNormal) {
  BlobPrimitive p = cone({0.0, 0.0, 0.0}, {0.3, 1.0, 0.2}, 2.0, 0.0, 0.2);
  BlobModel m = model_of({p});
  const double R = p.influence;
  for (double d : {0.05, 0.2, 0.35}) {
    glm::dvec3 q = at(p, 1.0, d, 0.4);
    double x = 1.0 - d * d / (R * R);
    glm::dvec3 expected = -6.0 * d / (R * R) * x * x * glm::normalize(q - at(p, 1.0, 0.0));
    glm::dvec3 g = ref::blob_gradient(m, q, 1e-5);
    EXPECT_LT(glm::length(g - expected), 1e-8) << d;
  }
}

TEST(BlobTreeReference, PcmExpansionIsC1) {
  const double w = 0.3, M = 0.15, k = 2.0, eps = 1e-7;
  auto h = [&](double r) { return ref::blob_pcm_expansion(r, w, M, k); };
  EXPECT_EQ(h(0.0), 0.0);
  EXPECT_NEAR((h(eps) - h(0.0)) / eps, k, 1e-5);
  EXPECT_NEAR(h(0.5 * w), M, 1e-14);
  EXPECT_NEAR(h(0.5 * w - eps), M, 1e-10);
  EXPECT_NEAR(h(0.5 * w + eps), M, 1e-10);
  EXPECT_NEAR((h(0.5 * w) - h(0.5 * w - eps)) / eps, 0.0, 1e-5);
  EXPECT_NEAR((h(0.5 * w + eps) - h(0.5 * w)) / eps, 0.0, 1e-5);
  EXPECT_NEAR(h(w - eps) / eps, 0.0, 1e-5);
  EXPECT_EQ(h(w), 0.0);
  EXPECT_EQ(h(2.0 * w), 0.0);
  for (double r = 0.0; r < w; r += w / 64) EXPECT_GE(h(r), 0.0);
}

// Two crossing line skeletons combined by PCM (different radii, so the contact surface is
// curved): inside both, their union is the iso-value exactly where their fields are equal.
BlobModel crossing_pair() {
  BlobPrimitive a = cone({-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 2.0, 0.0, 0.3);
  BlobPrimitive b = cone({0.0, -1.0, 0.05}, {0.0, 1.0, 0.0}, 2.0, 0.0, 0.25);
  for (BlobPrimitive* p : {&a, &b}) {
    p->group = 7;
    p->pcm = true;
    p->pcm_width = 0.75 * p->iso_distance;
    p->pcm_peak = 0.15;
  }
  return model_of({a, b});
}

// On the contact surface (f_a = f_b inside both) each deformed member is exactly the
// iso-value; the union keeps the wood there solid through the second largest field.
TEST(BlobTreeReference, PcmContactSurfaceStaysInsideTheWood) {
  BlobModel m = crossing_pair();
  const BlobPrimitive &a = m.primitives[0], &b = m.primitives[1];
  auto diff = [&](const glm::dvec3& q) { return field_of(a, q) - field_of(b, q); };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    // From a point of a's skeleton to one of b's, both inside both members.
    glm::dvec3 lo(0.12 * unit(rng), 0.0, 0.0), hi(0.0, 0.12 * unit(rng), 0.05);
    ASSERT_GT(diff(lo), 0.0);
    ASSERT_LT(diff(hi), 0.0);
    EXPECT_GT(ref::blob_field(m, lo), 0.5);
    for (int i = 0; i < 200; ++i) {
      glm::dvec3 mid = 0.5 * (lo + hi);
      (diff(mid) > 0.0 ? lo : hi) = mid;
    }
    glm::dvec3 contact = 0.5 * (lo + hi);
    ASSERT_GT(field_of(a, contact), 0.5);
    ASSERT_GT(field_of(b, contact), 0.5);
    EXPECT_NEAR(ref::blob_field(m, contact), std::min(field_of(a, contact), field_of(b, contact)), 1e-12);
    EXPECT_GT(ref::blob_field(m, contact), 0.5);
  }
  // Far from b (beyond its surface by more than a's width) a is undeformed; near b's
  // surface, outside it, a swells (the ridge).
  glm::dvec3 far(0.9, 0.0, 0.2);
  EXPECT_EQ(ref::blob_field(m, far), field_of(a, far));
  glm::dvec3 near(0.3, 0.0, 0.0);
  double r = 0.0;
  field_of(b, near, &r);
  r -= b.iso_distance;
  ASSERT_GT(r, 0.0);
  ASSERT_LT(r, a.pcm_width);
  double h = ref::blob_pcm_expansion(r, a.pcm_width, a.pcm_peak, ref::blob_surface_slope(b));
  EXPECT_GT(h, 0.0);
  EXPECT_NEAR(ref::blob_field(m, near), field_of(a, near) + h, 1e-14);
  EXPECT_NEAR(ref::blob_surface_slope(a), 1.7167760537297625 / a.influence, 1e-12);
}

// A primitive that is not PCM is summed on its own even when it shares the group number.
TEST(BlobTreeReference, OnlyPcmPrimitivesJoinTheUnion) {
  BlobModel pair = crossing_pair();
  BlobPrimitive basal = cone({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}, 1.0, 0.1, 0.3);
  basal.group = 7;
  BlobModel m = pair;
  m.primitives.push_back(basal);
  for (glm::dvec3 q :
       {glm::dvec3(0.1, 0.1, 0.0), glm::dvec3(0.0, 0.0, -0.2), glm::dvec3(0.3, 0.0, 0.1)}) {
    EXPECT_NEAR(ref::blob_field(m, q), ref::blob_field(pair, q) + field_of(basal, q), 1e-14);
  }
}

TEST(BlobTreeReference, CutLeavesAFlatFace) {
  BlobPrimitive p = cone({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.0, 0.1, 0.15);
  BlobCut cut;
  cut.point = {0.0, 1.2, 0.0};
  cut.normal = glm::normalize(glm::dvec3(0.2, 1.0, 0.1));
  cut.radius = 1.0;
  cut.ramp = 0.05;
  BlobModel m = model_of({p});
  m.cuts.push_back(cut);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    glm::dvec3 q(0.5 * unit(rng), 1.2 + 0.8 * unit(rng), 0.5 * unit(rng));
    EXPECT_LE(ref::blob_field(m, q), 1.0 - ref::blob_cutter(cut, q));
  }
  for (int k = 0; k < 40; ++k) {
    // Lines through the branch's core, slanted, crossing the cut plane.
    glm::dvec3 lo(0.08 * unit(rng), 0.9, 0.08 * unit(rng));
    glm::dvec3 hi(0.08 * unit(rng), 1.6, 0.08 * unit(rng));
    ASSERT_GT(ref::blob_field(m, lo), 0.5);
    ASSERT_LT(ref::blob_field(m, hi), 0.5);
    for (int i = 0; i < 200; ++i) {
      glm::dvec3 mid = 0.5 * (lo + hi);
      (ref::blob_field(m, mid) > 0.5 ? lo : hi) = mid;
    }
    EXPECT_NEAR(glm::dot(0.5 * (lo + hi) - cut.point, cut.normal), 0.0, 1e-12);
  }
  // Beyond the cutter's ball the branch is whole.
  glm::dvec3 outside = at(p, 1.2, 0.0) + 1.1 * glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
  EXPECT_EQ(ref::blob_cutter(cut, outside), 0.0);
}

TEST(BlobTreeReference, ScarLowersTheField) {
  BlobPrimitive branch = cone({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 2.0, 0.1, 0.2);
  BlobPrimitive scar = cone({0.15, 1.0, 0.0}, {1.0, 0.0, 0.0}, 0.1, 0.0, 0.1);
  scar.weight = -1.0;
  BlobModel whole = model_of({branch}), scarred = model_of({branch, scar});
  for (glm::dvec3 q :
       {glm::dvec3(0.2, 1.0, 0.0), glm::dvec3(0.25, 1.05, 0.02), glm::dvec3(0.3, 1.0, 0.0)}) {
    double s = field_of(scar, q);
    ASSERT_GT(s, 0.0);
    EXPECT_LT(ref::blob_field(scarred, q), ref::blob_field(whole, q));
    EXPECT_NEAR(ref::blob_field(scarred, q), ref::blob_field(whole, q) - s, 1e-14);
  }
  glm::dvec3 away(0.0, 0.3, 0.2);
  EXPECT_EQ(ref::blob_field(scarred, away), ref::blob_field(whole, away));
}

}  // namespace
}  // namespace boreas::test
