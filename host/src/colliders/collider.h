// boreas: a kinematic collider (boreas_collider_def): a sphere, capsule or oriented box that
// the caller moves, as a physics engine moves its kinematic bodies. Each step it sweeps from
// its pose along its velocity over dt (cl/shared/collider_types.h says what the plants'
// kernels see), then the world moves it there: pose += velocity dt, turned by
// angular_velocity dt. So a collider given a velocity drives on by itself, and a caller that
// sets its pose every step overrides that.
#pragma once

#include <array>
#include <string>

#include "boreas/boreas.h"
#include "pose.h"
#include "shared/collider_types.h"

namespace boreas::impl {

// The def checked (every field named on error, BOREAS_ERROR_INVALID_ARGUMENT), the
// orientation normalized. `what` prefixes the names ("collider_def").
boreas_collider_def checked_collider_def(const boreas_collider_def& def, const std::string& what);

// A world-axis box (min, max), m.
struct Bounds {
  std::array<double, 3> lo{}, hi{};
  bool overlaps(const Bounds& o) const;
};

struct Collider {
  boreas_collider_def def{};  // checked; pose is where the next step starts

  // Where it is: its pose's origin + position, in double (boreas_pose), m.
  Vec3d center() const;
  // What the plants' kernels see over a step of dt (the position in world floats).
  BoreasGpuCollider gpu(double dt) const;
  // The world box holding everything the shape sweeps over a step of dt (its shape at the
  // start and the end of the step, and all between: a translation's sweep is their hull),
  // grown by `margin` m on every side.
  Bounds swept_bounds(double dt, double margin) const;
  // Moves the pose on by the velocities over dt.
  void advance(double dt);
};

// Padding that touches nothing: far away (BOREAS_SILENT_COLLIDER_POSITION), no size.
BoreasGpuCollider silent_collider();

// The unit quaternion q turned by the rotation vector w (rad: axis times angle), w first:
// exp(w / 2) q, in double.
std::array<double, 4> turned(const std::array<double, 4>& q, const std::array<double, 3>& w);

}  // namespace boreas::impl
