// boreas: bark: the generated albedo and normal maps (render/textures/bark_textures.h),
// sun with shadow, sky and ground light with a crown occlusion term.
#include "lighting.glsl"
#include "tree_table.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec3 v_along;
in vec2 v_uv;
flat in vec3 v_crown_center;  // m: the tree's crown, for occlusion of its inner wood
flat in vec3 v_crown_radius;  // m, half extents
flat in float v_fade;         // the share of the pixels the tree's impostor takes

uniform sampler2D u_bark_albedo;
uniform sampler2D u_bark_normal;
#ifdef BOREAS_BAKE_PASS
uniform mat3 u_bake_to_template;  // world -> the template's space, for the normals
layout(location = 1) out vec4 o_normal;  // template space, 0.5 n + 0.5; a: the sky's share
layout(location = 2) out vec4 o_leaf;    // 0: bark (impostor.frag)
#endif
layout(location = 0) out vec4 o_color;

// Sky light reaching wood inside the crown: about a third at its center, all of it outside.
float crown_occlusion(vec3 p) {
  vec3 d = (p - v_crown_center) / max(v_crown_radius, vec3(0.1));
  float r = clamp(length(d), 0.0, 1.0);
  return mix(0.3, 1.0, r * r);
}

void main() {
  if (v_fade > 0.0 && handover_dither(gl_FragCoord.xy) < v_fade) discard;
#ifdef BOREAS_SHADOW_PASS
  o_color = vec4(0.0);
#else
  vec3 n = normalize(v_normal);
  vec3 b = normalize(v_along - dot(v_along, n) * n);
  vec3 t = cross(b, n);  // +u: around the branch
  vec3 nt = texture(u_bark_normal, v_uv).xyz;
  vec3 shading = normalize(t * nt.x + b * nt.y + n * nt.z);
  vec3 albedo = texture(u_bark_albedo, v_uv).rgb;
#ifdef BOREAS_BAKE_PASS
  o_color = vec4(albedo, 1.0);
  o_normal = vec4(normalize(u_bake_to_template * shading) * 0.5 + 0.5, crown_occlusion(v_position));
  o_leaf = vec4(0.0);
  return;
#endif
  float sun = max(dot(shading, u_sun_dir), 0.0) * (dot(n, u_sun_dir) > 0.0 ? sun_visibility(v_position, n) : 0.0);
  vec3 e = u_sun_irradiance * sun + ambient_irradiance(shading) * crown_occlusion(v_position);
  o_color = vec4(albedo / kPi * e, 1.0);
#endif
}
