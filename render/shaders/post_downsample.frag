// boreas: the post effects' input at a quarter of the frame's size (each pixel the mean of
// a 4 x 4 block): for bloom, the radiance above the bloom threshold (exposed luminance);
// for light shafts, the sky alone (depth at the far plane), weighted toward the sun, so the
// shafts are the sky light that gaps between leaves and branches let through (Mitchell,
// "Volumetric light scattering as a post-process", GPU Gems 3, ch. 13: the occluders black,
// the light source bright).
in vec2 v_ndc;

uniform sampler2D u_hdr;
uniform sampler2D u_depth;
uniform mat4 u_inverse_view_proj;
uniform vec3 u_sun_dir;        // unit, toward the sun
uniform float u_exposure;      // display units per radiance unit
uniform float u_threshold;     // exposed luminance where bloom starts

layout(location = 0) out vec4 o_bright;
layout(location = 1) out vec4 o_sky;

void main() {
  ivec2 base = ivec2(gl_FragCoord.xy) * 4;
  ivec2 size = textureSize(u_hdr, 0);
  vec3 bright = vec3(0.0), sky = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      ivec2 p = min(base + ivec2(i, j), size - 1);
      vec3 c = texelFetch(u_hdr, p, 0).rgb;
      float y = dot(c, vec3(0.2126, 0.7152, 0.0722)) * u_exposure;
      bright += y > u_threshold ? c * (1.0 - u_threshold / y) : vec3(0.0);
      if (texelFetch(u_depth, p, 0).r >= 1.0) sky += c;
    }
  }
  // The direction of this block's middle, for the sun's weight.
  vec2 ndc = (vec2(base) + 2.0) / vec2(size) * 2.0 - 1.0;
  vec4 far = u_inverse_view_proj * vec4(ndc, 1.0, 1.0);
  vec4 near = u_inverse_view_proj * vec4(ndc, -1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  // Within about 20 degrees of the sun (the forward peak of haze scattering).
  float toward_sun = pow(max(dot(dir, u_sun_dir), 0.0), 32.0);
  o_bright = vec4(bright / 16.0, 1.0);
  o_sky = vec4(sky / 16.0 * toward_sun, 1.0);
}
