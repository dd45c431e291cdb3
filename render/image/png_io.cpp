// boreas images: PNG output via OpenImageIO's ImageOutput.
#include "image/png_io.h"

#include <OpenImageIO/imageio.h>

namespace boreas::render {

void write_png(const std::string& path, const Image& image) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw ImageWriteError(path + ": cannot write images: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width(), image.height(), 3, OIIO::TypeDesc::UINT8);
  // zlib level 3 of 9: frames are written every run, and the higher levels cost about
  // twice the time for a few percent of size.
  spec.attribute("png:compressionLevel", 3);
  std::vector<uint8_t> pixels = image.to_rgb8();
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) ||
      !out->close()) {
    throw ImageWriteError(path + ": " + out->geterror());
  }
}

}  // namespace boreas::render
