// boreas: tree leaves as instanced quads from the leaf records the kernels wrote
// (boreas_tree_enqueue_leaf_records: base of the blade, axis, normal; 9 floats) and the
// static per-leaf data the renderer uploaded once (length, width, the crown's ambient
// occlusion r, g, b (boreas_tree_get_leaf_occlusion), the layer of its kind's leaf maps;
// kStaticFloats floats), one copy per template at scale 1 (leaf_static_of), scaled by the draw.
// Instance m of a draw is record m of its tree's in the frame (tree_table.glsl's entry_frame:
// the first, and the stride of the leaves the records' one call kept; one indirect command
// per tree, tree_ranges.comp): the tree's leaf (m * stride) mod n, whose static data it
// reads, its record's axis lengthened by the call by as much as the leaves it left out
// (coverage kept: the leaf is drawn that much longer and wider). The four vertices of a
// strip span the texture's square, placed so that the drawn blade starts at the record's
// position and has the leaf's length and width.
//
// Leaves too small to be resolved are thinned (Cook, Halstead, Planck and Ryu, "Stochastic
// simplification of aggregate detail", 2007): a leaf whose length x width covers A < A0
// pixels (shadow pass: shadow-map texels) is kept with probability A / A0 (at least
// kMinKeep), by a hash of its index so the same ones stay from frame to frame, and a kept
// leaf is drawn 1 / sqrt(keep) larger each way: the expected area the crown covers stays
// what it was, with fewer triangles, which is what a CPU rasterizer pays for. A0 is a
// 3 x 3-pixel leaf on screen, below which its outline is not resolved (a lobe, a tip or a
// notch takes a pixel of its own), and a 3 x 3-texel leaf in the shadow map, the footprint
// of the shadow filter (1.5 texels each way), below which its shape is blurred away.
#include "frame.glsl"
#include "tree_table.glsl"

layout(std430, binding = 2) readonly buffer LeafRecords { float leaf_record[]; };
layout(std430, binding = 3) readonly buffer LeafStatic { float leaf_static[]; };

// Where the blade lies on the texture (render/textures/leaf_shape.h): v of its base and tip,
// and its widest half-width in u.
uniform float u_blade_base_v;
uniform float u_blade_tip_v;
uniform float u_blade_half_width;
layout(location = 0) in uint a_draw;
#ifdef BOREAS_BAKE_PASS
layout(std430, binding = 19) readonly buffer BakeLeaves { int bake_leaf[]; };
uniform int u_bake_leaf_shift;  // ImpostorTemplate::rest_leaf_shift
#endif

const int kStaticFloats = 6;
const float kMinKeep = 0.05;
const float kResolvedArea = 9.0;  // pixels, or shadow-map texels in the shadow pass

out vec3 v_position;
out vec3 v_normal;   // the upper side's, unit
out vec3 v_across;   // unit, +u
out vec3 v_along;    // unit, +v
out vec2 v_uv;
out vec3 v_occlusion;  // the crown's occlusion, tinted by the leaves it crossed
flat out float v_layer;
flat out float v_fade;  // impostor_fade: the share of the pixels its impostor takes

vec3 record_vec3(int base) { return vec3(leaf_record[base], leaf_record[base + 1], leaf_record[base + 2]); }

// (m * stride) mod n without overflowing 32 bits (m, stride < n < 2^24), a byte of m at a
// time: the records' one call's order (cl/tree_leaves.cl).
int kept_leaf(int m, int stride, int n) {
  uint r = 0u, s = uint(stride) % uint(n), un = uint(n);
  for (int shift = 16; shift >= 0; shift -= 8) {
    uint byte_ = (uint(m) >> uint(shift)) & 255u;
    r = ((r * 256u) % un + (byte_ * s) % un) % un;
  }
  return int(r);
}

void main() {
  DrawEntry d = draw_entry[a_draw];
  int corner = gl_VertexID & 3;
#ifdef BOREAS_BAKE_PASS
  int leaf = bake_leaf[gl_InstanceID];  // kept already (impostor_thinning.comp)
  int record = leaf - u_bake_leaf_shift;  // the templates' trees alone, one after the other
#else
  // The command's first vertex is 4 x the pass's own stride (tree_ranges.comp: what the
  // pass cannot resolve of the call's records), each kept leaf that much larger.
  int pass_stride = max(gl_VertexID >> 2, 1);
  int m = gl_InstanceID * pass_stride;
  ivec2 frame = entry_frame[a_draw];
  int record = frame.x + m;
  int leaf = d.range.x + (frame.y > 1 ? kept_leaf(m, frame.y, d.range.y) : m);
#endif
#if defined(BOREAS_SHADOW_PASS) || defined(BOREAS_BAKE_PASS)
  v_fade = 0.0;
#else
  v_fade = impostor_fade(d.range.z, u_eye);
#endif
  int r = record * 9;
  vec3 base = record_vec3(r);
  vec3 axis = record_vec3(r + 3);
  float grow_kept = length(axis);  // the call's size factor: 1 where it kept every leaf
  axis /= grow_kept;
#ifndef BOREAS_BAKE_PASS
  grow_kept *= sqrt(float(pass_stride));
#endif
  vec3 normal = normalize(record_vec3(r + 6));
  vec3 across = cross(axis, normal);  // tangent space: +x across, +y along, +z up
  const int s = leaf_static_of(d, leaf) * kStaticFloats;
  float length = leaf_static[s] * d.crown_center.x;
  float width = leaf_static[s + 1] * d.crown_center.x;
  v_occlusion = vec3(leaf_static[s + 2], leaf_static[s + 3], leaf_static[s + 4]);
  v_layer = leaf_static[s + 5];
  float footprint = footprint_at(base);
  length *= grow_kept;
  width *= grow_kept;
  float keep = keep_probability(length * width / (footprint * footprint * kResolvedArea), kMinKeep);
#ifndef BOREAS_BAKE_PASS
  if (index_hash(leaf) >= keep) {
    // Thinned out: outside the clip volume, so nothing is drawn.
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_position = base;
    v_normal = normal;
    v_across = across;
    v_along = axis;
    v_uv = vec2(0.0);
    return;
  }
#endif
  float grow = inversesqrt(keep);
  length *= grow;
  width *= grow;
  // The quad spans the blade's box on the texture, not the whole square: every kind's
  // outline lies within half_width of the midrib and below the tip (cl/shared/
  // leaf_outline.h), so the rest is discarded texels, about a third of the square, that
  // the rasterizer would cover and the fragment shader test for nothing. A margin of 0.02
  // for the filtering at the box's edge.
  vec2 uv_min = vec2(0.48 - u_blade_half_width, 0.0);
  vec2 uv_max = vec2(0.52 + u_blade_half_width, min(u_blade_tip_v + 0.02, 1.0));
  vec2 uv = mix(uv_min, uv_max, vec2(float(corner & 1), float(corner >> 1)));
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
