/* boreas: one step of every underbrush component, all in parallel (Endo et al. sec. 4).
 * Per component:
 *  1. its base: fixed, or moved with its parent's center of mass (previous step, as the
 *     lagged trees do); X moves with the base, so the dynamics below run in the frame of
 *     the base and V is relative to it. Without this carry a part on a swaying stalk
 *     trailed its base by about 2 tau times the base's speed (the critically damped
 *     follower's lag). The base's acceleration is not fed back as an inertial load: the
 *     parts that ride on others (petals, leaflets) are light and stiff against it, with
 *     tau well under the stalk's sway period;
 *  2. the load per unit mass at its center of mass X: gravity, the wind's drag
 *     (drag_area |u| u / m, u from the grid plus sine sums), the pushes of the colliders
 *     near its tile (the host's per-tile list), which also say whether one ran over it;
 *  3. a load beyond the part's break threshold breaks it (once, for good);
 *  4. the equilibrium X0 from the forward table at the load's angle and norm, pulled
 *     toward the ground as far as the component lies flat (trampled or broken:
 *     underbrush_math.h, "Trampling"), whose flatness then relaxes or is renewed;
 *  5. impulses (rain, footsteps) change the velocity;
 *  6. X and V follow the critically damped constraint toward X0 with the air's damping
 *     (the drag on the wind relative to the component's own velocity, its base's
 *     included), exactly over dt (underbrush_math.h, boreas_ub_air_step);
 *  7. X stays within the part's reach of its base (an impulse could carry it past).
 * The wind's force is treated as spread over the part like its weight (a uniform load per
 * unit mass), which holds for blades of even thickness; that is what lets one table serve
 * gravity and wind together.
 * Planes: cl/shared/underbrush_types.h, stride n. Components come in tiles
 * (shared/launch_tiles.h): a tile's components are one meadow's, whose part indices count
 * from the tile's STATIC (the meadow's first part record); a parent is found by how many
 * components back it is (underbrush_pack.h, which also decodes axis, side and scale).
 * Levels of detail: built with BOREAS_UB_RATE r (1, 4 or 16), the kernel steps components
 * that are stepped only every r-th step, over r dt (the constraint step is exact for any
 * dt, so a component far from the focus follows the wind as it would, in fewer, longer
 * steps; the flatness loses 1 - (1 - loss)^r).
 * Scale (length_variation): the mass, drag area, stiffness and tau of a longer instance
 * scale with it (underbrush_math.h, boreas_ub_shape_load and its neighbours).
 * Colliders: built with BOREAS_UB_COLLIDERS 1, the kernel reads its tile's colliders
 * (tile_colliders: first and count per tile of the launch into colliders, which hold each
 * tile's own records, relative to its meadow's origin); with 0 (no collider near any tile
 * of the launch) it reads none. Tiles that a
 * collider is near are stepped at rate 1 (UnderbrushBatch), so a collider's sweep meets
 * every component in its way.
 * Origins: positions are the meadow's local ones (shared/underbrush_types.h); the tile
 * gives the origin. The wind is sampled relative to it with the waves' phases there
 * (wave_phases, one row of wave_count per meadow slot; wind_sample.h), so it is as precise
 * 100 km out as at 0. Impulses are met relative to the origin (their centers less it: a
 * difference of floats, exact near it, plus the rest of their double position:
 * BoreasGpuImpulse), colliders likewise (the host takes their double
 * positions less the origin: UnderbrushBatch, StepColliders::relative), so a collider far
 * out meets the components at X as one near 0 does.
 * Each work-item steps BOREAS_W consecutive components of its tile (simd_width.h; the
 * host launches group size / W work-items per tile): their parts, parents and tables are
 * read per lane. */
#include "shared/underbrush_math.h"
#include "shared/wind_sample.h"

#include "shared/launch_tiles.h"

#ifndef BOREAS_UB_RATE
#define BOREAS_UB_RATE 1
#endif

#ifndef BOREAS_UB_COLLIDERS
#define BOREAS_UB_COLLIDERS 0
#endif
#ifndef BOREAS_IMPULSE_SLOTS
#define BOREAS_IMPULSE_SLOTS -1
#endif

/* A field of each lane's part record: parts[p].field at width 1, a per-lane gather of
 * the record's word above. */
