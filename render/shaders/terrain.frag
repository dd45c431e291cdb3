// boreas: the ground: soil and dry grass mottled by value noise at two scales, lit by the
// sun (with the trees' and meadows' shadows) and the sky, fading into the sky's horizon
// color with distance (aerial perspective, a single extinction length).
#include "lighting.glsl"
#include "sky.glsl"

in vec3 v_position;

uniform float u_haze_distance;  // m: distance at which the ground keeps 1/e of its color
// The meadows' rectangles (min x, min z, max x, max z): the sward under their simulated
// components is green, fading out over two metres at the edges.
const int kMaxMeadowRects = 16;
uniform vec4 u_meadow_rects[kMaxMeadowRects];
uniform int u_meadow_count;

out vec4 o_color;

float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }

float value_noise(vec2 p) {
  vec2 i = floor(p), f = fract(p);
  vec2 s = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(i), hash(i + vec2(1, 0)), s.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), s.x), s.y);
}

void main() {
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec2 xz = v_position.xz;
  float patches = value_noise(xz * 0.08) * 0.65 + value_noise(xz * 0.7) * 0.35;
  // Linear albedos: dry grass and bare soil.
  vec3 albedo = mix(vec3(0.10, 0.12, 0.05), vec3(0.16, 0.13, 0.08), smoothstep(0.35, 0.75, patches));
  float sward = 0.0;
  for (int i = 0; i < u_meadow_count && i < kMaxMeadowRects; ++i) {
    vec4 r = u_meadow_rects[i];
    vec2 inside = min(xz - r.xy, r.zw - xz);  // m to the nearest edge, per axis
    sward = max(sward, smoothstep(0.0, 2.0, min(inside.x, inside.y)));
  }
  albedo = mix(albedo, mix(vec3(0.035, 0.085, 0.02), vec3(0.06, 0.10, 0.03), patches), sward);
  vec3 n = vec3(0.0, 1.0, 0.0);
  float visibility = u_sun_dir.y > 0.0 ? sun_visibility(v_position, n) : 0.0;
  vec3 radiance = albedo / kPi * (u_sun_irradiance * max(u_sun_dir.y, 0.0) * visibility + u_sky_irradiance);
  vec3 to_ground = v_position - u_eye;
  float fade = exp(-length(to_ground) / u_haze_distance);
  vec3 horizon = boreas_preetham_sky(vec3(to_ground.x, 0.0, to_ground.z));
  o_color = vec4(mix(horizon, radiance, fade), 1.0);
#endif
}
