/* boreas: one animation step of the branches listed by a tile list, all in parallel
 * (Skjermo 2007 sec. 4.2-4.3). Per branch:
 *  1. re-attach the unbent branch to its parent's curve (boreas_attach) and place its
 *     unpositioned control points, scaled by its tree's scale, in that frame;
 *  2. sample the wind at the placed tip; the bend factor's target F* is the drag load's,
 *     drag |w| w with w the wind relative to the tip (trees/wind_load.h: the branch as a
 *     cantilever under its crown's drag, times the tree's scale), or the paper's linear
 *     compliance * wind (tree_params.h, times the square root of the scale);
 *  3. advance the bend factor F toward F* by the branch's response over dt (quasi-static:
 *     F = F*; damped: an exact second-order step, coefficients from the host), from
 *     motion_in to motion_out (ping-pong too, so a failed step changes nothing);
 *  4. hold: F moves only (1 - h) of the way from where it was to that result, h carried
 *     by the tile (0 but for a short blend after the branch starts being stepped again, so
 *     a change of level of detail never makes it jump);
 *  5. bend P2 and P3 by b_2 = w2 F and b_3 = F, keeping segment lengths (eq. 17). w2 is
 *     (2/3)^gamma, eq. 15's i / (n - 1) raised to the exponent, not the (1/3)^1.8 that
 *     eq. 16 prints: P2 then moves by w2 / (1 + w2) of the tip's move, 0.32 at gamma 1.8,
 *     where a cantilever's point at 2/3 of its length moves by 0.52 (a load at the tip)
 *     to 0.56 (a uniform load) of the tip's; the printed reading gives 0.12 and bends a
 *     branch in its last third alone. Rendered side by side in 12 m/s the two differ
 *     little (the willow's hanging shoots most); gamma stays a tree_def field, 4.88 for
 *     the printed reading;
 *  6. write P0..P3 and O to the next state.
 * Built with BOREAS_TREE_CARRY, the same kernel carries branches instead (levels of
 * detail): no wind and no response, F decays as F h with h = `carry_hold` for every
 * branch, so the branch blends to its rest shape on its parent's current frame and then
 * rides it rigidly. Carried branches are updated only every few steps (trees/tree_tiles.h),
 * always level by level on their parents' new state, and write both halves of the
 * ping-pong state (state_alt, motion_alt: the current halves), so the steps that leave them
 * alone show their last update, not an older one; nothing reads a carried branch's
 * current half during its launch (its children read the new half).
 * Planes: the state and motion are the tree's own (stride n, entry FIRST + k); the parent
 * index, shape and response are its template's (stride sn, entry STATIC + k), the parent
 * counted from the tree's root entry. The parent's state comes from `parent_state`: the
 * previous step's buffer in lagged mode (one launch per step, each level one step behind
 * its parent, as in the paper) or the buffer being written in exact mode (one launch per
 * level, parents already done). Trunks hang from their tree's fixed root entry. */
#include "shared/launch_tiles.h"
#include "shared/tree_state.h"
#include "shared/wind_sample.h"

__kernel void boreas_tree_step(__global const float* parent_state, __global float* state,
                               __global const int* parents, __global const float* shape,
                               __global const float* response, __global const float* motion_in,
                               __global float* motion_out, __global float* state_alt,
                               __global float* motion_alt, int n, int sn,
                               __global const int* tiles, int tile_first, float carry_hold,
                               __global const BoreasGpuWave* waves, int wave_count,
                               __global const float* grid, BoreasGpuGrid g) {
  int tile = boreas_tile(tile_first);
  int k = boreas_tile_offset(tiles, tile);
  int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + k;
#ifdef BOREAS_TREE_CARRY
  /* A carried branch writes the half it reads (motion_alt is motion_in), so the work-items
   * past the tile's count, which redo its last item, would decay that branch once more
   * each: they write the sink, entry 0, instead (shared/launch_tiles.h). */
  i = (int)get_local_id(0) < boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT) ? i : 0;
