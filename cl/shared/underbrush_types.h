/* boreas: the device layout of underbrush components (Endo et al. 2003) — every
 * per-component quantity a plane of floats or ints (structure of arrays, plane k of a
 * buffer with stride n starting at k * n), as for trees (cl/shared/tree_types.h), plus
 * small per-part records and the precomputed shape tables.
 * Compiles as OpenCL C and C++; host code uses the same indices and structs.
 */
#ifndef BOREAS_CL_SHARED_UNDERBRUSH_TYPES_H
#define BOREAS_CL_SHARED_UNDERBRUSH_TYPES_H

#ifndef __OPENCL_C_VERSION__
#include <stdint.h>
typedef int32_t BoreasInt;
#else
typedef int BoreasInt;
#endif

/* Sections per component at most; shapes are stored with BOREAS_UB_JOINTS joints (the
 * base, then the end of every section), a part with fewer sections repeating its tip. */
#define BOREAS_UB_MAX_SECTIONS 8
#define BOREAS_UB_JOINTS (BOREAS_UB_MAX_SECTIONS + 1)

/* Animated state, ping-pong (underbrush_step.cl): center of mass X, its velocity V
 * relative to the base, whether the component broke (0, or 1 + the section it broke at,
 * kept as a float so that one buffer holds the whole state), where its base was when X
 * was computed (the step carries X along when a parent moves the base; the vertex kernel
 * and readbacks use it, so that base and X always belong together) and how flat it lies:
 * 1 when a collider ran over it or it broke, relaxing to 0 over its species'
 * recovery_time (underbrush_math.h, "Trampling"). */
#define BOREAS_UB_STATE_X 0 /* x, y, z: planes 0, 1, 2 */
#define BOREAS_UB_STATE_V 3
#define BOREAS_UB_STATE_BROKEN 6
#define BOREAS_UB_STATE_BASE 7
#define BOREAS_UB_STATE_FLAT 10
#define BOREAS_UB_STATE_PLANES 11

/* Positions (state X and BASE, frame BASE and REST) are relative to the meadow's origin
 * (its def's center; host/src/underbrush/meadow.h), so a meadow keeps the same float
 * precision wherever it stands. Each tile of a step launch carries that origin (3 exact
 * floats from BOREAS_TILE_VALUE on: the fields a tree's tile fills with its blend and
 * scale) and its meadow's slot in the batch (BOREAS_TILE_OBJECT), which picks the row of
 * the step's wave phases at that origin (wind_sample.h, boreas_wind_sample_local). */
#define BOREAS_UB_TILE_ORIGIN BOREAS_TILE_VALUE /* x, y, z: VALUE, SCALE, SCALE_ROOT */
#define BOREAS_UB_TILE_SLOT BOREAS_TILE_OBJECT

/* Static frame of each component, placed when the meadow is planted: positions in
 * floats; its part, parent, axis e_u, side e_w (unit, perpendicular to e_u: the way it
 * bends when the load runs exactly along e_u) and length scale packed in the integer
 * planes (cl/shared/underbrush_pack.h decodes them). */
#define BOREAS_UB_FRAME_BASE 0    /* where it is fixed at rest (ground or parent), m */
#define BOREAS_UB_FRAME_REST 3    /* X at rest under gravity, m */
#define BOREAS_UB_FRAME_FOLLOW 6  /* how far the base follows the parent's X (see step) */
#define BOREAS_UB_FRAME_PLANES 7

/* Integer planes (bits, underbrush_pack.h). */
#define BOREAS_UB_INDEX_LINK 0 /* its part and how far back its parent is */
#define BOREAS_UB_INDEX_AXIS 1 /* e_u, octahedral */
#define BOREAS_UB_INDEX_TURN 2 /* e_w's angle about e_u, and the scale as a half */
#define BOREAS_UB_INDEX_PLANES 3

