// boreas scenes: ground images through OpenImageIO.
#include "scene/ground_image.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstddef>

#include "boreas/boreas.hpp"

namespace boreas::render {

namespace {

// The library refuses larger pixel arrays; refusing before reading keeps a wrong file from
// exhausting memory.
constexpr size_t kMaxImageValues = size_t(BOREAS_IMAGE_MAX_FLOATS);

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw boreas::Error(BOREAS_ERROR_IO, "cannot read image '" + path + "': " + why);
}

}  // namespace

GroundImage read_ground_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) fail(path, OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  GroundImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  if (image.width < 1 || image.height < 1 || image.channels < 1 || spec.depth > 1) {
    fail(path, "it is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                   " x " + std::to_string(spec.depth) + " with " + std::to_string(image.channels) +
                   " channels, not a 2D image");
  }
  const size_t values = size_t(image.width) * size_t(image.height) * size_t(image.channels);
  if (values > kMaxImageValues) {
    fail(path, std::to_string(image.width) + " x " + std::to_string(image.height) + " x " +
                   std::to_string(image.channels) + " values is more than the " +
                   std::to_string(kMaxImageValues) + " a ground map may have");
  }
  image.pixels.resize(values);
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    fail(path, in->geterror());
  }
  for (size_t i = 0; i < values; ++i) {
    if (!std::isfinite(image.pixels[i])) {
      const size_t pixel = i / size_t(image.channels);
      fail(path, "pixel (" + std::to_string(pixel % size_t(image.width)) + ", " +
                     std::to_string(pixel / size_t(image.width)) + ") is not a finite number");
    }
  }
  return image;
}

}  // namespace boreas::render
