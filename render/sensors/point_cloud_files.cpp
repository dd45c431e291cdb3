// boreas command: PLY and PCD writers for LiDAR points (the record is in the header).
#include "sensors/point_cloud_files.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace boreas::render {

namespace {

// Appends v's bytes, little-endian (the only byte order boreas runs on, checked below).
template <typename T>
unsigned char* put(unsigned char* out, T v) {
  std::memcpy(out, &v, sizeof v);
  return out + sizeof v;
}

static_assert(sizeof(float) == 4, "float32 records");

bool little_endian() {
  const uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

void write_file(const std::string& path, const std::string& header,
                const std::vector<unsigned char>& body) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(header.data(), std::streamsize(header.size()));
  out.write(reinterpret_cast<const char*>(body.data()), std::streamsize(body.size()));
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the point cloud");
}

}  // namespace

std::vector<unsigned char> pack_points(const std::vector<boreas_lidar_point>& points) {
  if (!little_endian())
    throw std::runtime_error("point clouds: a big-endian host is not supported");
  std::vector<unsigned char> bytes(points.size() * kPointRecordBytes);
  unsigned char* out = bytes.data();
  for (const boreas_lidar_point& p : points) {
    out = put(out, p.x);
    out = put(out, p.y);
    out = put(out, p.z);
    out = put(out, p.intensity);
    out = put(out, p.ring);
    out = put(out, p.time);
    out = put(out, uint8_t(p.kind));
    out = put(out, p.object.index);
    out = put(out, p.part);
  }
  return bytes;
}

void write_ply(const std::string& path, const std::vector<boreas_lidar_point>& points,
               const std::vector<std::string>& comments) {
  std::ostringstream h;
  h << "ply\nformat binary_little_endian 1.0\n";
  for (const std::string& c : comments) h << "comment " << c << "\n";
  h << "element vertex " << points.size() << "\n"
    << "property float x\nproperty float y\nproperty float z\nproperty float intensity\n"
    << "property ushort ring\nproperty float time\nproperty uchar kind\n"
    << "property uint object\nproperty int part\nend_header\n";
  write_file(path, h.str(), pack_points(points));
}

void write_pcd(const std::string& path, const std::vector<boreas_lidar_point>& points,
               const boreas_pose& viewpoint) {
  const float* p = viewpoint.position;
  const float* q = viewpoint.orientation;
  std::ostringstream h;
  h.precision(9);
  h << "# .PCD v0.7 - Point Cloud Data file format (boreas LiDAR sweep)\n"
    << "VERSION 0.7\n"
    << "FIELDS x y z intensity ring time kind object part\n"
    << "SIZE 4 4 4 4 2 4 1 4 4\n"
    << "TYPE F F F F U F U U I\n"
    << "COUNT 1 1 1 1 1 1 1 1 1\n"
    << "WIDTH " << points.size() << "\nHEIGHT 1\n"
    << "VIEWPOINT " << p[0] << " " << p[1] << " " << p[2] << " " << q[3] << " " << q[0] << " "
    << q[1] << " " << q[2] << "\n"
    << "POINTS " << points.size() << "\nDATA binary\n";
  write_file(path, h.str(), pack_points(points));
}

}  // namespace boreas::render