/* A component species' part: its physical constants, the sizes of its precomputed tables
 * and where they start (float offsets into the meadow batch's table buffer).
 * Forward table (one per broken state b = 0..sections, forward_size floats apart): for the
 * load's angle theta_i = pi i / (angles - 1) from e_u and norm index j (|a| = a_ref q /
 * (1 - q) with q = q_max j / (norms - 1)), the equilibrium X in the bend plane as (u, v)
 * per unit scale: each shape stands for the interval of load norms around its j.
 * Inverse table (one per broken state, inverse_size floats apart): for X's polar angle
 * psi_k = pi k / (psi_count - 1) from e_u and its distance rho_l = rho_min + (1 - rho_min)
 * l / (rho_count - 1) in units of reach, the BOREAS_UB_JOINTS joints (u, v) of the shape
 * whose center of mass is there. Break table (per angle i): the load norm at which the
 * intact part breaks, and the section it breaks at. Widths: the half width at each joint. */
typedef struct BoreasGpuPart {
  float inv_mass;      /* 1/kg */
  float drag_area;     /* 1/2 rho_air C_d A, kg/m: the wind's force is drag_area |u| u */
  float tau;           /* s: the dynamic constraint's time constant */
  float air_coupling;  /* the part's compliance over tau^2: how much of the relative
                          wind's load reaches X0 (underbrush_math.h, boreas_ub_air_step) */
  float reach;         /* m per unit scale: base to X of the straight, unloaded part */
  float collider_push; /* m/s^2 at full overlap with a collider */
  float a_ref;         /* m/s^2: the norm axis's scale */
  float q_max;         /* largest tabulated q */
  float rho_min;       /* smallest tabulated rho */
  float recovery_loss; /* 1 - exp(-dt/recovery_time) for the step being taken
                          (host-written): the share of its flatness a component loses */
  BoreasInt sections;  /* 1..BOREAS_UB_MAX_SECTIONS */
  BoreasInt angles, norms, psi_count, rho_count;
  BoreasInt forward, forward_size, inverse, inverse_size, breaking, widths;
  float recovery_time; /* s: a flattened component rises with exp(-t / recovery_time) */
} BoreasGpuPart;

/* Colliders (the paper's soccer ball, and capsules and boxes): shared/collider_types.h. */

/* An impulse delivered this step (a rain drop, a footstep): momentum j at a point, shared
 * by the components around it with a weight falling linearly to zero at `radius`. The point
 * is x + lx (y + ly, z + lz), m, world: its double position as the float nearest and the
 * float nearest the rest, so a meadow whose origin o is near it takes (x - o) + lx, exact
 * to float relative to o wherever it stands (x - o is exact where x and o are within a
 * factor 2). */
typedef struct BoreasGpuImpulse {
  float x, y, z;
  float radius;
  float jx, jy, jz; /* momentum, N s */
  float pad;
  float lx, ly, lz; /* m: the rest of the point's position past x, y, z */
  float pad1;
} BoreasGpuImpulse;

/* A (tile, collider) pair of the contact pass (underbrush_contacts.cl): the tile's first
 * component, its count, its part base and root (as in its tile record), the index of the
 * collider's record relative to the tile's meadow origin; and what the pass writes for it:
 * force (3), torque (3), contacts, a spare float. */
#define BOREAS_UB_PAIR_INTS 5
#define BOREAS_UB_PAIR_FLOATS 8

/* Distance LOD of the vertex kernel (sec. 5.1). */
#define BOREAS_UB_LOD_LEVELS 4 /* full, every other joint, base and tip, culled */

/* One meadow of a vertex launch (underbrush_vertices.cl): one launch draws any list of
 * meadows, work-item item_first + k drawing component first + k into output slot
 * out_first + k, with the meadow's first part record and its LOD distances (m; 3e38 for
 * full detail everywhere); the camera relative to the meadow's origin, and the offset
 * added to its local positions for output (its origin less the output's origin: the
 * world's 0, or a renderer's camera-relative origin), both from the host's doubles. Draws
 * are sorted by item_first, the first at 0. */
typedef struct BoreasUbDraw {
  BoreasInt item_first;
  BoreasInt first, count, part_first, out_first;
  float lod[3];
  float camera[3];
  float offset[3];
} BoreasUbDraw;

#endif
