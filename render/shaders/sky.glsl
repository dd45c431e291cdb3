// boreas sky: Preetham, Shirley and Smits' analytic daylight model (SIGGRAPH 1999) per pixel,
// from uniforms that SkyModel::uniforms() (render/sky/preetham.h, where the equations are
// written out) computes once a frame. The C++ SkyModel is the reference for this file.
//
// A GLSL 4.50 function file: no #version line; the renderer includes or concatenates it.
// tests/render/sky also compiles it as C++ (glm, with `uniform` defined away) and checks it
// against the double-precision reference, so it keeps to what both languages accept:
// f-suffixed float literals, no swizzles, no in/out parameters.
//
// Conventions: world Y is up; directions point from the viewer outward, the sun's toward the
// sun. Radiance is linear sRGB (D65 primaries) scaled by the exposure.
//
// Uniforms (SkyUniforms fields, same order):
//   vec3  u_sky_perez[5]        Perez coefficients A..E; .x for the luminance Y, .y for the
//                               chromaticity x, .z for the chromaticity y
//   vec3  u_sky_zenith          zenith values (Y_z in kcd/m^2, x_z, y_z)
//   vec3  u_sky_inv_f0          1 / F(0, theta_s) for (Y, x, y): the model's normalization
//   vec3  u_sky_sun_dir         unit, toward the sun as the sky model sees it (held on the
//                               horizon while the sun is below it)
//   float u_sky_scale           exposure (display value per kcd/m^2) times the twilight fade
//   vec3  u_sky_disc_dir        unit, toward the sun's true position
//   vec3  u_sky_disc_radiance   radiance of the sun's disc, exposure applied (0 once set)
//   float u_sky_disc_cos_radius cos of the sun disc's angular radius (0.2665 deg)
// All are prefixed u_sky_ so that the renderer's own sun light uniforms cannot collide.

uniform vec3 u_sky_perez[5];
uniform vec3 u_sky_zenith;
uniform vec3 u_sky_inv_f0;
uniform vec3 u_sky_sun_dir;
uniform float u_sky_scale;
uniform vec3 u_sky_disc_dir;
uniform vec3 u_sky_disc_radiance;
uniform float u_sky_disc_cos_radius;

// cos(theta) is held at or above this (kMinCosViewZenith in preetham.h): at and below the
// horizon the horizon's value continues.
const float kBoreasSkyMinCosTheta = 0.01f;

// CIE XYZ -> linear sRGB (IEC 61966-2-1, D65 white), given column by column.
const mat3 kBoreasXyzToLinearSrgb = mat3(3.2404542f, -0.9692660f, 0.0556434f,
                                         -1.5371385f, 1.8760108f, -0.2040259f,
                                         -0.4985314f, 0.0415560f, 1.0572252f);

// The Perez distribution F(theta, gamma) for (Y, x, y).
vec3 boreas_preetham_perez(float cos_theta, float cos_gamma) {
  float gamma = acos(cos_gamma);
  return (1.0f + u_sky_perez[0] * exp(u_sky_perez[1] / cos_theta)) *
         (1.0f + u_sky_perez[2] * exp(u_sky_perez[3] * gamma) +
          u_sky_perez[4] * (cos_gamma * cos_gamma));
}

// Sky radiance toward dir (any nonzero length), exposure applied. The sun's disc is not
// included: add boreas_preetham_sun_disc(dir) where the sun should show.
vec3 boreas_preetham_sky(vec3 dir) {
  vec3 v = normalize(dir);
  float cos_theta = max(v.y, kBoreasSkyMinCosTheta);
  float cos_gamma = clamp(dot(v, u_sky_sun_dir), -1.0f, 1.0f);
  vec3 Yxy = u_sky_zenith * u_sky_inv_f0 * boreas_preetham_perez(cos_theta, cos_gamma);
  float Y = Yxy.x * u_sky_scale;
  vec3 xyz = vec3(Yxy.y / Yxy.z * Y, Y, (1.0f - Yxy.y - Yxy.z) / Yxy.z * Y);
  return max(kBoreasXyzToLinearSrgb * xyz, vec3(0.0f));
}

// Radiance of the sun's disc toward dir (zero outside it), exposure applied: the direct
// sunlight spread evenly over the disc, without limb darkening.
vec3 boreas_preetham_sun_disc(vec3 dir) {
  float cos_angle = dot(normalize(dir), u_sky_disc_dir);
  return cos_angle >= u_sky_disc_cos_radius ? u_sky_disc_radiance : vec3(0.0f);
}
