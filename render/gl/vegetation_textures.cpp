// boreas render: uploading the texture set.
#include "gl/vegetation_textures.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace boreas::render {

namespace {

void check_texels(int width, int height, int channels, const std::vector<float>& texels,
                  const std::string& what) {
  if (width <= 0 || height <= 0 || texels.size() != size_t(width) * size_t(height) * size_t(channels)) {
    throw std::invalid_argument("texture " + what + ": " + std::to_string(texels.size()) +
                                " values for " + std::to_string(width) + " x " +
                                std::to_string(height) + " texels of " + std::to_string(channels) +
                                " channels");
  }
}

int mip_levels(int width, int height) {
  return 1 + int(std::floor(std::log2(double(std::max(width, height)))));
}

void set_sampling(const GlObject& texture, GLenum wrap) {
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GLint(wrap));
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GLint(wrap));
}

GLenum internal_format(int channels) { return channels == 4 ? GL_RGBA16F : GL_RGB16F; }
GLenum pixel_format(int channels) { return channels == 4 ? GL_RGBA : GL_RGB; }

GlObject upload(int width, int height, int channels, const std::vector<float>& texels, GLenum wrap,
                const char* what) {
  check_texels(width, height, channels, texels, what);
  GlObject texture = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), mip_levels(width, height), internal_format(channels), width,
                     height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, pixel_format(channels), GL_FLOAT,
                      texels.data());
  glGenerateTextureMipmap(texture.id());
  set_sampling(texture, wrap);
  return texture;
}

// One layer per map in layers (each width x height), mipmapped by the driver.
GlObject upload_layers(int width, int height, int channels,
                       const std::vector<const std::vector<float>*>& layers, const char* what) {
  GlObject texture = make_texture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(texture.id(), mip_levels(width, height), internal_format(channels), width,
                     height, GLsizei(layers.size()));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t layer = 0; layer < layers.size(); ++layer) {
    check_texels(width, height, channels, *layers[layer],
                 std::string(what) + " (layer " + std::to_string(layer) + ")");
    glTextureSubImage3D(texture.id(), 0, 0, 0, GLint(layer), width, height, 1,
                        pixel_format(channels), GL_FLOAT, layers[layer]->data());
  }
  glGenerateTextureMipmap(texture.id());
  set_sampling(texture, GL_CLAMP_TO_EDGE);
  return texture;
}

// The fraction of texels whose alpha, times scale, passes the leaf shader's alpha test.
constexpr float kAlphaTest = 0.5f;
double coverage(const std::vector<float>& rgba, float scale) {
  size_t pass = 0, n = rgba.size() / 4;
  for (size_t i = 0; i < n; ++i) pass += rgba[4 * i + 3] * scale >= kAlphaTest;
  return n ? double(pass) / double(n) : 0.0;
}

// The leaf albedo with its mip chain made on the host: a 2x2 box filter, then each level's
// alpha scaled so that as many texels pass the alpha test as at level 0 (Castano 2010).
// Plain averaging thins a leaf's coverage level by level until distant leaves vanish.
void write_alpha_tested_mips(const GlObject& texture, int width, int height, GLint layer,
                             const std::vector<float>& rgba) {
  const double target = coverage(rgba, 1.0f);
  std::vector<float> level = rgba;
  int w = width, h = height;
  for (int mip = 1; w > 1 || h > 1; ++mip) {
    int nw = std::max(w / 2, 1), nh = std::max(h / 2, 1);
    std::vector<float> next(size_t(nw) * size_t(nh) * 4, 0.0f);
    for (int y = 0; y < nh; ++y) {
      for (int x = 0; x < nw; ++x) {
        for (int c = 0; c < 4; ++c) {
          float sum = 0.0f;
          for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
              int sx = std::min(2 * x + dx, w - 1), sy = std::min(2 * y + dy, h - 1);
              sum += level[(size_t(sy) * size_t(w) + size_t(sx)) * 4 + size_t(c)];
            }
          }
          next[(size_t(y) * size_t(nw) + size_t(x)) * 4 + size_t(c)] = 0.25f * sum;
        }
      }
    }
    // Bisection on the scale: coverage grows with it.
    float lo = 0.0f, hi = 64.0f;
    for (int i = 0; i < 24; ++i) {
      float mid = 0.5f * (lo + hi);
      (coverage(next, mid) < target ? lo : hi) = mid;
    }
    std::vector<float> scaled = next;
    for (size_t i = 3; i < scaled.size(); i += 4) scaled[i] = std::min(scaled[i] * hi, 1.0f);
    glTextureSubImage3D(texture.id(), mip, 0, 0, layer, nw, nh, 1, GL_RGBA, GL_FLOAT,
                        scaled.data());
    level = std::move(next);
    w = nw;
    h = nh;
  }
}

