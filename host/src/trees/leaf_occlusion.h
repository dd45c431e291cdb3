// boreas trees: the crown's ambient occlusion at each leaf (cl/leaf_occlusion.cl says the
// model): a grid of leaf area density built here from the leaves, marched on the device,
// sampled at the leaves on the device.
#pragma once

#include <array>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

class Runtime;

// The crown's leaf area density on a grid of cubic voxels.
struct LeafDensityGrid {
  std::array<double, 3> origin{};  // m: the grid's min corner
  double cell = 1.0;               // m
  std::array<int, 3> size{1, 1, 1};
  std::vector<float> density;  // m^2 of leaf per m^3, x fastest, then y, then z
};

// A leaf's one-sided area as a share of its length x width box (an ovate blade covers about
// 0.6 of it; lobed and lanceolate ones a little less).
inline constexpr double kLeafFill = 0.6;
// Voxels along the crown's longest side: fine enough to tell the rim from the core, coarse
// enough that a voxel holds a few dozen leaves (a quaking aspen's 22,000 in about 1,500
// filled voxels).
inline constexpr int kOcclusionVoxels = 20;
// Directions over the upper hemisphere, cosine-distributed (a Fibonacci spiral).
inline constexpr int kOcclusionDirections = 32;

// The grid around the leaves' bases: kOcclusionVoxels along the longest side, a voxel's
// margin all round. Each leaf's area goes to the voxel holding its base.
LeafDensityGrid leaf_density_grid(const std::vector<boreas_leaf>& leaves);

// kOcclusionDirections unit vectors (x, y, z), y up, cosine-distributed over the upper
// hemisphere, so that their plain mean is the cosine-weighted one.
std::vector<float> occlusion_directions(int count = kOcclusionDirections);

// Per leaf, the fraction of a uniform sky's light reaching it through the crown, per
// channel (r, g, b), for leaves passing `transmittance` (each in [0, 1]) of the light they
// intercept. Computed on runtime's device; empty for no leaves.
std::vector<float> leaf_occlusion(Runtime& runtime, const std::vector<boreas_leaf>& leaves,
                                  const float transmittance[3]);

}  // namespace boreas::impl
