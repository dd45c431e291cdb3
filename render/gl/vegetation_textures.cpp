// boreas render: uploading the texture set.
#include "gl/vegetation_textures.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boreas::render {

namespace {

GlObject upload(int width, int height, int channels, const std::vector<float>& texels,
                GLenum wrap, const char* what) {
  if (width <= 0 || height <= 0 || texels.size() != size_t(width) * size_t(height) * size_t(channels)) {
    throw std::invalid_argument(std::string("texture ") + what + ": " + std::to_string(texels.size()) +
                                " values for " + std::to_string(width) + " x " + std::to_string(height) +
                                " texels of " + std::to_string(channels) + " channels");
  }
  const GLenum internal = channels == 4 ? GL_RGBA16F : GL_RGB16F;
  const GLenum format = channels == 4 ? GL_RGBA : GL_RGB;
  int levels = 1 + int(std::floor(std::log2(double(std::max(width, height)))));
  GlObject texture = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), levels, internal, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, format, GL_FLOAT, texels.data());
  glGenerateTextureMipmap(texture.id());
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GLint(wrap));
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GLint(wrap));
  return texture;
}

}  // namespace

VegetationTextures::VegetationTextures(const TextureSet& set, const LeafShape& shape)
    : leaf_shape(shape) {
  const LeafTextureSet& leaf = set.leaf;
  leaf_albedo = upload(leaf.width, leaf.height, 4, leaf.albedo, GL_CLAMP_TO_EDGE, "leaf albedo");
  leaf_normal = upload(leaf.width, leaf.height, 3, leaf.normal, GL_CLAMP_TO_EDGE, "leaf normal");
  leaf_hl2 = upload(leaf.width, leaf.height, 3, leaf.hl2, GL_CLAMP_TO_EDGE, "leaf HL2");
  leaf_translucency =
      upload(leaf.width, leaf.height, 3, leaf.translucency, GL_CLAMP_TO_EDGE, "leaf translucency");
  const BarkTextureSet& bark = set.bark;
  bark_albedo = upload(bark.width, bark.height, 3, bark.albedo, GL_REPEAT, "bark albedo");
  bark_normal = upload(bark.width, bark.height, 3, bark.normal, GL_REPEAT, "bark normal");
}

}  // namespace boreas::render
