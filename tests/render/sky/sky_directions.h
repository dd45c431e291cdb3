// sky tests: directions written out independently of preetham.cpp, so that a wrong
// convention there shows.
#pragma once

#include <cmath>
#include <glm/vec3.hpp>

namespace boreas::render::test {

constexpr double kPi = 3.14159265358979323846;

// Unit vector at an elevation and azimuth in degrees, azimuth from +X toward +Z (the
// convention of preetham.h).
inline glm::dvec3 toward(double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * kPi / 180.0;
  const double a = azimuth_deg * kPi / 180.0;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

}  // namespace boreas::render::test
