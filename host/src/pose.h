// boreas: a pose (boreas_pose) as sensors and colliders use it: checked, in double, turning
// the body's axes into the world's, and in between two poses for a body that moves
// during a step.
#pragma once

#include <array>
#include <string>

#include "boreas/boreas.h"

namespace boreas::impl {

using Vec3d = std::array<double, 3>;

struct Pose {
  Vec3d position{0.0, 0.0, 0.0};                       // m
  std::array<double, 4> rotation{0.0, 0.0, 0.0, 1.0};  // unit quaternion x, y, z, w

  // v (in the sensor's axes) in the world's axes.
  Vec3d turn(const Vec3d& v) const;
};

// The pose checked (origin and position within +-BOREAS_WORLD_MAX_COORDINATE, orientation
// finite and of norm within kPoseNormTolerance of 1), its world position origin + position
// in double and its quaternion normalized. Errors name `what`.position[a], `what`.origin[a]
// or `what`.orientation.
Pose checked_pose(const boreas_pose& pose, const std::string& what);

// How far |orientation| may be from 1: a float quaternion written by hand to four
// decimals (0.7071) is well inside; one with a component left out or doubled is not.
inline constexpr double kPoseNormTolerance = 1e-3;

// The pose with its position counted from `frame` (m, world), in double.
Pose in_frame(Pose pose, const Vec3d& frame);

// The pose a fraction s (0..1) of the way from a to b: position linear, orientation
// spherical linear along the shorter arc.
Pose between(const Pose& a, const Pose& b, double s);

}  // namespace boreas::impl
