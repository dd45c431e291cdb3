/* boreas: one animation step of the branches listed by a tile list, all in parallel
 * (Skjermo 2007 sec. 4.2-4.3). Per branch:
 *  1. re-attach the unbent branch to its parent's curve (boreas_attach) and place its
 *     unpositioned control points, scaled by its tree's scale, in that frame;
 *  2. sample the wind at the placed tip; the bend factor's target F* is the drag load's,
 *     drag |w| w R with w the wind relative to the tip and R Vogel's reconfiguration
 *     (trees/wind_load.h: the branch as a cantilever under its crown's drag, times the
 *     tree's scale), or the paper's linear
 *     compliance * wind (tree_params.h, times the square root of the scale);
 *  3. advance the bend factor F toward F* by the branch's response over dt (quasi-static:
 *     F = F*; damped: an exact second-order step, coefficients from the host), from
 *     motion_in to motion_out (ping-pong too, so a failed step changes nothing);
 *  3b. break (trees/wind_load.h): once |F| passes the branch's break bend (its base's
 *     stress at the wood's modulus of rupture) the branch is broken for good (a motion
 *     plane, ping-pong like F) and counted in `breaks`; a broken branch's F is its hang,
 *     far along its drag plus weight, at once and at rest, and its first segment turns
 *     too, so it hangs from its base; its children ride it;
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
 * unbroken branch (a broken one keeps its F and its flag), so the branch blends to its rest shape on its parent's current frame and then
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
 * level, parents already done). Trunks hang from their tree's fixed root entry.
 * Each work-item steps BOREAS_W consecutive branches of its tile (simd_width.h; the host
 * launches group size / W work-items per tile), parents gathered per lane.
 * Built with BOREAS_TREE_CONTACT (at width 1), the same kernel steps the trees that
 * colliders touch (a second launch over them, after the plain one: it overwrites their
 * results): their targets take their children's contact loads, and after the step they are
 * pushed out of their colliders and record what they push back with
 * (cl/shared/tree_contact.h; trees/tree_batch_contacts.cpp).
 * Positions are relative to the tree's base (shared/tree_origin.h): the wind is sampled
 * at the tip relative to it, with the waves' phases there (`places`, the tile's object's
 * row), so a tree steps alike wherever it stands. Colliders come relative to it too.
 * Built with BOREAS_TREE_STILL (a batch with no damped template), the response planes and
 * dF/dt are neither held nor read nor written: zeros in their place, the same bits. */
#include "shared/launch_tiles.h"
#include "shared/tree_origin.h"
#include "shared/tree_state.h"
#include "shared/wind_sample.h"
#ifdef BOREAS_TREE_CONTACT
#include "shared/tree_contact.h"
#if BOREAS_W != 1 || defined(BOREAS_TREE_CARRY)
#error "the contact variant steps one branch per work-item, and carries nothing"
#endif
#endif

/* The row of the tile's tree in the step's places (shared/tree_origin.h): the tile's
 * object, or in the contact variant its touched tree's row. */
BOREAS_FN int boreas_tree_step_row(__global const int* tiles, int tile
#ifdef BOREAS_TREE_CONTACT
                                   , __global const int* touches
#endif
                                   ) {
#ifdef BOREAS_TREE_CONTACT
  return touches[boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT) * BOREAS_TREE_TOUCH_INTS +
                 BOREAS_TREE_TOUCH_ROW];
#else
  return boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT);
#endif
}

__kernel void boreas_tree_step(__global const float* parent_state, __global float* state,
                               __global const int* parents, __global const float* shape,
                               __global const float* response, __global const float* motion_in,
                               __global float* motion_out, __global float* state_alt,
                               __global float* motion_alt, int n, int sn,
                               __global const int* tiles, int tile_first, float carry_hold,
                               __global const BoreasGpuWave* waves, int wave_count,
                               __global const float* grid, BoreasGpuGrid g,
                               __global const float* places, __global int* breaks
#ifdef BOREAS_TREE_CONTACT
                               , __global const float* radius, __global const int* children,
                               __global const float* contact_in, __global float* contact_out,
                               __global int* touches,
                               __global const BoreasGpuCollider* colliders, __global float* records
#endif
                               ) {
  int tile = boreas_tile(tile_first);
  int count = boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT);
  int k = (int)get_local_id(0) * BOREAS_W; /* the first lane's item in the tile */
  int first = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST);
  int sfirst = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC);
  /* Where this work-item writes: its items; but a carried branch writes the half it reads
   * (motion_alt is motion_in), so at width 1 the work-items past the tile's count, which
   * redo its last item, would decay that branch once more each: they write the sink,
   * entry 0, instead (shared/launch_tiles.h). Wider work-items store no lane past the
   * count. */
  int out_first = first;
  int out_k = k;
