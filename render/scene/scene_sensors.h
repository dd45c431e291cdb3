// boreas scenes: the sensors a scene carries (its "sensors" array): spinning LiDARs and
// depth cameras, each standing at a pose or driven along a path of timed poses, as a
// vehicle carries them. render/SCENES.md lists the keys; `boreas run` writes what they see.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// Sensors in one scene: each writes files every frame, so a few are plenty.
constexpr int kMaxSensors = 64;
// Keyframes of one sensor's path.
constexpr int kMaxPathKeyframes = 100000;

// Where a sensor is at time t of a path (s, world time).
struct SensorKeyframe {
  double t = 0.0;
  boreas_pose pose = boreas_default_pose();
};

struct SceneSensor {
  enum class Type { lidar, depth };
  Type type = Type::lidar;
  // Its folder under the run's sensors/ ("lidar0", "depth1", ... by default: type and index).
  std::string name;
  // lidar: the def (a preset's or the library's defaults, with the scene's fields over it).
  // Its vertical_angles point into `angles` when the scene lists them, else into the
  // preset's table; SceneSensor::def() gives a def with the pointer set.
  boreas_lidar_def lidar = boreas_default_lidar_def();
  std::vector<float> angles;  // rad: the scene's own channel angles (empty: none given)
  std::string preset;         // "" for none
  // depth: the camera's def; its pose is replaced frame by frame from the path.
  boreas_depth_camera_def depth = boreas_default_depth_camera_def();
  // The pose it stands at (used when path is empty) and the path, in increasing t.
  boreas_pose pose = boreas_default_pose();
  std::vector<SensorKeyframe> path;

  // The LiDAR's def ready to add: vertical_angles pointing at this sensor's angles.
  boreas_lidar_def lidar_def() const {
    boreas_lidar_def d = lidar;
    if (!angles.empty()) d.vertical_angles = angles.data();
    return d;
  }
};

// The sensor's pose at world time t (s): its fixed pose, or its path's keyframes
// interpolated (position linearly, orientation by spherical linear interpolation), held
// at the first before it begins and at the last after it ends.
boreas_pose sensor_pose_at(const SceneSensor& sensor, double t);

// The unit quaternion (x, y, z, w) of a heading (rad, a turn about +Y: counter-clockwise
// seen from above, so a heading h turns local +X to (cos h, 0, -sin h)) followed by a pitch
// (rad, a turn about the turned local +X: positive looks up).
void heading_pitch_quaternion(double heading, double pitch, float out[4]);

}  // namespace boreas::render
