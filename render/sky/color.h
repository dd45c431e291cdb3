// boreas sky: CIE xyY -> XYZ -> linear sRGB, in double, for the daylight model and the
// sunlight spectrum. sky.glsl holds the same matrix for the GPU.
#pragma once

#include <glm/vec3.hpp>

namespace boreas::render {

// (Y, x, y) -> (X, Y, Z); y must be nonzero (it is about 0.24..0.42 for daylight).
inline glm::dvec3 xyz_from_Yxy(const glm::dvec3& Yxy) {
  const double Y = Yxy.x;
  const double x = Yxy.y;
  const double y = Yxy.z;
  return {x / y * Y, Y, (1.0 - x - y) / y * Y};
}

// CIE XYZ -> linear sRGB: IEC 61966-2-1 primaries and D65 white, no white adaptation, so
// daylight keeps its own color (a 5800 K sun is slightly warm, a clear zenith blue). Colors
// outside the sRGB gamut come out with a negative channel; callers clamp.
inline glm::dvec3 linear_srgb_from_xyz(const glm::dvec3& xyz) {
  return {3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
          -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
          0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z};
}

}  // namespace boreas::render
