// boreas: far trees as their templates' impostors (gl/impostor_math.h): per record (12
// floats: the records' one call's, or the handover's of tree_ranges.comp) a square facing
// the viewer through the template's sphere, placed as the tree stands and sheared by its
// trunk tip's sway, on which the three baked frames nearest the direction it is seen from
// are blended by their barycentric weights on the frames' grid (each frame read where the
// square's point lies on it, seen along the frame's direction). The shadow pass sees it
// from the sun.
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
// The three frames nearest the direction it is seen from (their cells of the atlas), their
// weights, and where the fragment lies on each frame (0..1 across the frame's square).
out vec2 v_local[3];
flat out vec2 v_cell[3];
flat out vec3 v_weight;
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
    for (int k = 0; k < 3; ++k) {
      v_local[k] = vec2(0.0);
      v_cell[k] = vec2(0.0);
    }
    v_weight = vec3(0.0);
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
  // The frames' centres on the grid g: the triangle of three around the direction, with
  // its barycentric weights, so that the picture turns smoothly from frame to frame.
  vec2 g = hemi_octahedral_uv(seen_from) * float(kFrames) - 0.5;
  ivec2 c0 = clamp(ivec2(floor(g)), ivec2(0), ivec2(kFrames - 2));
  vec2 f = clamp(g - vec2(c0), 0.0, 1.0);
  bool lower = f.x >= f.y;
  ivec2 cells[3] = ivec2[3](c0, c0 + (lower ? ivec2(1, 0) : ivec2(0, 1)), c0 + ivec2(1, 1));
  v_weight = lower ? vec3(1.0 - f.x, f.x - f.y, f.y) : vec3(1.0 - f.y, f.y - f.x, f.x);
#ifdef BOREAS_SHADOW_PASS
  // The shadow map's blur hides the switch between frames: the nearest alone.
  v_weight = v_weight.x >= max(v_weight.y, v_weight.z) ? vec3(1.0, 0.0, 0.0)
             : v_weight.y >= v_weight.z               ? vec3(0.0, 1.0, 0.0)
                                                      : vec3(0.0, 0.0, 1.0);
#endif
  // A square facing the viewer, through the sphere's centre, covering it.
  vec3 corner_up = abs(seen_from.y) > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(corner_up, seen_from));
  vec3 up = cross(seen_from, right);
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
  vec3 p = center + (right * corner.x + up * corner.y) * radius;  // template space
  for (int k = 0; k < 3; ++k) {
    // Where p lies on frame k, seen along its direction (impostor_frame_view_projection's
    // basis: right = up_ref x d, up = d x right).
    vec3 d = hemi_octahedral_direction((vec2(cells[k]) + 0.5) / float(kFrames));
    vec3 up_ref = abs(d.y) > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    vec3 r_k = normalize(cross(up_ref, d));
    vec3 u_k = cross(d, r_k);
    v_local[k] = vec2(dot(p - center, r_k), dot(p - center, u_k)) / radius * 0.5 + 0.5;
    v_cell[k] = vec2(cells[k]);
  }
  // impostor_matrix: placed, then sheared by the sway along the template's height.
  vec3 world = base + rotation * (p * scale) + sway * (p.y / max(t.transmittance_tip_height.w, 1e-3));
  v_position = world;
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
