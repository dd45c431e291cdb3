// boreas trees: the crown's ambient occlusion at each leaf (cl/leaf_occlusion.cl says the
// model): a grid of leaf area density built here from the leaves, marched on the device,
// sampled at the leaves on the device.
//
// The leaf area the light sees is calibrated per species, as the wind's is (leaf_shelter,
// wind_load.h): Weber-Penn leaves are a visual stand-in (the aspen's 17 cm blade is about
// three times a real one's), and its crowns carry two to four times the leaf area real
// crowns do. So every leaf's area (leaf_area.h, the rule the wind uses too) is scaled down,
// all alike, until the crown's leaf area index over its projection on the ground is the
// species' LeafAreaIndex, never up (a crown drawn sparse stays as sparse as drawn). The
// species' Clumping (Nilson's clumping index) scales the optical depth: leaves bunched on
// shoots shade each other and leave gaps between, so a clumped crown passes more light
// than the same leaf area spread at random within a voxel would. The projection G of the
// leaves' area toward each sky direction comes from their normals (Ross), not a
// spherical leaf-angle distribution's 0.5 for every direction: horizontal leaves shade the
// zenith with all their area and the horizon with none, and a grown aspen's leaves hang
// steep (G 0.36 toward the zenith, 0.56 toward the horizon).
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

// What the light sees of one tree's crown: its species' calibration, its leaves' outline.
struct CrownLight {
  // Target leaf area index over the crown's projection (the species' LeafAreaIndex); 0
  // takes the leaves' own area (for tests of the method).
  double leaf_area_index = 4.0;
  double clumping = 0.8;  // the species' Clumping, (0, 1]
  int outline = 0;        // the leaves' outline kind (cl/shared/leaf_outline.h)
};
// Voxels along the crown's longest side: fine enough to tell the rim from the core, coarse
// enough that a voxel holds a few dozen leaves (a quaking aspen's 22,000 in about 1,500
// filled voxels).
inline constexpr int kOcclusionVoxels = 20;
// Directions over the upper hemisphere, cosine-distributed (a Fibonacci spiral).
inline constexpr int kOcclusionDirections = 32;

// A leaf's centre, m: half its blade's length along its axis from where the blade starts.
std::array<double, 3> leaf_centre(const boreas_leaf& leaf);

// The crown's projection on the ground, m^2: the ellipse over its leaves' centres' extent
// in x and z (the foresters' crown projection area from two crown diameters).
double crown_projection(const std::vector<boreas_leaf>& leaves);

// The factor (0, 1] every leaf's area takes so that the crown's leaf area index over its
// projection is at most light.leaf_area_index (1 where it is already, or where that is 0).
double leaf_area_scale(const std::vector<boreas_leaf>& leaves, const CrownLight& light);

// The grid around the leaves' centres: kOcclusionVoxels along the longest side, a voxel's
// margin all round. Each leaf's area, scaled by leaf_area_scale, goes to the voxel holding
// its centre.
LeafDensityGrid leaf_density_grid(const std::vector<boreas_leaf>& leaves,
                                  const CrownLight& light);

// kOcclusionDirections unit vectors (x, y, z), y up, cosine-distributed over the upper
// hemisphere, so that their plain mean is the cosine-weighted one.
std::vector<float> occlusion_directions(int count = kOcclusionDirections);

// Ross's projection function G for each of `directions` (x, y, z triples): the leaves'
// mean |normal . direction|, weighted by their area. Horizontal leaves give cos(zenith);
// leaves spread evenly over every orientation 0.5 for any direction.
std::vector<float> leaf_projection(const std::vector<boreas_leaf>& leaves,
                                   const std::vector<float>& directions, int outline);

// Per leaf, the fraction of a uniform sky's light reaching its centre through the crown,
// per channel (r, g, b), for leaves passing `transmittance` (each in [0, 1]) of the light
// they intercept. Computed on runtime's device; empty for no leaves.
std::vector<float> leaf_occlusion(Runtime& runtime, const std::vector<boreas_leaf>& leaves,
                                  const float transmittance[3], const CrownLight& light);

}  // namespace boreas::impl
