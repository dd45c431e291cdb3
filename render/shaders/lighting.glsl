// boreas: sunlight, sky light and the sun's shadow, shared by the bark, leaf, meadow and
// terrain shaders (Kusternig sec. 3.3-3.4). Radiance is in the sky model's unit, kcd/m^2,
// and irradiance in klx (render/sky/preetham.h): a Lambertian surface of albedo a lit by
// E shows a / pi * E. The exposure is applied once, by the tone mapper.

uniform vec3 u_eye;               // m: the camera
uniform vec3 u_sun_dir;           // unit: toward the sun
uniform vec3 u_sun_irradiance;    // klx, linear sRGB: direct sun on a surface facing it
uniform vec3 u_sky_irradiance;    // klx: sky light on an upward surface
uniform vec3 u_ground_irradiance; // klx: light the ground throws back on a downward surface
uniform mat4 u_light_matrix;      // world -> shadow map texture coordinates and depth [0, 1]
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_radius;    // shadow map units: the spread of the six taps
uniform float u_shadow_offset;    // m: how far a lookup moves off the surface, along n
uniform float u_shadow_bias;      // shadow map depth units
uniform int u_shadows;            // 0: everything sees the sun

const float kPi = 3.14159265358979324;

// Six Poisson-disc taps in the unit disc (Kusternig sec. 3.3.1 keeps six: soft edges and no
// flicker of small leaf shadows). Minimum distance 0.6 between taps.
const vec2 kPoissonTaps[6] = vec2[6](vec2(-0.613, 0.617), vec2(0.170, -0.040), vec2(-0.299, -0.791),
                                    vec2(0.645, 0.493), vec2(-0.651, -0.070), vec2(0.421, -0.628));

// The fraction of the sun's light that reaches p (with geometric normal n, toward the
// light's side): six hardware-filtered (2x2 PCF) lookups on a Poisson disc.
float sun_visibility(vec3 p, vec3 n) {
  if (u_shadows == 0) return 1.0;
  // Offsetting along the normal by about a texel keeps surfaces from shadowing themselves
  // without the detached shadows a large depth bias gives.
  vec4 s = u_light_matrix * vec4(p + n * u_shadow_offset, 1.0);
  // Beyond the map's box (past its far plane, or off its sides) nothing casts a shadow.
  if (any(lessThan(s.xyz, vec3(0.0))) || any(greaterThan(s.xyz, vec3(1.0)))) return 1.0;
  float sum = 0.0;
  for (int i = 0; i < 6; ++i) {
    sum += texture(u_shadow_map, vec3(s.xy + kPoissonTaps[i] * u_shadow_radius, s.z - u_shadow_bias));
  }
  return sum / 6.0;
}

// Sky and ground light on a surface with unit normal n: the upper and lower hemispheres'
// irradiances blended by how far n points up (exact for a vertical or horizontal surface
// under uniform sky and ground, smooth in between).
vec3 ambient_irradiance(vec3 n) {
  float up = 0.5 + 0.5 * n.y;
  return mix(u_ground_irradiance, u_sky_irradiance, up);
}

// Cook-Torrance specular (Beckmann distribution with roughness m, Schlick's Fresnel from
// the refraction index's f0, the geometric attenuation of the original), as BRDF * cos:
// multiply by the irradiance at normal incidence.
float cook_torrance(vec3 n, vec3 v, vec3 l, float m, float f0) {
  float nl = dot(n, l), nv = dot(n, v);
  if (nl <= 0.0 || nv <= 0.0) return 0.0;
  vec3 h = normalize(l + v);
  float nh = max(dot(n, h), 1e-4), vh = max(dot(v, h), 1e-4);
  float nh2 = nh * nh, m2 = m * m;
  float d = exp((nh2 - 1.0) / (m2 * nh2)) / (kPi * m2 * nh2 * nh2);
  float f = f0 + (1.0 - f0) * pow(1.0 - vh, 5.0);
  float g = min(1.0, min(2.0 * nh * nv / vh, 2.0 * nh * nl / vh));
  return d * f * g / (4.0 * nv);
}
