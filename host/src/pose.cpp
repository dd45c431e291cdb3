// boreas: sensor poses (pose.h).
#include "pose.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "validation.h"

namespace boreas::impl {

Vec3d Pose::turn(const Vec3d& v) const {
  const double x = rotation[0], y = rotation[1], z = rotation[2], w = rotation[3];
  // v + 2 w (q x v) + 2 q x (q x v), with q the quaternion's vector part.
  const Vec3d t = {2.0 * (y * v[2] - z * v[1]), 2.0 * (z * v[0] - x * v[2]),
                   2.0 * (x * v[1] - y * v[0])};
  return {v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
          v[2] + w * t[2] + (x * t[1] - y * t[0])};
}

Pose checked_pose(const boreas_pose& pose, const std::string& what) {
  Pose p;
  const std::string position = what + ".position";
  check_position(pose.position, position.c_str());
  double norm2 = 0.0;
  for (int i = 0; i < 4; ++i) {
    check_finite(pose.orientation[i], what + ".orientation[" + std::to_string(i) + "]");
    norm2 += double(pose.orientation[i]) * pose.orientation[i];
  }
  const double norm = std::sqrt(norm2);
  if (std::fabs(norm - 1.0) > kPoseNormTolerance)
    fail_argument(what + ".orientation must be a unit quaternion (x, y, z, w), |q| within " +
                  num(kPoseNormTolerance) + " of 1 (got |q| = " + num(norm) + ")");
  for (int a = 0; a < 3; ++a)
    check_range(pose.origin[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                what + ".origin[" + std::to_string(a) + "]");
  for (int a = 0; a < 3; ++a) p.position[size_t(a)] = pose.origin[a] + double(pose.position[a]);
  for (int i = 0; i < 4; ++i) p.rotation[size_t(i)] = pose.orientation[i] / norm;
  return p;
}

Pose in_frame(Pose pose, const Vec3d& frame) {
  for (size_t a = 0; a < 3; ++a) pose.position[a] -= frame[a];
  return pose;
}

Pose between(const Pose& a, const Pose& b, double s) {
  Pose p;
  for (size_t i = 0; i < 3; ++i)
    p.position[i] = a.position[i] + s * (b.position[i] - a.position[i]);
  double dot = 0.0;
  for (size_t i = 0; i < 4; ++i) dot += a.rotation[i] * b.rotation[i];
  const double sign = dot < 0.0 ? -1.0 : 1.0;  // q and -q are one rotation: take the short way
  dot = std::fabs(dot);
  double wa = 1.0 - s, wb = s;
  if (dot < 1.0 - 1e-12) {
    const double angle = std::acos(std::min(dot, 1.0));
    wa = std::sin((1.0 - s) * angle) / std::sin(angle);
    wb = std::sin(s * angle) / std::sin(angle);
  }
  double norm2 = 0.0;
  for (size_t i = 0; i < 4; ++i) {
    p.rotation[i] = wa * a.rotation[i] + wb * sign * b.rotation[i];
    norm2 += p.rotation[i] * p.rotation[i];
  }
  for (double& c : p.rotation) c /= std::sqrt(norm2);
  return p;
}

}  // namespace boreas::impl
