// boreas render: sun, sky and ground light for a frame.
#include "gl/scene_light.h"

#include <algorithm>
#include <cmath>

namespace boreas::render {

SceneLight scene_light(const SkyModel& sky, float ground_albedo) {
  SceneLight light;
  light.sun_dir = glm::vec3(sky.sun_dir);
  // Below the horizon the sun lights nothing directly.
  light.sun_irradiance = sky.sun_dir.y > 0.0 ? glm::vec3(sky.sun_color) : glm::vec3(0.0f);
  // E = integral of L cos(theta) d(omega); with s = cos^2(theta), cos(theta) d(omega) =
  // ds dphi / 2, so equal cells in (s, phi) carry equal weight.
  constexpr int kRings = 32, kSectors = 64;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kRings; ++i) {
    double cos_theta = std::sqrt((i + 0.5) / kRings);
    double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
    for (int j = 0; j < kSectors; ++j) {
      double phi = 2.0 * M_PI * (j + 0.5) / kSectors;
      glm::dvec3 dir(sin_theta * std::cos(phi), cos_theta, sin_theta * std::sin(phi));
      sum += sky.radiance_rgb(dir);
    }
  }
  double cell = (1.0 / kRings) * (2.0 * M_PI / kSectors) * 0.5;
  light.sky_irradiance = glm::vec3(sum * cell);
  glm::vec3 on_ground = light.sun_irradiance * std::max(light.sun_dir.y, 0.0f) + light.sky_irradiance;
  // A uniformly bright ground of radiance rho E / pi gives a downward surface rho E.
  light.ground_irradiance = ground_albedo * on_ground;
  return light;
}

float automatic_exposure(const SceneLight& light) {
  glm::vec3 e = light.sun_irradiance * std::max(light.sun_dir.y, 0.0f) + light.sky_irradiance;
  float luminance = 0.2126f * e.x + 0.7152f * e.y + 0.0722f * e.z;
  float white_radiance = luminance / float(M_PI);  // kcd/m^2 of a white surface
  return 1.6f / std::max(white_radiance, 1e-6f);
}

}  // namespace boreas::render
