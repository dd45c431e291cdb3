// boreas: a far tree's impostor, lit as its leaves and bark would be: the baked albedo and
// normal (template space, turned as the tree stands) with the sky light's share through
// the crown, sun with the shadow map, sky and ground light, and light through the leaves
// from behind by their mean transmittance. The maps hold coverage-weighted values (the
// bake clears to zero), so what filtering blends is divided by the coverage again.
#include "lighting.glsl"
#include "tree_table.glsl"

in vec3 v_position;
in vec2 v_local[3];
flat in vec2 v_cell[3];
flat in vec3 v_weight;
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

// The three frames blended: each read half a texel in from its edge (filtering never
// reads the next frame); the maps hold coverage-weighted values, so the weighted sums are.
// The albedo (with the coverage) first: most of the square around a crown is empty, and
// its fragments stop there.
vec3 frame_uv(int k) {
  const float inset = 0.5 / float(BOREAS_IMPOSTOR_FRAME_TEXELS);
  return vec3((v_cell[k] + clamp(v_local[k], inset, 1.0 - inset)) / float(BOREAS_IMPOSTOR_FRAMES), v_layer);
}

vec4 blended_albedo() {
  vec4 albedo = vec4(0.0);
  for (int k = 0; k < 3; ++k)
    if (v_weight[k] > 0.0) albedo += v_weight[k] * texture(u_impostor_albedo, frame_uv(k));
  return albedo;
}

void main() {
  vec4 albedo = blended_albedo();
#ifdef BOREAS_SHADOW_PASS
  if (albedo.a < 0.5) discard;
  o_color = vec4(0.0);
#else
  // Three frames of a crown that is not flat agree on its middle and blur its outline: the
  // samples take the blend's coverage steepened about one half (the outline a single
  // frame would give), so the crown does not grow a halo.
  float samples = clamp(2.0 * albedo.a - 0.5, 0.0, 1.0);
  if (u_alpha_to_coverage == 0 ? albedo.a < 0.5 : samples < 1.0 / 255.0) discard;
  // The handover: the impostor keeps the pixels the geometry gives up (bark.frag, leaf.frag).
  if (handover_dither(gl_FragCoord.xy) >= v_fade) discard;
  vec4 normal_sum = vec4(0.0);
  float leaf_sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    normal_sum += v_weight[k] * texture(u_impostor_normal, frame_uv(k));
    leaf_sum += v_weight[k] * texture(u_impostor_leaf, frame_uv(k)).r;
  }
  float coverage = max(albedo.a, 1e-3);
  vec4 baked = normal_sum / coverage;
  vec3 color = albedo.rgb / coverage;
  vec3 n = normalize(v_to_world * (baked.xyz * 2.0 - 1.0));
  float leaf = clamp(leaf_sum / coverage, 0.0, 1.0);
  float sky_share = clamp(baked.w, 0.0, 1.0);
  vec3 l = u_sun_dir;
  float facing = dot(n, l);
  vec3 sun = u_sun_irradiance * sun_visibility(v_position, facing >= 0.0 ? n : -n);
  vec3 radiance = color / kPi * (sun * max(facing, 0.0) + ambient_irradiance(n) * sky_share);
  radiance += leaf * v_transmittance / kPi * (sun * max(-facing, 0.0) + ambient_irradiance(-n) * sky_share);
  o_color = vec4(radiance, u_alpha_to_coverage != 0 ? samples : 1.0);
#endif
}
