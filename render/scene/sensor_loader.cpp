// boreas scenes: reading a scene's sensors. The ranges are the library's (boreas.h); the
// scene gives angles in degrees, as its view does, and the library takes radians.
#include "scene/sensor_loader.h"

#include <cctype>
#include <cmath>
#include <sstream>

namespace boreas::render {

namespace {

constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
constexpr double kMaxUnitError = 1e-3;  // boreas_pose: |q| within 1e-3 of 1

}  // namespace

void read_unit_quaternion(JsonObjectReader& r, const std::string& key, float out[4]) {
  r.numbers(key, out, 4, NumberRule::within(2.0));
  double norm = 0.0;
  for (int i = 0; i < 4; ++i) norm += double(out[i]) * out[i];
  norm = std::sqrt(norm);
  if (!(std::fabs(norm - 1.0) <= kMaxUnitError)) {
    std::ostringstream detail;
    detail << "must be a unit quaternion x, y, z, w (its length within 1e-3 of 1; got " << norm
           << ")";
    r.fail(key, detail.str());
  }
}

namespace {

// {"position": [x, y, z], "orientation": [x, y, z, w]} or {"position", "heading_deg",
// "pitch_deg"}; the keys are read from r itself (a pose object or a path keyframe).
boreas_pose read_pose(JsonObjectReader& r) {
  boreas_pose pose = boreas_default_pose();
  r.numbers("position", pose.position, 3, NumberRule::within(BOREAS_WORLD_MAX_COORDINATE));
  const bool turned = r.has("heading_deg") || r.has("pitch_deg");
  if (r.has("orientation")) {
    if (turned) r.fail("orientation", "give an orientation or heading_deg/pitch_deg, not both");
    read_unit_quaternion(r, "orientation", pose.orientation);
    return pose;
  }
  const double heading = r.number("heading_deg", 0.0, NumberRule::within(1e6));
  const double pitch = r.number("pitch_deg", 0.0, NumberRule::in(-90, 90));
  heading_pitch_quaternion(heading * kRadPerDeg, pitch * kRadPerDeg, pose.orientation);
  return pose;
}

// "pose" or "path" (not both): where the sensor stands, or how it travels.
void read_placement(JsonObjectReader& r, SceneSensor& s) {
  if (r.has("pose") && r.has("path")) r.fail("path", "give a pose or a path, not both");
  if (r.has("pose")) {
    JsonObjectReader p = r.object("pose");
    s.pose = read_pose(p);
    p.finish();
  }
  r.objects("path", kMaxPathKeyframes, [&](JsonObjectReader& k) {
    SensorKeyframe key;
    key.t = k.number("t", 0.0, NumberRule::in(0, 1e9));
    if (!s.path.empty() && !(key.t > s.path.back().t)) {
      std::ostringstream detail;
      detail << "must be later than the keyframe before (" << s.path.back().t << " s; got " << key.t
             << ")";
      k.fail("t", detail.str());
    }
    key.pose = read_pose(k);
    s.path.push_back(key);
  });
  if (!s.path.empty()) s.pose = s.path.front().pose;
}

void read_preset(JsonObjectReader& r, SceneSensor& s) {
  s.preset = r.string("preset", "");
  if (s.preset.empty()) return;
  boreas_lidar_def def{};
  if (boreas_lidar_preset(s.preset.c_str(), &def) != BOREAS_OK) {
    std::vector<std::string> names;
    std::string list;
    for (int i = 0; boreas_lidar_preset_name(i); ++i) {
      names.push_back(boreas_lidar_preset_name(i));
      list += (list.empty() ? "" : ", ") + names.back();
    }
    r.fail("preset", "must be one of " + list + " (got \"" + s.preset + "\")" +
                         did_you_mean(s.preset, names));
  }
  s.lidar = def;
}

// The channels' elevations: a list, or a field of view spread over "channels".
void read_channels(JsonObjectReader& r, SceneSensor& s) {
  boreas_lidar_def& d = s.lidar;
  std::vector<float> degrees =
      r.number_list("vertical_angles_deg", 1, BOREAS_LIDAR_MAX_CHANNELS, NumberRule::in(-90, 90));
  const int channels = r.integer("channels", degrees.empty() ? d.channels : int(degrees.size()),
                                 NumberRule::in(1, BOREAS_LIDAR_MAX_CHANNELS));
  if (!degrees.empty()) {
    if (channels != int(degrees.size())) {
      r.fail("channels", "must equal the count of vertical_angles_deg (" +
                             std::to_string(degrees.size()) + "; got " + std::to_string(channels) +
                             ")");
    }
    if (r.has("vertical_fov_deg"))
      r.fail("vertical_fov_deg", "give vertical_angles_deg or vertical_fov_deg, not both");
    for (float a : degrees) s.angles.push_back(float(a * kRadPerDeg));
  } else if (channels != d.channels || r.has("vertical_fov_deg")) {
    // Another channel count than the preset's spreads them evenly over the field of view.
    float fov[2] = {float(d.vertical_fov[0] / kRadPerDeg), float(d.vertical_fov[1] / kRadPerDeg)};
    r.numbers("vertical_fov_deg", fov, 2, NumberRule::in(-90, 90));
    if (fov[0] > fov[1]) r.fail("vertical_fov_deg", "must be [lowest, highest] elevation");
    d.vertical_angles = nullptr;
    d.vertical_fov[0] = float(fov[0] * kRadPerDeg);
    d.vertical_fov[1] = float(fov[1] * kRadPerDeg);
  }
  d.channels = channels;
}

void read_reflectivity(JsonObjectReader r, float out[BOREAS_LIDAR_SURFACES]) {
  static const char* const kSurfaces[BOREAS_LIDAR_SURFACES] = {"bark", "leaf", "grass", "ground",
                                                               "solid"};
  for (int i = 0; i < BOREAS_LIDAR_SURFACES; ++i) {
    out[i] = float(r.number(kSurfaces[i], out[i], NumberRule::in(0, 1)));
  }
  r.finish();
}

void read_lidar(JsonObjectReader& r, SceneSensor& s) {
  read_preset(r, s);
  read_channels(r, s);
  boreas_lidar_def& d = s.lidar;
  d.points_per_turn = r.integer("points_per_turn", d.points_per_turn, NumberRule::in(1, 1 << 30));
  if (double(d.channels) * d.points_per_turn > BOREAS_LIDAR_MAX_RAYS_PER_TURN) {
    r.fail("points_per_turn", "times channels (" + std::to_string(d.channels) +
                                  ") must be at most " +
                                  std::to_string(BOREAS_LIDAR_MAX_RAYS_PER_TURN) + " rays a turn");
  }
  d.rotation_rate = float(r.number("rotation_rate", d.rotation_rate, NumberRule::in(0.01, 1000)));
  d.max_range = float(r.number("max_range", d.max_range, NumberRule::above_at_most(0, 1e5)));
  d.min_range = float(r.number("min_range", d.min_range, NumberRule::non_negative()));
  if (!(d.min_range < d.max_range)) r.fail("min_range", "must be less than max_range");
  d.range_noise = float(r.number("range_noise", d.range_noise, NumberRule::in(0, 100)));
  d.dropout = float(r.number("dropout", d.dropout, NumberRule::in(0, 1)));
  if (r.has("reflectivity")) read_reflectivity(r.object("reflectivity"), d.reflectivity);
  d.seed = r.unsigned_integer("seed", d.seed);
}

void read_depth(JsonObjectReader& r, SceneSensor& s) {
  boreas_depth_camera_def& d = s.depth;
  d.width = r.integer("width", d.width, NumberRule::in(1, BOREAS_DEPTH_CAMERA_MAX_PIXELS));
  d.height = r.integer("height", d.height, NumberRule::in(1, BOREAS_DEPTH_CAMERA_MAX_PIXELS));
  if (double(d.width) * d.height > BOREAS_DEPTH_CAMERA_MAX_PIXELS) {
    r.fail("height", "times width must be at most " +
                         std::to_string(BOREAS_DEPTH_CAMERA_MAX_PIXELS) + " pixels");
  }
  // The principal point in the middle unless given; the focal length from the vertical
  // field of view (square pixels) or given.
  d.cx = float(r.number("cx", 0.5 * (d.width - 1), NumberRule::within(1e7)));
  d.cy = float(r.number("cy", 0.5 * (d.height - 1), NumberRule::within(1e7)));
  if (r.has("fov_deg")) {
    if (r.has("fx") || r.has("fy")) r.fail("fov_deg", "give fov_deg or fx/fy, not both");
    const double fov = r.number("fov_deg", 60.0, NumberRule{0.0, 180.0, true, true});
    d.fx = d.fy = float(0.5 * d.height / std::tan(0.5 * fov * kRadPerDeg));
  }
  d.fx = float(r.number("fx", d.fx, NumberRule::in(1e-3, 1e7)));
  d.fy = float(r.number("fy", d.fy, NumberRule::in(1e-3, 1e7)));
  d.max_depth = float(r.number("max_depth", d.max_depth, NumberRule::in(1e-3, 1e5)));
}

bool is_folder_name(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  }
  return true;
}

}  // namespace

SceneSensor read_sensor(JsonObjectReader& r, int index, const std::vector<SceneSensor>& earlier) {
  SceneSensor s;
  const std::string type = r.string("type", "");
  if (type == "lidar") {
    s.type = SceneSensor::Type::lidar;
    read_lidar(r, s);
  } else if (type == "depth") {
    s.type = SceneSensor::Type::depth;
    read_depth(r, s);
  } else {
    r.fail("type", "must be \"lidar\" or \"depth\" (got " +
                       (r.has("type") ? "\"" + type + "\"" : std::string("nothing")) + ")");
  }
  s.name = r.string("name", type + std::to_string(index));
  if (!is_folder_name(s.name)) {
    r.fail("name", "must be 1 to 64 letters, digits, '_' or '-' (it names a folder; got \"" +
                       s.name + "\")");
  }
  for (const SceneSensor& e : earlier) {
    if (e.name == s.name) r.fail("name", "\"" + s.name + "\" names an earlier sensor too");
  }
  read_placement(r, s);
  s.lidar.pose = s.pose;
  s.depth.pose = s.pose;
  return s;
}

}  // namespace boreas::render
