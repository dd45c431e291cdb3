// boreas: one pass's draw commands for the frame's generated trees, on the GPU so that no
// tree costs the CPU anything per frame: per draw (a tree's level of branches or its leaves)
// an indirect command with the draw's instances, or none where the tree is out of the
// pass's view or far enough to be its impostor; per far tree an impostor record (12 floats:
// gl/impostor_math.h) appended to the list that the impostor draw's command counts.
// Stands in for the device-side records of boreas_world_enqueue_tree_records until the
// renderer reads those.
#include "frame.glsl"
#include "tree_table.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer BranchRecords { float branch_record[]; };
// DrawElementsIndirectCommand per branch draw, DrawArraysIndirectCommand per leaf draw.
layout(std430, binding = 13) writeonly buffer BranchCommands { uint branch_command[]; };
layout(std430, binding = 14) writeonly buffer LeafCommands { uint leaf_command[]; };
layout(std430, binding = 15) writeonly buffer ImpostorRecords { float impostor_record[]; };
layout(std430, binding = 16) buffer ImpostorCommand { uint impostor_command[4]; };

uniform mat4 u_cull_view_proj;    // the pass's
uniform mat4 u_camera_view_proj;  // the camera's, in either pass
uniform int u_shadow_pass;        // 1: the sun's shadow map
uniform vec3 u_sun_dir;           // unit, toward the sun
uniform float u_ground_y;         // m
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

bool tree_visible(int tree) {
  TreeEntry t = tree_entry[tree];
  if (box_outside(u_cull_view_proj, t.bounds_min.xyz, t.bounds_max.xyz)) return false;
  return u_shadow_pass == 0 || !shadow_outside(t.bounds_min.xyz, t.bounds_max.xyz);
}

// Whether the tree's geometry, and its impostor, are drawn in this pass: both over the
// handover in the camera's pass (dithered), one or the other at its middle in the shadow's.
bool draws_geometry(float fade) { return u_shadow_pass != 0 ? fade < 0.5 : fade < 1.0; }
bool draws_impostor(float fade) { return u_shadow_pass != 0 ? fade >= 0.5 : fade > 0.0; }

void write_impostor(int tree) {
  TreeEntry t = tree_entry[tree];
  uint slot = atomicAdd(impostor_command[1], 1u);
  int r = int(slot) * 12;
  vec3 sway = vec3(0.0);
  int trunk = int(t.bounds_max.w);
  if (trunk >= 0) {
    int b = trunk * 28 + 9;  // P3 of the trunk's record (branch_deform.glsl)
    sway = vec3(branch_record[b], branch_record[b + 1], branch_record[b + 2]) - t.rest_tip_rotation.xyz;
  }
  float record[12] = float[12](t.position_scale.x, t.position_scale.y, t.position_scale.z,
                               t.position_scale.w, t.rest_tip_rotation.w, t.bounds_min.w,
                               sway.x, sway.y, sway.z, 0.0, 0.0, 0.0);
  for (int k = 0; k < 12; ++k) impostor_record[r + k] = record[k];
}

// Leaves too small for the pass to resolve are thinned in two steps: here a tree draws
// every stride-th leaf, grown by as much (leaf.vert), when its leaves' mean area is a
// fraction of what its nearest point resolves; leaf.vert then thins each leaf for the rest.
// Together each leaf is kept with leaf.vert's probability alone and the expected coverage
// stays, but the vertex shader runs for a fraction of a far crown's leaves.
const int kMaxLeafStride = 16;
const float kLeafResolvedArea = 9.0;  // leaf.vert's

int leaf_stride(DrawEntry d) {
  if (u_thinning == 0 || d.crown_center.w <= 0.0) return 1;
  TreeEntry t = tree_entry[d.range.z];
  float f = u_shadow_pass != 0 ? u_shadow_texel
                               : pixel_footprint(clamp(u_eye, t.bounds_min.xyz, t.bounds_max.xyz));
  float resolved = d.crown_center.w / (f * f * kLeafResolvedArea);
  return resolved >= 1.0 ? 1 : clamp(int(1.0 / resolved), 1, kMaxLeafStride);
}

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < u_branch_draws) {
    DrawEntry d = draw_entry[i];
    bool drawn = tree_visible(d.range.z) && draws_geometry(impostor_fade(d.range.z, u_eye));
    int c = i * 5;
    branch_command[c] = uint(d.range.w);
    branch_command[c + 1] = drawn ? uint(d.range.y) : 0u;
    branch_command[c + 2] = uint(d.grid.z);
    branch_command[c + 3] = 0u;
    branch_command[c + 4] = uint(i);
  }
  if (i < u_leaf_draws) {
    int e = u_branch_draws + i;
    DrawEntry d = draw_entry[e];
    bool drawn = tree_visible(d.range.z) && draws_geometry(impostor_fade(d.range.z, u_eye));
    int c = i * 4;
    int stride = leaf_stride(d);
    leaf_command[c] = 4u;
    leaf_command[c + 1] = drawn ? uint((d.range.y + stride - 1) / stride) : 0u;
    leaf_command[c + 2] = uint(4 * stride);  // the first vertex: leaf.vert reads the stride
    leaf_command[c + 3] = uint(e);
  }
  if (i < u_trees && draws_impostor(impostor_fade(i, u_eye)) && tree_visible(i)) write_impostor(i);
}
