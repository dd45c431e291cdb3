// boreas: kinematic colliders (collider.h).
#include "colliders/collider.h"

#include "colliders/contacts.h"

#include <cmath>

#include "enum_as_int.h"
#include "errors.h"
#include "validation.h"

namespace boreas::impl {

namespace {

std::string field(const std::string& what, const char* name) { return what + "." + name; }

void check_vector(const float v[3], double limit, const std::string& name) {
  for (int a = 0; a < 3; ++a) check_range(v[a], -limit, limit, name + "[" + std::to_string(a) + "]");
}

}  // namespace

boreas_collider_def checked_collider_def(const boreas_collider_def& def, const std::string& what) {
  boreas_collider_def d = def;
  const int shape = enum_as_int(def.shape);
  if (shape < BOREAS_COLLIDER_SPHERE || shape > BOREAS_COLLIDER_BOX)
    fail_argument(field(what, "shape") + " must be BOREAS_COLLIDER_SPHERE (0), _CAPSULE (1) or " +
                  "_BOX (2) (got " + std::to_string(shape) + ")");
  const Pose pose = checked_pose(def.pose, field(what, "pose"));
  for (int i = 0; i < 4; ++i) d.pose.orientation[i] = float(pose.rotation[size_t(i)]);
  if (shape != BOREAS_COLLIDER_BOX) check_range(def.radius, 1e-3, 1e3, field(what, "radius"));
  if (shape == BOREAS_COLLIDER_CAPSULE)
    check_range(def.half_height, 0.0, 1e3, field(what, "half_height"));
  if (shape == BOREAS_COLLIDER_BOX)
    for (int a = 0; a < 3; ++a)
      check_range(def.half_extents[a], 1e-3, 1e3,
                  field(what, "half_extents") + "[" + std::to_string(a) + "]");
  check_vector(def.velocity, BOREAS_COLLIDER_MAX_SPEED, field(what, "velocity"));
  check_vector(def.angular_velocity, BOREAS_COLLIDER_MAX_SPIN, field(what, "angular_velocity"));
  return d;
}

BoreasGpuCollider silent_collider() {
  BoreasGpuCollider c{};
  c.cx = c.cy = c.cz = BOREAS_SILENT_COLLIDER_POSITION;
  c.ix = c.iy = c.iz = 1e20f;
  c.axx = c.ayy = c.azz = 1.0f;
  return c;
}

bool Bounds::overlaps(const Bounds& o) const {
  for (size_t a = 0; a < 3; ++a)
    if (hi[a] < o.lo[a] || o.hi[a] < lo[a]) return false;
  return true;
}

std::array<double, 4> turned(const std::array<double, 4>& q, const std::array<double, 3>& w) {
  const double angle = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (angle == 0.0) return q;
  const double s = std::sin(0.5 * angle) / angle, c = std::cos(0.5 * angle);
  const double rx = w[0] * s, ry = w[1] * s, rz = w[2] * s;  // r = exp(w / 2); r q
  std::array<double, 4> out = {c * q[0] + rx * q[3] + ry * q[2] - rz * q[1],
                               c * q[1] + ry * q[3] + rz * q[0] - rx * q[2],
                               c * q[2] + rz * q[3] + rx * q[1] - ry * q[0],
                               c * q[3] - rx * q[0] - ry * q[1] - rz * q[2]};
  double norm = 0.0;
  for (double v : out) norm += v * v;
  for (double& v : out) v /= std::sqrt(norm);
  return out;
}

namespace {

struct Shape {
  Pose pose;                      // the orientation at the middle of the step
  std::array<double, 3> half{};   // the box's half extents
  double radius = 0.0;
};

Shape shape_over_step(const boreas_collider_def& def, double dt) {
  Shape s;
  for (size_t a = 0; a < 3; ++a) s.pose.position[a] = def.pose.origin[a] + double(def.pose.position[a]);
  std::array<double, 4> q;
  for (size_t i = 0; i < 4; ++i) q[i] = def.pose.orientation[i];
  const std::array<double, 3> half_turn = {0.5 * dt * def.angular_velocity[0],
                                           0.5 * dt * def.angular_velocity[1],
                                           0.5 * dt * def.angular_velocity[2]};
  s.pose.rotation = turned(q, half_turn);
  switch (enum_as_int(def.shape)) {
    case BOREAS_COLLIDER_SPHERE:
      s.radius = def.radius;
      break;
    case BOREAS_COLLIDER_CAPSULE:
      s.radius = def.radius;
      s.half = {0.0, double(def.half_height), 0.0};
      break;
    default:
      s.half = {double(def.half_extents[0]), double(def.half_extents[1]),
                double(def.half_extents[2])};
  }
  return s;
}

}  // namespace

Vec3d Collider::center() const {
  return {def.pose.origin[0] + double(def.pose.position[0]),
          def.pose.origin[1] + double(def.pose.position[1]),
          def.pose.origin[2] + double(def.pose.position[2])};
}

BoreasGpuCollider Collider::gpu(double dt) const {
  const Shape s = shape_over_step(def, dt);
  const Vec3d axes[3] = {s.pose.turn({1, 0, 0}), s.pose.turn({0, 1, 0}), s.pose.turn({0, 0, 1})};
  const Vec3d d = {def.velocity[0] * dt, def.velocity[1] * dt, def.velocity[2] * dt};
  double local[3], inv[3];
  for (int i = 0; i < 3; ++i) {
    local[i] = d[0] * axes[i][0] + d[1] * axes[i][1] + d[2] * axes[i][2];
    // A move below a nanometre along an axis is none (collider_types.h).
    inv[i] = std::fabs(local[i]) < 1e-9 ? 1e20 : 1.0 / local[i];
    if (std::fabs(local[i]) < 1e-9) local[i] = 0.0;
  }
  BoreasGpuCollider g{};
  g.cx = float(s.pose.position[0]);
  g.cy = float(s.pose.position[1]);
  g.cz = float(s.pose.position[2]);
  g.radius = float(s.radius);
  g.dx = float(d[0]);
  g.dy = float(d[1]);
  g.dz = float(d[2]);
  g.lx = float(local[0]);
  g.ly = float(local[1]);
  g.lz = float(local[2]);
  g.ix = float(inv[0]);
  g.iy = float(inv[1]);
  g.iz = float(inv[2]);
  g.axx = float(axes[0][0]), g.axy = float(axes[0][1]), g.axz = float(axes[0][2]);
  g.ayx = float(axes[1][0]), g.ayy = float(axes[1][1]), g.ayz = float(axes[1][2]);
  g.azx = float(axes[2][0]), g.azy = float(axes[2][1]), g.azz = float(axes[2][2]);
  g.hx = float(s.half[0]), g.hy = float(s.half[1]), g.hz = float(s.half[2]);
  return g;
}

Bounds Collider::swept_bounds(double dt, double margin) const {
  const Shape s = shape_over_step(def, dt);
  const Vec3d axes[3] = {s.pose.turn({1, 0, 0}), s.pose.turn({0, 1, 0}), s.pose.turn({0, 0, 1})};
  Bounds b;
  for (size_t w = 0; w < 3; ++w) {
    double extent = s.radius + margin;
    for (size_t i = 0; i < 3; ++i) extent += std::fabs(axes[i][w]) * s.half[i];
    const double start = s.pose.position[w], end = start + def.velocity[w] * dt;
    b.lo[w] = std::min(start, end) - extent;
    b.hi[w] = std::max(start, end) + extent;
  }
  return b;
}

void Collider::advance(double dt) {
  std::array<double, 4> q;
  for (size_t i = 0; i < 4; ++i) q[i] = def.pose.orientation[i];
  q = turned(q, {dt * def.angular_velocity[0], dt * def.angular_velocity[1],
                 dt * def.angular_velocity[2]});
  for (int i = 0; i < 4; ++i) def.pose.orientation[i] = float(q[size_t(i)]);
  // The position moves from its origin, which stays: as precise far out as near 0.
  for (int a = 0; a < 3; ++a)
    def.pose.position[a] = float(double(def.pose.position[a]) + double(def.velocity[a]) * dt);
}

void StepColliders::add(const Collider& c) {
  gpu.push_back(c.gpu(dt));
  bounds.push_back(c.swept_bounds(dt, 0.0));
  centers.push_back(c.center());
}

BoreasGpuCollider StepColliders::relative(int c, const std::array<double, 3>& origin) const {
  BoreasGpuCollider r = gpu[size_t(c)];
  const std::array<double, 3>& at = centers[size_t(c)];
  r.cx = float(at[0] - origin[0]);
  r.cy = float(at[1] - origin[1]);
  r.cz = float(at[2] - origin[2]);
  return r;
}

std::vector<int> StepColliders::touching(const Bounds& b, double margin) const {
  std::vector<int> out;
  for (size_t i = 0; i < bounds.size(); ++i) {
    Bounds grown = bounds[i];
    for (size_t a = 0; a < 3; ++a) {
      grown.lo[a] -= margin;
      grown.hi[a] += margin;
    }
    if (grown.overlaps(b)) out.push_back(int(i));
  }
  return out;
}

}  // namespace boreas::impl
