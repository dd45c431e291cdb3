// sky tests: direct sunlight after the atmosphere: the transmittance formulas against hand
// evaluations, the spectral tables against known totals, and the sun's brightness and color
// as the sun and the haze change.
#include "sky/sunlight.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sky/preetham.h"

namespace boreas::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

SkyModel model(double turbidity, double elevation_deg) {
  SkyParams params;
  params.turbidity = turbidity;
  params.sun_elevation_deg = elevation_deg;
  return SkyModel(params);
}

// r1 / b1 > r0 / b0 without dividing: a low sun's blue channel clamps to 0 (its color lies
// outside the sRGB gamut), which counts as redder than any color with some blue.
bool redder(const glm::dvec3& rgb, const glm::dvec3& than) {
  return rgb.x * than.z > than.x * rgb.z;
}

// CIE x chromaticity, which grows from white toward red along the daylight locus.
double chromaticity_x(const glm::dvec3& xyz) { return xyz.x / (xyz.x + xyz.y + xyz.z); }

TEST(SunlightSpectrum, TransmittanceMatchesHandEvaluation) {
  // Air mass: 1 / (cos theta + 0.15 (93.885 - theta_deg)^-1.253).
  EXPECT_NEAR(relative_air_mass(0.0), 0.999493932591203, 1e-12);
  EXPECT_NEAR(relative_air_mass(kPi / 2.0), 36.5103245002888, 1e-9);
  // 550 nm, T = 2, sun at the zenith: Rayleigh exp(-0.008735 * 0.55^-4.08 m), aerosol
  // exp(-(0.04608 * 2 - 0.04586) 0.55^-1.3 m), ozone exp(-0.085 * 0.35 m); no gas or water
  // band there.
  const double m = 0.999493932591203;
  const double rayleigh = std::exp(-0.008735 * std::pow(0.55, -4.08) * m);
  const double aerosol = std::exp(-0.0463 * std::pow(0.55, -1.3) * m);
  const double ozone = std::exp(-0.085 * 0.35 * m);
  EXPECT_NEAR(rayleigh, 0.904761697608396, 1e-12);
  EXPECT_NEAR(sun_transmittance(550.0, 2.0, 0.0), rayleigh * aerosol * ozone, 1e-12);
  EXPECT_NEAR(sun_transmittance(550.0, 2.0, 0.0), 0.794147379421374, 1e-12);
  // The oxygen A band at 760 nm and the water band at 720 nm absorb.
  EXPECT_LT(sun_transmittance(760.0, 3.0, 0.0), 0.8 * sun_transmittance(750.0, 3.0, 0.0));
  EXPECT_LT(sun_transmittance(720.0, 3.0, 0.0), 0.95 * sun_transmittance(710.0, 3.0, 0.0));
  // Blue is scattered out more than red, more so through more air.
  EXPECT_LT(sun_transmittance(450.0, 3.0, 0.0), sun_transmittance(650.0, 3.0, 0.0));
  EXPECT_LT(sun_transmittance(450.0, 3.0, 1.4), sun_transmittance(450.0, 3.0, 0.0));
}

TEST(SunlightSpectrum, AbsorptionTablesMatchIqbal) {
  // Table entries (1/cm): ozone 0.125 at 600 nm, mixed gases 3.0 at 760 nm, water vapour 1.0
  // at 720 nm; between entries the tables interpolate linearly.
  EXPECT_DOUBLE_EQ(atmosphere_absorption_per_cm(600.0).x, 0.125);
  EXPECT_DOUBLE_EQ(atmosphere_absorption_per_cm(760.0).y, 3.0);
  EXPECT_DOUBLE_EQ(atmosphere_absorption_per_cm(720.0).z, 1.0);
  EXPECT_NEAR(atmosphere_absorption_per_cm(577.5).x, 0.121, 1e-12);
  EXPECT_NEAR(atmosphere_absorption_per_cm(725.0).z, 0.935, 1e-12);
  EXPECT_NEAR(atmosphere_absorption_per_cm(380.0).x, 0.003 * 25.0 / 90.0, 1e-12);
  EXPECT_EQ(atmosphere_absorption_per_cm(550.0).y, 0.0);
  EXPECT_EQ(atmosphere_absorption_per_cm(550.0).z, 0.0);
  // Integrals over 380-780 nm of the published tables (linear between entries), computed
  // separately from all 64, 4 and 13 entries: a changed entry changes them.
  glm::dvec3 integral(0.0);
  for (double nm = 380.0; nm <= 780.0; nm += 1.0) {
    const double weight = (nm == 380.0 || nm == 780.0) ? 0.5 : 1.0;
    integral += weight * atmosphere_absorption_per_cm(nm);
  }
  EXPECT_NEAR(integral.x, 17.2170833333, 1e-9);
  EXPECT_NEAR(integral.y, 17.655, 1e-9);
  EXPECT_NEAR(integral.z, 19.7762, 1e-9);
}

