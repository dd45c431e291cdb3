// boreas: the ground a meadow grows on — a height field with nutrient maps over the
// meadow's rectangle (Endo et al. sec. 5.2). Procedural by default (deterministic per
// seed), or from pixel arrays the caller gives (boreas_image).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

constexpr int kMaxNutrients = 3;

// A regular grid of samples over [origin_x, origin_x + size_x] x [origin_z, origin_z +
// size_z], nx x nz samples (x fastest), corners included. Values between samples are
// bilinear; outside the rectangle they clamp to the edge.
struct GroundGrid {
  int nx = 0, nz = 0;
  double origin_x = 0.0, origin_z = 0.0;
  double size_x = 0.0, size_z = 0.0;
  // Bilinear value of plane `values` (nx * nz floats) at (x, z).
  double sample(const std::vector<float>& values, double x, double z) const;
};

struct Terrain {
  GroundGrid grid;
  std::vector<float> height;  // m, world y of the ground
  double height_at(double x, double z) const;
  // Unit upward normal of the bilinear surface at (x, z).
  void normal_at(double x, double z, double n[3]) const;
};

struct NutrientMaps {
  GroundGrid grid;
  int channels = 0;                              // 1..kMaxNutrients
  std::vector<float> values[kMaxNutrients];      // each nx * nz, in [0, 1]
  double at(int channel, double x, double z) const;
};

// Where the ground is: the meadow's rectangle (center x, z and size x, z) and the height of
// its center.
struct GroundRect {
  double center_x = 0.0, center_y = 0.0, center_z = 0.0;
  double size_x = 1.0, size_z = 1.0;
};

// Rolling ground: a sum of a few smooth random waves of amplitude up to `relief` (m)
// around center_y. relief 0 gives a flat plane. Deterministic per seed.
Terrain procedural_terrain(const GroundRect& rect, double relief, uint64_t seed);
// A caller's pixels, checked and copied: channel fastest, then x, then rows (row 0 at the
// -z edge). Empty for the none image.
struct GroundPixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> data;
  bool empty() const { return data.empty(); }
};
// Checks a boreas_image (sizes, NULL with a size, non-finite values) and copies it; errors
// (Error(BOREAS_ERROR_INVALID_ARGUMENT)) name `field` and the pixel.
GroundPixels checked_ground_pixels(const boreas_image& image, const std::string& field);

// Pixels stretched over the rectangle: the ground's y is center_y + relief * the first
// channel. Throws Error naming the pixel whose height is out of range.
Terrain pixel_terrain(const GroundRect& rect, double relief, const GroundPixels& pixels);

// kMaxNutrients smooth random maps in [0, 1] with patches a few meters across. Deterministic
// per seed.
NutrientMaps procedural_nutrients(const GroundRect& rect, uint64_t seed);
// Pixels stretched over the rectangle: each of the first kMaxNutrients channels is a
// nutrient, clamped to 0..1; one channel gives one nutrient.
NutrientMaps pixel_nutrients(const GroundRect& rect, const GroundPixels& pixels);

}  // namespace boreas::impl