#endif
  int j = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + k;
  int p = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + parents[j];
  float scale = boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);

  BoreasV3 parent_o;
  BoreasBezier parent = boreas_tree_load_curve(parent_state, n, p, &parent_o);

  BoreasAttachFrame a = boreas_attach(parent, parent_o, shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_V, sn, j)],
                                      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_COS_THETA, sn, j)],
                                      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_SIN_THETA, sn, j)],
                                      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_COS_ALPHA, sn, j)],
                                      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_SIN_ALPHA, sn, j)]);
  BoreasV3 l1 = boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P1, j), scale);
  BoreasV3 l2 = boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P2, j), scale);
  BoreasV3 l3 = boreas_v3_scale(boreas_tree_load3(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P3, j), scale);
  BoreasV3 p0 = a.origin;
  BoreasV3 p1 = boreas_attach_place(a, l1.x, l1.y, l1.z);
  BoreasV3 p2 = boreas_attach_place(a, l2.x, l2.y, l2.z);
  BoreasV3 p3 = boreas_attach_place(a, l3.x, l3.y, l3.z);

  BoreasV3 f_in = boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_F, i);
  BoreasV3 u_in = boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_DF, i);
#ifdef BOREAS_TREE_CARRY
  float h = carry_hold;
  BoreasV3 bend = boreas_v3(0.0f, 0.0f, 0.0f);
  BoreasV3 rate = boreas_v3(0.0f, 0.0f, 0.0f);
#else
  float h = boreas_tile_float(tiles, tile, BOREAS_TILE_VALUE);
  BoreasV3 wind;
  boreas_wind_sample(p3.x, p3.y, p3.z, waves, wave_count, grid, g, &wind.x, &wind.y, &wind.z);
  BoreasV3 target = boreas_bend_target(
      wind, u_in, shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_W2, sn, j)],
      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_COMPLIANCE, sn, j)] * boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE_ROOT),
      shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_DRAG, sn, j)] * scale);

  /* x = F - F*, u = dF/dt advanced exactly over the step with F* held. */
  float ra = response[BOREAS_TREE_AT(BOREAS_TREE_RESPONSE_A, sn, j)];
  float rb = response[BOREAS_TREE_AT(BOREAS_TREE_RESPONSE_B, sn, j)];
  float rc = response[BOREAS_TREE_AT(BOREAS_TREE_RESPONSE_C, sn, j)];
  float rd = response[BOREAS_TREE_AT(BOREAS_TREE_RESPONSE_D, sn, j)];
  BoreasV3 x = boreas_v3_sub(f_in, target);
  BoreasV3 bend = boreas_v3_add(target, boreas_v3_lin2(x, ra, u_in, rb));
  BoreasV3 rate = boreas_v3_lin2(x, rc, u_in, rd);
#endif
  /* bend + h (F - bend) is bend itself, bit for bit, at h = 0. */
  bend = boreas_v3_add(bend, boreas_v3_scale(boreas_v3_sub(f_in, bend), h));
  rate = boreas_v3_add(rate, boreas_v3_scale(boreas_v3_sub(u_in, rate), h));
  boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_F, i, bend);
  boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_DF, i, rate);

  BoreasV3 bent2 = boreas_bend_point(p1, boreas_v3_sub(p2, p1),
                                     boreas_v3_scale(bend, shape[BOREAS_TREE_AT(BOREAS_TREE_SHAPE_W2, sn, j)]));
  BoreasV3 bent3 = boreas_bend_point(bent2, boreas_v3_sub(p3, p2), bend);

  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i, p0);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, i, p1);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, i, bent2);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, i, bent3);
  /* O: the child's own y axis, perpendicular to its first segment whatever alpha is (the
   * paper's parent direction is parallel to that segment when alpha = 0). */
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
#ifdef BOREAS_TREE_CARRY
  boreas_tree_store3(motion_alt, n, BOREAS_TREE_MOTION_F, i, bend);
  boreas_tree_store3(motion_alt, n, BOREAS_TREE_MOTION_DF, i, rate);
  boreas_tree_store3(state_alt, n, BOREAS_TREE_STATE_P0, i, p0);
  boreas_tree_store3(state_alt, n, BOREAS_TREE_STATE_P1, i, p1);
  boreas_tree_store3(state_alt, n, BOREAS_TREE_STATE_P2, i, bent2);
  boreas_tree_store3(state_alt, n, BOREAS_TREE_STATE_P3, i, bent3);
  boreas_tree_store3(state_alt, n, BOREAS_TREE_STATE_O, i, a.y);
#endif
}
