// boreas: the colliders of one step as every plant batch sees them, and the sums of what the
// plants push back with (boreas_collider_get_contact).
//
// The world lists its colliders once a step, in its slot order: a collider's index there is
// its index in every kernel's collider array. Each batch that plants touch adds its part of
// each collider's contact (force, torque about the collider's position at the end of the
// step, count) to `sums` when asked (read back after the step, in a fixed order, so the
// sums are the same bits every run).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "colliders/collider.h"

namespace boreas::impl {

struct StepColliders {
  double dt = 0.0;
  std::vector<BoreasGpuCollider> gpu;  // what the kernels read, index = collider number
  std::vector<Bounds> bounds;          // each one's swept_bounds(dt, 0)
  // Each one's world position at the step's start in double (Collider::center): where a
  // batch that keeps its plants relative to their own origins takes its collider from
  // (gpu's float position is 8 mm apart 100 km out).
  std::vector<std::array<double, 3>> centers;

  bool empty() const { return gpu.empty(); }
  // Lists c as the next collider (its gpu record, swept bounds and center over dt).
  void add(const Collider& c);
  // The indices of the colliders whose swept bounds, grown by `margin`, meet `b`.
  std::vector<int> touching(const Bounds& b, double margin) const;
  // Collider c's record with its position taken relative to `origin` (a meadow's or an
  // imported tree's) in double and rounded once: exact to float near that origin wherever
  // it stands (the record's move and axes are directions or differences).
  BoreasGpuCollider relative(int c, const std::array<double, 3>& origin) const;
};

struct ContactSum {
  std::array<double, 3> force{};   // N, on the collider
  std::array<double, 3> torque{};  // N m, about its position at the step's end
  int64_t contacts = 0;

  // Adds one pair's sum as every contact kernel writes it: floats force x, y, z, torque x,
  // y, z, contacts (underbrush_contacts.cl, tree_contact_sums.cl, mesh_tree_contact.cl).
  void add(const float* pair) {
    for (size_t a = 0; a < 3; ++a) {
      force[a] += double(pair[a]);
      torque[a] += double(pair[3 + a]);
    }
    contacts += int64_t(pair[6]);
  }
};

}  // namespace boreas::impl
