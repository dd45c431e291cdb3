/* boreas: every component's triangle strip from its current center of mass (Endo et al.
 * sec. 3.1 and 5.1). The inverse table gives the joints of the shape whose center of mass
 * is X (so the shape follows the dynamics, not just its target); the main axis runs
 * through the joints, the border vectors cross it perpendicular to the bend plane (a blade
 * bends about its width), and the strip joins the borders' ends.
 *
 * One launch draws the meadows of a list (BoreasUbDraw, shared/underbrush_types.h): a
 * work-item finds its meadow by bisection (a handful of meadows: a few steps), and
 * component first + k of a meadow (its part indices count from part_first, its first part
 * record) owns output vertices
 * [o * BOREAS_UB_STRIP, (o + 1) * BOREAS_UB_STRIP) with o = out_first + k, each 8 floats
 * (position, normal, uv as boreas_meadow_vertex), and counts[o] of them form its strip at
 * its distance LOD from the camera:
 *   level 0 (nearer than lod0):   every joint,          2 (S + 1) vertices
 *   level 1 (nearer than lod1):   every other joint,    2 (ceil(S / 2) + 1)
 *   level 2 (nearer than lod2):   base and tip,         4
 *   level 3:                      culled,               0
 * (S: the part's sections). Slots past the count repeat the tip, so the whole range also
 * draws as a strip of degenerate triangles.
 * The normal is perpendicular to the strip, on the side away from the load (up for a blade
 * drooping under its weight).
 * The strip is built in the meadow's local coordinates (shared/underbrush_types.h) and
 * written moved by the draw's offset: into the world's frame, or a renderer's near its
 * camera, as precise there as float allows. */
#include "shared/range_table.h"
#include "shared/underbrush_math.h"

#define BOREAS_UB_STRIP (2 * BOREAS_UB_JOINTS)

BOREAS_FN void boreas_ub_put_vertex(__global float* out, int at, BoreasV3 p, BoreasV3 nrm, float u,
                                    float v) {
  __global float* o = out + at * 8;
  o[0] = p.x;
  o[1] = p.y;
  o[2] = p.z;
  o[3] = nrm.x;
  o[4] = nrm.y;
  o[5] = nrm.z;
  o[6] = u;
  o[7] = v;
}

__kernel void boreas_underbrush_vertices(__global const float* state, __global const int* index, __global const BoreasGpuPart* parts,
                                         __global const float* tables, int n,
                                         __global const BoreasUbDraw* draws, int draw_count,
                                         int items, __global float* out, __global int* counts) {
  int item = min((int)get_global_id(0), items - 1);
  /* The draw of this work-item's meadow (its rows begin with item_first). */
  BoreasUbDraw m = draws[boreas_range_row((__global const int*)draws,
                                                (int)(sizeof(BoreasUbDraw) / sizeof(int)), draw_count, item)];
  int k_item = item - m.item_first;
  int i = m.first + k_item;
  int o = m.out_first + k_item;
  float lod0 = m.lod[0], lod1 = m.lod[1], lod2 = m.lod[2];
  int p = m.part_first + boreas_ub_link_part(index[BOREAS_UB_INDEX_LINK * n + i]);
  BoreasV3 offset = boreas_v3(m.offset[0], m.offset[1], m.offset[2]);
  BoreasV3 base = boreas_tree_load3(state, n, BOREAS_UB_STATE_BASE, i);
  int turn = index[BOREAS_UB_INDEX_TURN * n + i];
  BoreasV3 e_u = boreas_ub_unpack_axis(index[BOREAS_UB_INDEX_AXIS * n + i]);
  BoreasV3 e_w = boreas_ub_unpack_side(e_u, turn);
  float scale = boreas_ub_unpack_scale(turn);
  BoreasV3 x = boreas_tree_load3(state, n, BOREAS_UB_STATE_X, i);
  int broken = (int)state[BOREAS_UB_STATE_BROKEN * n + i];
  int sections = parts[p].sections;

  BoreasUbPlane plane = boreas_ub_plane(boreas_v3_sub(x, base), e_u, e_w);
  BoreasUbCell psi, rho;
  boreas_ub_shape_cell(plane.par, plane.perp, parts[p].reach * scale, parts[p].psi_count, parts[p].rho_count,
                       parts[p].rho_min, &psi, &rho);
  int inverse = parts[p].inverse + broken * parts[p].inverse_size;
  __global const float* widths = tables + parts[p].widths;
  BoreasV3 across = boreas_v3_cross(e_u, plane.e_v); /* unit: e_u and e_v are orthonormal */

  BoreasV3 d = boreas_v3_sub(base, boreas_v3(m.camera[0], m.camera[1], m.camera[2]));
  float dist = boreas_v3_length(d);
  int level = (dist > lod0 ? 1 : 0) + (dist > lod1 ? 1 : 0) + (dist > lod2 ? 1 : 0);
  int step = level == 0 ? 1 : (level == 1 ? 2 : sections);
  int used = level == 0 ? sections + 1 : (level == 1 ? (sections + 1) / 2 + 1 : (level == 2 ? 2 : 0));
  counts[o] = 2 * used;

  BoreasV3 joint[BOREAS_UB_JOINTS];
  float half_width[BOREAS_UB_JOINTS];
  float along[BOREAS_UB_JOINTS];
  for (int j = 0; j < BOREAS_UB_JOINTS; ++j) {
    int k = min(j * step, sections);
    float u, v;
    boreas_ub_shape_joint(tables, inverse, parts[p].rho_count, psi, rho, k, &u, &v);
    joint[j] = boreas_v3_lin3(base, 1.0f, e_u, u * scale, plane.e_v, v * scale);
    half_width[j] = widths[k]; /* length_variation keeps the width */
    along[j] = (float)k / (float)sections;
  }
  for (int j = 0; j < BOREAS_UB_JOINTS; ++j) {
    /* Tangent from the neighbouring drawn joints (one-sided at the ends; a repeated tip
     * gives a zero difference, so the last real one is used through `prev`). */
    BoreasV3 next = joint[j < BOREAS_UB_JOINTS - 1 ? j + 1 : j];
    BoreasV3 prev = joint[j > 0 ? j - 1 : j];
    BoreasV3 t = boreas_v3_sub(next, prev);
    t = boreas_v3_dot(t, t) > 0.0f ? t : boreas_v3_sub(joint[j], prev);
    BoreasV3 nrm = boreas_v3_normalize(boreas_v3_cross(t, across));
    /* Built locally, then moved: one rounding at the output's precision. */
    BoreasV3 left = boreas_v3_add(boreas_v3_madd(joint[j], across, -half_width[j]), offset);
    BoreasV3 right = boreas_v3_add(boreas_v3_madd(joint[j], across, half_width[j]), offset);
    boreas_ub_put_vertex(out, o * BOREAS_UB_STRIP + 2 * j, left, nrm, 0.0f, along[j]);
    boreas_ub_put_vertex(out, o * BOREAS_UB_STRIP + 2 * j + 1, right, nrm, 1.0f, along[j]);
  }
}
