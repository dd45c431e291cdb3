// render tests: the scene's "sensors" (scene_sensors.h) read and checked, their paths
// interpolated, and `boreas run` writing what they see: PLY and PCD sweeps equal to the
// library's own sweep of the same scene, depth images of flat ground equal to the analytic
// depth, and --view lidar drawing the points over the frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command_runner.h"
#include "png_reader.h"
#include "scene/scene_loader.h"
#include "scene/scene_world.h"
#include "scene_error_for.h"
#include "sensors/point_cloud_files.h"
#include "test_scenes.h"
#include "view/lidar_overlay.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

std::string sensor_scene(const std::string& sensors, int frames = 2) {
  return scene_with(R"({"waves": [{"direction": [1, 0], "amplitude": 6, "wavelength": 30,
                                  "speed": 10, "sharpness": 1}]})",
                    R"("trees": [{"species": "quaking_aspen", "position": [4, 0, 0], "seed": 4}],
  "meadows": [{"center": [0, 0, 0], "size": [24, 24], "density": 0}],
  "sensors": )" + sensors,
                    frames);
}

// A 16-channel LiDAR driven along +x 2 m above the ground, past the aspen.
const char* kDrivenLidar = R"([{"type": "lidar", "name": "roof", "preset": "VLP-16",
  "points_per_turn": 360, "path": [{"t": 0, "position": [-6, 2, 0], "heading_deg": 0},
                                   {"t": 2, "position": [4, 2, 0], "heading_deg": 0}]}])";

TEST(SceneSensors, ReadsALidarPresetOnAPathAndADepthCamera) {
  Scene s = load_scene_text(sensor_scene(R"([
    {"type": "lidar", "preset": "HDL-32E", "max_range": 50,
     "path": [{"t": 0, "position": [0, 2, 0]}, {"t": 4, "position": [20, 2, 0], "heading_deg": 90}]},
    {"type": "depth", "name": "front", "width": 40, "height": 30, "fov_deg": 90,
     "pose": {"position": [0, 3, 0], "pitch_deg": -90}}])"),
                            "s.json");
  ASSERT_EQ(s.sensors.size(), 2u);
  const SceneSensor& lidar = s.sensors[0];
  EXPECT_EQ(lidar.name, "lidar0");
  EXPECT_EQ(lidar.lidar.channels, 32);
  EXPECT_FLOAT_EQ(lidar.lidar.max_range, 50.0f);
  ASSERT_EQ(lidar.path.size(), 2u);
  EXPECT_FLOAT_EQ(lidar.lidar.pose.position[1], 2.0f);
  const SceneSensor& camera = s.sensors[1];
  EXPECT_EQ(camera.name, "front");
  // 90 degrees over 30 rows: f = 15 / tan(45 degrees).
  EXPECT_NEAR(camera.depth.fx, 15.0, 1e-4);
  EXPECT_NEAR(camera.depth.cx, 19.5, 1e-6);
  // Pitched straight down: the camera's -Z (its view) turns to the world's -Y.
  const float* q = camera.depth.pose.orientation;
  EXPECT_NEAR(q[0], -std::sin(kPi / 4), 1e-6);
  EXPECT_NEAR(q[3], std::cos(kPi / 4), 1e-6);
}

