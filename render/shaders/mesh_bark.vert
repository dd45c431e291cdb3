// boreas: the trunk and branches of an imported tree (Kusternig sec. 5), as the kernels
// moved them (boreas_mesh_tree_enqueue_vertices: 3 floats per vertex) with the shading
// attributes the renderer derived once from the rest pose (gl/mesh_tree_surface.h: normal,
// the bark's along direction, bark uv in texture repeats; 8 floats per vertex). Drawn with
// the element indices of the model, so gl_VertexID is the vertex.
//
// The normals stay the rest normals: a branch sways as a whole, smoothly along its length,
// so its surface turns by the sway's slope, a few degrees in strong wind.
#include "frame.glsl"

layout(std430, binding = 5) readonly buffer MeshTrunkPositions { float trunk_position[]; };
layout(std430, binding = 6) readonly buffer MeshTrunkStatic { float trunk_static[]; };

out vec3 v_position;
out vec3 v_normal;
out vec3 v_along;  // unit: the bark texture's +v on the surface
out vec2 v_uv;     // bark texture coordinates, in repeats
flat out vec3 v_crown_center;
flat out vec3 v_crown_radius;
flat out float v_fade;  // imported trees have no impostor

uniform vec3 u_crown_center;  // m: the tree's crown, for occlusion of its inner wood
uniform vec3 u_crown_radius;  // m, half extents

void main() {
  int p = gl_VertexID * 3, s = gl_VertexID * 8;
  vec3 position = vec3(trunk_position[p], trunk_position[p + 1], trunk_position[p + 2]);
  v_position = position;
  v_normal = vec3(trunk_static[s], trunk_static[s + 1], trunk_static[s + 2]);
  v_along = vec3(trunk_static[s + 3], trunk_static[s + 4], trunk_static[s + 5]);
  v_uv = vec2(trunk_static[s + 6], trunk_static[s + 7]);
  v_crown_center = u_crown_center;
  v_crown_radius = u_crown_radius;
  v_fade = 0.0;
  gl_Position = u_view_proj * vec4(position, 1.0);
}
