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
 *     (drag_area |u| u / m, u from the grid plus sine sums), the colliders' pushes;
 *  3. a load beyond the part's break threshold breaks it (once, for good);
 *  4. the equilibrium X0 from the forward table at the load's angle and norm;
 *  5. impulses (rain, footsteps) change the velocity;
 *  6. X and V follow the critically damped constraint toward X0, exactly over dt;
 *  7. X stays within the part's reach of its base (an impulse could carry it past).
 * The wind's force is treated as spread over the part like its weight (a uniform load per
 * unit mass), which holds for blades of even thickness; that is what lets one table serve
 * gravity and wind together.
 * Planes: cl/shared/underbrush_types.h, stride n. Components come in tiles
 * (shared/launch_tiles.h): a tile's components are one meadow's, whose part and parent
 * indices count from the tile's STATIC (the meadow's first part record) and ROOT (its
 * first component).
 * Levels of detail: built with BOREAS_UB_RATE r (1, 4 or 16), the kernel steps components
 * that are stepped only every r-th step, over r dt (the constraint step is exact for any
 * dt, so a component far from the focus follows the wind as it would, in fewer, longer
 * steps; decay^r is the decay of r dt). */
#include "shared/underbrush_math.h"
#include "shared/wind_sample.h"

#include "shared/launch_tiles.h"

#ifndef BOREAS_UB_RATE
#define BOREAS_UB_RATE 1
#endif

#ifndef BOREAS_COLLIDER_SLOTS
#define BOREAS_COLLIDER_SLOTS -1
#endif
#ifndef BOREAS_IMPULSE_SLOTS
#define BOREAS_IMPULSE_SLOTS -1
#endif

__kernel void boreas_underbrush_step(__global const float* state_in, __global float* state_out,
                                     __global const float* frame, __global const int* index,
                                     __global const BoreasGpuPart* parts, __global const float* tables,
                                     int n, float dt, float gravity,
                                     __global const BoreasGpuWave* waves, int wave_count,
                                     __global const float* grid, BoreasGpuGrid g,
                                     __global const BoreasGpuCollider* colliders, int collider_count,
                                     __global const BoreasGpuImpulse* impulses, int impulse_count,
                                     __global const int* tiles, int tile_first) {
  int tile = boreas_tile(tile_first);
  int i = boreas_tile_int(tiles, tile, BOREAS_TILE_FIRST) + boreas_tile_offset(tiles, tile);
  int p = boreas_tile_int(tiles, tile, BOREAS_TILE_STATIC) + index[BOREAS_UB_INDEX_PART * n + i];
  int parent = boreas_tile_int(tiles, tile, BOREAS_TILE_ROOT) + index[BOREAS_UB_INDEX_PARENT * n + i];

  BoreasV3 base = boreas_ub_base(frame, state_in, n, i, parent);
  BoreasV3 base_before = boreas_tree_load3(state_in, n, BOREAS_UB_STATE_BASE, i);
  BoreasV3 e_u = boreas_tree_load3(frame, n, BOREAS_UB_FRAME_AXIS, i);
  BoreasV3 e_w = boreas_tree_load3(frame, n, BOREAS_UB_FRAME_SIDE, i);
  float scale = frame[BOREAS_UB_FRAME_SCALE * n + i];
  BoreasV3 x = boreas_v3_add(boreas_tree_load3(state_in, n, BOREAS_UB_STATE_X, i), boreas_v3_sub(base, base_before));
  BoreasV3 v = boreas_tree_load3(state_in, n, BOREAS_UB_STATE_V, i);
  float broken = state_in[BOREAS_UB_STATE_BROKEN * n + i];

  float inv_mass = parts[p].inv_mass;
  BoreasV3 wind;
  boreas_wind_sample(x.x, x.y, x.z, waves, wave_count, grid, g, &wind.x, &wind.y, &wind.z);
  float drag = parts[p].drag_area * inv_mass * boreas_v3_length(wind);
  /* Loads and velocities are summed as scalars, in unrolled loops: a loop left in the
   * kernel, or a BoreasV3 carried from one iteration to the next (a <2 x float> in the IR),
   * stops PoCL's work-item vectorizer. */
  float load_x = wind.x * drag;
  float load_y = wind.y * drag - gravity;
  float load_z = wind.z * drag;

  float reach = parts[p].reach * scale;
  float push = parts[p].collider_push;
#if BOREAS_COLLIDER_SLOTS >= 0
#pragma unroll
  for (int c = 0; c < BOREAS_COLLIDER_SLOTS; ++c) {
#else
  for (int c = 0; c < collider_count; ++c) {
#endif
    boreas_ub_add_collider_push(x, colliders[c].x, colliders[c].y, colliders[c].z, colliders[c].radius, reach, push,
                                &load_x, &load_y, &load_z);
  }
  BoreasV3 load = boreas_v3(load_x, load_y, load_z);

  BoreasUbPlane plane = boreas_ub_plane(load, e_u, e_w);
  float norm = boreas_v3_length(load);
  float theta = boreas_ub_angle(plane.par, plane.perp);
  broken = boreas_ub_broken(tables + parts[p].breaking, parts[p].angles, theta, norm, broken);
  int state = (int)broken;
  BoreasV3 x0 = boreas_ub_equilibrium(tables + parts[p].forward + state * parts[p].forward_size, parts[p].angles,
                                      parts[p].norms, parts[p].a_ref, parts[p].q_max, base, e_u, plane, theta,
                                      norm, scale);

  float v_x = v.x, v_y = v.y, v_z = v.z;
#if BOREAS_IMPULSE_SLOTS >= 0
#pragma unroll
  for (int k = 0; k < BOREAS_IMPULSE_SLOTS; ++k) {
#else
  for (int k = 0; k < impulse_count; ++k) {
#endif
    boreas_ub_add_impulse(x, impulses[k].x, impulses[k].y, impulses[k].z, impulses[k].radius,
                          boreas_v3(impulses[k].jx, impulses[k].jy, impulses[k].jz), inv_mass, &v_x, &v_y, &v_z);
  }
  v = boreas_v3(v_x, v_y, v_z);

  float decay = parts[p].decay;
#if BOREAS_UB_RATE >= 4
  decay *= decay;
  decay *= decay;
#endif
#if BOREAS_UB_RATE >= 16
  decay *= decay;
  decay *= decay;
#endif
  boreas_ub_constraint_step(&x, &v, x0, parts[p].tau, decay, dt * (float)BOREAS_UB_RATE);
  boreas_ub_keep_within_reach(&x, &v, base, reach);
  boreas_tree_store3(state_out, n, BOREAS_UB_STATE_X, i, x);
  boreas_tree_store3(state_out, n, BOREAS_UB_STATE_V, i, v);
  state_out[BOREAS_UB_STATE_BROKEN * n + i] = broken;
  boreas_tree_store3(state_out, n, BOREAS_UB_STATE_BASE, i, base);
}