TEST(SceneSensors, MistakesNameTheirKey) {
  struct Case {
    std::string sensors, where;
  };
  const std::vector<Case> cases = {
      {R"([{"type": "radar"}])", "/sensors/0/type"},
      {R"([{"type": "lidar", "preset": "VLP-61"}])", "/sensors/0/preset"},
      {R"([{"type": "lidar", "channels": 0}])", "/sensors/0/channels"},
      {R"([{"type": "lidar", "vertical_angles_deg": [1, 2], "channels": 3}])",
       "/sensors/0/channels"},
      {R"([{"type": "lidar", "vertical_angles_deg": [1, 95]}])",
       "/sensors/0/vertical_angles_deg/1"},
      {R"([{"type": "lidar", "min_range": 5, "max_range": 2}])", "/sensors/0/min_range"},
      {R"([{"type": "lidar", "points_per_turn": 100000, "channels": 128}])",
       "/sensors/0/points_per_turn"},
      {R"([{"type": "lidar", "reflectivity": {"bark": 2}}])", "/sensors/0/reflectivity/bark"},
      {R"([{"type": "lidar", "pose": {"orientation": [0, 0, 0, 2]}}])",
       "/sensors/0/pose/orientation"},
      {R"([{"type": "lidar", "pose": {}, "path": []}])", "/sensors/0/path"},
      {R"([{"type": "lidar", "path": [{"t": 1}, {"t": 1}]}])", "/sensors/0/path/1/t"},
      {R"([{"type": "lidar", "path": [{"t": 0, "positon": [0, 0, 0]}]}])",
       "/sensors/0/path/0/positon"},
      {R"([{"type": "depth", "width": 0}])", "/sensors/0/width"},
      {R"([{"type": "depth", "fov_deg": 60, "fx": 100}])", "/sensors/0/fov_deg"},
      {R"([{"type": "depth", "fov_deg": 180}])", "/sensors/0/fov_deg"},
      {R"([{"type": "depth", "name": "a/b"}])", "/sensors/0/name"},
      {R"([{"type": "depth", "name": "a"}, {"type": "lidar", "name": "a"}])", "/sensors/1/name"},
  };
  for (const Case& c : cases) {
    SceneError e = error_for(sensor_scene(c.sensors));
    EXPECT_EQ(e.where(), c.where) << c.sensors << "\n" << e.what();
    EXPECT_EQ(e.source(), "s.json");
  }
}

TEST(SensorPath, InterpolatesPositionLinearlyAndHeadingSpherically) {
  SceneSensor s;
  SensorKeyframe a, b;
  a.t = 1.0;
  b.t = 3.0;
  b.pose.position[0] = 10.0f;
  heading_pitch_quaternion(kPi / 2, 0.0, b.pose.orientation);
  s.path = {a, b};
  boreas_pose mid = sensor_pose_at(s, 2.0);
  EXPECT_FLOAT_EQ(mid.position[0], 5.0f);
  // Halfway through a quarter turn about +Y: an eighth of a turn.
  EXPECT_NEAR(mid.orientation[1], std::sin(kPi / 8), 1e-6);
  EXPECT_NEAR(mid.orientation[3], std::cos(kPi / 8), 1e-6);
  // Held at the ends.
  EXPECT_FLOAT_EQ(sensor_pose_at(s, 0.0).position[0], 0.0f);
  EXPECT_FLOAT_EQ(sensor_pose_at(s, 9.0).position[0], 10.0f);
}

// The header of a PLY or PCD (through end_header / DATA binary) and the bytes after it.
std::pair<std::string, std::string> split_file(const fs::path& path, const std::string& end) {
  std::string text = read_text(path);
  size_t at = text.find(end);
  if (at == std::string::npos) return {text, ""};
  return {text.substr(0, at + end.size()), text.substr(at + end.size())};
}

