// boreas images: an RGB canvas in floats (0..1, sRGB-encoded values) that frames, legends
// and contact sheets are drawn on before they are written as 8-bit PNGs.
#pragma once

#include <cstdint>
#include <vector>

namespace boreas::render {

struct Rgb {
  float r = 0.0f;
  float g = 0.0f;
  float b = 0.0f;
};

Rgb mix(Rgb a, Rgb b, float t);

class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgb fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
  // Draws c over the pixel with the given opacity; pixels outside are ignored, so shapes
  // may run off the edge.
  void blend(int x, int y, Rgb c, float alpha);
  // Blends c over the pixels [x0, x1) x [y0, y1), clipped to the image.
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c, float alpha = 1.0f);
  // Copies source with its top-left corner at (x, y), clipped to the image.
  void paste(const Image& source, int x, int y);

  // 3 floats per pixel, rows top to bottom.
  const std::vector<float>& data() const { return rgb_; }
  std::vector<float>& data() { return rgb_; }
  // 3 bytes per pixel, rounded and clamped, for writing.
  std::vector<uint8_t> to_rgb8() const;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<float> rgb_;
};

}  // namespace boreas::render
