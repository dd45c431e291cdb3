// boreas command: LiDAR points as files other tools read: binary little-endian PLY
// (numpy, CloudCompare, Open3D, MeshLab) and binary PCD (PCL, Open3D, ROS's pcl_ros).
// Both hold the same packed record per point, in the order the LiDAR fired them:
//   x, y, z    float32  m, world frame
//   intensity  float32  0..1
//   ring       uint16   the channel
//   time       float32  s since the sweep began
//   kind       uint8    boreas_hit_kind (1 branch, 2 leaf, 3 mesh trunk, 4 mesh leaf,
//                       5 underbrush, 6 BlobTree, 7 ground, 8 solid box)
//   object     uint32   the index of the object's id (boreas_object_id.index)
//   part       int32    which part of it (boreas_hit.part)
// 31 bytes a point; the header says the count.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// Bytes of one point's record in both files.
constexpr int kPointRecordBytes = 31;

// The packed little-endian records of the points, kPointRecordBytes each.
std::vector<unsigned char> pack_points(const std::vector<boreas_lidar_point>& points);

// Writes a PLY (format binary_little_endian 1.0, one element "vertex") with the comment
// lines given (each a line of text without newlines). Throws std::runtime_error naming
// the path when the file cannot be written.
void write_ply(const std::string& path, const std::vector<boreas_lidar_point>& points,
               const std::vector<std::string>& comments);

// Writes a PCD v0.7 with DATA binary, VIEWPOINT the sensor's pose (position, then the
// orientation as w, x, y, z, PCD's order). Throws std::runtime_error naming the path.
void write_pcd(const std::string& path, const std::vector<boreas_lidar_point>& points,
               const boreas_pose& viewpoint);

}  // namespace boreas::render
