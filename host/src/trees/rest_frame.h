// boreas: where a grown tree's stems lie at rest — the kernels' attachment (Skjermo 2007
// sec. 4.2, cl/shared/tree_math.h) in double, for the generator. Weber-Penn's rules that
// look at the world need it: AttractionUp turns stems toward "up", pruning keeps them in an
// envelope around the trunk, splits turn clones about the vertical and LeafBend turns leaves
// toward the light; a stem grown in its own frame knows none of these until it is placed.
//
// The same equations as the kernels (Sloan frame, blended handles, attachment), so the rest
// state the kernels build from the model is this one up to float rounding; tests compare
// against the independent reference in host/src/reference.
#pragma once

#include <array>
#include <cmath>

namespace boreas::impl {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 operator*(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
// a / |a|, or zero for a zero vector (as the kernels' normalize).
inline Vec3 unit(const Vec3& a) {
  const double l = norm(a);
  return l > 0.0 ? a * (1.0 / l) : Vec3{0.0, 0.0, 0.0};
}
// Rodrigues: v turned about the unit axis by the angle whose cosine and sine are c, s (a
// frame's three axes turn by one angle: one sincos).
inline Vec3 rotate(const Vec3& v, const Vec3& axis, double c, double s) {
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}
// ... by angle (radians).
inline Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {
  return rotate(v, axis, std::cos(angle), std::sin(angle));
}

inline constexpr Vec3 kUp{0.0, 1.0, 0.0};

// A branch at rest: its world control points, the orientation vector O its Sloan frame
// starts from, and that frame's handles S0..S2, T0..T2 (eq. 8), computed once by
// rest_curve() for every child and leaf attached to it.
struct RestCurve {
  std::array<Vec3, 4> p{};
  Vec3 o{1.0, 0.0, 0.0};
  std::array<Vec3, 3> s{}, t{};
};
RestCurve rest_curve(const std::array<Vec3, 4>& p, const Vec3& o);

// A child's frame on its parent: origin on the parent's curve, x along the child's first
// segment, y in the plane of the parent's tangent and the child, z = x cross y.
struct RestFrame {
  Vec3 origin{}, x{}, y{}, z{};
};

// The root a tree's trunks hang from: the vertical unit segment at the origin, O along +x
// (tree_layout.h).
RestCurve rest_root();

// A curve's point at Bezier parameter v with the Sloan frame's blended handles S(v), T(v)
// and the unit tangent there: what every attachment at v shares.
struct RestPoint {
  Vec3 origin{}, s{}, t{}, u{};
};
RestPoint rest_point(const RestCurve& c, double v);

// The child at `at`, theta around the parent, alpha down from its tangent.
RestFrame rest_attach(const RestPoint& at, double theta, double alpha);
inline RestFrame rest_attach(const RestCurve& parent, double v, double theta, double alpha) {
  return rest_attach(rest_point(parent, v), theta, alpha);
}

// The (theta, alpha) at which a child at `at` starts along the unit direction d: exact at
// v = 0 and 1 (where the blended handles are perpendicular to the tangent), within their
// small tilt between.
void rest_attach_angles(const RestPoint& at, const Vec3& d, double* theta, double* alpha);
// The cosines and sines of those angles, taken from the projections of d (ratios, no libm
// call), and the frame rest_attach gives them: the same to rounding.
struct RestAngles {
  double cos_theta = 1.0, sin_theta = 0.0, cos_alpha = 1.0, sin_alpha = 0.0;
};
RestFrame rest_attach_along(const RestPoint& at, const Vec3& d, RestAngles* angles);
// rest_attach for angles given as cosines and sines.
RestFrame rest_attach(const RestPoint& at, const RestAngles& angles);

// A point in a frame's coordinates to the world, and back.
inline Vec3 rest_place(const RestFrame& f, const Vec3& local) {
  return f.origin + f.x * local[0] + f.y * local[1] + f.z * local[2];
}
inline Vec3 rest_local(const RestFrame& f, const Vec3& world) {
  const Vec3 d = world - f.origin;
  return {dot(d, f.x), dot(d, f.y), dot(d, f.z)};
}

}  // namespace boreas::impl
