// boreas: the ground: soil and dry grass in patches of metres, a grain of clods, grit and
// litter down to the pixel (octaves finer than a pixel left out), a bump from that grain,
// and under the meadows low growth over dark soil; lit by the sun (with the trees' and
// meadows' shadows) and the sky, fading into the sky's horizon color with distance
// (aerial perspective, a single extinction length).
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

// Value noise summed over octaves (each half the size and weight of the last), stopping
// at the octave whose cells would be smaller than a pixel there: the detail that would
// only alias is left out, so the ground is as fine as the screen can show and no finer.
float ground_noise(vec2 p, float pixel_m, int octaves) {
  float sum = 0.0, weight = 0.5, total = 0.0;
  for (int i = 0; i < octaves; ++i) {
    float fade = 1.0 - smoothstep(0.5, 1.0, 2.0 * pixel_m);  // cells of 1 unit, at 0.5..1 px
    sum += weight * fade * value_noise(p) + weight * (1.0 - fade) * 0.5;
    total += weight;
    p *= 2.03;
    pixel_m *= 2.03;
    weight *= 0.5;
  }
  return sum / total;
}

void main() {
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec2 xz = v_position.xz;
  // m of ground a pixel spans here (its footprint), for the noise's finest octave.
  float pixel_m = max(length(dFdx(v_position)), length(dFdy(v_position)));
  // Large patches (metres): where soil shows through the dry grass.
  float patches = value_noise(xz * 0.08) * 0.65 + value_noise(xz * 0.7) * 0.35;
  // Fine grain (decimetres to centimetres): clods, grit, litter, fading out with distance.
  float grain = ground_noise(xz * 9.0, pixel_m * 9.0, 5);
  // Linear albedos: dry grass, bare soil, and dark litter in the hollows of the grain.
  vec3 dry_grass = vec3(0.13, 0.12, 0.055), soil = vec3(0.15, 0.11, 0.07), litter = vec3(0.06, 0.05, 0.03);
  vec3 albedo = mix(dry_grass, soil, smoothstep(0.35, 0.75, patches));
  albedo *= mix(0.7, 1.25, grain);
  albedo = mix(albedo, litter, smoothstep(0.45, 0.25, grain) * 0.5);
  float sward = 0.0;
  for (int i = 0; i < u_meadow_count && i < kMaxMeadowRects; ++i) {
    vec4 r = u_meadow_rects[i];
    vec2 inside = min(xz - r.xy, r.zw - xz);  // m to the nearest edge, per axis
    sward = max(sward, smoothstep(0.0, 2.0, min(inside.x, inside.y)));
  }
  // Under the meadows: low green growth and old brown leaves over dark soil, mottled.
  vec3 under = mix(vec3(0.05, 0.045, 0.025), vec3(0.045, 0.09, 0.025), smoothstep(0.3, 0.7, grain));
  under = mix(under, vec3(0.07, 0.10, 0.03), 0.5 * patches);
  albedo = mix(albedo, under, sward);
  // A bump from the grain: clods 2 cm high (the grain times kClodHeight), so the sun rakes
  // across them instead of a flat plane; faded out where a pixel spans several clods. The
  // grain's slope over the ground from its screen derivatives: d(grain)/d(screen) =
  // J * slope, with J the rows d(xz)/dx and d(xz)/dy, solved for the slope.
  const float kClodHeight = 0.02;  // m
  vec2 ax = dFdx(xz), ay = dFdy(xz);
  float det = ax.x * ay.y - ax.y * ay.x;
  vec2 slope = abs(det) > 1e-12
                   ? vec2(dFdx(grain) * ay.y - dFdy(grain) * ax.y, ax.x * dFdy(grain) - ay.x * dFdx(grain)) / det
                   : vec2(0.0);
  slope *= kClodHeight * (1.0 - smoothstep(0.02, 0.1, pixel_m));
  vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
  float visibility = u_sun_dir.y > 0.0 ? sun_visibility(v_position, vec3(0.0, 1.0, 0.0)) : 0.0;
  vec3 radiance = albedo / kPi * (u_sun_irradiance * max(dot(n, u_sun_dir), 0.0) * visibility + u_sky_irradiance);
  vec3 to_ground = v_position - u_eye;
  float fade = exp(-length(to_ground) / u_haze_distance);
  vec3 horizon = boreas_preetham_sky(vec3(to_ground.x, 0.0, to_ground.z));
  o_color = vec4(mix(horizon, radiance, fade), 1.0);
#endif
}
