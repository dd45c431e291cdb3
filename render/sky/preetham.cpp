// boreas sky: the Preetham daylight model in double precision and the uniforms of sky.glsl;
// the equations, conventions and units are in preetham.h.
#include "sky/preetham.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sky/color.h"
#include "sky/sunlight.h"

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Appendix A.2: each Perez coefficient is slope * T + offset, A..E in order.
struct Linear {
  double slope;
  double offset;
};
// clang-format off
constexpr Linear kPerezLuminance[5] = {
    {0.1787, -1.4630}, {-0.3554, 0.4275}, {-0.0227, 5.3251}, {0.1206, -2.5771}, {-0.0670, 0.3703}};
constexpr Linear kPerezChromaX[5] = {
    {-0.0193, -0.2592}, {-0.0665, 0.0008}, {-0.0004, 0.2125}, {-0.0641, -0.8989},
    {-0.0033, 0.0452}};
constexpr Linear kPerezChromaY[5] = {
    {-0.0167, -0.2608}, {-0.0950, 0.0092}, {-0.0079, 0.2102}, {-0.0441, -1.6537},
    {-0.0109, 0.0529}};
// clang-format on

// Appendix A.2: x_z = [T^2 T 1] M [theta_s^3 theta_s^2 theta_s 1]^T, rows for T^2, T and 1.
constexpr double kZenithChromaX[3][4] = {
    {0.00166, -0.00375, 0.00209, 0.0},
    {-0.02903, 0.06377, -0.03202, 0.00394},
    {0.11693, -0.21196, 0.06052, 0.25886},
};
constexpr double kZenithChromaY[3][4] = {
    {0.00275, -0.00610, 0.00317, 0.0},
    {-0.04214, 0.08970, -0.04153, 0.00516},
    {0.15346, -0.26756, 0.06670, 0.26688},
};

double radians(double degrees) { return degrees * kPi / 180.0; }

// Unit vector at an elevation and azimuth (degrees); azimuth from +X toward +Z.
glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
  const double e = radians(elevation_deg);
  const double a = radians(azimuth_deg);
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

double zenith_chromaticity(const double (&m)[3][4], double turbidity, double theta_s) {
  const double t[4] = {theta_s * theta_s * theta_s, theta_s * theta_s, theta_s, 1.0};
  const double T[3] = {turbidity * turbidity, turbidity, 1.0};
  double sum = 0.0;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 4; ++col) sum += T[row] * m[row][col] * t[col];
  }
  return sum;
}

