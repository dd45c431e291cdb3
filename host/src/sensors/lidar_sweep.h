// boreas: when a spinning LiDAR fires. Firing k (0, 1, ...) of a LiDAR whose sweeps began
// at `start` happens at start + k / (rotation_rate * points_per_turn) and sends one ray per
// channel at azimuth 2 pi (k mod points_per_turn) / points_per_turn; it belongs to sweep
// k / points_per_turn. A step from t0 to t1 casts the firings whose times fall in
// [t0, t1), so consecutive steps cast every firing exactly once however they cut time.
#pragma once

#include <cstdint>

#include "sensors/lidar_params.h"

namespace boreas::impl {

// Firings [first, end).
struct Firings {
  int64_t first = 0, end = 0;
  int64_t count() const { return end - first; }
};

// The number of firings that happen before time t (firing k happens before t when
// start + k / rate < t).
int64_t firings_before(double t, double start, const LidarParams& p);

// The firings a step that ends at t1 casts when `next` is the first not yet cast: those
// before t1, but of a step longer than a turn only the last complete sweep's and the
// one under way (the others could never be read: boreas_lidar_get_points keeps one sweep).
Firings step_firings(int64_t next, double t1, double start, const LidarParams& p);

// Firing k's time (s, world), azimuth (rad), sweep and time since its sweep began (s).
double firing_time(int64_t k, double start, const LidarParams& p);
double firing_azimuth(int64_t k, const LidarParams& p);
inline int64_t sweep_of(int64_t k, const LidarParams& p) { return k / p.points_per_turn; }
double time_in_sweep(int64_t k, const LidarParams& p);

}  // namespace boreas::impl