#if defined(BOREAS_TREE_CARRY) && BOREAS_W == 1
  out_first = k < count ? first : 0;
  out_k = k < count ? k : 0;
#endif
  BOREAS_I p =
      boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + boreas_load_wi(parents + sfirst, k, count);
  float scale = boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE);
#define BOREAS_SHAPE(plane) boreas_tree_load_w(shape, sn, (plane), sfirst, k, count)
#ifdef BOREAS_TREE_CONTACT
  /* This branch (width 1: the work-item's item) in its tree and its template; its tree's
   * colliders and its records. Most branches of a touched tree are near none of them: the
   * plain launch's result stands. */
  const int offset = first + min(k, count - 1) - boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT);
  const int root = first + min(k, count - 1) - offset;
  const int static_root = sfirst + min(k, count - 1) - offset;
  __global const int* touch =
      touches + boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT) * BOREAS_TREE_TOUCH_INTS;
  const int collider_count = touch[BOREAS_TREE_TOUCH_COLLIDER_COUNT];
  colliders += touch[BOREAS_TREE_TOUCH_COLLIDER_FIRST];
  records += (touch[BOREAS_TREE_TOUCH_RECORD] + offset * collider_count) * BOREAS_TREE_CONTACT_RECORD_FLOATS;
  BoreasBranchRadius contact_shape =
      boreas_tree_load_radius(radius, sn, sfirst + min(k, count - 1));
  contact_shape.radius *= scale;
  if (boreas_tree_contact_idle(contact_in, state, n, root, children, shape, sn, static_root, offset,
                               boreas_contact_reach(contact_shape), colliders, collider_count,
                               records, contact_out))
    return;
#endif

  BOREAS_V3 parent_o;
  BOREAS_BEZIER parent = boreas_tree_gather_curve(parent_state, n, p, &parent_o);

  BOREAS_ATTACH a;
  BOREAS_BEZIER placed = boreas_tree_place(
      parent, parent_o, BOREAS_SHAPE(BOREAS_TREE_SHAPE_V), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_THETA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_THETA), BOREAS_SHAPE(BOREAS_TREE_SHAPE_COS_ALPHA),
      BOREAS_SHAPE(BOREAS_TREE_SHAPE_SIN_ALPHA),
      boreas_tree_load3_w(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P0, sfirst, k, count),
      boreas_tree_load3_w(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P1, sfirst, k, count),
      boreas_tree_load3_w(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P2, sfirst, k, count),
      boreas_tree_load3_w(shape, sn, BOREAS_TREE_SHAPE_LOCAL_P3, sfirst, k, count),
      (BOREAS_F)(scale), &a);
  BOREAS_V3 p0 = placed.p0, p1 = placed.p1, p2 = placed.p2, p3 = placed.p3;

  const BOREAS_F zero = (BOREAS_F)(0.0f);
  BOREAS_V3 f_in = boreas_tree_load3_w(motion_in, n, BOREAS_TREE_MOTION_F, first, k, count);
#ifdef BOREAS_TREE_STILL
  /* A batch with no damped template (cl/shared/tree_types.h): no dF/dt and no response
   * planes, both 0 for every branch of it; the same arithmetic on those zeros, bit for bit. */
  BOREAS_V3 u_in = boreas_v3(zero, zero, zero);
#define BOREAS_RESPONSE(plane) zero
#else
  BOREAS_V3 u_in = boreas_tree_load3_w(motion_in, n, BOREAS_TREE_MOTION_DF, first, k, count);
#define BOREAS_RESPONSE(plane) boreas_tree_load_w(response, sn, (plane), sfirst, k, count)
#endif
  BOREAS_F broken_in = boreas_tree_load_w(motion_in, n, BOREAS_TREE_MOTION_BROKEN, first, k, count);
#ifdef BOREAS_TREE_CARRY
  /* A broken branch keeps its hanging bend (h 1): carrying never mends it. */
  BOREAS_F h = (BOREAS_F)(carry_hold) + broken_in * (1.0f - carry_hold);
  BOREAS_V3 bend = boreas_v3(zero, zero, zero);
  BOREAS_V3 rate = boreas_v3(zero, zero, zero);
  BOREAS_F broken = broken_in;
