// boreas sky: Preetham, Shirley and Smits' analytic daylight model ("A Practical Analytic
// Model for Daylight", SIGGRAPH 1999) for the renderer's sky and sun light: a double-precision
// reference here, and the uniforms with which shaders/sky.glsl evaluates the same model per pixel.
//
// The model, in order (the formulas and coefficients are the paper's appendix A.2):
//   1. theta_s, the sun's zenith angle, from its elevation; held at 90 deg (the sun on the
//      horizon, at its azimuth) while the sun is below the horizon, where the fit has no data;
//   2. the zenith luminance and chromaticity from the turbidity T and theta_s:
//        chi = (4/9 - T/120) (pi - 2 theta_s)
//        Y_z = (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192          [kcd/m^2]
//        x_z = [T^2 T 1] M_x [theta_s^3 theta_s^2 theta_s 1]^T, y_z likewise with M_y;
//   3. the Perez coefficients A..E for Y, x and y, each linear in T;
//   4. in a view direction at zenith angle theta and at angle gamma from the sun,
//        value = zenith value * F(theta, gamma) / F(0, theta_s),
//        F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma),
//      for Y, x and y alike, so the zenith reproduces Y_z, x_z, y_z exactly;
//   5. CIE xyY -> XYZ -> linear sRGB (sky/color.h), negative (out of gamut) channels clamped.
//   Direct sunlight comes from the paper's appendix A.1, spectrally: sky/sunlight.h.
//
// Conventions: world Y is up; a sky direction points from the viewer toward the sky, the sun
// direction toward the sun. Azimuth is measured in the XZ plane from +X toward +Z: 0 deg = +X,
// 90 deg = +Z (clockwise seen from above in a right-handed frame with Y up).
//
// Units: sky radiance is linear sRGB scaled so that its CIE Y is the luminance in kcd/m^2
// (the unit of Y_z). Sunlight is linear sRGB whose Y is the direct normal illuminance in klx,
// so a Lambertian surface of albedo a facing the sun shows a / pi * sun_color in the sky's
// unit; one exposure serves both.
//
// Range: turbidity in [1.7, 10] (the fit was made for about 2..10: 2 very clear, 3 clear,
// 6 light haze, 10 haze). As T falls the luminance's zenith factor 1 + A_Y exp(B_Y) falls
// (0.17 at T = 2, 0.03 at 1.7) and crosses zero near T = 1.64, where the model breaks down:
// the zenith darkens and the horizon brightens relative to it, a known weakness of the fit
// (Zotti, Wilkie and Purgathofer, "A Critical Review of the Preetham Skylight Model", WSCG
// 2007). Hence the lower bound 1.7.
// Sun below the horizon, which Preetham does not model: the sky is evaluated with the sun on
// the horizon and faded to black over civil twilight (elevation 0 to -6 deg, smoothstep); the
// sunlight is scaled by the fraction of the sun's disc above the horizon, so it is gone once
// the disc has set (-0.27 deg). Refraction is ignored.
#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace boreas::render {

inline constexpr double kMinTurbidity = 1.7;
inline constexpr double kMaxTurbidity = 10.0;
// Sun elevation (deg) at which the sky has faded to black: the end of civil twilight.
inline constexpr double kTwilightEndDeg = -6.0;
// cos(theta) is held at or above this for view directions at or below the horizon (theta is
// 89.4 deg there): the horizon's value continues below it, where the renderer draws ground.
inline constexpr double kMinCosViewZenith = 0.01;

struct SkyParams {
  // Atmospheric turbidity, [1.7, 10]: 2 very clear, 3 clear, 6 light haze, 10 haze.
  double turbidity = 3.0;
  // The sun's angle above the horizon, degrees, [-90, 90].
  double sun_elevation_deg = 45.0;
  // The sun's azimuth, degrees in the XZ plane from +X (0) toward +Z (90); any finite value.
  double sun_azimuth_deg = 0.0;
};

// Throws std::invalid_argument naming the field and its value when params is out of range.
void validate(const SkyParams& params);

// Perez coefficients A..E (indices 0..4), each for the three quantities at once: .x for the
// luminance Y, .y for the chromaticity x, .z for the chromaticity y.
using PerezCoefficients = std::array<glm::dvec3, 5>;

// Preetham's Perez coefficients for a turbidity (appendix A.2).
PerezCoefficients preetham_perez_coefficients(double turbidity);

