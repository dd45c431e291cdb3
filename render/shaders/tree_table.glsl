// boreas: the frame's generated trees as the renderer laid them out once (gl/tree_table.h):
// per tree its placement and box, per template its impostor's sphere, per draw (a tree's
// level of branches or its leaves) its records and grid. The draw commands that tree_ranges.comp
// writes each frame carry the draw's index as their base instance, which the vertex shaders
// read back through the instanced attribute a_draw (a divisor larger than any instance
// count, so every instance of a draw sees its base instance).
struct TreeEntry {
  vec4 position_scale;     // m: the trunk's base; the template's scale
  vec4 rest_tip_rotation;  // m: the trunk tip at rest, world space; rad about +Y
  vec4 bounds_min;         // m: the box it sways in; w: its template, -1 none
  vec4 bounds_max;         // m; w: its trunk's branch record, -1 none
  ivec4 draws;             // its branch draws [x, y), its leaf draw z (-1 none), 0
};
struct TemplateEntry {
  vec4 center_radius;             // m, template space: its bounding sphere
  vec4 transmittance_tip_height;  // linear rgb of its leaves; m: the trunk tip's height
  vec4 layer;                     // x: its layer of the impostor maps; y: 1 once baked
  vec4 unused;
};
struct DrawEntry {
  ivec4 range;          // first record (branch or leaf), count, tree, element indices (0: leaves)
  ivec4 grid;           // rings, sides, first element index of the grid, 0; leaves: x
                        // their first static data (LeafDraw::first_static), 0, 0, 0
  vec4 crown_center;    // m: the tree's crown, for the bark's occlusion; leaves: x what
                        // multiplies their static lengths, w their mean area (m^2)
  vec4 crown_radius;    // m, half extents
};
// Where a leaf draw's leaf (its index among every draw's, d.range.x on) has its static
// data, in leaves: trees of one template share theirs (LeafDraw::first_static).
int leaf_static_of(DrawEntry d, int leaf) { return d.grid.x + (leaf - d.range.x); }

layout(std430, binding = 10) readonly buffer Trees { TreeEntry tree_entry[]; };
layout(std430, binding = 11) readonly buffer Templates { TemplateEntry template_entry[]; };
layout(std430, binding = 12) readonly buffer Draws { DrawEntry draw_entry[]; };
// Per draw, this frame (tree_ranges.comp): its first record in the frame's buffers, and
// for leaves the stride of the leaves kept (record m is the draw's leaf (m * stride) mod
// its count).
layout(std430, binding = 20) buffer EntryFrame { ivec2 entry_frame[]; };

// m: where trees begin to change into their impostors (RenderSettings::impostor_distance;
// 0: never), and the share of it the change takes (kImpostorHandover).
uniform float u_impostor_distance;
uniform float u_impostor_handover;
uniform int u_impostors_baked;  // 0: no template has been baked yet

// How far the tree has changed into its impostor as the camera at eye sees it: 0 all
// geometry, 1 all impostor; in between both are drawn, each in its share of the pixels.
// impostor_fade_at: the same for a tree with an impostor whose base is at `base`.
float impostor_fade_at(vec3 base, vec3 eye) {
  if (u_impostors_baked == 0 || u_impostor_distance <= 0.0) return 0.0;
  float d = distance(eye, base);
  return clamp((d - u_impostor_distance) / (u_impostor_distance * u_impostor_handover), 0.0, 1.0);
}

float impostor_fade(int tree, vec3 eye) {
  TreeEntry t = tree_entry[tree];
  if (t.bounds_min.w < 0.0 || template_entry[int(t.bounds_min.w)].layer.y == 0.0) return 0.0;
  return impostor_fade_at(t.position_scale.xyz, eye);
}

// A threshold per pixel in [0, 1) (interleaved gradient noise, Jimenez 2014): geometry keeps
// the pixels above the fade, the impostor those below, so together they cover it once.
float handover_dither(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