#else
  BOREAS_F h = (BOREAS_F)(boreas_tile_float(tiles, tile, BOREAS_TILE_VALUE));
  BOREAS_V3 wind;
  boreas_tree_wind(places, boreas_tree_step_row(tiles, tile
#ifdef BOREAS_TREE_CONTACT
                                                , touches
#endif
                                                ),
                   waves, wave_count, grid, g, p3, &wind);
  BOREAS_F vogel_b = BOREAS_SHAPE(BOREAS_TREE_SHAPE_VOGEL_B);
  BOREAS_F vogel_inv_speed = BOREAS_SHAPE(BOREAS_TREE_SHAPE_VOGEL_SPEED);
  BOREAS_F load_plane = BOREAS_SHAPE(BOREAS_TREE_SHAPE_LOAD);
  BOREAS_F drag = boreas_tree_drag(load_plane) * scale;
  BOREAS_V3 target = boreas_bend_target(wind, boreas_tree_compliance(load_plane) *
                                            boreas_tile_float(tiles, tile, BOREAS_TILE_SCALE_ROOT),
                                        drag, vogel_b, vogel_inv_speed);

  /* x = F - F*, u = dF/dt advanced exactly over the step with F* held, the drag's
   * aerodynamic damping included (boreas_damped_step). */
  BOREAS_F ra = BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_A);
  BOREAS_F rb = BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_B);
  BOREAS_F rc = BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_C);
  BOREAS_F rd = BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_D);
  BOREAS_V3 x = boreas_v3_sub(f_in, target);
#ifdef BOREAS_TREE_CONTACT
  const float stiffness = BOREAS_SHAPE(BOREAS_TREE_SHAPE_CONTACT_STIFFNESS) * scale;
  BoreasV3 load;  /* on this branch: its children's loads, then its colliders' pushes */
  const BoreasV3 plain_target = target, plain_x = x; /* the plain launch's, for the break */
  target = boreas_v3_add(target, boreas_tree_child_load(contact_in, n, root, children, shape, sn,
                                                        static_root, offset,
                                                        BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2), stiffness,
                                                        &load));
  x = boreas_v3_sub(f_in, target);
#endif
  /* One step of the response from x = F - F* (the contact variant takes it twice). */
#define BOREAS_TREE_RESPONSE_STEP(x0, next, rate_out)                                          \
  boreas_damped_step(x0, u_in, ra, rb, rc, rd, BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_ALPHA_DT),    \
                     BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_OMEGA_DT),                           \
                     BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_DT),                                 \
                     BOREAS_RESPONSE(BOREAS_TREE_RESPONSE_OMEGA2_DT), wind,                    \
                     (1.0f + BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2)) * drag, vogel_b,               \
                     vogel_inv_speed, next, rate_out)
  BOREAS_V3 x_next, rate;
  BOREAS_TREE_RESPONSE_STEP(x, &x_next, &rate);
  BOREAS_V3 bend = boreas_v3_add(target, x_next);
  /* Storms (trees/wind_load.h): a bend past the break bend breaks the branch for good; a
   * broken one hangs along its load at once (its stiffness gone), at rest. */
  BOREAS_V3 breaking = bend;
#ifdef BOREAS_TREE_CONTACT
  /* The break is the wind's, decided on the bend the plain launch made (which counted it),
   * without the children's contact loads: those hold limbs against a collider they cannot
   * leave (one placed in a fork gave tens of kN before they were bounded by the wood's
   * strength, tree_contact.h), and breaking on them broke the trunk beneath,
   * which then hung upside down unless the collider happened to catch it (as its last
   * step's surface point, inside or just outside it, had it). */
  {
    BoreasV3 plain_next, plain_rate;
    BOREAS_TREE_RESPONSE_STEP(plain_x, &plain_next, &plain_rate);
    breaking = boreas_v3_add(plain_target, plain_next);
  }
#endif
  BOREAS_F broken = boreas_break_flag(broken_in, breaking, BOREAS_SHAPE(BOREAS_TREE_SHAPE_BREAK) * scale);
  BOREAS_V3 hang = boreas_hang_bend(wind, BOREAS_SHAPE(BOREAS_TREE_SHAPE_HANG) / scale, vogel_b,
                                    vogel_inv_speed, BOREAS_TREE_HANG_REACH * scale);
  bend = boreas_v3_toward(bend, hang, broken);
  rate = boreas_v3_scale(rate, 1.0f - broken);
  /* Breaks this step, counted once per work-item (lanes past the tile's count are copies). */
  BOREAS_I fresh = BOREAS_SELECT((BOREAS_I)(0), (BOREAS_I)(1),
                                 (broken > broken_in) & (k + BOREAS_LANES < count));
  int fresh_count = BOREAS_HSUM(fresh);
#ifndef BOREAS_TREE_CONTACT /* its plain launch counted them: the same bend, before any push */
  if (fresh_count != 0) atomic_add(breaks, fresh_count);
#endif
#endif
  /* bend + h (F - bend) is bend itself, bit for bit, at h = 0. */
  bend = boreas_v3_add(bend, boreas_v3_scale(boreas_v3_sub(f_in, bend), h));
  rate = boreas_v3_add(rate, boreas_v3_scale(boreas_v3_sub(u_in, rate), h));
