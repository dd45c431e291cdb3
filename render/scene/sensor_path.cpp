// boreas scenes: a sensor's pose over time, from its fixed pose or its path of keyframes.
#include <algorithm>
#include <cmath>

#include "boreas/boreas.hpp"
#include "scene/scene_sensors.h"

namespace boreas::render {

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
  // The library's own motion between two poses (a LiDAR's across a step); the keyframes
  // were checked when the scene was read.
  return boreas::pose_between(a.pose, b.pose, float((t - a.t) / (b.t - a.t)));
}

}  // namespace boreas::render
