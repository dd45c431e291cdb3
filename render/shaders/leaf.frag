// boreas: the leaf shader of Kusternig sec. 3: alpha-tested albedo and normal maps, sun with
// the shadow map's six Poisson taps, Cook-Torrance specular on the upper side, sky and
// ground light with ambient occlusion, and translucency through the "Half-Life 2" basis:
// light from the far side passes the blade by the HL2 coefficients map evaluated for the
// light's tangent-space direction, colored by the translucency map.
//
// One texture set serves both sides (render/textures/leaf_textures.h): seen from below,
// the normal map's z is mirrored. The HL2 intensity already holds the green transmittance
// of the slab, so the color is the translucency map divided by its green channel
// (render/textures/leaf_translucency.h), not the paper's plain product.
#include "lighting.glsl"
#include "tree_table.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec3 v_across;
in vec3 v_along;
in vec2 v_uv;
in vec3 v_occlusion;  // sky light's share through the crown, per channel
flat in float v_layer;  // the leaf kind's layer of the maps
flat in float v_fade;   // the share of the pixels the tree's impostor takes

// One layer per leaf kind (render/gl/vegetation_textures.h).
uniform sampler2DArray u_leaf_albedo;        // rgb linear, a coverage
uniform sampler2DArray u_leaf_normal;        // tangent space, upper side
uniform sampler2DArray u_leaf_hl2;           // c0, c1, c2
uniform sampler2DArray u_leaf_translucency;  // rgb transmittance at normal incidence
uniform int u_translucency;             // 0: opaque leaves (for comparison)

// Of leaf cuticle (Bousquet et al. 2005 measure roughness 0.2-0.5 and an index near 1.5).
const float kLeafRoughness = 0.35;
const float kLeafF0 = 0.034;  // ((1.45 - 1) / (1.45 + 1))^2

// The HL2 basis of render/textures/hl2_basis.h.
const vec3 kHl2Basis0 = vec3(-0.408248290463863, 0.707106781186548, 0.577350269189626);
const vec3 kHl2Basis1 = vec3(-0.408248290463863, -0.707106781186548, 0.577350269189626);
const vec3 kHl2Basis2 = vec3(0.816496580927726, 0.0, 0.577350269189626);

#ifdef BOREAS_BAKE_PASS
uniform mat3 u_bake_to_template;  // world -> the template's space, for the normals
layout(location = 1) out vec4 o_normal;  // template space, 0.5 n + 0.5; a: the sky's share
layout(location = 2) out vec4 o_leaf;    // 1: a leaf (impostor.frag)
#endif
layout(location = 0) out vec4 o_color;

void main() {
  vec4 albedo = texture(u_leaf_albedo, vec3(v_uv, v_layer));
  if (albedo.a < 0.5) discard;
  if (v_fade > 0.0 && handover_dither(gl_FragCoord.xy) < v_fade) discard;
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec3 n_up = normalize(v_normal);
  vec3 view = normalize(u_eye - v_position);
  float seen = dot(n_up, view) >= 0.0 ? 1.0 : -1.0;  // +1: the upper side faces the camera
  vec3 nt = texture(u_leaf_normal, vec3(v_uv, v_layer)).xyz;
  vec3 n = normalize(v_across * nt.x + v_along * nt.y + n_up * (nt.z * seen));
  vec3 n_seen = n_up * seen;  // the geometric normal on the camera's side
#ifdef BOREAS_BAKE_PASS
  o_color = vec4(albedo.rgb, 1.0);
  o_normal = vec4(normalize(u_bake_to_template * n) * 0.5 + 0.5, dot(v_occlusion, vec3(1.0 / 3.0)));
  o_leaf = vec4(1.0);
  return;
#endif

  vec3 l = u_sun_dir;
  float lit_side = dot(n_seen, l);
  float visibility = sun_visibility(v_position, lit_side >= 0.0 ? n_seen : -n_seen);
  vec3 sun = u_sun_irradiance * visibility;

  vec3 radiance = vec3(0.0);
  if (lit_side > 0.0) {
    radiance += albedo.rgb / kPi * sun * max(dot(n, l), 0.0);
    if (seen > 0.0) radiance += sun * cook_torrance(n, view, l, kLeafRoughness, kLeafF0);
  }
  radiance += albedo.rgb / kPi * ambient_irradiance(n) * v_occlusion;

  if (u_translucency != 0) {
    vec3 color = texture(u_leaf_translucency, vec3(v_uv, v_layer)).rgb;
    color /= max(color.g, 1e-4);
    vec3 c = texture(u_leaf_hl2, vec3(v_uv, v_layer)).xyz;
    if (lit_side < 0.0) {
      // w = (L.x, L.y, |L.z|) in tangent space, whichever side the light is on.
      vec3 w = vec3(dot(l, v_across), dot(l, v_along), abs(dot(l, n_up)));
      float intensity = max(c.x * dot(w, kHl2Basis0) + c.y * dot(w, kHl2Basis1) + c.z * dot(w, kHl2Basis2), 0.0);
      radiance += color / kPi * sun * intensity;
    }
    // Sky and ground light through the blade from behind: the HL2 intensity integrated over
    // a uniformly bright hemisphere is pi times its z component, (c0 + c1 + c2) / sqrt(3).
    float diffuse_transmission = max((c.x + c.y + c.z) * 0.577350269189626, 0.0);
    radiance += color / kPi * ambient_irradiance(-n_seen) * diffuse_transmission * v_occlusion;
  }
  o_color = vec4(radiance, 1.0);
#endif
}