#ifdef BOREAS_TREE_CONTACT
  {
    BoreasContactBranch b;
    b.p0 = p0;
    b.p1 = p1;
    b.seg2 = boreas_v3_sub(p2, p1);
    b.seg3 = boreas_v3_sub(p3, p2);
    b.bend = bend;
    b.target = target;
    b.previous = f_in;
    b.w2 = BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2);
    b.shape = contact_shape;
    b.radius = boreas_contact_reach(contact_shape);
    b.stiffness = stiffness;
    b.break_bend = BOREAS_SHAPE(BOREAS_TREE_SHAPE_BREAK) * scale;
    b.parents_share = p != root ? BOREAS_CONTACT_SHARE_MIN : 0.0f; /* a trunk's parent: the root */
    BoreasV3 push = boreas_tree_contact(b, colliders, collider_count, records, &load);
    /* The tree is in contact: every branch that touches a collider writes the same 1 (the
     * host steps it at full detail from the next step on, and sums its records). */
    int touching = push.x != 0.0f || push.y != 0.0f || push.z != 0.0f;
    for (int j = 0; j < collider_count; ++j)
      touching |= records[j * BOREAS_TREE_CONTACT_RECORD_FLOATS + BOREAS_TREE_CONTACT_RECORD_TOUCHING] > 0.0f;
    if (touching)
      touches[boreas_tile_int(tiles, tile, BOREAS_TILE_OBJECT) * BOREAS_TREE_TOUCH_INTS +
              BOREAS_TREE_TOUCH_PUSHED] = 1;
    bend = boreas_v3_add(bend, push);
    rate = boreas_contact_rate(rate, push);
    boreas_tree_store3(contact_out, n, 0, root + offset, load);
  }
#endif
  boreas_tree_store3_w(motion_out, n, BOREAS_TREE_MOTION_F, out_first, out_k, count, bend);
#ifndef BOREAS_TREE_STILL
  boreas_tree_store3_w(motion_out, n, BOREAS_TREE_MOTION_DF, out_first, out_k, count, rate);
#endif
  boreas_tree_store_w(motion_out, n, BOREAS_TREE_MOTION_BROKEN, out_first, out_k, count, broken);

  /* Bent (a broken branch's first segment turned too), and O: the child's own y axis,
   * perpendicular to its first segment whatever alpha is (the paper's parent direction is
   * parallel to that segment when alpha = 0). */
  BOREAS_V3 o;
  BOREAS_BEZIER bent = boreas_tree_bend(a, placed, bend, broken, BOREAS_SHAPE(BOREAS_TREE_SHAPE_W2), &o);
  boreas_tree_store3_w(state, n, BOREAS_TREE_STATE_P0, out_first, out_k, count, bent.p0);
  boreas_tree_store3_w(state, n, BOREAS_TREE_STATE_P1, out_first, out_k, count, bent.p1);
  boreas_tree_store3_w(state, n, BOREAS_TREE_STATE_P2, out_first, out_k, count, bent.p2);
  boreas_tree_store3_w(state, n, BOREAS_TREE_STATE_P3, out_first, out_k, count, bent.p3);
  boreas_tree_store3_w(state, n, BOREAS_TREE_STATE_O, out_first, out_k, count, o);
#ifdef BOREAS_TREE_CARRY
  boreas_tree_store3_w(motion_alt, n, BOREAS_TREE_MOTION_F, out_first, out_k, count, bend);
#ifndef BOREAS_TREE_STILL
  boreas_tree_store3_w(motion_alt, n, BOREAS_TREE_MOTION_DF, out_first, out_k, count, rate);
#endif
  boreas_tree_store_w(motion_alt, n, BOREAS_TREE_MOTION_BROKEN, out_first, out_k, count, broken);
  boreas_tree_store3_w(state_alt, n, BOREAS_TREE_STATE_P0, out_first, out_k, count, bent.p0);
  boreas_tree_store3_w(state_alt, n, BOREAS_TREE_STATE_P1, out_first, out_k, count, bent.p1);
  boreas_tree_store3_w(state_alt, n, BOREAS_TREE_STATE_P2, out_first, out_k, count, bent.p2);
  boreas_tree_store3_w(state_alt, n, BOREAS_TREE_STATE_P3, out_first, out_k, count, bent.p3);
  boreas_tree_store3_w(state_alt, n, BOREAS_TREE_STATE_O, out_first, out_k, count, o);
#endif
#undef BOREAS_TREE_RESPONSE_STEP
#undef BOREAS_RESPONSE
#undef BOREAS_SHAPE
}
