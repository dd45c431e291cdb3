// boreas textures: a tiling bark texture (albedo and tangent-space normals) for the bark
// shader: vertical plates of bark between furrows that wander with noise, broken across by
// occasional cracks, with fine grain and patches of lichen.
//
// u runs around the trunk and v along it, and both repeat: every noise has a whole number
// of cells per period and the normals wrap at the edges. Layout and tangent space as in
// leaf_textures.h (row 0 at v = 0; +x along u, +y along v, +z out of the bark).
#pragma once

#include <cstdint>
#include <vector>

namespace boreas::render {

struct BarkTextureParams {
  int width = 256;   // texels, 16..8192
  int height = 256;  // texels, 16..8192
  uint32_t seed = 1;
  double tile_width_mm = 200.0;   // bark the texture covers across (u)
  double tile_height_mm = 200.0;  // and along the trunk (v)
  int furrows = 7;                // across one tile
  int crack_rows = 3;             // cross cracks per plate and tile, on average
  double furrow_depth_mm = 6.0;
};

struct BarkTextureSet {
  int width = 0;
  int height = 0;
  std::vector<float> albedo;  // RGB, linear
  std::vector<float> normal;  // xyz unit vectors, tangent space
};

// The set for params; throws TextureError naming a parameter out of range.
BarkTextureSet generate_bark_textures(const BarkTextureParams& params = {});

}  // namespace boreas::render
