// boreas: the kernels' attachment in double, for the generator (rest_frame.h).
#include "trees/rest_frame.h"

namespace boreas::impl {
namespace {

Vec3 bezier_point(const RestCurve& c, double u) {
  const double w = 1.0 - u;
  return c.p[0] * (w * w * w) + c.p[1] * (3.0 * u * w * w) + c.p[2] * (3.0 * u * u * w) +
         c.p[3] * (u * u * u);
}

Vec3 bezier_derivative(const RestCurve& c, double u) {
  const double w = 1.0 - u;
  return (c.p[1] - c.p[0]) * (3.0 * w * w) + (c.p[2] - c.p[1]) * (6.0 * u * w) +
         (c.p[3] - c.p[2]) * (3.0 * u * u);
}

}  // namespace

RestCurve rest_curve(const std::array<Vec3, 4>& p, const Vec3& o) {
  RestCurve c;
  c.p = p;
  c.o = o;
  const Vec3 l0 = unit(p[1] - p[0]), l1 = unit(p[2] - p[1]), l2 = unit(p[3] - p[2]);
  c.s[0] = unit(cross(l0, o));
  c.t[0] = cross(c.s[0], l0);
  c.t[1] = unit(cross(c.s[0], l1));
  c.s[1] = cross(l1, c.t[1]);
  c.t[2] = unit(cross(c.s[1], l2));
  c.s[2] = cross(l2, c.t[2]);
  return c;
}

RestCurve rest_root() {
  return rest_curve({Vec3{0.0, 0.0, 0.0}, Vec3{0.0, 1.0 / 3.0, 0.0}, Vec3{0.0, 2.0 / 3.0, 0.0},
                     Vec3{0.0, 1.0, 0.0}},
                    {1.0, 0.0, 0.0});
}

RestPoint rest_point(const RestCurve& c, double v) {
  const double w = 1.0 - v, q0 = w * w, q1 = 2.0 * v * w, q2 = v * v;
  RestPoint p;
  p.origin = bezier_point(c, v);
  p.s = c.s[0] * q0 + c.s[1] * q1 + c.s[2] * q2;
  p.t = c.t[0] * q0 + c.t[1] * q1 + c.t[2] * q2;
  p.u = unit(bezier_derivative(c, v));
  return p;
}

RestFrame rest_attach(const RestPoint& at, double theta, double alpha) {
  return rest_attach(at, {std::cos(theta), std::sin(theta), std::cos(alpha), std::sin(alpha)});
}

void rest_attach_angles(const RestPoint& at, const Vec3& d, double* theta, double* alpha) {
  const double along = dot(d, at.u);
  const Vec3 across = d - at.u * along;
  *alpha = std::atan2(norm(across), along);
  // e2 = sin(theta) S + cos(theta) T made perpendicular to U: the radial direction whose
  // projection is `across`.
  *theta = norm(across) > 0.0 ? std::atan2(dot(across, at.s), dot(across, at.t)) : 0.0;
}

RestFrame rest_attach_along(const RestPoint& at, const Vec3& d, RestAngles* angles) {
  const double along = dot(d, at.u);
  const Vec3 across = d - at.u * along;
  const double width = norm(across);
  const double reach = std::sqrt(width * width + along * along);
  RestAngles a;
  if (reach > 0.0) {
    a.cos_alpha = along / reach;
    a.sin_alpha = width / reach;
  }
  const double ps = dot(across, at.s), pt = dot(across, at.t), p = std::sqrt(ps * ps + pt * pt);
  if (width > 0.0 && p > 0.0) {
    a.sin_theta = ps / p;
    a.cos_theta = pt / p;
  }
  *angles = a;
  return rest_attach(at, a);
}

RestFrame rest_attach(const RestPoint& at, const RestAngles& a) {
  const Vec3 radial = at.s * a.sin_theta + at.t * a.cos_theta;
  const Vec3 e2 = unit(radial - at.u * dot(radial, at.u));
  RestFrame f;
  f.origin = at.origin;
  f.x = at.u * a.cos_alpha + e2 * a.sin_alpha;
  f.y = e2 * a.cos_alpha - at.u * a.sin_alpha;
  f.z = cross(at.u, e2);
  return f;
}

}  // namespace boreas::impl