// "WIDTH 12" -> {"WIDTH": "12"}: the first word of each header line and the rest.
std::map<std::string, std::string> header_lines(const std::string& header) {
  std::map<std::string, std::string> out;
  std::istringstream in(header);
  std::string line;
  while (std::getline(in, line)) {
    size_t space = line.find(' ');
    std::string key = line.substr(0, space);
    if (key == "property") key += " " + line.substr(space + 1);
    out[key] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return out;
}

// The LiDAR's last sweep after each frame, by the library, as the command steps the scene.
std::vector<std::vector<boreas_lidar_point>> library_sweeps(const std::string& text, int frames) {
  const Scene scene = load_scene_text(text, "s.json");
  SceneIds ids;
  boreas::World world = make_world(scene, std::nullopt, &ids);
  std::vector<std::vector<boreas_lidar_point>> sweeps;
  for (int f = 0; f < frames; ++f) {
    step_scene(world, scene, scene.run.steps_per_frame, scene.run.dt, ids.lidars);
    sweeps.push_back(world.lidar_get_points(ids.lidars[0], BOREAS_LIDAR_LAST_SWEEP));
  }
  return sweeps;
}

TEST(CliSensors, LidarFilesHoldTheLibrarysSweepWithHeadersOthersRead) {
  TempDir dir;
  const std::string text = sensor_scene(kDrivenLidar, 3);
  dir.write("s.json", text);
  CommandResult r = run_boreas("run --view slice s.json --out out -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto sweeps = library_sweeps(text, 3);
  const fs::path folder = dir.path() / "out" / "sensors" / "roof";
  for (int f = 0; f < 3; ++f) {
    const std::string base = "frame_000" + std::to_string(f);
    auto [ply_header, ply_body] = split_file(folder / (base + ".ply"), "end_header\n");
    auto ply = header_lines(ply_header);
    EXPECT_EQ(ply["format"], "binary_little_endian 1.0");
    EXPECT_EQ(ply["element"], "vertex " + std::to_string(sweeps[f].size()));
    for (const char* p : {"float x", "float y", "float z", "float intensity", "ushort ring",
                          "float time", "uchar kind", "uint object", "int part"}) {
      EXPECT_TRUE(ply.count(std::string("property ") + p)) << p;
    }
    ASSERT_GT(sweeps[f].size(), 100u) << "frame " << f;
    const std::vector<unsigned char> expected = pack_points(sweeps[f]);
    EXPECT_EQ(ply_body, std::string(expected.begin(), expected.end())) << "frame " << f;

    auto [pcd_header, pcd_body] = split_file(folder / (base + ".pcd"), "DATA binary\n");
    auto pcd = header_lines(pcd_header);
    EXPECT_EQ(pcd["FIELDS"], "x y z intensity ring time kind object part");
    EXPECT_EQ(pcd["SIZE"], "4 4 4 4 2 4 1 4 4");
    EXPECT_EQ(pcd["POINTS"], std::to_string(sweeps[f].size()));
    EXPECT_EQ(pcd["WIDTH"], std::to_string(sweeps[f].size()));
    EXPECT_EQ(pcd_body, ply_body);
  }
  nlohmann::json summary = nlohmann::json::parse(read_text(dir.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["sensors"][0]["points"][2], sweeps[2].size());
  // The vehicle moves: every point lies within the unit's range of the path's segment.
  for (const boreas_lidar_point& p : sweeps[2]) {
    const double x = std::clamp(double(p.x), -6.0, 4.0);
    EXPECT_LE(std::hypot(p.x - x, p.y - 2.0, p.z), 100.0 + 0.1);
  }
}

// An .npy's payload (after its header) as values of T.
template <typename T>
std::vector<T> npy_values(const fs::path& path, std::string* header) {
  std::string text = read_text(path);
  const size_t length = size_t(uint8_t(text[8])) | size_t(uint8_t(text[9])) << 8;
  *header = text.substr(10, length);
  std::vector<T> out((text.size() - 10 - length) / sizeof(T));
  std::memcpy(out.data(), text.data() + 10 + length, out.size() * sizeof(T));
  return out;
}

TEST(CliSensors, DepthOfFlatGroundIsTheAnalyticDepth) {
  // 3 m above flat ground, pitched 60 degrees down: the pixel whose ray runs along
  // d = ((u - cx) / f, -(v - cy) / f, -1) in the camera meets the ground at depth
  // h / -(R d).y, where (R d).y = cos(p) * d.y - sin(p) for pitch p (along the axis, which
  // the ray's z is: the range h / cos of the angle from straight down, projected).
  const double h = 3.0, pitch = -60.0 * kPi / 180.0;
  TempDir dir;
  dir.write("s.json", sensor_scene(R"([{"type": "depth", "name": "cam", "width": 24,
    "height": 18, "fov_deg": 50, "pose": {"position": [-8, 3, -4], "pitch_deg": -60}}])",
                                   1));
  CommandResult r = run_boreas("run --view slice s.json --out out -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const std::vector<float> depth =
      npy_values<float>(dir.path() / "out/sensors/cam/frame_0000_depth.npy", &header);
  EXPECT_NE(header.find("'descr': '<f4'"), std::string::npos) << header;
  EXPECT_NE(header.find("'shape': (18, 24)"), std::string::npos) << header;
  const std::vector<int32_t> labels =
      npy_values<int32_t>(dir.path() / "out/sensors/cam/frame_0000_labels.npy", &header);
  EXPECT_NE(header.find("'shape': (18, 24, 3)"), std::string::npos) << header;
  ASSERT_EQ(depth.size(), 24u * 18u);
  ASSERT_EQ(labels.size(), 3 * depth.size());
  // The depth does not depend on the column u: the ground is level across the view.
  const double f = 9.0 / std::tan(25.0 * kPi / 180.0), cy = 8.5;
  for (int v = 0; v < 18; ++v) {
    for (int u = 0; u < 24; ++u) {
      const size_t i = size_t(v) * 24 + size_t(u);
      const double dy = -(v - cy) / f;
      const double expected = h / -(std::cos(pitch) * dy + std::sin(pitch));
      EXPECT_EQ(labels[3 * i], BOREAS_HIT_GROUND) << u << ", " << v;
      EXPECT_NEAR(depth[i], expected, 1e-4 * expected) << u << ", " << v;
    }
  }
}

TEST(CliSensors, LidarViewNeedsALidar) {
  TempDir dir;
  dir.write("s.json", sensor_scene(R"([{"type": "depth"}])", 1));
  CommandResult r = run_boreas("run --view lidar s.json --out out -q", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--view lidar"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

// 8-bit colors the overlay draws points in.
std::vector<std::array<uint8_t, 3>> point_colors() {
  std::vector<std::array<uint8_t, 3>> out;
  for (int kind = BOREAS_HIT_BRANCH; kind <= BOREAS_HIT_SOLID_BOX; ++kind) {
    std::vector<uint8_t> rgb = Image(1, 1, lidar_surface_color(kind)).to_rgb8();
    out.push_back({rgb[0], rgb[1], rgb[2]});
  }
  return out;
}

TEST(CliLidarView, PointsAreDrawnOverThePlainFrame) {
  TempDir dir;
  dir.write("s.json", sensor_scene(kDrivenLidar, 3));
  const std::string common = " s.json -q --size 160x120 --animation none --frames 3";
  CommandResult plain = run_boreas("run --view scene --out plain" + common, dir);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  CommandResult lidar = run_boreas("run --view lidar --out lidar" + common, dir);
  ASSERT_EQ(lidar.exit_code, 0) << lidar.err;
  Png a = read_png((dir.path() / "plain/frame_0002.png").string());
  Png b = read_png((dir.path() / "lidar/frame_0002.png").string());
  ASSERT_EQ(a.width, b.width);
  const auto colors = point_colors();
  int changed = 0, off_color = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (std::equal(a.at(x, y), a.at(x, y) + 3, b.at(x, y))) continue;
      if (x < 64 && y < 56) continue;  // the legend
      ++changed;
      std::array<uint8_t, 3> c = {b.at(x, y)[0], b.at(x, y)[1], b.at(x, y)[2]};
      if (std::find(colors.begin(), colors.end(), c) == colors.end()) ++off_color;
    }
  }
  EXPECT_GT(changed, 50);
  EXPECT_EQ(off_color, 0) << "pixels changed to a color no point is drawn in";
}

// The example scene render/scenes/lidar_forest.json, two frames small: its LiDAR's sweep
// (PLY and PCD) and its depth camera's images appear, and what they hold is what a vehicle
// 2 m up in a forest over a meadow sees: many points, all within the unit's range of the
// path, on trees, underbrush and ground, ground points at the ground's height; depth
// finite where a label names a surface and inf where none does, within max_depth.
TEST(CliSensors, TheLidarForestExampleWritesPlausibleSweepsAndDepth) {
  TempDir dir;
  const std::string scene = std::string(BOREAS_SCENES_DIR) + "/lidar_forest.json";
  CommandResult r = run_boreas("run --view slice '" + scene + "' --out out --frames 2 --size 64x36 "
                               "--animation none -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = dir.path() / "out";
  nlohmann::json summary = nlohmann::json::parse(read_text(out / "summary.json"));
  ASSERT_EQ(summary["sensors"].size(), 2u) << summary["sensors"].dump();
  // The last frame (t = 0.2 s: two turns at 10 Hz) holds a complete sweep.
  auto [ply_header, ply_body] = split_file(out / "sensors/roof/frame_0001.ply", "end_header\n");
  auto [pcd_header, pcd_body] = split_file(out / "sensors/roof/frame_0001.pcd", "DATA binary\n");
  EXPECT_EQ(pcd_body, ply_body);
  const size_t n = ply_body.size() / kPointRecordBytes;
  ASSERT_EQ(ply_body.size(), n * kPointRecordBytes);
  EXPECT_EQ(header_lines(ply_header)["element"], "vertex " + std::to_string(n));
  EXPECT_EQ(summary["sensors"][0]["points"][1], n);
  EXPECT_GT(n, 2000u) << "540 firings of 32 channels, in a forest";
  std::map<int, size_t> kinds;
  for (size_t i = 0; i < n; ++i) {
    const char* rec = ply_body.data() + i * kPointRecordBytes;
    float xyz[3];
    uint16_t ring = 0;
    std::memcpy(xyz, rec, sizeof xyz);
    std::memcpy(&ring, rec + 16, sizeof ring);
    const int kind = uint8_t(rec[22]);
    ++kinds[kind];
    EXPECT_LT(ring, 32) << i;
    // The path runs along +x at y = 2, z = 1.5 from x = -14 (t = 0) at 5 m/s.
    const double x = std::clamp(double(xyz[0]), -14.0, -12.9);
    EXPECT_LE(std::hypot(xyz[0] - x, xyz[1] - 2.0, xyz[2] - 1.5), 100.0 + 0.1) << i;
    // The meadow's ground is flat at y = 0 (no terrain_relief); the preset's 1 cm range
    // noise moves a point along its ray.
    if (kind == BOREAS_HIT_GROUND) EXPECT_NEAR(xyz[1], 0.0, 0.1) << i;
  }
  EXPECT_EQ(kinds.count(BOREAS_HIT_NONE), 0u);
  for (int k : {BOREAS_HIT_BRANCH, BOREAS_HIT_LEAF, BOREAS_HIT_UNDERBRUSH, BOREAS_HIT_GROUND})
    EXPECT_GT(kinds[k], 10u) << "kind " << k;

  std::string header;
  const std::vector<float> depth =
      npy_values<float>(out / "sensors/front/frame_0001_depth.npy", &header);
  EXPECT_NE(header.find("'shape': (90, 160)"), std::string::npos) << header;
  const std::vector<int32_t> labels =
      npy_values<int32_t>(out / "sensors/front/frame_0001_labels.npy", &header);
  ASSERT_EQ(depth.size(), 160u * 90u);
  ASSERT_EQ(labels.size(), 3 * depth.size());
  size_t seen = 0;
  for (size_t i = 0; i < depth.size(); ++i) {
    const bool hit = labels[3 * i] != BOREAS_HIT_NONE;
    seen += hit;
    if (hit) {
      EXPECT_GT(depth[i], 0.0f) << i;
      EXPECT_LE(depth[i], 60.0f) << i;
      EXPECT_GE(labels[3 * i + 2], 0) << i;
    } else {
      EXPECT_TRUE(std::isinf(depth[i])) << i;
      EXPECT_EQ(labels[3 * i + 2], -1) << i;
    }
  }
  // Pitched 8 degrees down 2 m up in a forest: the lower half of the view is ground and
  // underbrush (the ground is 2 / tan 8 deg = 14 m ahead at the middle row), most of it seen.
  EXPECT_GT(seen, depth.size() / 2);
}

}  // namespace
}  // namespace boreas::render::testing
