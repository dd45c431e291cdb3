// render tests: reads a PNG back with OpenImageIO, as 8-bit RGB.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <string>
#include <vector>

namespace boreas::render::testing {

struct Png {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<uint8_t> pixels;  // channels bytes per pixel, rows top to bottom

  const uint8_t* at(int x, int y) const {
    return &pixels[(size_t(y) * size_t(width) + size_t(x)) * size_t(channels)];
  }
};

// An empty Png (width 0) when the file cannot be read.
inline Png read_png(const std::string& path) {
  Png png;
  auto in = OIIO::ImageInput::open(path);
  if (!in) return png;
  const OIIO::ImageSpec& spec = in->spec();
  png.width = spec.width;
  png.height = spec.height;
  png.channels = spec.nchannels;
  png.pixels.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, png.pixels.data())) {
    png.width = 0;
  }
  in->close();
  return png;
}

}  // namespace boreas::render::testing
