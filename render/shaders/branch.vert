// boreas: branches swept by the deformer (Skjermo sec. 3) from the branch records the
// kernels wrote. One instanced draw per tree and level: instance i is branch
// u_first_record + i, and the element indices walk its (u_rings + 1) x (u_sides + 1) grid.
#include "frame.glsl"
#include "branch_deform.glsl"

uniform int u_first_record;
uniform int u_rings;
uniform int u_sides;
uniform float u_bark_tile;  // m of bark one texture repeat covers, around and along

out vec3 v_position;
out vec3 v_normal;
out vec3 v_along;  // unit: the branch's axis direction, the bark's v
out vec2 v_uv;     // bark texture coordinates, in repeats

void main() {
  int ring = gl_VertexID / (u_sides + 1);
  int side = gl_VertexID - ring * (u_sides + 1);
  Branch b = load_branch(u_first_record + gl_InstanceID);
  float v = float(ring) / float(u_rings);
  float turns = float(side) / float(u_sides);
  vec3 position, normal;
  branch_surface(b, v, turns, position, normal);
  v_position = position;
  v_normal = normal;
  vec3 axis = bezier_derivative(b, v);
  v_along = normalize(axis - dot(axis, normal) * normal);
  // Whole repeats around the branch, so the seam closes; along it, metres of the control
  // polygon (the curve is within a few percent of it).
  float around = max(1.0, floor(kTwoPi * b.radius / u_bark_tile + 0.5));
  float length = distance(b.p0, b.p1) + distance(b.p1, b.p2) + distance(b.p2, b.p3);
  v_uv = vec2(turns * around, v * length / u_bark_tile);
  gl_Position = u_view_proj * vec4(position, 1.0);
}
