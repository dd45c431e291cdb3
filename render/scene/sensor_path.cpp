// boreas scenes: a sensor's pose over time, from its fixed pose or its path of keyframes.
#include <algorithm>
#include <cmath>

#include "scene/scene_sensors.h"

namespace boreas::render {

namespace {

// Spherical linear interpolation of unit quaternions, along the shorter arc.
void slerp(const float a[4], const float b[4], double s, float out[4]) {
  double dot = 0.0;
  for (int i = 0; i < 4; ++i) dot += double(a[i]) * b[i];
  const double sign = dot < 0.0 ? -1.0 : 1.0;
  dot *= sign;
  double wa = 1.0 - s, wb = s * sign;
  // Nearly equal orientations: the linear blend is exact to float precision and avoids
  // dividing by a vanishing sine.
  if (dot < 0.9995) {
    const double angle = std::acos(dot);
    wa = std::sin((1.0 - s) * angle) / std::sin(angle);
    wb = std::sin(s * angle) / std::sin(angle) * sign;
  }
  double q[4], norm = 0.0;
  for (int i = 0; i < 4; ++i) {
    q[i] = wa * a[i] + wb * b[i];
    norm += q[i] * q[i];
  }
  norm = std::sqrt(norm);
  for (int i = 0; i < 4; ++i) out[i] = float(q[i] / norm);
}

}  // namespace

void heading_pitch_quaternion(double heading, double pitch, float out[4]) {
  // (turn about +Y by heading) * (turn about +X by pitch), as x, y, z, w.
  const double sh = std::sin(heading / 2), ch = std::cos(heading / 2);
  const double sp = std::sin(pitch / 2), cp = std::cos(pitch / 2);
  out[0] = float(ch * sp);
  out[1] = float(sh * cp);
  out[2] = float(-sh * sp);
  out[3] = float(ch * cp);
}

boreas_pose sensor_pose_at(const SceneSensor& sensor, double t) {
  const std::vector<SensorKeyframe>& path = sensor.path;
  if (path.empty()) return sensor.pose;
  if (t <= path.front().t) return path.front().pose;
  if (t >= path.back().t) return path.back().pose;
  auto next = std::upper_bound(path.begin(), path.end(), t,
                               [](double time, const SensorKeyframe& k) { return time < k.t; });
  const SensorKeyframe& b = *next;
  const SensorKeyframe& a = *(next - 1);
  const double s = (t - a.t) / (b.t - a.t);
  boreas_pose pose;
  for (int i = 0; i < 3; ++i) {
    pose.position[i] = float(double(a.pose.position[i]) +
                             s * (double(b.pose.position[i]) - double(a.pose.position[i])));
  }
  slerp(a.pose.orientation, b.pose.orientation, s, pose.orientation);
  return pose;
}

}  // namespace boreas::render
