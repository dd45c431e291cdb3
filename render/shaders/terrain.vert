// boreas: the ground, a flat square around the scene at height u_ground_y.
#include "frame.glsl"

uniform vec4 u_ground_rect;  // m: min x, min z, max x, max z
uniform float u_ground_y;    // m

out vec3 v_position;

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  vec2 xz = mix(u_ground_rect.xy, u_ground_rect.zw, corner);
  v_position = vec3(xz.x, u_ground_y, xz.y);
  gl_Position = u_view_proj * vec4(v_position, 1.0);
}