#if BOREAS_W == 1
#define BOREAS_PART_F(field) (parts[p].field)
#define BOREAS_PART_I(field) (parts[p].field)
#else
#define BOREAS_PART_WORD(field)                                                             \
  (p * (int)(sizeof(BoreasGpuPart) / sizeof(float)) +                                     \
   (int)(__builtin_offsetof(BoreasGpuPart, field) / sizeof(float)))
#define BOREAS_PART_F(field) BOREAS_GATHER((__global const float*)parts, BOREAS_PART_WORD(field))
#define BOREAS_PART_I(field) BOREAS_AS_INT(BOREAS_PART_F(field))
#endif

__kernel void boreas_underbrush_step(__global const float* state_in, __global float* state_out,
                                     __global const float* frame, __global const int* index,
                                     __global const BoreasGpuPart* parts, __global const float* tables,
                                     int n, float dt, float gravity,
                                     __global const BoreasGpuWave* waves, int wave_count,
                                     __global const float* wave_phases,
                                     __global const float* grid, BoreasGpuGrid g,
                                     __global const BoreasGpuCollider* colliders,
                                     __global const int* tile_colliders,
                                     __global const BoreasGpuImpulse* impulses, int impulse_count,
                                     __global const int* tiles, int tile_first) {
  int tile = boreas_tile(tile_first);
  int count = boreas_tile_int(tiles, tile, BOREAS_TILE_COUNT);
  int k = (int)get_local_id(0) * BOREAS_W; /* the first lane's component in the tile */
  int first = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST);
  BOREAS_I i = first + min(k + BOREAS_LANES, count - 1);
  BOREAS_I link = boreas_load_wi(index + BOREAS_UB_INDEX_LINK * n + first, k, count);
  BOREAS_I p = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + boreas_ub_link_part(link);
  BOREAS_I parent = i - boreas_ub_link_back(link);
  float ox = boreas_tile_float(tiles, tile, BOREAS_UB_TILE_ORIGIN);
  float oy = boreas_tile_float(tiles, tile, BOREAS_UB_TILE_ORIGIN + 1);
  float oz = boreas_tile_float(tiles, tile, BOREAS_UB_TILE_ORIGIN + 2);
  __global const float* phases =
      wave_phases + boreas_tile_int(tiles, tile, BOREAS_UB_TILE_SLOT) * wave_count;

  BOREAS_V3 base = boreas_ub_base(frame, state_in, n, i, parent);
  BOREAS_V3 base_before = boreas_tree_load3_w(state_in, n, BOREAS_UB_STATE_BASE, first, k, count);
  BOREAS_I turn = boreas_load_wi(index + BOREAS_UB_INDEX_TURN * n + first, k, count);
  BOREAS_V3 e_u =
      boreas_ub_unpack_axis(boreas_load_wi(index + BOREAS_UB_INDEX_AXIS * n + first, k, count));
  BOREAS_V3 e_w = boreas_ub_unpack_side(e_u, turn);
  BOREAS_F scale = boreas_ub_unpack_scale(turn);
  BOREAS_V3 x = boreas_v3_add(boreas_tree_load3_w(state_in, n, BOREAS_UB_STATE_X, first, k, count),
                              boreas_v3_sub(base, base_before));
  BOREAS_V3 v = boreas_tree_load3_w(state_in, n, BOREAS_UB_STATE_V, first, k, count);
  BOREAS_F broken = boreas_tree_load_w(state_in, n, BOREAS_UB_STATE_BROKEN, first, k, count);
  BOREAS_F flat = boreas_tree_load_w(state_in, n, BOREAS_UB_STATE_FLAT, first, k, count);

  BOREAS_F inv_mass = BOREAS_PART_F(inv_mass);
  BOREAS_V3 wind;
  boreas_wind_sample_local(ox, oy, oz, x.x, x.y, x.z, waves, wave_count, phases, grid, g,
                           &wind.x, &wind.y, &wind.z);
  BOREAS_F drag_per_mass = BOREAS_PART_F(drag_area) * inv_mass; /* the same at every scale */
  BOREAS_F drag = drag_per_mass * boreas_v3_length(wind);
  /* Loads and velocities are summed as scalars, in unrolled loops: a loop left in the
   * kernel, or a BoreasV3 carried from one iteration to the next (a <2 x float> in the IR),
   * stops PoCL's work-item vectorizer. */
  BOREAS_F load_x = wind.x * drag;
  BOREAS_F load_y = wind.y * drag - gravity;
  BOREAS_F load_z = wind.z * drag;

  BOREAS_F wind_load = drag * boreas_v3_length(wind); /* the wind's alone, m/s^2 */

  BOREAS_F reach = BOREAS_PART_F(reach) * scale;
  BOREAS_F crushed = 0.0f;
