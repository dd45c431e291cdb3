// boreas images: writing canvases as 8-bit RGB PNGs through OpenImageIO.
#pragma once

#include <stdexcept>
#include <string>

#include "image/image.h"

namespace boreas::render {

// A file that could not be written; the message names it and says why.
class ImageWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes image to path (PNG, by the extension); throws ImageWriteError.
void write_png(const std::string& path, const Image& image);

}  // namespace boreas::render
