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

// The Sloan frame's blended handles S(v), T(v) (tree_math.h) and the unit tangent.
void handles(const RestCurve& c, double v, Vec3* s, Vec3* t, Vec3* u) {
  const Vec3 l0 = unit(c.p[1] - c.p[0]), l1 = unit(c.p[2] - c.p[1]), l2 = unit(c.p[3] - c.p[2]);
  const Vec3 s0 = unit(cross(l0, c.o));
  const Vec3 t0 = cross(s0, l0);
  const Vec3 t1 = unit(cross(s0, l1));
  const Vec3 s1 = cross(l1, t1);
  const Vec3 t2 = unit(cross(s1, l2));
  const Vec3 s2 = cross(l2, t2);
  const double w = 1.0 - v, q0 = w * w, q1 = 2.0 * v * w, q2 = v * v;
  *s = s0 * q0 + s1 * q1 + s2 * q2;
  *t = t0 * q0 + t1 * q1 + t2 * q2;
  *u = unit(bezier_derivative(c, v));
}

}  // namespace

Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}

RestCurve rest_root() {
  RestCurve r;
  for (int k = 0; k < 4; ++k) r.p[size_t(k)] = {0.0, double(k) / 3.0, 0.0};
  r.o = {1.0, 0.0, 0.0};
  return r;
}

RestFrame rest_attach(const RestCurve& parent, double v, double theta, double alpha) {
  Vec3 s, t, u;
  handles(parent, v, &s, &t, &u);
  const Vec3 radial = s * std::sin(theta) + t * std::cos(theta);
  const Vec3 e2 = unit(radial - u * dot(radial, u));
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  RestFrame f;
  f.origin = bezier_point(parent, v);
  f.x = u * ca + e2 * sa;
  f.y = e2 * ca - u * sa;
  f.z = cross(u, e2);
  return f;
}

void rest_attach_angles(const RestCurve& parent, double v, const Vec3& d, double* theta,
                        double* alpha) {
  Vec3 s, t, u;
  handles(parent, v, &s, &t, &u);
  const double along = dot(d, u);
  const Vec3 across = d - u * along;
  *alpha = std::atan2(norm(across), along);
  // e2 = sin(theta) S + cos(theta) T made perpendicular to U: the radial direction whose
  // projection is `across`.
  *theta = norm(across) > 0.0 ? std::atan2(dot(across, s), dot(across, t)) : 0.0;
}

}  // namespace boreas::impl
