// boreas: a ball: a red rubber sphere with a broad highlight, lit like the rest.
#include "lighting.glsl"

in vec3 v_position;
in vec3 v_normal;

out vec4 o_color;

void main() {
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec3 n = normalize(v_normal);
  vec3 view = normalize(u_eye - v_position);
  const vec3 kAlbedo = vec3(0.45, 0.04, 0.03);
  float lit = max(dot(n, u_sun_dir), 0.0);
  vec3 sun = u_sun_irradiance * (lit > 0.0 ? sun_visibility(v_position, n) : 0.0);
  vec3 radiance = kAlbedo / kPi * (sun * lit + ambient_irradiance(n)) + sun * cook_torrance(n, view, u_sun_dir, 0.3, 0.04);
  o_color = vec4(radiance, 1.0);
#endif
}
