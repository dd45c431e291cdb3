// boreas: LiDAR defs, their defaults and their checks (lidar_params.h).
#include "sensors/lidar_params.h"

#include <cmath>
#include <string>

#include "errors.h"
#include "validation.h"

namespace boreas::impl {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The elevations of `channels` rings spread evenly over [lo, hi], ring 0 at lo.
std::vector<double> spread(int channels, double lo, double hi) {
  std::vector<double> out(static_cast<size_t>(channels));
  for (int i = 0; i < channels; ++i)
    out[size_t(i)] = channels == 1 ? 0.5 * (lo + hi) : lo + (hi - lo) * i / (channels - 1);
  return out;
}

std::vector<double> checked_elevations(const boreas_lidar_def& def) {
  if (def.vertical_angles) {
    std::vector<double> out(size_t(def.channels));
    for (int i = 0; i < def.channels; ++i) {
      check_range(def.vertical_angles[i], -kPi / 2, kPi / 2,
                  "vertical_angles[" + std::to_string(i) + "] (rad)");
      out[size_t(i)] = def.vertical_angles[i];
    }
    return out;
  }
  check_range(def.vertical_fov[0], -kPi / 2, kPi / 2, "vertical_fov[0] (rad)");
  check_range(def.vertical_fov[1], -kPi / 2, kPi / 2, "vertical_fov[1] (rad)");
  if (def.vertical_fov[0] > def.vertical_fov[1])
    fail_argument("vertical_fov[0] must not exceed vertical_fov[1] (got " +
                  num(def.vertical_fov[0]) + " > " + num(def.vertical_fov[1]) + " rad)");
  return spread(def.channels, def.vertical_fov[0], def.vertical_fov[1]);
}

}  // namespace

boreas_pose default_pose() {
  boreas_pose p{};
  p.orientation[3] = 1.0f;
  return p;
}

boreas_lidar_def default_lidar_def() {
  boreas_lidar_def d{};
  d.channels = 16;
  d.vertical_fov[0] = float(-15.0 * kPi / 180.0);
  d.vertical_fov[1] = float(15.0 * kPi / 180.0);
  d.points_per_turn = 1800;
  d.rotation_rate = 10.0f;
  d.min_range = 0.5f;
  d.max_range = 100.0f;
  d.range_noise = 0.015f;
  // Near-infrared (905 nm) reflectances, README "Sensors" says where from.
  d.reflectivity[BOREAS_LIDAR_BARK] = 0.35f;
  d.reflectivity[BOREAS_LIDAR_LEAF] = 0.5f;
  d.reflectivity[BOREAS_LIDAR_GRASS] = 0.45f;
  d.reflectivity[BOREAS_LIDAR_GROUND] = 0.3f;
  d.reflectivity[BOREAS_LIDAR_SOLID] = 0.35f;
  d.pose = default_pose();
  d.seed = 1;
  return d;
}

LidarParams checked_lidar_def(const boreas_lidar_def& def) {
  LidarParams p;
  check_count(def.channels, 1, BOREAS_LIDAR_MAX_CHANNELS, "channels");
  p.elevations = checked_elevations(def);
  if (def.points_per_turn < 1)
    fail_argument("points_per_turn must be >= 1 (got " + std::to_string(def.points_per_turn) + ")");
  static_assert(BOREAS_LIDAR_MAX_RAYS_PER_TURN == 1 << 22, "the message spells it 2^22");
  if (int64_t(def.channels) * def.points_per_turn > BOREAS_LIDAR_MAX_RAYS_PER_TURN)
    fail_argument("channels * points_per_turn must be at most 2^22 (got " +
                  std::to_string(def.channels) + " * " + std::to_string(def.points_per_turn) + ")");
  p.points_per_turn = def.points_per_turn;
  check_range(def.rotation_rate, 0.01, 1000.0, "rotation_rate (Hz)");
  p.rotation_rate = def.rotation_rate;
  check_range(def.max_range, 0.0, 1e5, "max_range (m)");
  check_range(def.min_range, 0.0, 1e5, "min_range (m)");
  if (!(def.min_range < def.max_range))
    fail_argument("min_range must be below max_range (got " + num(def.min_range) +
                  " >= " + num(def.max_range) + " m)");
  p.min_range = def.min_range;
  p.max_range = def.max_range;
  check_range(def.range_noise, 0.0, 100.0, "range_noise (m)");
  p.range_noise = def.range_noise;
  check_range(def.dropout, 0.0, 1.0, "dropout");
  p.dropout = def.dropout;
  for (int s = 0; s < BOREAS_LIDAR_SURFACES; ++s) {
    check_range(def.reflectivity[s], 0.0, 1.0, "reflectivity[" + std::to_string(s) + "]");
    p.reflectivity[size_t(s)] = def.reflectivity[s];
  }
  p.pose = checked_pose(def.pose, "pose");
  p.seed = def.seed;
  return p;
}


}  // namespace boreas::impl
