// boreas scenes: the "sensors" array of a scene file read into SceneSensors, every value
// checked against the library's ranges (boreas_lidar_def, boreas_depth_camera_def,
// boreas_pose) so that errors name the file and the JSON path.
#pragma once

#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene_sensors.h"

namespace boreas::render {

// One element of "sensors"; index is its place in the array (for its default name),
// earlier the sensors read before it (their names must differ from this one's).
SceneSensor read_sensor(JsonObjectReader& r, int index, const std::vector<SceneSensor>& earlier);

// A unit quaternion x, y, z, w under key (boreas_pose's orientation: its length within 1e-3
// of 1), for sensors' and colliders' poses; absent leaves out as it is.
void read_unit_quaternion(JsonObjectReader& r, const std::string& key, float out[4]);

}  // namespace boreas::render