TEST(SunlightSpectrum, ColorMatchingFunctionsFitTheCieTable) {
  // CIE 1931 2-degree values: y_bar(555) = 1.0000, x_bar(600) = 1.0622, z_bar(450) = 1.7721,
  // x_bar(445) = 0.3481; the fit is within about 2 % of them.
  EXPECT_NEAR(cie_1931_color_matching(555.0).y, 1.0000, 0.02);
  EXPECT_NEAR(cie_1931_color_matching(600.0).x, 1.0622, 0.02);
  EXPECT_NEAR(cie_1931_color_matching(450.0).z, 1.7721, 0.03);
  EXPECT_NEAR(cie_1931_color_matching(445.0).x, 0.3481, 0.02);
  // The fit itself (Wyman, Sloan and Shirley's lobes, evaluated separately) at the peaks of
  // some of its lobes.
  const double nms[4] = {442.0, 530.9, 600.0, 459.0};
  const glm::dvec3 fit[4] = {{0.36120352871394, 0.0212367768817284, 1.75525603622704},
                             {0.169683948000527, 0.8782971248858, 0.0405470939911039},
                             {1.05592570314339, 0.634432074806952, 4.3013480626366e-05},
                             {0.288917529471004, 0.0530030572669855, 1.690707231412}};
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(cie_1931_color_matching(nms[i])[c], fit[i][c], 1e-12) << nms[i] << " " << c;
    }
  }
  // The three integrals are equal (equal-energy white is x = y = 1/3), 106.86 nm each.
  glm::dvec3 integral(0.0);
  for (double nm = 360.0; nm <= 830.0; nm += 1.0) integral += cie_1931_color_matching(nm);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral[c], 106.86, 0.02 * 106.86) << c;
}

TEST(SunlightSpectrum, SolarTableGivesTheSolarConstantsLuminance) {
  // Outside the atmosphere the sun gives about 128 klx (the luminous solar constant, quoted
  // between 127 and 134 klx); the table is radiance, so irradiance needs the disc's
  // solid angle.
  EXPECT_NEAR(sun_solid_angle_sr(), 6.7943107064622e-05, 1e-15);
  double y = 0.0;
  for (double nm = 380.0; nm <= 780.0; nm += 1.0) {
    y += solar_spectral_radiance(nm) * cie_1931_color_matching(nm).y;
  }
  const double klx = 683.0 * y * sun_solid_angle_sr() / 1000.0;
  EXPECT_GT(klx, 120.0);
  EXPECT_LT(klx, 136.0);
  // The integral of the whole table (linear between entries), 380-750 nm: a changed entry
  // changes it.
  double integral = 0.0;
  for (double nm = 380.0; nm <= 750.0; nm += 1.0) {
    integral += (nm == 380.0 || nm == 750.0 ? 0.5 : 1.0) * solar_spectral_radiance(nm);
  }
  EXPECT_NEAR(integral, 8942664.0, 1e-3);
  // Table ends: 380 nm and 750 nm, held beyond.
  EXPECT_DOUBLE_EQ(solar_spectral_radiance(380.0), 16559.0);
  EXPECT_DOUBLE_EQ(solar_spectral_radiance(750.0), 18259.2);
  EXPECT_DOUBLE_EQ(solar_spectral_radiance(780.0), 18259.2);
  EXPECT_DOUBLE_EQ(solar_spectral_radiance(485.0), 0.5 * (30663.7 + 28830.4));
}

