// boreas: blades, leaflets and petals with the leaf lighting of leaf.frag, without textures:
// diffuse on the lit side, Cook-Torrance on the upper side, light through the blade from
// the far side (a thin slab's transmittance per channel, cosine-weighted like the HL2
// term of a flat leaf), and occlusion by the meadow itself that lifts from base to tip.
#include "lighting.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
flat in vec3 v_albedo;
flat in vec3 v_transmittance;

uniform int u_translucency;

const float kBladeRoughness = 0.4;
const float kBladeF0 = 0.034;

out vec4 o_color;

void main() {
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec3 n_up = normalize(v_normal);
  vec3 view = normalize(u_eye - v_position);
  float seen = dot(n_up, view) >= 0.0 ? 1.0 : -1.0;
  vec3 n = n_up * seen;
  vec3 l = u_sun_dir;
  float lit_side = dot(n, l);
  vec3 sun = u_sun_irradiance * sun_visibility(v_position, lit_side >= 0.0 ? n : -n);
  // Light deep in the sward is shaded by the neighbours: a quarter at the ground.
  float occlusion = mix(0.25, 1.0, clamp(v_uv.y, 0.0, 1.0));
  vec3 radiance = v_albedo / kPi * (sun * max(lit_side, 0.0) + ambient_irradiance(n) * occlusion);
  if (seen > 0.0) radiance += sun * cook_torrance(n, view, l, kBladeRoughness, kBladeF0);
  if (u_translucency != 0) {
    radiance += v_transmittance / kPi * (sun * max(-lit_side, 0.0) + ambient_irradiance(-n) * occlusion);
  }
  o_color = vec4(radiance, 1.0);
#endif
}