GlObject upload_alpha_tested(int width, int height,
                             const std::vector<const std::vector<float>*>& layers,
                             const char* what) {
  GlObject texture = upload_layers(width, height, 4, layers, what);
  for (size_t layer = 0; layer < layers.size(); ++layer) {
    write_alpha_tested_mips(texture, width, height, GLint(layer), *layers[layer]);
  }
  return texture;
}

}  // namespace

VegetationTextures::VegetationTextures(const TextureSet& set, const LeafShape& shape)
    : leaf_shape(shape) {
  const LeafTextureSet& leaf = set.leaf;
  std::vector<const LeafTextureSet*> maps{&leaf};
  leaf_layers.push_back("");
  for (const KindLeafTextures& kind : set.kind_leaves) {
    if (kind.maps.width != leaf.width || kind.maps.height != leaf.height) {
      throw std::invalid_argument("texture leaf kind '" + kind.kind +
                                  "': " + std::to_string(kind.maps.width) + " x " +
                                  std::to_string(kind.maps.height) + " texels, the leaf's are " +
                                  std::to_string(leaf.width) + " x " + std::to_string(leaf.height));
    }
    maps.push_back(&kind.maps);
    leaf_layers.push_back(kind.kind);
  }
  for (const LeafTextureSet* m : maps) {
    glm::dvec3 sum(0.0);
    size_t n = 0;
    for (size_t i = 0; i * 4 + 3 < m->albedo.size() && i * 3 + 2 < m->translucency.size(); ++i) {
      if (m->albedo[i * 4 + 3] < 1.0f) continue;
      sum += glm::dvec3(m->translucency[i * 3], m->translucency[i * 3 + 1],
                        m->translucency[i * 3 + 2]);
      ++n;
    }
    leaf_transmittance.push_back(n ? glm::vec3(sum / double(n)) : glm::vec3(0.1f));
  }
  auto layers = [&](std::vector<float> LeafTextureSet::*member) {
    std::vector<const std::vector<float>*> out;
    for (const LeafTextureSet* m : maps) out.push_back(&(m->*member));
    return out;
  };
  leaf_albedo =
      upload_alpha_tested(leaf.width, leaf.height, layers(&LeafTextureSet::albedo), "leaf albedo");
  leaf_normal =
      upload_layers(leaf.width, leaf.height, 3, layers(&LeafTextureSet::normal), "leaf normal");
  leaf_hl2 = upload_layers(leaf.width, leaf.height, 3, layers(&LeafTextureSet::hl2), "leaf HL2");
  leaf_translucency = upload_layers(leaf.width, leaf.height, 3,
                                    layers(&LeafTextureSet::translucency), "leaf translucency");
  const BarkTextureSet& bark = set.bark;
  bark_albedo = upload(bark.width, bark.height, 3, bark.albedo, GL_REPEAT, "bark albedo");
  bark_normal = upload(bark.width, bark.height, 3, bark.normal, GL_REPEAT, "bark normal");
}

int VegetationTextures::leaf_layer(const std::string& kind) const {
  for (size_t i = 1; i < leaf_layers.size(); ++i) {
    if (leaf_layers[i] == kind) return int(i);
  }
  return 0;
}

}  // namespace boreas::render
