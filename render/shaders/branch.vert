// boreas: branches swept by the deformer (Skjermo sec. 3) from the branch records the
// kernels wrote. One instanced draw per tree and level: instance i is branch
// u_first_record + i, and the element indices walk its (u_rings + 1) x (u_sides + 1) grid.
//
// Twigs thinner than a pixel (shadow pass: a shadow-map texel) are thinned as the blades and
// leaves are (Cook et al., "Stochastic simplification of aggregate detail"): a branch w
// pixels across at its base (w < 1) is kept with probability w, by a hash of its record so
// the same ones stay, and the kept ones are swept 1 / w times thicker, so the expected area
// the twigs cover stays while the rasterizer sees a fraction of them. A weeping willow
// hangs some 26,000 twigs of about 2 mm.
#include "frame.glsl"
#include "branch_deform.glsl"

uniform int u_first_record;
uniform int u_rings;
uniform int u_sides;
uniform float u_bark_tile;  // m of bark one texture repeat covers, around and along

const float kMinKeep = 0.05;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_along;  // unit: the branch's axis direction, the bark's v
out vec2 v_uv;     // bark texture coordinates, in repeats

void main() {
  int ring = gl_VertexID / (u_sides + 1);
  int side = gl_VertexID - ring * (u_sides + 1);
  int record = u_first_record + gl_InstanceID;
  Branch b = load_branch(record);
  float keep = keep_probability(2.0 * b.radius / footprint_at(b.p0), kMinKeep);
  if (index_hash(record) >= keep) {
    // Thinned out: outside the clip volume, so nothing is drawn.
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = b.p0;
    v_normal = vec3(0.0, 1.0, 0.0);
    v_along = vec3(0.0, 1.0, 0.0);
    v_uv = vec2(0.0);
    return;
  }
  b.radius /= keep;
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
