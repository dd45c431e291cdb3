// sky tests: the Preetham daylight model: its coefficient tables against hand evaluations of
// the paper's formulas, its normalization, conventions, physical behaviour and parameter
// checks.
#include "sky/preetham.h"
#include "sky_directions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

namespace boreas::render {
namespace {

using test::kPi;
using test::toward;

double blue_over_red(const glm::dvec3& rgb) { return rgb.z / rgb.x; }

SkyModel model(double turbidity, double elevation_deg, double azimuth_deg = 0.0) {
  SkyParams params;
  params.turbidity = turbidity;
  params.sun_elevation_deg = elevation_deg;
  params.sun_azimuth_deg = azimuth_deg;
  return SkyModel(params);
}

const glm::dvec3 kUp(0.0, 1.0, 0.0);

TEST(PreethamCoefficients, PerezTablesMatchHandEvaluation) {
  // A..E = slope * T + offset from the paper's appendix A.2, multiplied out by hand.
  const double luminance_t2[5] = {-1.1056, -0.2833, 5.2797, -2.3359, 0.2363};
  const double chroma_x_t2[5] = {-0.2978, -0.1322, 0.2117, -1.0271, 0.0386};
  const double chroma_y_t2[5] = {-0.2942, -0.1808, 0.1944, -1.7419, 0.0311};
  const double luminance_t10[5] = {0.324, -3.1265, 5.0981, -1.3711, -0.2997};
  const double chroma_x_t10[5] = {-0.4522, -0.6642, 0.2085, -1.5399, 0.0122};
  const double chroma_y_t10[5] = {-0.4278, -0.9408, 0.1312, -2.0947, -0.0561};
  const PerezCoefficients t2 = preetham_perez_coefficients(2.0);
  const PerezCoefficients t10 = preetham_perez_coefficients(10.0);
  for (int i = 0; i < 5; ++i) {
    const char name = char('A' + i);
    EXPECT_NEAR(t2[i].x, luminance_t2[i], 1e-12) << "Y " << name;
    EXPECT_NEAR(t2[i].y, chroma_x_t2[i], 1e-12) << "x " << name;
    EXPECT_NEAR(t2[i].z, chroma_y_t2[i], 1e-12) << "y " << name;
    EXPECT_NEAR(t10[i].x, luminance_t10[i], 1e-12) << "Y " << name;
    EXPECT_NEAR(t10[i].y, chroma_x_t10[i], 1e-12) << "x " << name;
    EXPECT_NEAR(t10[i].z, chroma_y_t10[i], 1e-12) << "y " << name;
  }
}

TEST(PreethamCoefficients, ZenithValuesMatchHandEvaluation) {
  // T = 2, sun at the zenith (theta_s = 0): chi = (4/9 - 2/120) pi, and the chromaticity
  // polynomials keep only their theta_s^0 column: x_z = 0.00394 * 2 + 0.25886.
  {
    const glm::dvec3 z = preetham_zenith(2.0, 0.0);
    const double chi = (4.0 / 9.0 - 2.0 / 120.0) * kPi;
    EXPECT_NEAR(z.x, 3.1196 * std::tan(chi) + 1.9882, 1e-9);
    EXPECT_NEAR(z.x, 15.5006721374168, 1e-9);
    EXPECT_NEAR(z.y, 0.26674, 1e-9);
    EXPECT_NEAR(z.z, 0.27720, 1e-9);
  }
  // T = 2, sun on the horizon (theta_s = pi/2): chi = 0, so Y_z = -0.2155 * 2 + 2.4192.
  {
    const glm::dvec3 z = preetham_zenith(2.0, kPi / 2.0);
    EXPECT_NEAR(z.x, 1.9882, 1e-9);
    EXPECT_NEAR(z.y, 0.282936284998416, 1e-9);
    EXPECT_NEAR(z.z, 0.304449209699045, 1e-9);
  }
  // T = 4, sun 30 deg high (theta_s = pi/3), and T = 7.5, sun 15 deg high (theta_s = 5 pi/12),
  // evaluated separately in double precision from the appendix's formulas.
  {
    const glm::dvec3 z = preetham_zenith(4.0, kPi / 3.0);
    EXPECT_NEAR(z.x, 6.7054164844366, 1e-9);
    EXPECT_NEAR(z.y, 0.251809805696455, 1e-9);
    EXPECT_NEAR(z.z, 0.262735158667388, 1e-9);
  }
  {
    const glm::dvec3 z = preetham_zenith(7.5, 5.0 * kPi / 12.0);
    EXPECT_NEAR(z.x, 5.94507104109889, 1e-9);
    EXPECT_NEAR(z.y, 0.28540913555336, 1e-9);
    EXPECT_NEAR(z.z, 0.307202730445945, 1e-9);
  }
}

TEST(SkyModel, ZenithReproducesTheZenithValues) {
  for (double turbidity : {1.7, 2.0, 3.0, 6.0, 10.0}) {
    for (double elevation : {0.0, 5.0, 30.0, 60.0, 90.0}) {
      const SkyModel sky = model(turbidity, elevation, 37.0);
      const glm::dvec3 Yxy = sky.luminance_chromaticity(kUp);
      EXPECT_NEAR(Yxy.x / sky.zenith.x, 1.0, 1e-12) << turbidity << " " << elevation;
      EXPECT_NEAR(Yxy.y / sky.zenith.y, 1.0, 1e-12) << turbidity << " " << elevation;
      EXPECT_NEAR(Yxy.z / sky.zenith.z, 1.0, 1e-12) << turbidity << " " << elevation;
      EXPECT_DOUBLE_EQ(sky.luminance(kUp * 3.0), Yxy.x);  // any length
      // The zenith values are the formula's for this theta_s.
      const glm::dvec3 expected = preetham_zenith(turbidity, (90.0 - elevation) * kPi / 180.0);
      EXPECT_NEAR(sky.zenith.x, expected.x, 1e-12 * expected.x);
    }
  }
}

TEST(SkyModel, SunDirectionFollowsTheAzimuthConvention) {
  const SkyModel east = model(3.0, 0.0, 0.0);
  EXPECT_NEAR(glm::length(east.sun_dir - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
  const SkyModel quarter = model(3.0, 0.0, 90.0);
  EXPECT_NEAR(glm::length(quarter.sun_dir - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
  const SkyModel noon = model(3.0, 90.0, 123.0);
  EXPECT_NEAR(glm::length(noon.sun_dir - kUp), 0.0, 1e-12);
  const SkyModel tilted = model(3.0, 30.0, 225.0);
  EXPECT_NEAR(glm::length(tilted.sun_dir - toward(30.0, 225.0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(tilted.sun_dir), 1.0, 1e-12);
  EXPECT_NEAR(tilted.sun_zenith_rad, kPi / 3.0, 1e-12);
  EXPECT_NEAR(model(3.0, 30.0, 225.0 + 360.0).sun_dir.x, tilted.sun_dir.x, 1e-12);
}

TEST(SkyModel, SkyIsBrighterNearTheSunThanOpposite) {
  for (double turbidity : {2.0, 3.0, 6.0, 10.0}) {
    for (double elevation : {5.0, 30.0, 60.0}) {
      const SkyModel sky = model(turbidity, elevation, 20.0);
      // Same elevation, so only the angle to the sun differs.
      const double near_sun = sky.luminance(toward(elevation, 20.0 + 15.0));
      const double opposite = sky.luminance(toward(elevation, 20.0 + 180.0));
      EXPECT_GT(near_sun, 2.0 * opposite) << turbidity << " " << elevation;
      // And the 15 deg circle around the sun is brighter than the zenith.
      EXPECT_GT(near_sun, sky.luminance(kUp)) << turbidity << " " << elevation;
    }
  }
}

TEST(SkyModel, HazeBrightensAndWhitensTheZenith) {
  // More aerosol scatters more light into the sky and less selectively: a brighter, paler
  // zenith as the turbidity rises.
  for (double elevation : {10.0, 30.0, 60.0}) {
    double previous_luminance = 0.0;
    double previous_blue = 1e9;
    for (double turbidity : {2.0, 3.0, 5.0, 8.0, 10.0}) {
      const SkyModel sky = model(turbidity, elevation);
      const double blue = blue_over_red(sky.radiance_rgb(kUp));
      EXPECT_GT(sky.luminance(kUp), previous_luminance) << turbidity << " " << elevation;
      EXPECT_LT(blue, previous_blue) << turbidity << " " << elevation;
      EXPECT_GT(blue, 1.0) << turbidity << " " << elevation;  // still a blue sky
      previous_luminance = sky.luminance(kUp);
      previous_blue = blue;
    }
  }
}

TEST(SkyModel, HorizonBrighteningRelativeToTheZenithFadesWithHaze) {
  // Preetham's fit gives the clearest air the strongest horizon brightening: the zenith
  // factor 1 + A_Y exp(B_Y) shrinks as T falls (0.17 at T = 2) and darkens the zenith, while
  // at T = 10 the horizon opposite the sun is darker than the zenith. So in this model the
  // hazier sky is flatter, not brighter at the horizon relative to the zenith (Zotti et al.
  // 2007 discuss the low-turbidity end). From T = 8 to 10 the ratio levels off (0.373 and
  // 0.374 with the sun 60 deg high), so the sweep stops at 8.
  for (double elevation : {10.0, 30.0, 60.0}) {
    double previous_ratio = 1e9;
    for (double turbidity : {2.0, 3.0, 5.0, 8.0}) {
      const SkyModel sky = model(turbidity, elevation);
      const double ratio = sky.luminance(toward(2.0, 180.0)) / sky.luminance(kUp);
      EXPECT_LT(ratio, previous_ratio) << turbidity << " " << elevation;
      previous_ratio = ratio;
    }
  }
  EXPECT_GT(model(2.0, 30.0).luminance(toward(2.0, 180.0)) / model(2.0, 30.0).luminance(kUp), 3.0);
  EXPECT_LT(model(10.0, 30.0).luminance(toward(2.0, 180.0)) / model(10.0, 30.0).luminance(kUp),
            1.0);
}

TEST(SkyModel, ZenithIsBluerThanTheHorizonInClearAir) {
  for (double turbidity : {2.0, 3.0}) {
    for (double elevation : {10.0, 30.0, 60.0}) {
      const SkyModel sky = model(turbidity, elevation);
      const double zenith = blue_over_red(sky.radiance_rgb(kUp));
      for (double azimuth : {90.0, 180.0, 270.0}) {
        const double horizon = blue_over_red(sky.radiance_rgb(toward(2.0, azimuth)));
        EXPECT_GT(zenith, 1.5 * horizon) << turbidity << " " << elevation << " " << azimuth;
      }
    }
  }
}

TEST(SkyModel, SymmetricAboutTheSunsVerticalPlane) {
  const double sun_azimuth = 40.0;
  const SkyModel sky = model(4.0, 25.0, sun_azimuth);
  for (double elevation : {-10.0, 2.0, 20.0, 50.0, 80.0}) {
    for (double offset : {5.0, 30.0, 90.0, 150.0}) {
      const glm::dvec3 left = sky.radiance_rgb(toward(elevation, sun_azimuth - offset));
      const glm::dvec3 right = sky.radiance_rgb(toward(elevation, sun_azimuth + offset));
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(left[c], right[c], 1e-12 * right[c]) << elevation << " " << offset;
      }
    }
  }
}

TEST(SkyModel, RadianceIsFiniteAndNonNegativeEverywhere) {
  for (double turbidity : {1.7, 2.0, 10.0}) {
    for (double sun_elevation : {-5.0, 0.0, 0.1, 45.0, 90.0}) {
      const SkyModel sky = model(turbidity, sun_elevation, 10.0);
      for (double elevation = -90.0; elevation <= 90.0; elevation += 7.5) {
        for (double azimuth = 0.0; azimuth < 360.0; azimuth += 15.0) {
          const glm::dvec3 rgb = sky.radiance_rgb(toward(elevation, azimuth));
          for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(rgb[c]) && rgb[c] >= 0.0)
                << turbidity << " " << sun_elevation << " " << elevation << " " << azimuth;
          }
        }
      }
    }
  }
}

TEST(SkyModel, BelowTheHorizonTheHorizonValueContinues) {
  // With the sun on the horizon at +X, every direction in the YZ plane is 90 deg from it, so
  // only theta differs between these: held at cos(theta) = 0.01 they all read the same.
  const SkyModel sky = model(3.0, 0.0, 0.0);
  const double horizon = sky.luminance(glm::dvec3(0.0, 0.0, 1.0));
  EXPECT_GT(horizon, 0.0);
  EXPECT_EQ(sky.luminance(glm::dvec3(0.0, 0.005, 1.0)), horizon);
  EXPECT_EQ(sky.luminance(glm::dvec3(0.0, -0.5, 1.0)), horizon);
  EXPECT_EQ(sky.luminance(glm::dvec3(0.0, -1.0, 0.0)), horizon);
  EXPECT_NE(sky.luminance(glm::dvec3(0.0, 0.1, 1.0)), horizon);
}

TEST(SkyModel, SunBelowTheHorizonFadesTheSkyOverTwilight) {
  const SkyModel day = model(3.0, 0.0, 60.0);
  const SkyModel dusk = model(3.0, -3.0, 60.0);
  const SkyModel night = model(3.0, -6.5, 60.0);
  EXPECT_DOUBLE_EQ(day.twilight_fade, 1.0);
  EXPECT_DOUBLE_EQ(dusk.twilight_fade, 0.5);  // halfway through civil twilight
  EXPECT_DOUBLE_EQ(night.twilight_fade, 0.0);
  // Smoothstep in between, so the fade starts and ends gently.
  EXPECT_DOUBLE_EQ(model(3.0, -1.5).twilight_fade, 0.84375);
  EXPECT_DOUBLE_EQ(model(3.0, -4.5).twilight_fade, 0.15625);
  // The sky keeps the sun-on-the-horizon distribution, dimmed.
  EXPECT_NEAR(dusk.sun_zenith_rad, kPi / 2.0, 1e-15);
  EXPECT_NEAR(dusk.sky_sun_dir.y, 0.0, 1e-15);
  EXPECT_LT(dusk.sun_dir.y, 0.0);
  for (const glm::dvec3& dir : {kUp, toward(10.0, 60.0), toward(10.0, 240.0)}) {
    EXPECT_NEAR(dusk.luminance(dir), 0.5 * day.luminance(dir), 1e-12 * day.luminance(dir));
    EXPECT_EQ(night.luminance(dir), 0.0);
  }
  // Continuous at the horizon: a sun just above it gives nearly the same sky.
  const SkyModel just_up = model(3.0, 1e-6, 60.0);
  EXPECT_NEAR(just_up.luminance(kUp), day.luminance(kUp), 1e-6 * day.luminance(kUp));
  EXPECT_NEAR(model(3.0, -1e-6, 60.0).luminance(kUp), day.luminance(kUp),
              1e-6 * day.luminance(kUp));
}

TEST(SkyModel, UniformsCarryTheModelAsFloats) {
  const SkyModel sky = model(3.5, 20.0, 70.0);
  const SkyUniforms u = sky.uniforms(0.25);
  for (int i = 0; i < 5; ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(u.perez[i][c], float(sky.perez[i][c]));
  }
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(u.zenith[c], float(sky.zenith[c]));
    EXPECT_FLOAT_EQ(u.inv_f0[c], float(sky.inv_f0[c]));
    EXPECT_FLOAT_EQ(u.sun_dir[c], float(sky.sky_sun_dir[c]));
    EXPECT_FLOAT_EQ(u.disc_dir[c], float(sky.sun_dir[c]));
    EXPECT_FLOAT_EQ(u.disc_radiance[c], float(0.25 * sky.sun_disc_radiance()[c]));
  }
  EXPECT_FLOAT_EQ(u.scale, 0.25f);
  EXPECT_FLOAT_EQ(model(3.5, -3.0).uniforms(0.25).scale, 0.125f);
  EXPECT_NEAR(u.disc_cos_radius, std::cos(0.2665 * kPi / 180.0), 1e-7);
}

// Runs f and returns the std::invalid_argument message it throws ("" when none).
template <typename F>
std::string invalid_argument_message(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SkyParams, BadValuesThrowNamingTheField) {
  struct Case {
    SkyParams params;
    std::string field;
    std::string value;
  };
  const double nan = std::nan("");
  const double inf = INFINITY;
  const Case cases[] = {
      {{1.0, 45.0, 0.0}, "SkyParams.turbidity", "got 1"},
      {{1.69, 45.0, 0.0}, "SkyParams.turbidity", "got 1.69"},
      {{10.5, 45.0, 0.0}, "SkyParams.turbidity", "got 10.5"},
      {{nan, 45.0, 0.0}, "SkyParams.turbidity", "got nan"},
      {{3.0, 90.5, 0.0}, "SkyParams.sun_elevation_deg", "got 90.5"},
      {{3.0, -91.0, 0.0}, "SkyParams.sun_elevation_deg", "got -91"},
      {{3.0, nan, 0.0}, "SkyParams.sun_elevation_deg", "got nan"},
      {{3.0, 45.0, inf}, "SkyParams.sun_azimuth_deg", "got inf"},
      {{3.0, 45.0, nan}, "SkyParams.sun_azimuth_deg", "got nan"},
  };
  for (const Case& c : cases) {
    const std::string message = invalid_argument_message([&] { SkyModel sky(c.params); });
    EXPECT_NE(message.find(c.field), std::string::npos) << message;
    EXPECT_NE(message.find(c.value), std::string::npos) << message;
    EXPECT_EQ(invalid_argument_message([&] { validate(c.params); }), message);
  }
  // The ends of the ranges are valid.
  EXPECT_NO_THROW(model(kMinTurbidity, -90.0, -720.0));
  EXPECT_NO_THROW(model(kMaxTurbidity, 90.0, 1e6));

  const SkyModel sky = model(3.0, 45.0);
  for (double exposure : {-1.0, nan, inf}) {
    const std::string message = invalid_argument_message([&] { (void)sky.uniforms(exposure); });
    EXPECT_NE(message.find("exposure"), std::string::npos) << exposure;
  }
  EXPECT_NO_THROW((void)sky.uniforms(0.0));
}

}  // namespace
}  // namespace boreas::render
