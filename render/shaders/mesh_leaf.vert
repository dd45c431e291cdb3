// boreas: the leaves of an imported tree (Kusternig sec. 5) for the leaf shader: the kernels
// wrote each vertex's position and turned normal (boreas_mesh_tree_enqueue_vertices: 6
// floats per vertex); the renderer derived the rest of what leaf.frag reads once (gl/
// mesh_tree_surface.h: the texture's +v direction at rest, uv, ambient occlusion; 6 floats).
// Outputs are leaf.vert's.
#include "frame.glsl"

layout(std430, binding = 7) readonly buffer MeshLeafVertices { float leaf_vertex[]; };
layout(std430, binding = 8) readonly buffer MeshLeafStatic { float leaf_static[]; };

// Where the blade lies on the texture (render/textures/leaf_shape.h): leaves whose model had
// no texture coordinates (uv < 0, gl/mesh_tree_surface.h) sample the middle of the blade.
uniform float u_blade_base_v;
uniform float u_blade_tip_v;

out vec3 v_position;
out vec3 v_normal;   // unit
out vec3 v_across;   // unit, +u
out vec3 v_along;    // unit, +v
out vec2 v_uv;
out vec3 v_occlusion;
flat out float v_layer;  // imported trees use the set's own leaf (layer 0)
flat out float v_fade;   // imported trees have no impostor

void main() {
  int d = gl_VertexID * 6, s = gl_VertexID * 6;
  vec3 position = vec3(leaf_vertex[d], leaf_vertex[d + 1], leaf_vertex[d + 2]);
  vec3 normal = normalize(vec3(leaf_vertex[d + 3], leaf_vertex[d + 4], leaf_vertex[d + 5]));
  // The rest pose's +v, kept in the turned blade's plane: exact for a turn about the
  // normal's own plane and close for the small turns of a leaf in wind.
  vec3 rest_along = vec3(leaf_static[s], leaf_static[s + 1], leaf_static[s + 2]);
  vec3 along = rest_along - dot(rest_along, normal) * normal;
  along = dot(along, along) > 1e-12 ? normalize(along) : normalize(cross(normal, vec3(0.31, 0.9, 0.3)));
  vec2 uv = vec2(leaf_static[s + 3], leaf_static[s + 4]);
  if (uv.x < 0.0) uv = vec2(0.5, 0.5 * (u_blade_base_v + u_blade_tip_v));
  v_position = position;
  v_normal = normal;
  v_along = along;
  v_across = cross(along, normal);  // as leaf.vert: (across, along, normal) right-handed
  v_uv = uv;
  v_occlusion = vec3(leaf_static[s + 5]);
  v_layer = 0.0;
  v_fade = 0.0;
  gl_Position = u_view_proj * vec4(position, 1.0);
}
