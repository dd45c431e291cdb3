// boreas: HDR to display: Reinhard's operator on luminance with a white point (Reinhard et
// al. 2002, eq. 4; Kusternig sec. 6.1 uses a modified Reinhard), then the sRGB curve.
in vec2 v_ndc;

uniform sampler2D u_hdr;
uniform sampler2D u_bloom;    // quarter size, linear: the blurred radiance above the threshold
uniform sampler2D u_shafts;   // quarter size, linear: light shafts' radiance
uniform float u_bloom_strength;  // 0: no bloom
uniform int u_post;           // 0: no post effects drawn this frame
uniform float u_exposure;     // display units per kcd/m^2
uniform float u_white;        // exposed luminance that maps to white

out vec4 o_color;

vec3 srgb_encode(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
  vec3 c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
  if (u_post != 0) {
    // The post effects add radiance before exposure and tone mapping (Kusternig sec. 6.1).
    vec2 uv = v_ndc * 0.5 + 0.5;
    c += texture(u_bloom, uv).rgb * u_bloom_strength + texture(u_shafts, uv).rgb;
  }
  c *= u_exposure;
  float y = dot(c, vec3(0.2126, 0.7152, 0.0722));
  float mapped = y * (1.0 + y / (u_white * u_white)) / (1.0 + y);
  vec3 display = y > 0.0 ? c * (mapped / y) : vec3(0.0);
  o_color = vec4(srgb_encode(clamp(display, 0.0, 1.0)), 1.0);
}
