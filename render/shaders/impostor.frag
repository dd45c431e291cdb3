// boreas: a far tree's impostor, lit as its leaves and bark would be: the baked albedo and
// normal (template space, turned as the tree stands) with the sky light's share through
// the crown, sun with the shadow map, sky and ground light, and light through the leaves
// from behind by their mean transmittance. The maps hold coverage-weighted values (the
// bake clears to zero), so what filtering blends is divided by the coverage again.
#include "lighting.glsl"
#include "tree_table.glsl"

in vec3 v_position;
in vec2 v_uv;
flat in float v_layer;
flat in float v_fade;
flat in mat3 v_to_world;
flat in vec3 v_transmittance;

uniform sampler2DArray u_impostor_albedo;  // rgb albedo x coverage, a coverage
// (0.5 n + 0.5, s) x coverage, s the sky light's share through the crown.
uniform sampler2DArray u_impostor_normal;
// The leaves' share x coverage: only leaves pass light through from behind. A channel of
// its own: packed into the sky's share (a flag above one half), texels that filtering
// mixed of bark and leaves fell below the flag and lost the light through the leaves,
// and the sky's share read from them doubled: dark and pale blobs.
uniform sampler2DArray u_impostor_leaf;
uniform int u_alpha_to_coverage;  // 1: the coverage goes to the samples, else a test at 0.5

layout(location = 0) out vec4 o_color;

void main() {
  vec4 albedo = texture(u_impostor_albedo, vec3(v_uv, v_layer));
#ifdef BOREAS_SHADOW_PASS
  if (albedo.a < 0.5) discard;
  o_color = vec4(0.0);
#else
  if (u_alpha_to_coverage == 0 ? albedo.a < 0.5 : albedo.a < 1.0 / 255.0) discard;
  // The handover: the impostor keeps the pixels the geometry gives up (bark.frag, leaf.frag).
  if (handover_dither(gl_FragCoord.xy) >= v_fade) discard;
  float coverage = max(albedo.a, 1e-3);
  vec4 baked = texture(u_impostor_normal, vec3(v_uv, v_layer)) / coverage;
  vec3 color = albedo.rgb / coverage;
  vec3 n = normalize(v_to_world * (baked.xyz * 2.0 - 1.0));
  float leaf = clamp(texture(u_impostor_leaf, vec3(v_uv, v_layer)).r / coverage, 0.0, 1.0);
  float sky_share = clamp(baked.w, 0.0, 1.0);
  vec3 l = u_sun_dir;
  float facing = dot(n, l);
  vec3 sun = u_sun_irradiance * sun_visibility(v_position, facing >= 0.0 ? n : -n);
  vec3 radiance = color / kPi * (sun * max(facing, 0.0) + ambient_irradiance(n) * sky_share);
  radiance += leaf * v_transmittance / kPi * (sun * max(-facing, 0.0) + ambient_irradiance(-n) * sky_share);
  o_color = vec4(radiance, u_alpha_to_coverage != 0 ? albedo.a : 1.0);
#endif
}
