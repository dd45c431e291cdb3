// boreas: a LiDAR's definition as the library keeps it: checked, its vertical angles
// copied (or spread over the field of view), its pose in double.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "pose.h"

namespace boreas::impl {

struct LidarParams {
  std::vector<double> elevations;  // rad, one per channel (ring)
  int points_per_turn = 0;
  double rotation_rate = 0.0;               // Hz
  double min_range = 0.0, max_range = 0.0;  // m
  double range_noise = 0.0;                 // m, standard deviation
  double dropout = 0.0;                     // chance a hit gives no point
  std::array<double, BOREAS_LIDAR_SURFACES> reflectivity{};
  Pose pose;
  uint64_t seed = 0;

  int channels() const { return int(elevations.size()); }
  double firing_rate() const { return rotation_rate * points_per_turn; }  // firings per s
};

boreas_pose default_pose();
boreas_lidar_def default_lidar_def();

// Every field checked (errors name it: "vertical_angles[3] must be ...") before anything
// is kept.
LidarParams checked_lidar_def(const boreas_lidar_def& def);

}  // namespace boreas::impl
