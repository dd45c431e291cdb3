// boreas: the branch deformer alone, for tests and benchmarks: vertex gl_VertexID of the
// branches [u_first_record, ...) on a (u_rings + 1) x (u_sides + 1) grid each, written to
// the probe buffer as position, normal (6 floats) at u_out_first + gl_VertexID. Drawn as
// points with the rasterizer off.
#include "branch_deform.glsl"

layout(std430, binding = 1) writeonly buffer Probe { float probe[]; };

uniform int u_first_record;
uniform int u_rings;
uniform int u_sides;
uniform int u_out_first;

void main() {
  int per_branch = (u_rings + 1) * (u_sides + 1);
  int b = gl_VertexID / per_branch;
  int r = gl_VertexID - b * per_branch;
  int ring = r / (u_sides + 1);
  int side = r - ring * (u_sides + 1);
  vec3 position, normal;
  Branch probed = load_branch(u_first_record + b);
  float v = ring_v(ring, u_rings, probed.tip_cap);
  branch_surface(probed, v, float(side) / float(u_sides), position, normal);
  int o = (u_out_first + gl_VertexID) * 6;
  probe[o + 0] = position.x;
  probe[o + 1] = position.y;
  probe[o + 2] = position.z;
  probe[o + 3] = normal.x;
  probe[o + 4] = normal.y;
  probe[o + 5] = normal.z;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
