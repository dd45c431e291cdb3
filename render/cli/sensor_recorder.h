// boreas command: what the scene's sensors see, written every frame of `boreas run` under
// <out>/sensors/<name>/ (render/SCENES.md, "sensors"):
//   LiDAR         frame_NNNN.ply and frame_NNNN.pcd: the last complete sweep as of the
//                 frame's end (sensors/point_cloud_files.h); empty before the first sweep
//                 completes, and the same sweep again when a frame is shorter than a turn
//                 (the PLY's comments name the sweep)
//   depth camera  frame_NNNN_depth.npy and frame_NNNN_labels.npy, captured at the frame's
//                 end from the camera's pose then (sensors/depth_files.h)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "scene/scene.h"

namespace boreas::render {

// What summary.json says about one sensor.
struct SensorStats {
  std::string name;
  std::string type;                   // "lidar" or "depth"
  std::string folder;                 // relative to the output folder
  std::vector<int> frame_points;      // LiDAR: the points in each frame's files
  std::vector<int64_t> frame_sweeps;  // LiDAR: the sweep each frame's files hold (1: the first)
  int frames = 0;                     // frames written
};

class SensorRecorder {
 public:
  // Makes <out_dir>/sensors/<name>/ for each of the scene's sensors and removes frame files
  // an earlier run left there. lidars: SceneIds::lidars. Throws CliError (exit 3).
  SensorRecorder(const Scene& scene, const std::vector<boreas_lidar_id>& lidars,
                 const std::filesystem::path& out_dir, int frame_count);

  bool empty() const { return sensors_.empty(); }

  // Reads every sensor as of the world's last step and writes frame `index`'s files.
  void record(const boreas::World& world, int index);

  // The sweeps the last record() wrote, every LiDAR's together (for --view lidar).
  const std::vector<boreas_lidar_point>& latest_points() const { return latest_; }
  const std::vector<SensorStats>& stats() const { return stats_; }

 private:
  void record_lidar(const boreas::World& world, size_t i, const std::string& base);
  void record_depth(const boreas::World& world, size_t i, const std::string& base);

  const std::vector<SceneSensor>& sensors_;
  std::vector<boreas_lidar_id> lidars_;
  std::vector<std::filesystem::path> folders_;
  int frame_count_ = 1;
  std::vector<boreas_lidar_point> latest_;
  std::vector<SensorStats> stats_;
};

}  // namespace boreas::render
