// boreas: the defs of common spinning LiDARs (boreas_lidar_preset), with their published
// vertical angles.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

// The preset's def; an unknown name throws, listing the known ones. Its vertical_angles
// point into a table that lives as long as the process.
boreas_lidar_def lidar_preset(const std::string& name);
// Preset number index's name, or nullptr past the last.
const char* lidar_preset_name(int index);
// A preset's vertical angles in degrees, as its maker's table lists them (laser by laser,
// in the order of the maker's laser ids), for tests that check the table.
const std::vector<double>& lidar_preset_table_degrees(const std::string& name);

}  // namespace boreas::impl
