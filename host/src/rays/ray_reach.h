// boreas: what a cast's rays can reach, for the update of the ray structure: the box of all
// their segments, and for rays passed from the host a cone over each run of consecutive
// rays (kReachRun), with cones over runs of those (kReachGroup runs).
//
// The box alone keeps a LiDAR's update at the whole stand: a slice of a sweep reaches 100 m
// on every side it turns through, and a box over a 60-degree slice is a quarter of the
// disc. A run of consecutive rays (a firing's channels; a camera row's neighbours) shares
// an origin and a narrow fan of directions, so a cone from that origin holds every point of
// its rays, and a plant is updated only where some cone meets the sphere that holds all it
// can sway into. Cones hold their rays' points within `spread` of their axis's cone (the
// rays' origins may differ), so the test is conservative for any rays: rays with no common
// origin or direction only make wide cones, which meet everything the box meets.
#pragma once

#include <array>
#include <vector>

#include "boreas/boreas.h"
#include "rays/bvh_build.h"
#include "rays/ray_directions.h"

namespace boreas::impl {

inline constexpr int kReachRun = 16;    // rays a cone
inline constexpr int kReachGroup = 16;  // cones a group cone

struct ReachCone {
  std::array<double, 3> apex{};   // m
  double spread = 0.0;            // m: every ray's origin within this of the apex
  std::array<double, 3> axis{};   // unit
  double cos_half = -1.0, sin_half = 0.0;  // the half-angle holding every direction
  double length = 0.0;            // m: the farthest any ray reaches (may be infinite)
};

struct RayReach {
  Box box = empty_box();
  std::vector<ReachCone> cones;   // empty: the box alone says what the rays reach
  std::vector<ReachCone> groups;  // group g bounds cones [g kReachGroup, (g + 1) kReachGroup)
  DirectionMap directions;        // no sums: the box and cones alone say it

  // Whether any ray may reach the sphere at center of radius (m) inside the box `bound`.
  bool meets(const Box& bound, const std::array<double, 3>& center, double radius) const;
  // The same asked of a part of a plant that meets() already met (a tree's branch): the
  // box and the map of directions only, in constant time, leaving out fewer than the cones.
  bool meets_part(const Box& bound, const std::array<double, 3>& center, double radius) const;
};

// The reach of count checked rays: their box, and cones over runs of them.
RayReach reach_of(const boreas_ray* rays, int count);

// The cone over `cones` (group cones over runs of cones).
ReachCone cone_over(const ReachCone* cones, int count);

}  // namespace boreas::impl
