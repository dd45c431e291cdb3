// boreas: a spinning LiDAR of a world: its params, its pose, where its sweep stands and the
// points it kept. World::step casts each LiDAR's slice of the sweep after the plants
// moved (cast), and keeps the result only once every LiDAR has cast (commit), so a failed
// cast leaves every LiDAR as it was.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "boreas/boreas.h"
#include "sensors/lidar_params.h"
#include "sensors/lidar_sweep.h"
#include "pose.h"
#include "state_hash.h"

namespace boreas::impl {

// Casts count rays and writes count hits (World::cast_rays; tests pass their own).
using RayCaster = std::function<void(const boreas_ray* rays, int count, boreas_hit* hits)>;

// What one step of one LiDAR saw: its firings, their points, and where each sweep's points
// begin among them.
struct LidarStep {
  Firings firings;
  std::vector<boreas_lidar_point> points;
  std::vector<std::pair<int64_t, size_t>> sweep_begins;  // (sweep, first point), in order
  int rays = 0;
};

class Lidar {
 public:
  // Its first sweep begins at `now` (s, world time).
  Lidar(LidarParams params, double now);

  // The pose reached at the end of the next step (boreas_lidar_set_pose).
  void set_pose(const Pose& pose) { to_ = pose; }

  // The firings in [t0, t1), cast from the poses between the last and the one set. The
  // rays and so the points count from `frame` (the world's output origin: the caster takes
  // rays relative to it, rays/ray_scene.h), the poses moved there in double.
  LidarStep cast(double t0, double t1, const RayCaster& caster, const Vec3d& frame = {}) const;
  void commit(LidarStep step);

  const std::vector<boreas_lidar_point>& last_step() const { return last_step_; }
  const std::vector<boreas_lidar_point>& last_sweep() const { return last_sweep_; }
  boreas_lidar_info info() const;
  const LidarParams& params() const { return params_; }

  // Its state for World::state_hash: the schedule, the poses and the last step's points.
  void hash(StateHash* h) const;

 private:
  LidarParams params_;
  double start_;           // s, world time firing 0 happens
  Pose from_, to_;         // at the start and the end of the next step
  int64_t next_ = 0;       // the first firing not yet cast
  int64_t under_way_ = 0;  // the sweep whose points under_way_points_ gathers
  int64_t sweeps_ = 0;     // complete sweeps
  int last_rays_ = 0;
  std::vector<boreas_lidar_point> last_step_, under_way_points_, last_sweep_;
};

}  // namespace boreas::impl
