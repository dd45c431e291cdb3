/* boreas: one animation step of every branch in a range, all in parallel (Skjermo 2007
 * sec. 4.2-4.3). Per branch:
 *  1. re-attach the unbent branch to its parent's curve (boreas_attach) and place its
 *     unpositioned control points in that frame;
 *  2. sample the wind at the placed tip; the bend factor's target is F* = compliance * wind;
 *  3. advance the bend factor F toward F* by the branch's response over dt (quasi-static:
 *     F = F*; damped: an exact second-order step, coefficients from the host), from
 *     motion_in to motion_out (ping-pong too, so a failed step changes nothing);
 *  4. bend P2 and P3 by b_2 = w2 F and b_3 = F, keeping segment lengths (eq. 17);
 *  5. write P0..P3 and O to the next state.
 * The parent's state comes from `parent_state`: the previous step's buffer in lagged mode
 * (one launch per step, each level one step behind its parent, as in the paper) or the
 * buffer being written in exact mode (one launch per level, parents already done).
 * Trunks hang from a fixed root entry of the same buffers, so there is no special case.
 * The global size may exceed count; extra work-items redo the last branch. */
#include "shared/tree_state.h"
#include "shared/wind_sample.h"

__kernel void boreas_tree_step(__global const float* parent_state, __global float* state,
                               __global const int* parents, __global const float* shape,
                               __global const float* response, __global const float* motion_in,
                               __global float* motion_out,
                               int first, int count, int n,
                               __global const BoreasGpuWave* waves, int wave_count,
                               __global const float* grid, BoreasGpuGrid g) {
  int i = first + min((int)get_global_id(0), count - 1);
  int p = parents[i];

  BoreasV3 parent_o;
  BoreasBezier parent = boreas_tree_load_curve(parent_state, n, p, &parent_o);

  BoreasAttachFrame a = boreas_attach(parent, parent_o, shape[BOREAS_TREE_SHAPE_V * n + i],
                                      shape[BOREAS_TREE_SHAPE_COS_THETA * n + i],
                                      shape[BOREAS_TREE_SHAPE_SIN_THETA * n + i],
                                      shape[BOREAS_TREE_SHAPE_COS_ALPHA * n + i],
                                      shape[BOREAS_TREE_SHAPE_SIN_ALPHA * n + i]);
  BoreasV3 l1 = boreas_tree_load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P1, i);
  BoreasV3 l2 = boreas_tree_load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P2, i);
  BoreasV3 l3 = boreas_tree_load3(shape, n, BOREAS_TREE_SHAPE_LOCAL_P3, i);
  BoreasV3 p0 = a.origin;
  BoreasV3 p1 = boreas_attach_place(a, l1.x, l1.y, l1.z);
  BoreasV3 p2 = boreas_attach_place(a, l2.x, l2.y, l2.z);
  BoreasV3 p3 = boreas_attach_place(a, l3.x, l3.y, l3.z);

  BoreasV3 wind;
  boreas_wind_sample(p3.x, p3.y, p3.z, waves, wave_count, grid, g, &wind.x, &wind.y, &wind.z);
  BoreasV3 target = boreas_v3_scale(wind, shape[BOREAS_TREE_SHAPE_COMPLIANCE * n + i]);

  /* x = F - F*, u = dF/dt advanced exactly over the step with F* held. */
  float ra = response[BOREAS_TREE_RESPONSE_A * n + i];
  float rb = response[BOREAS_TREE_RESPONSE_B * n + i];
  float rc = response[BOREAS_TREE_RESPONSE_C * n + i];
  float rd = response[BOREAS_TREE_RESPONSE_D * n + i];
  BoreasV3 x = boreas_v3_sub(boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_F, i), target);
  BoreasV3 u = boreas_tree_load3(motion_in, n, BOREAS_TREE_MOTION_DF, i);
  BoreasV3 bend = boreas_v3_add(target, boreas_v3_lin2(x, ra, u, rb));
  BoreasV3 rate = boreas_v3_lin2(x, rc, u, rd);
  boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_F, i, bend);
  boreas_tree_store3(motion_out, n, BOREAS_TREE_MOTION_DF, i, rate);

  BoreasV3 bent2 = boreas_bend_point(p1, boreas_v3_sub(p2, p1),
                                     boreas_v3_scale(bend, shape[BOREAS_TREE_SHAPE_W2 * n + i]));
  BoreasV3 bent3 = boreas_bend_point(bent2, boreas_v3_sub(p3, p2), bend);

  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P0, i, p0);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P1, i, p1);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P2, i, bent2);
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_P3, i, bent3);
  /* O: the child's own y axis, perpendicular to its first segment whatever alpha is (the
   * paper's parent direction is parallel to that segment when alpha = 0). */
  boreas_tree_store3(state, n, BOREAS_TREE_STATE_O, i, a.y);
}
