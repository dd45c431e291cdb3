// boreas images: OpenEXR output.
#include "image/exr_io.h"

#include <OpenImageIO/imageio.h>

#include "image/png_io.h"

namespace boreas::render {

void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3) {
    throw ImageWriteError(path + ": " + std::to_string(rgb.size()) + " values for a " + std::to_string(width) + " x " +
                          std::to_string(height) + " RGB image");
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw ImageWriteError(path + ": cannot write images: " + OIIO::geterror());
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::HALF);
  spec.attribute("compression", "zip");
  // OpenEXR stamps the second of writing otherwise.
  spec.attribute("DateTime", "");
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close()) {
    throw ImageWriteError(path + ": " + out->geterror());
  }
}

}  // namespace boreas::render
