// boreas render: the leaf and bark texture set (render/textures) as OpenGL textures:
// half-float, mipmapped, the leaf's clamped at its edges and the bark's repeating. The leaf
// maps are 2D array textures: layer 0 the set's leaf, then one layer per leaf kind the set
// holds (TextureSet::kind_leaves), so one draw shades every tree with its own leaf.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "gl/gl_objects.h"
#include "textures/texture_files.h"

namespace boreas::render {

struct VegetationTextures {
  // shape: where the blade lies on the leaf maps (a user's own maps follow the default
  // layout: blade from v 0.15 to 0.97, half as wide as 0.6 of the square).
  // Throws std::invalid_argument naming a kind's map whose size differs from the leaf's.
  explicit VegetationTextures(const TextureSet& set, const LeafShape& shape = {});

  // The layer of the leaf maps for a leaf kind: its own, or 0 (the set's leaf) where the set
  // has none for it.
  int leaf_layer(const std::string& kind) const;

  GlObject leaf_albedo;        // rgb linear albedo, a coverage
  GlObject leaf_normal;        // tangent-space normal
  GlObject leaf_hl2;           // HL2 coefficients
  GlObject leaf_translucency;  // rgb transmittance
  GlObject bark_albedo;
  GlObject bark_normal;
  LeafShape leaf_shape;        // where the blade lies on the leaf textures
  std::vector<std::string> leaf_layers;  // the kind of each layer ("" for layer 0)
  // Per layer: the mean transmittance (translucency map) over the texels wholly on the leaf.
  std::vector<glm::vec3> leaf_transmittance;
};

}  // namespace boreas::render