// (Y_z in kcd/m^2, x_z, y_z) for a turbidity and sun zenith angle in [0, pi/2] (appendix A.2).
glm::dvec3 preetham_zenith(double turbidity, double sun_zenith_rad);

// The Perez distribution F(theta, gamma) for Y, x and y, from cos(theta) (> 0) and
// cos(gamma) (in [-1, 1]).
glm::dvec3 perez_distribution(const PerezCoefficients& c, double cos_theta, double cos_gamma);

// What sky.glsl reads, as floats, in the order and meaning of its uniforms (names beside each
// field, and in kSkyUniformNames). Vectors are tightly packed floats, so `perez` uploads with
// one glUniform3fv(location, 5, &perez[0].x).
struct SkyUniforms {
  std::array<glm::vec3, 5> perez{};  // u_sky_perez: A..E for (Y, x, y)
  glm::vec3 zenith{};                // u_sky_zenith: (Y_z kcd/m^2, x_z, y_z)
  glm::vec3 inv_f0{};                // u_sky_inv_f0: 1 / F(0, theta_s) for (Y, x, y)
  glm::vec3 sun_dir{};               // u_sky_sun_dir: unit, toward the sun as the sky sees it
  float scale = 0.0f;                // u_sky_scale: exposure * twilight fade
  glm::vec3 disc_dir{};              // u_sky_disc_dir: unit, toward the sun's true position
  glm::vec3 disc_radiance{};         // u_sky_disc_radiance: the sun disc, exposure applied
  float disc_cos_radius = 1.0f;      // u_sky_disc_cos_radius: cos of the disc's angular radius
};
static_assert(sizeof(std::array<glm::vec3, 5>) == 15 * sizeof(float),
              "u_sky_perez uploads as 15 packed floats");

inline constexpr std::array<const char*, 8> kSkyUniformNames = {
    "u_sky_perez", "u_sky_zenith",   "u_sky_inv_f0",        "u_sky_sun_dir",
    "u_sky_scale", "u_sky_disc_dir", "u_sky_disc_radiance", "u_sky_disc_cos_radius",
};

// The model for one set of parameters, computed once (a frame) on the CPU.
struct SkyModel {
  // Validates params (std::invalid_argument naming the field) and computes the model.
  explicit SkyModel(const SkyParams& params);

  SkyParams params;
  // theta_s, radians, as the model uses it: pi/2 while the sun is below the horizon.
  double sun_zenith_rad = 0.0;
  PerezCoefficients perez{};
  // (Y_z kcd/m^2, x_z, y_z) for theta_s.
  glm::dvec3 zenith{};
  // 1 / F(0, theta_s) for (Y, x, y): the model's normalization.
  glm::dvec3 inv_f0{};
  // Unit, world, toward the sun's true position (below the horizon when it has set).
  glm::dvec3 sun_dir{};
  // Unit, toward the sun as the sky model sees it: sun_dir with the elevation held at 0 or
  // above.
  glm::dvec3 sky_sun_dir{};
  // Sky brightness factor: 1 with the sun above the horizon, 0 from kTwilightEndDeg down.
  double twilight_fade = 1.0;
  // Direct sunlight at the ground, linear sRGB; its Y is the direct normal illuminance, klx.
  // A sun within a few degrees of the horizon lies outside the sRGB gamut (deep orange-red):
  // its negative blue is clamped to 0.
  glm::dvec3 sun_color{};
  // The direct normal illuminance itself (CIE Y before that clamp), klx: about 100 for a
  // clear noon sun.
  double sun_illuminance_klx = 0.0;

  // (Y kcd/m^2 with the twilight fade, x, y) toward dir (any nonzero length).
  glm::dvec3 luminance_chromaticity(const glm::dvec3& dir) const;
  // Sky luminance toward dir, kcd/m^2.
  double luminance(const glm::dvec3& dir) const;
  // Sky radiance toward dir: linear sRGB, Y in kcd/m^2, negative channels clamped to 0. The
  // same math as boreas_preetham_sky() in sky.glsl (which multiplies by the exposure).
  glm::dvec3 radiance_rgb(const glm::dvec3& dir) const;
  // Radiance of the sun's disc (sun_color spread evenly over its solid angle), kcd/m^2.
  glm::dvec3 sun_disc_radiance() const;

  // The uniforms of sky.glsl; exposure (finite, >= 0) is the display value per kcd/m^2
  // (about 0.1 puts a clear noon zenith near 1). Throws std::invalid_argument otherwise.
  SkyUniforms uniforms(double exposure) const;
};

}  // namespace boreas::render
