// boreas: light shafts as a radial blur of the sky mask toward the sun's place on the screen
// (Mitchell, GPU Gems 3 ch. 13, eq. 3): kSamples samples from the pixel toward the sun, each
// weighted by decay^i, so light let through a gap streaks along the line to the sun, as
// haze scattering toward the camera makes it. Where the sun is off the screen the line
// still points to it.
in vec2 v_ndc;

uniform sampler2D u_sky;     // post_downsample's sky mask (linear filtering)
uniform vec2 u_sun_uv;       // the sun's place, texture coordinates (may be outside 0..1)
uniform float u_strength;    // radiance added per unit of mean mask along the line

out vec4 o_color;

const int kSamples = 48;
const float kDensity = 0.9;  // the share of the way to the sun the samples cover
const float kDecay = 0.96;
const float kReach = 0.5;  // texture units

void main() {
  vec2 uv = v_ndc * 0.5 + 0.5;
  // Toward the sun, covering kDensity of the way there but at most kReach of the screen (a
  // sun far off the screen would otherwise smear the whole sky mask into a veil).
  vec2 toward = (u_sun_uv - uv) * kDensity;
  float reach = length(toward);
  if (reach > kReach) toward *= kReach / reach;
  vec2 step = toward / float(kSamples);
  vec3 sum = vec3(0.0);
  float weight = 1.0, total = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    sum += texture(u_sky, uv).rgb * weight;
    total += weight;
    weight *= kDecay;
    uv += step;
  }
  o_color = vec4(sum / total * u_strength, 1.0);
}
