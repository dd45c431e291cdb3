// boreas command: the scene's sensors read and written every frame.
#include "cli/sensor_recorder.h"

#include <cstdio>
#include <regex>
#include <stdexcept>

#include "cli/cli_error.h"
#include "cli/frame_files.h"
#include "sensors/depth_files.h"
#include "sensors/point_cloud_files.h"

namespace boreas::render {

namespace fs = std::filesystem;

namespace {

// The folder made and emptied of an earlier run's frame files (they would pass for this
// run's).
void prepare_sensor_folder(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw CliError(kExitFailure, dir.string() + ": cannot create the sensor's folder" +
                                     (error ? ": " + error.message() : ""));
  }
  static const std::regex kFrameName("frame_[0-9]+(\\.ply|\\.pcd|_depth\\.npy|_labels\\.npy)");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrameName)) {
      fs::remove(entry.path());
    }
  }
}

// A file written, its failure (std::runtime_error naming the path) as exit 3.
template <typename Write>
void writing(Write&& write) {
  try {
    write();
  } catch (const std::runtime_error& e) {
    throw CliError(kExitFailure, e.what());
  }
}

}  // namespace

SensorRecorder::SensorRecorder(const Scene& scene, const std::vector<boreas_lidar_id>& lidars,
                               const fs::path& out_dir, int frame_count)
    : sensors_(scene.sensors), lidars_(lidars), frame_count_(frame_count) {
  for (const SceneSensor& s : sensors_) {
    SensorStats stats;
    stats.name = s.name;
    stats.type = s.type == SceneSensor::Type::lidar ? "lidar" : "depth";
    stats.folder = "sensors/" + s.name;
    folders_.push_back(out_dir / "sensors" / s.name);
    prepare_sensor_folder(folders_.back());
    stats_.push_back(stats);
  }
}

void SensorRecorder::record(const boreas::World& world, int index) {
  latest_.clear();
  const std::string base = frame_file(index, frame_count_, "");
  for (size_t i = 0; i < sensors_.size(); ++i) {
    if (sensors_[i].type == SceneSensor::Type::lidar) {
      record_lidar(world, i, base);
    } else {
      record_depth(world, i, base);
    }
    stats_[i].frames += 1;
  }
}

void SensorRecorder::record_lidar(const boreas::World& world, size_t i, const std::string& base) {
  std::vector<boreas_lidar_point> points =
      world.lidar_get_points(lidars_[i], BOREAS_LIDAR_LAST_SWEEP);
  const boreas_lidar_info info = world.lidar_get_info(lidars_[i]);
  // The pose the sensor had when the sweep ended (a moving one's points were each fired
  // from the pose of their own moment).
  const boreas_pose pose = sensor_pose_at(sensors_[i], info.next_sweep_start);
  char sweep[160];
  std::snprintf(sweep, sizeof sweep, "boreas LiDAR %s: sweep %lld from t = %.6f s to %.6f s",
                sensors_[i].name.c_str(), (long long)info.sweeps, info.sweep_start,
                info.next_sweep_start);
  writing([&] {
    write_ply((folders_[i] / (base + ".ply")).string(), points,
              {sweep, "fields: see boreas render/SCENES.md, sensors"});
    write_pcd((folders_[i] / (base + ".pcd")).string(), points, pose);
  });
  stats_[i].frame_points.push_back(int(points.size()));
  stats_[i].frame_sweeps.push_back(info.sweeps);
  latest_.insert(latest_.end(), points.begin(), points.end());
}

void SensorRecorder::record_depth(const boreas::World& world, size_t i, const std::string& base) {
  boreas_depth_camera_def camera = sensors_[i].depth;
  camera.pose = sensor_pose_at(sensors_[i], world.get_time());
  boreas::World::DepthImage image = world.capture_depth(camera);
  writing([&] {
    write_depth_npy((folders_[i] / (base + "_depth.npy")).string(), image.depth, camera.width,
                    camera.height);
    write_labels_npy((folders_[i] / (base + "_labels.npy")).string(), image.labels, camera.width,
                     camera.height);
  });
}

}  // namespace boreas::render
