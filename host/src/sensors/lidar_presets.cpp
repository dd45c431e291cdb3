// boreas: common spinning LiDARs (lidar_presets.h). Each table is typed as its maker
// lists it, laser id by laser id, in degrees; the preset hands them out sorted from the
// lowest to the highest, so ring 0 is the lowest beam, as the ROS velodyne driver numbers
// its rings.
#include "sensors/lidar_presets.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "errors.h"
#include "sensors/lidar_params.h"

namespace boreas::impl {

namespace {

// Velodyne, "VLP-16 User Manual" (63-9243), the table of vertical angles by laser id:
// -15 to +15 degrees, 2 degrees apart, interleaved.
const std::vector<double> kVlp16 = {-15, 1, -13, 3, -11, 5, -9, 7, -7, 9, -5, 11, -3, 13, -1, 15};

// Velodyne, "HDL-32E User's Manual" (63-9113), the table of vertical angles by laser id:
// -30.67 to +10.67 degrees, 1.33 apart, interleaved.
const std::vector<double> kHdl32e = {-30.67, -9.33, -29.33, -8.00, -28.00, -6.67, -26.67, -5.33,
                                     -25.33, -4.00, -24.00, -2.67, -22.67, -1.33, -21.33, 0.00,
                                     -20.00, 1.33,  -18.67, 2.67,  -17.33, 4.00,  -16.00, 5.33,
                                     -14.67, 6.67,  -13.33, 8.00,  -12.00, 9.33,  -10.67, 10.67};

// Velodyne, "HDL-64E S3 User's Manual and Programming Guide" (63-HDL64ES3): an upper block
// of 32 lasers from +2 degrees down at 1/3 degree and a lower block of 32 from -8.83 down
// at 1/2 degree, which ends at -24.33. The data sheet's field of view (+2 to -24.9) is a
// calibrated unit's: the lower block's lasers spread a little wider than the nominal half
// degree. These are the nominal angles: every HDL-64E ships with its own calibration file
// (db.xml); pass its vertCorrection angles as vertical_angles to model one unit.
std::vector<double> hdl64e() {
  std::vector<double> out;
  for (int i = 0; i < 32; ++i) out.push_back(std::round((2.0 - i / 3.0) * 100.0) / 100.0);
  for (int i = 0; i < 32; ++i) out.push_back(-8.83 - 0.5 * i);
  return out;
}

// Ouster, "OS1 Mid-Range High-Resolution Imaging Lidar" data sheet (Rev 7), 128 channels
// with uniform beam spacing over a 45 degree vertical field of view (+22.5 to -22.5),
// listed from the top beam (channel 0) down. Nominal: each unit reports its calibrated
// beam_altitude_angles in its metadata.
std::vector<double> os1_128() {
  std::vector<double> out;
  for (int i = 0; i < 128; ++i) out.push_back(22.5 - 45.0 * i / 127.0);
  return out;
}

struct Preset {
  const char* name;
  const std::vector<double>* table;  // degrees, the maker's order
  int points_per_turn;               // at rate_hz
  float rate_hz;
  float max_range;    // m
  float range_noise;  // m: the data sheet's accuracy taken as two sigma
};

// Points per turn at 10 Hz: VLP-16 0.2 degrees (1800); HDL-32E a firing each 46.08 us
// (2170); HDL-64E S3 0.1728 degrees (2083); OS1 its 1024 x 10 mode. Ranges and accuracies
// as the data sheets state them: VLP-16 100 m, +-3 cm; HDL-32E 100 m, +-2 cm; HDL-64E
// 120 m, +-2 cm; OS1-128 120 m, +-3 cm.
const std::vector<Preset>& presets() {
  static const std::vector<double> kHdl64e = hdl64e();
  static const std::vector<double> kOs1 = os1_128();
  static const std::vector<Preset> all = {
      {"VLP-16", &kVlp16, 1800, 10.0f, 100.0f, 0.015f},
      {"HDL-32E", &kHdl32e, 2170, 10.0f, 100.0f, 0.01f},
      {"HDL-64E", &kHdl64e, 2083, 10.0f, 120.0f, 0.01f},
      {"OS1-128", &kOs1, 1024, 10.0f, 120.0f, 0.015f},
  };
  return all;
}

// Every preset's angles in radians, lowest first, built once (a thread-safe static) and
// kept for the process's life: the defs point into them.
const std::vector<float>& sorted_radians(const Preset& p) {
  static const std::vector<std::vector<float>> all = [] {
    std::vector<std::vector<float>> out;
    for (const Preset& each : presets()) {
      std::vector<float> angles;
      for (double d : *each.table) angles.push_back(float(d * 3.14159265358979323846 / 180.0));
      std::sort(angles.begin(), angles.end());
      out.push_back(std::move(angles));
    }
    return out;
  }();
  return all[size_t(&p - presets().data())];
}

bool same_name(const std::string& a, const char* b) {
  const std::string bs(b);
  return a.size() == bs.size() && std::equal(a.begin(), a.end(), bs.begin(), [](char x, char y) {
           return std::tolower((unsigned char)x) == std::tolower((unsigned char)y);
         });
}

const Preset& find(const std::string& name) {
  for (const Preset& p : presets())
    if (same_name(name, p.name)) return p;
  std::string known;
  for (const Preset& p : presets()) known += (known.empty() ? "" : ", ") + std::string(p.name);
  fail_argument("no LiDAR preset named \"" + name + "\" (known: " + known + ")");
}

}  // namespace

boreas_lidar_def lidar_preset(const std::string& name) {
  const Preset& p = find(name);
  boreas_lidar_def d = default_lidar_def();
  const std::vector<float>& angles = sorted_radians(p);
  d.channels = int(angles.size());
  d.vertical_angles = angles.data();
  d.vertical_fov[0] = angles.front();  // the span, for a def that spreads its own channels
  d.vertical_fov[1] = angles.back();
  d.points_per_turn = p.points_per_turn;
  d.rotation_rate = p.rate_hz;
  d.max_range = p.max_range;
  d.range_noise = p.range_noise;
  return d;
}

const char* lidar_preset_name(int index) {
  return index >= 0 && size_t(index) < presets().size() ? presets()[size_t(index)].name : nullptr;
}

const std::vector<double>& lidar_preset_table_degrees(const std::string& name) {
  return *find(name).table;
}

}  // namespace boreas::impl