TEST(Sunlight, ClearNoonSunGivesAboutAHundredKilolux) {
  const SkyModel noon = model(2.0, 90.0);
  EXPECT_GT(noon.sun_illuminance_klx, 85.0);
  EXPECT_LT(noon.sun_illuminance_klx, 115.0);
  EXPECT_NEAR(noon.sun_illuminance_klx, sunlight_xyz_klx(2.0, 0.0).y, 1e-12);
  // Near white: the chromaticity of a clear noon sun lies close to D65 (0.3127, 0.3290),
  // a little warmer.
  const glm::dvec3 xyz = sunlight_xyz_klx(2.0, 0.0);
  const double x = xyz.x / (xyz.x + xyz.y + xyz.z);
  const double y = xyz.y / (xyz.x + xyz.y + xyz.z);
  EXPECT_GT(x, 0.3127);
  EXPECT_LT(x, 0.345);
  EXPECT_GT(y, 0.3127);
  EXPECT_LT(y, 0.36);
}

TEST(Sunlight, LowSunIsRedderAndDimmer) {
  for (double turbidity : {2.0, 3.0, 6.0}) {
    SkyModel previous = model(turbidity, 90.0);
    for (double elevation : {60.0, 30.0, 15.0, 5.0, 2.0}) {
      const SkyModel sky = model(turbidity, elevation);
      EXPECT_LT(sky.sun_illuminance_klx, previous.sun_illuminance_klx)
          << turbidity << " " << elevation;
      EXPECT_GT(chromaticity_x(sunlight_xyz_klx(turbidity, sky.sun_zenith_rad)),
                chromaticity_x(sunlight_xyz_klx(turbidity, previous.sun_zenith_rad)))
          << turbidity << " " << elevation;
      if (elevation >= 5.0) {
        EXPECT_TRUE(redder(sky.sun_color, previous.sun_color)) << turbidity << " " << elevation;
      }
      previous = sky;
    }
  }
  // A clear noon sun is near white; near the horizon it is orange-red.
  const glm::dvec3 noon = model(3.0, 90.0).sun_color;
  const glm::dvec3 low = model(3.0, 5.0).sun_color;
  EXPECT_LT(noon.x / noon.z, 1.5);
  EXPECT_GT(low.x / low.z, 10.0);
}

TEST(Sunlight, HazeDimsAndReddensTheSun) {
  SkyModel previous = model(2.0, 40.0);
  for (double turbidity : {3.0, 5.0, 8.0, 10.0}) {
    const SkyModel sky = model(turbidity, 40.0);
    EXPECT_LT(sky.sun_illuminance_klx, previous.sun_illuminance_klx) << turbidity;
    EXPECT_TRUE(redder(sky.sun_color, previous.sun_color)) << turbidity;
    previous = sky;
  }
}

TEST(Sunlight, SetsWithItsDisc) {
  const double radius_deg = kSunAngularRadiusRad * 180.0 / kPi;
  const double horizon_klx = sunlight_xyz_klx(3.0, kPi / 2.0).y;
  EXPECT_NEAR(model(3.0, 0.0).sun_illuminance_klx, 0.5 * horizon_klx, 1e-12 * horizon_klx);
  EXPECT_GT(model(3.0, -0.5 * radius_deg).sun_illuminance_klx, 0.0);
  EXPECT_LT(model(3.0, -0.5 * radius_deg).sun_illuminance_klx, 0.5 * horizon_klx);
  EXPECT_EQ(model(3.0, -radius_deg * 1.001).sun_illuminance_klx, 0.0);
  EXPECT_EQ(model(3.0, -30.0).sun_color, glm::dvec3(0.0));
  // A whole disc above the horizon is all there.
  const double up = radius_deg * 1.001;
  EXPECT_NEAR(model(3.0, up).sun_illuminance_klx,
              sunlight_xyz_klx(3.0, (90.0 - up) * kPi / 180.0).y, 1e-12);
}

TEST(Sunlight, DiscRadianceSpreadsTheSunOverItsSolidAngle) {
  const SkyModel sky = model(3.0, 35.0);
  const glm::dvec3 back = sky.sun_disc_radiance() * sun_solid_angle_sr();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], sky.sun_color[c], 1e-12 * sky.sun_color[c]);
  // About 1.5e6 kcd/m^2 at 100 klx: the disc outshines the sky by five orders of magnitude.
  EXPECT_GT(sky.sun_disc_radiance().y, 1e5 * sky.luminance(glm::dvec3(0.0, 1.0, 0.0)));
}

}  // namespace
}  // namespace boreas::render
