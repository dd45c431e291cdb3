// boreas: one direction of a separable Gaussian blur (9 taps, sigma 2 texels) of the bloom
// texture; run across, then along.
in vec2 v_ndc;

uniform sampler2D u_source;
uniform ivec2 u_step;  // (1, 0) or (0, 1)

out vec4 o_color;

void main() {
  const float w[5] = float[5](0.2042, 0.1802, 0.1238, 0.0663, 0.0276);  // sum 2w - w0 = 1
  ivec2 p = ivec2(gl_FragCoord.xy), size = textureSize(u_source, 0) - 1;
  vec3 c = texelFetch(u_source, p, 0).rgb * w[0];
  for (int k = 1; k < 5; ++k) {
    c += texelFetch(u_source, clamp(p + k * u_step, ivec2(0), size), 0).rgb * w[k];
    c += texelFetch(u_source, clamp(p - k * u_step, ivec2(0), size), 0).rgb * w[k];
  }
  o_color = vec4(c, 1.0);
}
