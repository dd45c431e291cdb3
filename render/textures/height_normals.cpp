// boreas textures: finite-difference normals of a height field.
#include "textures/height_normals.h"

#include <cmath>
#include <string>

#include "textures/texture_error.h"

namespace boreas::render {
namespace {

// The two neighbours of index i along an axis of n texels and the distance between them in
// texels: (i - 1, i + 1, 2) inside, wrapped or one-sided at the edges.
struct Neighbours {
  int before;
  int after;
  double span;
};

Neighbours neighbours(int i, int n, HeightEdges edges) {
  if (n == 1) return {0, 0, 1.0};
  if (edges == HeightEdges::kWrap) return {(i + n - 1) % n, (i + 1) % n, 2.0};
  int before = i > 0 ? i - 1 : i;
  int after = i < n - 1 ? i + 1 : i;
  return {before, after, double(after - before)};
}

}  // namespace

std::vector<float> normals_from_height(const std::vector<double>& height, int width,
                                       int height_texels, double texel_x, double texel_y,
                                       HeightEdges edges) {
  if (width < 1 || height_texels < 1 ||
      height.size() != static_cast<size_t>(width) * height_texels) {
    throw TextureError("normals_from_height: height has " + std::to_string(height.size()) +
                       " values for " + std::to_string(width) + " x " +
                       std::to_string(height_texels) + " texels");
  }
  if (!(texel_x > 0.0) || !(texel_y > 0.0)) {
    throw TextureError("normals_from_height: texel sizes must be > 0");
  }
  std::vector<float> normals(static_cast<size_t>(width) * height_texels * 3);
  for (int y = 0; y < height_texels; ++y) {
    Neighbours ny = neighbours(y, height_texels, edges);
    for (int x = 0; x < width; ++x) {
      Neighbours nx = neighbours(x, width, edges);
      double dhdx = (height[size_t(y) * width + nx.after] - height[size_t(y) * width + nx.before]) /
                    (nx.span * texel_x);
      double dhdy = (height[size_t(ny.after) * width + x] - height[size_t(ny.before) * width + x]) /
                    (ny.span * texel_y);
      double inv = 1.0 / std::sqrt(dhdx * dhdx + dhdy * dhdy + 1.0);
      float* n = &normals[(size_t(y) * width + x) * 3];
      n[0] = float(-dhdx * inv);
      n[1] = float(-dhdy * inv);
      n[2] = float(inv);
    }
  }
  return normals;
}

}  // namespace boreas::render
