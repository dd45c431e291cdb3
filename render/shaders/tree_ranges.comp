// boreas: a frame's draw commands for the generated trees, from what the records' one call
// (boreas_world_enqueue_tree_records, gl/tree_view.h) wrote: one invocation per range
// record (a tree it drew), which finds the tree by its id and points the tree's draws
// (its levels of branches, its leaves; tree_table.glsl) at its records for the frame:
//  - entry_frame: the draw's first record in the frame's buffers and its leaf stride (the
//    call keeps leaf (m * stride) mod n as record m, its axis lengthened to keep coverage);
//  - commands, two sets: the scene pass's skip the trees whose box is out of the camera's
//    frustum, the shadow pass's those whose box swept to the ground away from the sun is
//    (the call's view is the camera's widened toward the sun by the tallest tree's
//    shadow: this is per tree); a tree handing over to its impostor (impostor_fade) draws
//    geometry and impostor in the scene pass, one or the other in the shadow pass;
//  - a pass draws every n-th of a crown's leaf records, n times larger in area, where its
//    leaves are too small to resolve: the command's first vertex is 4 n (leaf.vert), so
//    the vertex shader runs for a fraction of them. The call thinned them for the camera
//    from the tree's base, down to kRecordsMinKeep (gl/tree_view.h); the scene pass takes
//    the rest from the crown's nearest point (the vertex shader then thins each leaf by its
//    own distance), the shadow pass from the shadow map's texel, far coarser;
//  - the handover's impostor records (the call's layout, but the renderer's template), for
//    the trees the call made in full; the call's own impostors are drawn from its buffer.
// Without ranges (u_from_ranges 0: the records lie at the draws' own offsets, every tree
// at full detail) invocation i stands for tree i as if the call had drawn it whole.
// The command buffers are cleared before: a tree not drawn keeps zero instances.
#include "frame.glsl"
#include "tree_table.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer BranchRecords { float branch_record[]; };
// DrawElementsIndirectCommand per branch draw, DrawArraysIndirectCommand per leaf draw:
// the scene pass's, then the shadow pass's.
layout(std430, binding = 13) writeonly buffer BranchCommands { uint branch_command[]; };
layout(std430, binding = 14) writeonly buffer LeafCommands { uint leaf_command[]; };
// Impostor records (12 floats) of the handover: the scene pass's u_trees, then the shadow
// pass's; and their two DrawArraysIndirectCommands.
layout(std430, binding = 15) writeonly buffer HandoverRecords { float handover_record[]; };
layout(std430, binding = 16) buffer HandoverCommands { uint handover_command[8]; };
layout(std430, binding = 21) readonly buffer Ranges { int range_record[]; };  // 8 ints each
layout(std430, binding = 22) readonly buffer Indirect { uint indirect[]; };   // 20 words
// Per boreas_tree_id index: the renderer's tree and the id's generation (-1: none).
layout(std430, binding = 23) readonly buffer TreeOfId { ivec2 tree_of_id[]; };

uniform mat4 u_camera_view_proj;
uniform vec3 u_sun_dir;  // unit, toward the sun
uniform float u_ground_y;  // m
uniform int u_from_ranges;  // 1: the call's ranges; 0: every tree at its own offsets
uniform int u_range_capacity;
uniform int u_ids;          // entries of tree_of_id
uniform int u_branch_draws;
uniform int u_leaf_draws;
uniform int u_trees;

// gl/frustum_cull.cpp's box_outside_frustum.
bool box_outside(mat4 vp, vec3 lo, vec3 hi) {
  vec4 c[8];
  for (int i = 0; i < 8; ++i) {
    vec3 p = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z);
    c[i] = vp * vec4(p, 1.0);
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int k = 0; k < 2; ++k) {
      float sign = k == 0 ? -1.0 : 1.0;
      bool all_out = true;
      for (int i = 0; i < 8; ++i) all_out = all_out && sign * c[i][axis] > c[i].w;
      if (all_out) return true;
    }
  }
  return false;
}

// gl/frustum_cull.cpp's shadow_outside_frustum.
bool shadow_outside(vec3 lo, vec3 hi) {
  if (u_sun_dir.y <= 0.01) return false;
  vec3 swept_lo = lo, swept_hi = hi;
  for (int i = 0; i < 8; ++i) {
    vec3 p = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z);
    vec3 q = p - u_sun_dir * (max(p.y - u_ground_y, 0.0) / u_sun_dir.y);
    swept_lo = min(swept_lo, q);
    swept_hi = max(swept_hi, q);
  }
  return box_outside(u_camera_view_proj, swept_lo, swept_hi);
}

