// boreas: the world's sensors (World's sensor calls and stage 8 of its step, world.h).
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "world.h"

namespace boreas::impl {

boreas_lidar_id World::add_lidar(const boreas_lidar_def& def) {
  return lidars_.insert(Lidar(checked_lidar_def(def), time_));
}

void World::remove_lidar(boreas_lidar_id id) { lidars_.erase(id); }

void World::set_lidar_pose(boreas_lidar_id id, const boreas_pose* pose) {
  Lidar& lidar = lidars_.get(id);
  if (!pose) fail_argument("pose is NULL");
  lidar.set_pose(checked_pose(*pose, "pose"));
}

void World::sense(double t0, double t1) {
  const RayCaster caster = [this](const boreas_ray* rays, int count, boreas_hit* hits) {
    cast_rays(rays, count, hits);
  };
  // Every LiDAR casts before any keeps its points: a failed cast changes none of them.
  std::vector<std::pair<Lidar*, LidarStep>> steps;
  lidars_.for_each([&](Lidar& lidar) {
    steps.emplace_back(&lidar, lidar.cast(t0, t1, caster, output_origin_));
  });
  for (auto& [lidar, step] : steps) lidar->commit(std::move(step));
}

void World::capture_depth(const boreas_depth_camera_def& camera, float* depth,
                          boreas_pixel_label* labels) {
  DepthCamera checked = checked_depth_camera_def(camera);
  checked.pose = in_frame(checked.pose, output_origin_);  // the rays count from it
  impl::capture_depth(
      checked,
      [this](const boreas_ray* rays, int count, boreas_hit* hits) { cast_rays(rays, count, hits); },
      depth, labels);
}

}  // namespace boreas::impl