// Smooth fade of the sky over civil twilight: 1 at elevation 0 and above, 0 at -6 deg.
double twilight_fade_at(double elevation_deg) {
  const double t = std::clamp((elevation_deg - kTwilightEndDeg) / -kTwilightEndDeg, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Fraction of the sun's disc above the horizon (a flat horizon, no refraction): the area of a
// unit circle above a chord at signed distance d = elevation / radius from its center.
double visible_disc_fraction(double elevation_deg) {
  const double d = std::clamp(radians(elevation_deg) / kSunAngularRadiusRad, -1.0, 1.0);
  return 1.0 - (std::acos(d) - d * std::sqrt(1.0 - d * d)) / kPi;
}

std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

void validate(const SkyParams& params) {
  if (!(params.turbidity >= kMinTurbidity && params.turbidity <= kMaxTurbidity)) {
    throw std::invalid_argument(
        "SkyParams.turbidity must be in [1.7, 10] (Preetham's fit covers very clear (2) to "
        "hazy (10) skies), got " +
        text(params.turbidity));
  }
  if (!(params.sun_elevation_deg >= -90.0 && params.sun_elevation_deg <= 90.0)) {
    throw std::invalid_argument("SkyParams.sun_elevation_deg must be in [-90, 90] degrees, got " +
                                text(params.sun_elevation_deg));
  }
  if (!std::isfinite(params.sun_azimuth_deg)) {
    throw std::invalid_argument("SkyParams.sun_azimuth_deg must be finite (degrees), got " +
                                text(params.sun_azimuth_deg));
  }
}

PerezCoefficients preetham_perez_coefficients(double turbidity) {
  PerezCoefficients c;
  for (int i = 0; i < 5; ++i) {
    c[i] = {kPerezLuminance[i].slope * turbidity + kPerezLuminance[i].offset,
            kPerezChromaX[i].slope * turbidity + kPerezChromaX[i].offset,
            kPerezChromaY[i].slope * turbidity + kPerezChromaY[i].offset};
  }
  return c;
}

glm::dvec3 preetham_zenith(double turbidity, double sun_zenith_rad) {
  const double chi = (4.0 / 9.0 - turbidity / 120.0) * (kPi - 2.0 * sun_zenith_rad);
  const double luminance =
      (4.0453 * turbidity - 4.9710) * std::tan(chi) - 0.2155 * turbidity + 2.4192;
  return {luminance, zenith_chromaticity(kZenithChromaX, turbidity, sun_zenith_rad),
          zenith_chromaticity(kZenithChromaY, turbidity, sun_zenith_rad)};
}

glm::dvec3 perez_distribution(const PerezCoefficients& c, double cos_theta, double cos_gamma) {
  const double gamma = std::acos(cos_gamma);
  return (1.0 + c[0] * glm::exp(c[1] / cos_theta)) *
         (1.0 + c[2] * glm::exp(c[3] * gamma) + c[4] * (cos_gamma * cos_gamma));
}

SkyModel::SkyModel(const SkyParams& p) : params(p) {
  validate(p);
  const double sky_elevation_deg = std::max(p.sun_elevation_deg, 0.0);
  sun_zenith_rad = radians(90.0 - sky_elevation_deg);
  sun_dir = direction(p.sun_elevation_deg, p.sun_azimuth_deg);
  sky_sun_dir = direction(sky_elevation_deg, p.sun_azimuth_deg);
  perez = preetham_perez_coefficients(p.turbidity);
  zenith = preetham_zenith(p.turbidity, sun_zenith_rad);
  // F(0, theta_s) exactly as a view straight up evaluates it (cos gamma = sky_sun_dir.y), so
  // the zenith reproduces Y_z, x_z, y_z to rounding.
  inv_f0 = 1.0 / perez_distribution(perez, 1.0, sky_sun_dir.y);
  twilight_fade = twilight_fade_at(p.sun_elevation_deg);

  const glm::dvec3 sun_xyz =
      sunlight_xyz_klx(p.turbidity, sun_zenith_rad) * visible_disc_fraction(p.sun_elevation_deg);
  sun_illuminance_klx = sun_xyz.y;
  sun_color = glm::max(linear_srgb_from_xyz(sun_xyz), glm::dvec3(0.0));
}

glm::dvec3 SkyModel::luminance_chromaticity(const glm::dvec3& dir) const {
  const glm::dvec3 v = glm::normalize(dir);
  const double cos_theta = std::max(v.y, kMinCosViewZenith);
  const double cos_gamma = std::clamp(glm::dot(v, sky_sun_dir), -1.0, 1.0);
  glm::dvec3 Yxy = zenith * inv_f0 * perez_distribution(perez, cos_theta, cos_gamma);
  Yxy.x *= twilight_fade;
  return Yxy;
}

double SkyModel::luminance(const glm::dvec3& dir) const { return luminance_chromaticity(dir).x; }

glm::dvec3 SkyModel::radiance_rgb(const glm::dvec3& dir) const {
  return glm::max(linear_srgb_from_xyz(xyz_from_Yxy(luminance_chromaticity(dir))), glm::dvec3(0.0));
}

glm::dvec3 SkyModel::sun_disc_radiance() const { return sun_color / sun_solid_angle_sr(); }

SkyUniforms SkyModel::uniforms(double exposure) const {
  if (!(exposure >= 0.0 && std::isfinite(exposure))) {
    throw std::invalid_argument(
        "SkyModel::uniforms: exposure (display value per kcd/m^2) must be finite and >= 0, "
        "got " +
        text(exposure));
  }
  SkyUniforms u;
  for (int i = 0; i < 5; ++i) u.perez[i] = glm::vec3(perez[i]);
  u.zenith = glm::vec3(zenith);
  u.inv_f0 = glm::vec3(inv_f0);
  u.sun_dir = glm::vec3(sky_sun_dir);
  u.scale = float(exposure * twilight_fade);
  u.disc_dir = glm::vec3(sun_dir);
  u.disc_radiance = glm::vec3(sun_disc_radiance() * exposure);
  u.disc_cos_radius = float(std::cos(kSunAngularRadiusRad));
  return u;
}

}  // namespace boreas::render
