// boreas scenes: reading a meadow's terrain or nutrient image (PNG, EXR, TIFF, ...) through
// OpenImageIO into the pixel array the library takes (boreas_image). The library reads no
// image files, so this is where a scene's image keys become pixels.
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// An image's pixels as floats (an integer format's 0..max maps to 0..1), channel fastest,
// then x, then rows from the top row of the file.
struct GroundImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
  // The library's view of it; valid while this object lives.
  boreas_image view() const { return boreas_image{width, height, channels, pixels.data()}; }
};

// Reads a 2D image of at most BOREAS_IMAGE_MAX_FLOATS values. Throws
// boreas::Error(BOREAS_ERROR_IO) whose message names the path and what is wrong (missing,
// not an image, a volume, too large, a pixel that is not a finite number).
GroundImage read_ground_image(const std::string& path);

}  // namespace boreas::render
