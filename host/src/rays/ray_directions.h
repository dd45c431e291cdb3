// boreas: a map of the directions a cast's rays point in, for the update of the ray
// structure (ray_reach.h): which branches of a tree can a ray reach at all.
//
// The cones over runs of rays (ray_reach.h) decide per plant; per branch they cost too
// much (a crown's thousands of branches each against the hundreds of cones that meet the
// tree). The map answers the same question for any sphere in constant time: the rays'
// directions, counted on a grid of azimuth and elevation cells seen from one apex (the
// first ray's origin), kept as a summed-area table, so that a sphere is reached only if
// some cell its angular disc overlaps holds a ray. Sound for any rays: a ray from o within
// `spread` of the apex that meets a sphere of radius r has, moved to the apex, a direction
// within asin((r + spread) / d) of the sphere's center (d its distance), so growing the
// sphere by the spread (and the disc by a hair for rounding) never leaves a ray out. What it
// leaves out that the cones keep: a LiDAR's crowns above its top channel or below its
// lowest, and what lies between its channels' fans when it is small or far.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

inline constexpr int kDirectionAzimuthCells = 720;    // 0.5 degree on average (ray_directions.cpp)
// Rays whose origins lie farther apart than this (m) get no map: every sphere would be
// grown by as much, and rays from scattered places point everywhere (a sensor moving in a
// step, or a vehicle's several units, stay well within it).
inline constexpr double kDirectionMapSpread = 4.0;
inline constexpr int kDirectionElevationCells = 360;  // of equal sine: 0.32 degree at the horizon

struct DirectionMap {
  std::array<double, 3> apex{};  // m: the first ray's origin
  double spread = 0.0;           // m: every ray's origin within this of the apex
  double length = 0.0;           // m: the farthest any ray reaches (may be infinite)
  // (elevation cells + 1) x (azimuth cells + 1) counts of rays below and left of each
  // corner; empty: no map (RayReach asks the cones alone; meets() meets nothing).
  std::vector<int32_t> sums;

  // Whether any ray may meet the sphere at center of radius (m).
  bool meets(const std::array<double, 3>& center, double radius) const;
};

// The map of count checked rays (unit or not: directions are normalized here); without
// sums where their origins lie more than kDirectionMapSpread apart.
DirectionMap direction_map(const boreas_ray* rays, int count);

}  // namespace boreas::impl
