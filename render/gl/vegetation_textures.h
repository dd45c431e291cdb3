// boreas render: the leaf and bark texture set (render/textures) as OpenGL textures:
// half-float, mipmapped, the leaf's clamped at its edges and the bark's repeating.
#pragma once

#include "gl/gl_objects.h"
#include "textures/texture_files.h"

namespace boreas::render {

struct VegetationTextures {
  // shape: where the blade lies on the leaf maps (a user's own maps follow the default
  // layout: blade from v 0.15 to 0.97, half as wide as 0.6 of the square).
  explicit VegetationTextures(const TextureSet& set, const LeafShape& shape = {});

  GlObject leaf_albedo;        // rgb linear albedo, a coverage
  GlObject leaf_normal;        // tangent-space normal
  GlObject leaf_hl2;           // HL2 coefficients
  GlObject leaf_translucency;  // rgb transmittance
  GlObject bark_albedo;
  GlObject bark_normal;
  LeafShape leaf_shape;        // where the blade lies on the leaf textures
};

}  // namespace boreas::render
