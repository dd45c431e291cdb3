// boreas: tree leaves as instanced quads from the leaf records the kernels wrote
// (boreas_tree_enqueue_leaf_records: base of the blade, axis, normal; 9 floats) and the
// static per-leaf data the renderer uploaded once (length, width, ambient occlusion).
// Instance i is leaf i; the four vertices of a strip span the texture's square, placed so
// that the drawn blade starts at the record's position and has the leaf's length and width.
#include "frame.glsl"

layout(std430, binding = 2) readonly buffer LeafRecords { float leaf_record[]; };
layout(std430, binding = 3) readonly buffer LeafStatic { float leaf_static[]; };

// Where the blade lies on the texture (render/textures/leaf_shape.h): v of its base and tip,
// and its widest half-width in u.
uniform float u_blade_base_v;
uniform float u_blade_tip_v;
uniform float u_blade_half_width;

out vec3 v_position;
out vec3 v_normal;   // the upper side's, unit
out vec3 v_across;   // unit, +u
out vec3 v_along;    // unit, +v
out vec2 v_uv;
out float v_occlusion;

vec3 record_vec3(int base) { return vec3(leaf_record[base], leaf_record[base + 1], leaf_record[base + 2]); }

void main() {
  int r = gl_InstanceID * 9;
  vec3 base = record_vec3(r);
  vec3 axis = normalize(record_vec3(r + 3));
  vec3 normal = normalize(record_vec3(r + 6));
  vec3 across = cross(axis, normal);  // tangent space: +x across, +y along, +z up
  float length = leaf_static[gl_InstanceID * 3];
  float width = leaf_static[gl_InstanceID * 3 + 1];
  v_occlusion = leaf_static[gl_InstanceID * 3 + 2];
  vec2 uv = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  float side_v = length / (u_blade_tip_v - u_blade_base_v);
  float side_u = width / (2.0 * u_blade_half_width);
  vec3 p = base + axis * ((uv.y - u_blade_base_v) * side_v) + across * ((uv.x - 0.5) * side_u);
  v_position = p;
  v_normal = normal;
  v_across = across;
  v_along = axis;
  v_uv = uv;
  gl_Position = u_view_proj * vec4(p, 1.0);
}
