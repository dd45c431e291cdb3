// sky tests: sky.glsl compiled as C++ (glm stands in for GLSL's types and built-ins) and run
// on the CPU with SkyModel's uniforms, against the double-precision reference; and its uniform
// declarations against kSkyUniformNames.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/glm.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "sky/color.h"
#include "sky/preetham.h"
#include "sky_directions.h"

// The shader's functions and uniforms live in this namespace; `uniform` declarations become
// plain variables that the tests set.
namespace sky_glsl {
using namespace glm;
#define uniform
#include "shaders/sky.glsl"
#undef uniform
}  // namespace sky_glsl

namespace boreas::render {
namespace {

using test::kPi;
using test::toward;

void set_uniforms(const SkyUniforms& u) {
  for (int i = 0; i < 5; ++i) sky_glsl::u_sky_perez[i] = u.perez[i];
  sky_glsl::u_sky_zenith = u.zenith;
  sky_glsl::u_sky_inv_f0 = u.inv_f0;
  sky_glsl::u_sky_sun_dir = u.sun_dir;
  sky_glsl::u_sky_scale = u.scale;
  sky_glsl::u_sky_disc_dir = u.disc_dir;
  sky_glsl::u_sky_disc_radiance = u.disc_radiance;
  sky_glsl::u_sky_disc_cos_radius = u.disc_cos_radius;
}

TEST(SkyGlsl, MatchesTheDoubleReference) {
  const double exposure = 0.1;
  int compared = 0;
  for (double turbidity : {1.7, 2.0, 3.0, 6.0, 10.0}) {
    for (double sun_elevation : {-3.0, 0.0, 4.0, 25.0, 60.0, 90.0}) {
      SkyParams params;
      params.turbidity = turbidity;
      params.sun_elevation_deg = sun_elevation;
      params.sun_azimuth_deg = 130.0;
      const SkyModel sky(params);
      set_uniforms(sky.uniforms(exposure));
      for (double elevation = -20.0; elevation <= 90.0; elevation += 5.0) {
        for (double azimuth = 0.0; azimuth < 360.0; azimuth += 10.0) {
          const glm::dvec3 dir = toward(elevation, azimuth);
          const glm::dvec3 expected = exposure * sky.radiance_rgb(dir);
          const glm::dvec3 actual(sky_glsl::boreas_preetham_sky(glm::vec3(dir)));
          // Float against double: relative to the brightest channel (a dark channel next to
          // a bright one carries the bright one's rounding).
          // Measured: below 5e-6.
          const double tolerance = 2e-5 * std::max({expected.x, expected.y, expected.z}) + 1e-9;
          for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(actual[c], expected[c], tolerance)
                << "T " << turbidity << " sun " << sun_elevation << " view " << elevation << " "
                << azimuth << " channel " << c;
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(SkyGlsl, ColorMatrixIsTheReferences) {
  // Too small a difference in the matrix would hide inside the float tolerance above, so
  // compare it column by column with color.h's.
  for (int column = 0; column < 3; ++column) {
    glm::dvec3 unit(0.0);
    unit[column] = 1.0;
    const glm::dvec3 expected = linear_srgb_from_xyz(unit);
    for (int row = 0; row < 3; ++row) {
      EXPECT_EQ(sky_glsl::kBoreasXyzToLinearSrgb[column][row], float(expected[row]))
          << column << " " << row;
    }
  }
  EXPECT_EQ(sky_glsl::kBoreasSkyMinCosTheta, float(kMinCosViewZenith));
}

TEST(SkyGlsl, SunDiscShowsOnlyAroundTheSun) {
  SkyParams params;
  params.turbidity = 3.0;
  params.sun_elevation_deg = 20.0;
  params.sun_azimuth_deg = 75.0;
  const SkyModel sky(params);
  set_uniforms(sky.uniforms(0.5));
  const glm::dvec3 centre = 0.5 * sky.sun_disc_radiance();
  const glm::vec3 on = sky_glsl::boreas_preetham_sun_disc(glm::vec3(sky.sun_dir * 2.0));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(on[c], centre[c], 1e-6 * centre[c]);
  // 0.2 deg off the centre is inside the 0.2665 deg disc; 0.4 deg is outside.
  const glm::vec3 inside = sky_glsl::boreas_preetham_sun_disc(glm::vec3(toward(20.2, 75.0)));
  const glm::vec3 outside = sky_glsl::boreas_preetham_sun_disc(glm::vec3(toward(20.4, 75.0)));
  EXPECT_GT(inside.y, 0.0f);
  EXPECT_EQ(outside, glm::vec3(0.0f));
}

TEST(SkyGlsl, DeclaresExactlyTheDocumentedUniforms) {
  std::ifstream file(BOREAS_SKY_GLSL_PATH);
  ASSERT_TRUE(file) << BOREAS_SKY_GLSL_PATH;
  std::stringstream text;
  text << file.rdbuf();
  const std::string source = text.str();
  const std::regex declaration(R"(^uniform\s+\w+\s+(\w+))");
  const std::regex version(R"(^\s*#\s*version)");
  std::set<std::string> declared;
  std::istringstream lines(source);
  for (std::string line; std::getline(lines, line);) {
    std::smatch match;
    if (std::regex_search(line, match, declaration)) declared.insert(match[1]);
    // No #version line: the renderer supplies it.
    EXPECT_FALSE(std::regex_search(line, version)) << line;
  }
  const std::set<std::string> documented(kSkyUniformNames.begin(), kSkyUniformNames.end());
  EXPECT_EQ(declared, documented);
  // And the header comment documents each of them.
  for (const char* name : kSkyUniformNames) {
    const std::regex documentation(std::string(R"(//\s+\w+\s+)") + name + R"((\[\d+\])?\s)");
    EXPECT_TRUE(std::regex_search(source, documentation)) << name;
  }
}

}  // namespace
}  // namespace boreas::render
