// boreas: the scene's balls (colliders), each a UV sphere made from gl_VertexID: u_segments
// around by u_segments / 2 rings, two triangles per quad; instance i is ball i of u_balls.
#include "frame.glsl"

const int kMaxBalls = 64;
uniform vec4 u_balls[kMaxBalls];  // center (m), radius (m)
uniform int u_segments;

out vec3 v_position;
out vec3 v_normal;

void main() {
  const int corner_u[6] = int[6](0, 1, 1, 0, 1, 0);
  const int corner_v[6] = int[6](0, 0, 1, 0, 1, 1);
  int quad = gl_VertexID / 6, corner = gl_VertexID - quad * 6;
  int rings = u_segments / 2;
  int i = quad % u_segments + corner_u[corner];
  int j = quad / u_segments + corner_v[corner];
  float phi = 6.28318530717958647 * float(i) / float(u_segments);
  float theta = 3.14159265358979324 * float(j) / float(rings);
  vec3 n = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
  vec4 ball = u_balls[gl_InstanceID];
  v_normal = n;
  v_position = ball.xyz + ball.w * n;
  gl_Position = u_view_proj * vec4(v_position, 1.0);
}
