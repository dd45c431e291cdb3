// boreas: solid boxes laid into the grid's cells. The boxes are kept as given, so that a
// grid that follows the focus lays them again into the cells it moves onto.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shared/wind_types.h"

namespace boreas::impl {

// min xyz, max xyz (m).
using SolidBox = std::array<float, 6>;

// The box from the public call's corners, checked: finite, min <= max on every axis.
SolidBox checked_solid_box(const float min[3], const float max[3]);

// Marks in mask (one byte per cell, x fastest) the cells of grid g whose centers lie in
// box. Visits only the cells the box may cover: a small box in a large grid costs its
// own cells.
void lay_solid_box(const BoreasGpuGrid& g, const SolidBox& box, std::vector<uint8_t>& mask);

}  // namespace boreas::impl