#if BOREAS_UB_COLLIDERS
  /* The tile's colliders: the same count for every work-item of the tile. */
  BOREAS_F push = BOREAS_PART_F(collider_push);
  int list_first = tile_colliders[2 * tile];
  int list_count = tile_colliders[2 * tile + 1];
  for (int c = 0; c < list_count; ++c) {
    boreas_ub_add_collider_push(x, base, colliders + list_first + c, reach, push, &load_x,
                                &load_y, &load_z, &crushed);
  }
#endif
  BOREAS_V3 load = boreas_v3(load_x, load_y, load_z);

  BOREAS_UB_PLANE plane = boreas_ub_plane(load, e_u, e_w);
  BOREAS_F norm = boreas_v3_length(load);
  BOREAS_F theta = boreas_ub_angle(plane.par, plane.perp);
  BOREAS_F joint;
  BOREAS_F break_load =
      boreas_ub_break_load(tables, BOREAS_PART_I(breaking), BOREAS_PART_I(angles), theta, &joint);
  BOREAS_F broken_before = broken;
  broken = boreas_ub_broken_at(break_load, joint, boreas_ub_break_norm(norm, scale), broken);
  BOREAS_I state = BOREAS_TO_INT(broken);
  BOREAS_V3 x0 =
      boreas_ub_equilibrium(tables, BOREAS_PART_I(forward) + state * BOREAS_PART_I(forward_size),
                            BOREAS_PART_I(angles), BOREAS_PART_I(norms), BOREAS_PART_F(a_ref),
                            BOREAS_PART_F(q_max), base, e_u, plane, theta, norm, scale);
  x0 = boreas_ub_flatten(x0, x, base, e_w, reach, flat);
  BOREAS_F loss = BOREAS_PART_F(recovery_loss);
#if BOREAS_UB_RATE >= 4
  loss = loss * (2.0f - loss);
  loss = loss * (2.0f - loss);
#endif
#if BOREAS_UB_RATE >= 16
  loss = loss * (2.0f - loss);
  loss = loss * (2.0f - loss);
#endif
  flat = boreas_ub_flat_next(flat, loss, crushed, broken_before, broken,
                             boreas_ub_break_norm(wind_load, scale), break_load);

  BOREAS_F v_x = v.x, v_y = v.y, v_z = v.z;
#if BOREAS_IMPULSE_SLOTS >= 0
#pragma unroll
  for (int m = 0; m < BOREAS_IMPULSE_SLOTS; ++m) {
#else
  for (int m = 0; m < impulse_count; ++m) {
#endif
    boreas_ub_add_impulse(x, (impulses[m].x - ox) + impulses[m].lx,
                          (impulses[m].y - oy) + impulses[m].ly,
                          (impulses[m].z - oz) + impulses[m].lz, impulses[m].radius,
                          boreas_v3(impulses[m].jx, impulses[m].jy, impulses[m].jz),
                          boreas_ub_inv_mass(inv_mass, scale), &v_x, &v_y, &v_z);
  }
  v = boreas_v3(v_x, v_y, v_z);

  BOREAS_F step_dt = (BOREAS_F)(dt * (float)BOREAS_UB_RATE);
  BOREAS_V3 v_base = boreas_v3_scale(boreas_v3_sub(base, base_before), 1.0f / step_dt);
  boreas_ub_air_step(&x, &v, x0, wind, v_base, drag_per_mass * BOREAS_PART_F(air_coupling),
                     boreas_ub_tau(BOREAS_PART_F(tau), scale), step_dt);
  boreas_ub_keep_within_reach(&x, &v, base, reach);
  boreas_tree_store3_w(state_out, n, BOREAS_UB_STATE_X, first, k, count, x);
  boreas_tree_store3_w(state_out, n, BOREAS_UB_STATE_V, first, k, count, v);
  boreas_tree_store_w(state_out, n, BOREAS_UB_STATE_BROKEN, first, k, count, broken);
  boreas_tree_store3_w(state_out, n, BOREAS_UB_STATE_BASE, first, k, count, base);
  boreas_tree_store_w(state_out, n, BOREAS_UB_STATE_FLAT, first, k, count, flat);
}
