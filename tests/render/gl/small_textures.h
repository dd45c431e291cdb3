// boreas render tests: a small generated texture set (leaf atlas and bark of the given sizes
// in texels), enough for the shaders to sample, made in milliseconds.
#pragma once

#include "textures/texture_files.h"

namespace boreas::render {

inline TextureSet small_texture_set(int leaf_size, int bark_size) {
  LeafTextureParams leaf;
  leaf.width = leaf.height = leaf_size;
  BarkTextureParams bark;
  bark.width = bark.height = bark_size;
  return generate_texture_set(leaf, bark);
}

}  // namespace boreas::render