// A pass's leaf stride: every n-th of the call's records where the mean kept leaf (the
// tree's mean area, grown as the call grew them) is a fraction 1 / n of what a 3 x 3 block
// of pixels (texels) of footprint m resolves (leaf.vert's kResolvedArea).
const int kMaxLeafStride = 16;
int leaf_stride(float footprint, float mean_area, int leaves, int kept) {
  if (u_thinning == 0 || mean_area <= 0.0 || kept <= 0) return 1;
  float area = mean_area * float(leaves) / float(kept);
  float resolved = area / (footprint * footprint * 9.0);
  return resolved >= 1.0 ? 1 : clamp(int(1.0 / resolved), 1, kMaxLeafStride);
}

// The tree's records this frame: first branch record, first leaf record, leaves, stride.
struct Frame {
  int tree;
  int branch_first;
  int leaf_first;
  int leaf_count;
  int stride;
};

bool frame_of(int i, out Frame f) {
  if (u_from_ranges == 0) {
    f.tree = i;
    TreeEntry t = tree_entry[i];
    f.branch_first = t.draws.x < t.draws.y ? draw_entry[t.draws.x].range.x : 0;
    f.leaf_first = t.draws.z >= 0 ? draw_entry[t.draws.z].range.x : 0;
    f.leaf_count = t.draws.z >= 0 ? draw_entry[t.draws.z].range.y : 0;
    f.stride = 1;
    return true;
  }
  if (i >= min(int(indirect[12]), u_range_capacity)) return false;
  int r = i * 8;
  int id = range_record[r];
  if (id < 0 || id >= u_ids || tree_of_id[id].y != range_record[r + 1] || tree_of_id[id].x < 0) return false;
  f.tree = tree_of_id[id].x;
  f.branch_first = range_record[r + 2];
  f.leaf_first = range_record[r + 4];
  f.leaf_count = range_record[r + 5];
  f.stride = max(range_record[r + 7], 1);
  return true;
}

void write_handover(int tree, Frame f, int pass) {
  TreeEntry t = tree_entry[tree];
  uint slot = atomicAdd(handover_command[pass * 4 + 1], 1u);
  int r = (pass * u_trees + int(slot)) * 12;
  vec3 sway = vec3(0.0);
  int trunk = int(t.bounds_max.w);  // its trunk's record at its own offsets
  if (trunk >= 0 && t.draws.x < t.draws.y) {
    int b = (f.branch_first + trunk - draw_entry[t.draws.x].range.x) * 28 + 9;  // P3 (branch_deform.glsl)
    sway = vec3(branch_record[b], branch_record[b + 1], branch_record[b + 2]) - t.rest_tip_rotation.xyz;
  }
  float record[12] = float[12](t.position_scale.x, t.position_scale.y, t.position_scale.z,
                               t.position_scale.w, t.rest_tip_rotation.w, t.bounds_min.w,
                               sway.x, sway.y, sway.z, 0.0, 0.0, 0.0);
  for (int k = 0; k < 12; ++k) handover_record[r + k] = record[k];
}

void main() {
  int i = int(gl_GlobalInvocationID.x);
  Frame f;
  if (i >= u_trees || !frame_of(i, f)) return;
  TreeEntry t = tree_entry[f.tree];
  float fade = impostor_fade(f.tree, u_eye);
  bool scene = fade < 1.0 && !box_outside(u_camera_view_proj, t.bounds_min.xyz, t.bounds_max.xyz);
  bool shadow = fade < 0.5 && !shadow_outside(t.bounds_min.xyz, t.bounds_max.xyz);
  for (int e = t.draws.x; e < t.draws.y; ++e) {
    DrawEntry d = draw_entry[e];
    entry_frame[e] = ivec2(f.branch_first + d.range.x - draw_entry[t.draws.x].range.x, 1);
    for (int pass = 0; pass < 2; ++pass) {
      int c = (pass * u_branch_draws + e) * 5;
      branch_command[c] = uint(d.range.w);
      branch_command[c + 1] = (pass == 0 ? scene : shadow) ? uint(d.range.y) : 0u;
      branch_command[c + 2] = uint(d.grid.z);
      branch_command[c + 3] = 0u;
      branch_command[c + 4] = uint(e);
    }
  }
  if (t.draws.z >= 0) {
    int e = t.draws.z;
    DrawEntry d = draw_entry[e];
    entry_frame[e] = ivec2(f.leaf_first, f.stride);
    float nearest = pixel_footprint(clamp(u_eye, t.bounds_min.xyz, t.bounds_max.xyz));
    for (int pass = 0; pass < 2; ++pass) {
      int c = (pass * u_leaf_draws + e - u_branch_draws) * 4;
      int n = leaf_stride(pass == 0 ? nearest : u_shadow_texel, d.crown_center.w, d.range.y, f.leaf_count);
      leaf_command[c] = 4u;
      leaf_command[c + 1] = (pass == 0 ? scene : shadow) ? uint((f.leaf_count + n - 1) / n) : 0u;
      leaf_command[c + 2] = uint(4 * n);
      leaf_command[c + 3] = uint(e);
    }
  }
  if (fade > 0.0) write_handover(f.tree, f, 0);
  if (fade >= 0.5) write_handover(f.tree, f, 1);
}
