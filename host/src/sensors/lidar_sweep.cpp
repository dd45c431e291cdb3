// boreas: a spinning LiDAR's firing schedule (lidar_sweep.h).
#include "sensors/lidar_sweep.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

int64_t firings_before(double t, double start, const LidarParams& p) {
  return std::max<int64_t>(0, int64_t(std::ceil((t - start) * p.firing_rate())));
}

Firings step_firings(int64_t next, double t1, double start, const LidarParams& p) {
  Firings f{next, std::max(next, firings_before(t1, start, p))};
  if (f.count() > 0) {
    const int64_t previous_sweep = std::max<int64_t>(0, sweep_of(f.end - 1, p) - 1);
    f.first = std::max(f.first, previous_sweep * p.points_per_turn);
  }
  return f;
}

double firing_time(int64_t k, double start, const LidarParams& p) {
  return start + double(k) / p.firing_rate();
}

double firing_azimuth(int64_t k, const LidarParams& p) {
  return 2.0 * 3.14159265358979323846 * double(k % p.points_per_turn) / p.points_per_turn;
}

double time_in_sweep(int64_t k, const LidarParams& p) {
  return double(k % p.points_per_turn) / p.firing_rate();
}

}  // namespace boreas::impl
