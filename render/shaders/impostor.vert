// boreas: far trees as their templates' impostors (gl/impostor_math.h): per record (12
// floats: the records' one call's, or the handover's of tree_ranges.comp) a quad on the image plane of the
// template's baked frame nearest the direction it is seen from, placed as the tree stands
// and sheared by its trunk tip's sway; the frame's texels are its uv. The shadow pass sees
// it from the sun.
#include "frame.glsl"
#include "tree_table.glsl"

layout(std430, binding = 15) readonly buffer ImpostorRecords { float impostor_record[]; };
// The world's templates (boreas_tree_get_template) as the renderer's, -1 none.
layout(std430, binding = 24) readonly buffer TemplateOfWorld { int template_of_world[]; };
uniform int u_first_record;     // the draw's first record
uniform int u_world_templates;  // 1: a record names the world's template (the call's)
uniform int u_world_template_count;

uniform vec3 u_toward_sun;  // unit: the shadow pass looks along its opposite

const int kFrames = BOREAS_IMPOSTOR_FRAMES;

out vec3 v_position;  // m, world
out vec2 v_uv;        // in the template's atlas
flat out float v_layer;
flat out float v_fade;
flat out mat3 v_to_world;  // template space -> world, rotation only
flat out vec3 v_transmittance;

// gl/impostor_math.cpp's hemi_octahedral_uv and hemi_octahedral_direction.
vec2 hemi_octahedral_uv(vec3 d) {
  d.y = max(d.y, 0.0);
  float l1 = abs(d.x) + d.y + abs(d.z);
  if (l1 <= 0.0) return vec2(0.5);
  float x = d.x / l1, z = d.z / l1;
  return vec2(0.5 + 0.5 * (x + z), 0.5 + 0.5 * (x - z));
}

vec3 hemi_octahedral_direction(vec2 uv) {
  float a = 2.0 * uv.x - 1.0, b = 2.0 * uv.y - 1.0;
  float x = 0.5 * (a + b), z = 0.5 * (a - b);
  return normalize(vec3(x, max(1.0 - abs(x) - abs(z), 0.0), z));
}

void main() {
  int r = (u_first_record + gl_InstanceID) * 12;
  vec3 base = vec3(impostor_record[r], impostor_record[r + 1], impostor_record[r + 2]);
  float scale = impostor_record[r + 3], angle = impostor_record[r + 4];
  int tmpl = int(impostor_record[r + 5]);
  if (u_world_templates != 0) tmpl = tmpl >= 0 && tmpl < u_world_template_count ? template_of_world[tmpl] : -1;
  if (tmpl < 0 || template_entry[tmpl].layer.y == 0.0) {
    // No baked impostor (the view's impostor distance is set only where every tree has one).
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = base;
    v_uv = vec2(0.0);
    v_layer = 0.0;
    v_fade = 0.0;
    v_to_world = mat3(1.0);
    v_transmittance = vec3(0.0);
    return;
  }
  vec3 sway = vec3(impostor_record[r + 6], impostor_record[r + 7], impostor_record[r + 8]);
  TemplateEntry t = template_entry[tmpl];
  vec3 center = t.center_radius.xyz;
  float radius = t.center_radius.w;
  // gl/impostor_math.cpp's tree_placement: x -> (c, 0, -s), z -> (s, 0, c).
  float c = cos(angle), s = sin(angle);
  mat3 rotation = mat3(vec3(c, 0.0, -s), vec3(0.0, 1.0, 0.0), vec3(s, 0.0, c));
  vec3 world_center = base + rotation * (center * scale);
#ifdef BOREAS_SHADOW_PASS
  vec3 toward = u_toward_sun;
#else
  vec3 toward = normalize(u_eye - world_center);
#endif
  vec3 seen_from = transpose(rotation) * toward;  // template space
  ivec2 cell = clamp(ivec2(floor(hemi_octahedral_uv(seen_from) * float(kFrames))), ivec2(0), ivec2(kFrames - 1));
  vec3 d = hemi_octahedral_direction((vec2(cell) + 0.5) / float(kFrames));
  // impostor_frame_view_projection's basis: right = up_ref x d, up = d x right.
  vec3 up_ref = abs(d.y) > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(up_ref, d));
  vec3 up = cross(d, right);
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
  vec3 p = center + (right * corner.x + up * corner.y) * radius;  // template space
  // impostor_matrix: placed, then sheared by the sway along the template's height.
  vec3 world = base + rotation * (p * scale) + sway * (p.y / max(t.transmittance_tip_height.w, 1e-3));
  v_position = world;
  // Half a texel in from the frame's edge, so filtering never reads the next frame.
  const float inset = 0.5 / float(BOREAS_IMPOSTOR_FRAME_TEXELS);
  vec2 in_frame = clamp(corner * 0.5 + 0.5, inset, 1.0 - inset);
  v_uv = (vec2(cell) + in_frame) / float(kFrames);
  v_layer = t.layer.x;
  v_to_world = rotation;
  v_transmittance = t.transmittance_tip_height.xyz;
#ifdef BOREAS_SHADOW_PASS
  v_fade = 1.0;
#else
  v_fade = impostor_fade_at(base, u_eye);
#endif
  gl_Position = u_view_proj * vec4(world, 1.0);
}
