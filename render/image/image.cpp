// boreas images: the float RGB canvas.
#include "image/image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace boreas::render {

Rgb mix(Rgb a, Rgb b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("image size must be positive (got " + std::to_string(width) + "x" +
                                std::to_string(height) + ")");
  }
  rgb_.resize(size_t(width) * size_t(height) * 3);
  for (size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = fill.r;
    rgb_[i + 1] = fill.g;
    rgb_[i + 2] = fill.b;
  }
}

Rgb Image::at(int x, int y) const {
  size_t i = (size_t(y) * size_t(width_) + size_t(x)) * 3;
  return {rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  if (!contains(x, y)) return;
  size_t i = (size_t(y) * size_t(width_) + size_t(x)) * 3;
  rgb_[i] = c.r;
  rgb_[i + 1] = c.g;
  rgb_[i + 2] = c.b;
}

void Image::blend(int x, int y, Rgb c, float alpha) {
  if (!contains(x, y) || !(alpha > 0.0f)) return;
  set(x, y, mix(at(x, y), c, std::min(alpha, 1.0f)));
}

void Image::fill_rect(int x0, int y0, int x1, int y1, Rgb c, float alpha) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_);
  y1 = std::min(y1, height_);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) blend(x, y, c, alpha);
  }
}

void Image::paste(const Image& source, int x, int y) {
  for (int sy = 0; sy < source.height(); ++sy) {
    for (int sx = 0; sx < source.width(); ++sx) set(x + sx, y + sy, source.at(sx, sy));
  }
}

std::vector<uint8_t> Image::to_rgb8() const {
  std::vector<uint8_t> out(rgb_.size());
  for (size_t i = 0; i < rgb_.size(); ++i) {
    out[i] = static_cast<uint8_t>(std::lround(std::clamp(rgb_[i], 0.0f, 1.0f) * 255.0f));
  }
  return out;
}

}  // namespace boreas::render
