// boreas: the sky behind everything: Preetham's model (sky.glsl) and the sun's disc, toward
// the direction of each pixel. Drawn last with depth test LEQUAL at the far plane.
#include "sky.glsl"

in vec2 v_ndc;

uniform mat4 u_inverse_view_proj;

out vec4 o_color;

void main() {
  vec4 near = u_inverse_view_proj * vec4(v_ndc, -1.0, 1.0);
  vec4 far = u_inverse_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  o_color = vec4(boreas_preetham_sky(dir) + boreas_preetham_sun_disc(dir), 1.0);
}
