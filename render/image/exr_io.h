// boreas images: HDR frames as OpenEXR (half floats, linear RGB) through OpenImageIO.
#pragma once

#include <string>
#include <vector>

namespace boreas::render {

// rgb: width * height * 3 linear floats, rows top to bottom. Throws ImageWriteError
// (png_io.h) naming the file. The same pixels write the same bytes (no time stamp).
void write_exr(const std::string& path, int width, int height, const std::vector<float>& rgb);

}  // namespace boreas::render
