// boreas: the leaves and branches of the tree a template's impostor is baked from that the
// bake's thinning keeps (frame.glsl's keep_probability at a frame's texel, the same hash of
// the index as leaf.vert and branch.vert), listed once so the kImpostorFrames^2 frames draw
// only those: at a frame's 64 texels a crown's leaves and twigs are kept at a few percent.
// The kept ones are counted into the bake's indirect commands (one per level of branches,
// one for the leaves), whose instance counts start at 0.
#include "frame.glsl"
#include "tree_table.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer BranchRecords { float branch_record[]; };
layout(std430, binding = 3) readonly buffer LeafStatic { float leaf_static[]; };
layout(std430, binding = 17) buffer BakeCommands { uint bake_command[]; };  // 5 uints each
layout(std430, binding = 18) writeonly buffer BakeBranches { int bake_branch[]; };
layout(std430, binding = 19) writeonly buffer BakeLeaves { int bake_leaf[]; };

uniform int u_bake_first_branch;  // the tree's first branch record
uniform int u_bake_branches;      // its branches, all levels
uniform int u_bake_leaf_entry;    // its leaves' draw entry, -1 none
// Its branch entries, in its records' order (as many as its levels, -1 past them).
uniform ivec4 u_bake_branch_entries;
// How far before the tree's own offsets its records lie (ImpostorTemplate::rest_*_shift).
uniform int u_bake_branch_shift;

const float kLeafMinKeep = 0.05;     // leaf.vert's kMinKeep and kResolvedArea
const float kLeafResolvedArea = 9.0;
const float kBranchMinKeep = 0.05;   // branch.vert's kMinKeep

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < u_bake_branches) {
    int record = u_bake_first_branch + i;
    float keep = keep_probability(2.0 * branch_record[(record - u_bake_branch_shift) * 28 + 15] / u_shadow_texel, kBranchMinKeep);
    if (index_hash(record) < keep) {
      for (int k = 0; k < 4; ++k) {
        int e = u_bake_branch_entries[k];
        if (e < 0) break;
        DrawEntry d = draw_entry[e];
        if (record >= d.range.x && record < d.range.x + d.range.y) {
          uint slot = atomicAdd(bake_command[k * 5 + 1], 1u);
          bake_branch[(d.range.x - u_bake_first_branch) + int(slot)] = record;
        }
      }
    }
  }
  if (u_bake_leaf_entry >= 0 && i < draw_entry[u_bake_leaf_entry].range.y) {
    DrawEntry d = draw_entry[u_bake_leaf_entry];
    int leaf = d.range.x + i;
    int s = leaf_static_of(d, leaf) * 6;
    float area = leaf_static[s] * leaf_static[s + 1] * d.crown_center.x * d.crown_center.x;
    float keep = keep_probability(area / (u_shadow_texel * u_shadow_texel * kLeafResolvedArea), kLeafMinKeep);
    if (index_hash(leaf) < keep) bake_leaf[atomicAdd(bake_command[4 * 5 + 1], 1u)] = leaf;
  }
}
