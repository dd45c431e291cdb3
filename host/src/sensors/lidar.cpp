// boreas: a world's spinning LiDAR (lidar.h).
#include "sensors/lidar.h"

#include "errors.h"
#include "sensors/lidar_scan.h"

namespace boreas::impl {

Lidar::Lidar(LidarParams params, double now)
    : params_(std::move(params)), start_(now), from_(params_.pose), to_(params_.pose) {}

LidarStep Lidar::cast(double t0, double t1, const RayCaster& caster, const Vec3d& frame) const {
  LidarStep step;
  step.firings = step_firings(next_, t1, start_, params_);
  const std::vector<boreas_ray> rays =
      lidar_rays(params_, in_frame(from_, frame), in_frame(to_, frame), t0, t1, start_, step.firings);
  std::vector<boreas_hit> hits(rays.size());
  // At most two turns of BOREAS_LIDAR_MAX_RAYS_PER_TURN: within an int.
  step.rays = int(rays.size());
  if (!rays.empty()) caster(rays.data(), step.rays, hits.data());
  const int64_t n = params_.points_per_turn;
  // The points one sweep at a time, so that each sweep's begin is known.
  for (int64_t s = sweep_of(step.firings.first, params_);
       step.firings.count() > 0 && s <= sweep_of(step.firings.end - 1, params_); ++s) {
    const Firings part{std::max(step.firings.first, s * n),
                       std::min(step.firings.end, (s + 1) * n)};
    const size_t skip = size_t(part.first - step.firings.first) * size_t(params_.channels());
    step.sweep_begins.emplace_back(s, step.points.size());
    const std::vector<boreas_lidar_point> points =
        lidar_points(params_, part, rays.data() + skip, hits.data() + skip);
    step.points.insert(step.points.end(), points.begin(), points.end());
  }
  return step;
}

void Lidar::commit(LidarStep step) {
  const int64_t n = params_.points_per_turn;
  for (size_t i = 0; i < step.sweep_begins.size(); ++i) {
    const auto [sweep, begin] = step.sweep_begins[i];
    const size_t end =
        i + 1 < step.sweep_begins.size() ? step.sweep_begins[i + 1].second : step.points.size();
    if (sweep != under_way_) {  // a long step skipped the rest of the sweep under way
      under_way_points_.clear();
      under_way_ = sweep;
    }
    under_way_points_.insert(under_way_points_.end(), step.points.begin() + long(begin),
                             step.points.begin() + long(end));
    if (step.firings.end >= (sweep + 1) * n) {  // its last firing was cast: complete
      last_sweep_ = std::move(under_way_points_);
      under_way_points_.clear();
      under_way_ = sweep + 1;
      sweeps_ = sweep + 1;
    }
  }
  next_ = step.firings.end;
  last_rays_ = step.rays;
  last_step_ = std::move(step.points);
  from_ = to_;
}

boreas_lidar_info Lidar::info() const {
  boreas_lidar_info info{};
  const int64_t n = params_.points_per_turn;
  info.sweep_start = sweeps_ > 0 ? firing_time((sweeps_ - 1) * n, start_, params_) : 0.0;
  info.next_sweep_start = firing_time(under_way_ * n, start_, params_);
  info.sweeps = sweeps_;
  info.firings = next_;
  info.last_step_rays = last_rays_;
  return info;
}

void Lidar::hash(StateHash* h) const {
  h->value(start_);
  h->value(double(next_));
  for (const Pose* p : {&from_, &to_}) {
    for (double c : p->position) h->value(c);
    for (double c : p->rotation) h->value(c);
  }
  // The points without their objects' tags: a tag names the world that issued the id, and
  // equal worlds must hash equal (the index and generation name the object within it).
  std::vector<boreas_lidar_point> points = last_step_;
  for (boreas_lidar_point& p : points) p.object.tag = 0;
  h->values(points);
}

}  // namespace boreas::impl
