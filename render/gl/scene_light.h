// boreas render: the light of a frame from the sky model (render/sky): the sun's direction
// and irradiance, the sky's irradiance on an upward surface integrated from Preetham's
// radiance, and what the ground throws back; and the exposure that puts a sunlit white
// surface near the top of the tone curve.
#pragma once

#include <glm/vec3.hpp>

#include "sky/preetham.h"

namespace boreas::render {

struct SceneLight {
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};  // unit, toward the sun
  glm::vec3 sun_irradiance{0.0f};       // klx, linear sRGB, at normal incidence (0 after sunset)
  glm::vec3 sky_irradiance{0.0f};       // klx on an upward surface
  glm::vec3 ground_irradiance{0.0f};    // klx on a downward surface, from the lit ground
};

// Ground albedo 0.15: grassland and soil (0.1-0.25 in the literature).
constexpr float kGroundAlbedo = 0.15f;

// The sky irradiance is the cosine-weighted integral of radiance_rgb over the upper
// hemisphere, by the midpoint rule on 32 x 64 cells in (cos^2 of the zenith angle,
// azimuth) (equal irradiance weight per cell: within 0.5 % of a 256 x 512 grid).
SceneLight scene_light(const SkyModel& sky, float ground_albedo = kGroundAlbedo);

// Display value per kcd/m^2 (the tone mapper's exposure): a white Lambertian surface lying
// in the open maps to 1.6 before Reinhard's curve, whatever the sun's height.
float automatic_exposure(const SceneLight& light);

}  // namespace boreas::render
