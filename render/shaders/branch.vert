// boreas: branches swept by the deformer (Skjermo sec. 3) from the branch records the
// kernels wrote. One indirect command per tree and level (tree_ranges.comp): instance i is
// branch i of the draw's (tree_table.glsl), at its record of the frame (entry_frame), and
// the element indices walk its (rings + 1) x (sides + 1) grid.
//
// Twigs thinner than a pixel (shadow pass: a shadow-map texel) are thinned as the blades and
// leaves are (Cook et al., "Stochastic simplification of aggregate detail"): a branch w
// pixels across at its base (w < 1) is kept with probability w, by a hash of its record so
// the same ones stay, and the kept ones are swept 1 / w times thicker, so the expected area
// the twigs cover stays while the rasterizer sees a fraction of them. A weeping willow
// hangs some 26,000 twigs of about 2 mm.
#include "frame.glsl"
#include "branch_deform.glsl"
#include "tree_table.glsl"

layout(location = 0) in uint a_draw;
#ifdef BOREAS_BAKE_PASS
layout(std430, binding = 18) readonly buffer BakeBranches { int bake_branch[]; };
uniform int u_bake_first_branch;
uniform int u_bake_branch_shift;  // ImpostorTemplate::rest_branch_shift
#endif
uniform float u_bark_tile;  // m of bark one texture repeat covers, around and along

const float kMinKeep = 0.05;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_along;  // unit: the branch's axis direction, the bark's v
out vec2 v_uv;     // bark texture coordinates, in repeats
flat out vec3 v_crown_center;  // m: the tree's crown, for the bark's occlusion
flat out vec3 v_crown_radius;  // m, half extents
flat out float v_fade;         // impostor_fade: the share of the pixels its impostor takes

void main() {
  DrawEntry d = draw_entry[a_draw];
  int rings = d.grid.x, sides = d.grid.y;
  int ring = gl_VertexID / (sides + 1);
  int side = gl_VertexID - ring * (sides + 1);
  // The thinning's hash is of the branch's own index (its record at the draw's own
  // offset), not of where the frame's view put it, so the same twigs stay as others come
  // and go.
#ifdef BOREAS_BAKE_PASS
  int record = bake_branch[(d.range.x - u_bake_first_branch) + gl_InstanceID];  // kept already
  int own = record;
  record -= u_bake_branch_shift;  // the templates' trees alone, one after the other
#else
  int record = entry_frame[a_draw].x + gl_InstanceID;
  int own = d.range.x + gl_InstanceID;
#endif
  v_crown_center = d.crown_center.xyz;
  v_crown_radius = d.crown_radius.xyz;
#if defined(BOREAS_SHADOW_PASS) || defined(BOREAS_BAKE_PASS)
  v_fade = 0.0;
#else
  v_fade = impostor_fade(d.range.z, u_eye);
#endif
  Branch b = load_branch(record);
  float keep = keep_probability(2.0 * b.radius / footprint_at(b.p0), kMinKeep);
#ifndef BOREAS_BAKE_PASS
  if (index_hash(own) >= keep) {
    // Thinned out: outside the clip volume, so nothing is drawn.
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = b.p0;
    v_normal = vec3(0.0, 1.0, 0.0);
    v_along = vec3(0.0, 1.0, 0.0);
    v_uv = vec2(0.0);
    return;
  }
#endif
  b.radius /= keep;
  float v = ring_v(ring, rings, b.tip_cap);
  float turns = float(side) / float(sides);
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
