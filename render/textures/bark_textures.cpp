// boreas textures: generating the tiling bark texture.
#include "textures/bark_textures.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "textures/hash_noise.h"
#include "textures/height_normals.h"
#include "textures/texture_error.h"

namespace boreas::render {
namespace {

void require(bool ok, const char* name, const std::string& rule, double value) {
  require_param(ok, "BarkTextureParams", name, rule, value);
}

// Linear RGB: grey-brown plate surface (about sRGB 120, 102, 86), the darker furrow floor,
// and a grey-green lichen.
constexpr double kPlateColor[3] = {0.19, 0.135, 0.093};
constexpr double kFurrowColor[3] = {0.045, 0.033, 0.026};
constexpr double kLichenColor[3] = {0.22, 0.25, 0.16};

}  // namespace

BarkTextureSet generate_bark_textures(const BarkTextureParams& p) {
  require(p.width >= 16 && p.width <= 8192, "width", "in 16..8192", p.width);
  require(p.height >= 16 && p.height <= 8192, "height", "in 16..8192", p.height);
  require(p.tile_width_mm > 0.0, "tile_width_mm", "> 0", p.tile_width_mm);
  require(p.tile_height_mm > 0.0, "tile_height_mm", "> 0", p.tile_height_mm);
  require(p.furrows >= 1 && p.furrows <= 256, "furrows", "in 1..256", p.furrows);
  require(p.crack_rows >= 0 && p.crack_rows <= 256, "crack_rows", "in 0..256", p.crack_rows);
  require(p.furrow_depth_mm >= 0.0, "furrow_depth_mm", ">= 0", p.furrow_depth_mm);

  const int w = p.width, h = p.height;
  const size_t n = size_t(w) * h;
  const uint32_t seed = noise::hash(p.seed ^ 0xba4cU);
  BarkTextureSet set;
  set.width = w;
  set.height = h;
  set.albedo.resize(n * 3);
  std::vector<double> height(n);

  for (int y = 0; y < h; ++y) {
    double v = (y + 0.5) / h;
    for (int x = 0; x < w; ++x) {
      double u = (x + 0.5) / w;
      size_t i = size_t(y) * w + x;

      // Position across the plates: the furrows wander sideways with noise of two scales.
      double warp = 1.1 * (noise::fbm(u, v, 3, 2, 3, seed + 1U) - 0.5) +
                    0.3 * (noise::fbm(u, v, 8, 4, 2, seed + 2U) - 0.5);
      double s = u * p.furrows + warp;
      double plate = std::floor(s);
      double f = s - plate;
      int column = ((int(plate) % p.furrows) + p.furrows) % p.furrows;
      double column_u = (column + 0.5) / p.furrows;
      // A plate fills 45-90% of its column, varying along the trunk: the furrow between two
      // plates widens and narrows. r is 1 on the plate's spine and 0 at its edge.
      double fill = 0.45 + 0.45 * noise::value_noise(column_u, v, p.furrows, 5, seed + 3U);
      double r = std::max(0.0, 1.0 - std::abs(f - 0.5) * 2.0 / fill);
      double relief = 0.7 + 0.3 * noise::hash01(column, 2U, seed);
      double ridge = noise::smoothstep(0.0, 0.55, r) * relief;

      // Cross cracks: each plate breaks at its own places along v, on a jagged line.
      double crack = 0.0;
      if (p.crack_rows > 0) {
        double c = v * p.crack_rows + noise::hash01(column, 4U, seed) +
                   0.25 * (noise::fbm(u, v, 2 * p.furrows, 8, 2, seed + 5U) - 0.5);
        double g = c - std::floor(c);
        crack = 1.0 - noise::smoothstep(0.0, 0.05, std::min(g, 1.0 - g));
      }
      // Fibres: noise stretched along the trunk, and a fine grain.
      double fibre = noise::fbm(u, v, 40, 5, 3, seed + 7U);
      double grain = noise::fbm(u, v, 32, 32, 2, seed + 8U);
      double top = ridge * (1.0 - 0.85 * crack);
      height[i] = p.furrow_depth_mm * (top * (0.8 + 0.4 * fibre) + 0.08 * (grain - 0.5));

      double lichen = noise::smoothstep(0.64, 0.74, noise::fbm(u, v, 4, 4, 4, seed + 9U)) * top;
      double shade = 0.5 + 0.7 * fibre + 0.4 * (grain - 0.5);
      for (int k = 0; k < 3; ++k) {
        double bark = (kFurrowColor[k] + (kPlateColor[k] - kFurrowColor[k]) * top) * shade;
        set.albedo[i * 3 + k] = float(bark + (kLichenColor[k] - bark) * 0.8 * lichen);
      }
    }
  }
  set.normal = normals_from_height(height, w, h, p.tile_width_mm / w, p.tile_height_mm / h,
                                   HeightEdges::kWrap);
  return set;
}

}  // namespace boreas::render
