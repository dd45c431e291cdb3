/* boreas: the device layout of trees — every per-branch quantity is a plane of floats
 * (structure of arrays), plane k of a buffer with stride n starting at float k * n.
 * Planes rather than packed structs because PoCL vectorizes across work-items only when
 * each load and store is a plain float at the work-item's index (cl/shared/tree_math.h).
 * Compiles as OpenCL C and C++; host code uses the same indices.
 */
#ifndef BOREAS_CL_SHARED_TREE_TYPES_H
#define BOREAS_CL_SHARED_TREE_TYPES_H

/* Animated state, ping-pong (written by tree_step.cl each step): the four control points,
 * relative to the tree's base (tree_origin.h: its root entry stands at 0), and the
 * orientation vector O the branch's Sloan frame starts from. */
#define BOREAS_TREE_STATE_P0 0 /* x, y, z: planes 0, 1, 2 */
#define BOREAS_TREE_STATE_P1 3
#define BOREAS_TREE_STATE_P2 6
#define BOREAS_TREE_STATE_P3 9
#define BOREAS_TREE_STATE_O 12
#define BOREAS_TREE_STATE_PLANES 15
/* A derived branch's state planes (tree_state.h, boreas_tree_pose) hold no pose but: */
#define BOREAS_TREE_DERIVED_MARK 0x7fde1e7e /* plane P0.x's bits: a NaN no step writes */
#define BOREAS_TREE_DERIVED_PARENT 1       /* plane holding the parent's entry (int bits) */
#define BOREAS_TREE_DERIVED_STATIC 2       /* ... its template entry (int bits) */
#define BOREAS_TREE_DERIVED_SCALE 3        /* ... its tree's scale */
/* The longest chain of derived branches a reader walks: a finest level's pieces of split
 * depths 0..kMaxSplitDepth (trees/tree_model.h, which static_asserts it), each derived
 * from the one before (tree_state.h). */
#define BOREAS_TREE_MAX_CHAIN 8
/* The settled space: a derived branch held apart from the trees' own planes, with only what
 * its pose is derived from, one copy (no ping-pong: nothing steps it). A reader's entry
 * index i >= n (the own planes' stride) is entry i - n of these planes (stride tn;
 * tree_state.h, boreas_tree_pose). 28 bytes an entry against the own planes' 152-176. */
#define BOREAS_TREE_SETTLED_PARENT 0 /* the parent's entry in the own planes, or -d: the settled \
                                        entry d before it (a split piece's; int bits) */
#define BOREAS_TREE_SETTLED_STATIC 1 /* its template entry (int bits) */
#define BOREAS_TREE_SETTLED_SCALE 2  /* its tree's scale */
#define BOREAS_TREE_SETTLED_F 3      /* x y z: F as the last carry left it */
#define BOREAS_TREE_SETTLED_BROKEN 6 /* the broken flag */
#define BOREAS_TREE_SETTLED_PLANES 7
/* A batch that holds rates (BOREAS_TREE_MOTION_DF) keeps a settled branch's dF/dt too, as
 * the last carry left it (decayed, not 0): the step resumes from it when the branch is
 * stepped again. Read by the host only (un-settling); 40 bytes an entry then. */
#define BOREAS_TREE_SETTLED_DF 7 /* x y z */
#define BOREAS_TREE_SETTLED_RATE_PLANES 10

/* Static shape and attachment (from the generator). */
#define BOREAS_TREE_SHAPE_LOCAL_P1 0 /* unpositioned control points P1..P3, x y z each */
#define BOREAS_TREE_SHAPE_LOCAL_P2 3
#define BOREAS_TREE_SHAPE_LOCAL_P3 6
#define BOREAS_TREE_SHAPE_V 9           /* where P0 sits on the parent, Bezier parameter */
#define BOREAS_TREE_SHAPE_COS_THETA 10  /* angle around the parent */
#define BOREAS_TREE_SHAPE_SIN_THETA 11
#define BOREAS_TREE_SHAPE_COS_ALPHA 12  /* down angle */
#define BOREAS_TREE_SHAPE_SIN_ALPHA 13
/* The bend's target is F* = (compliance sqrt(s) + drag s |u|) u for a tree of scale s and
 * the wind u relative to the tip: one of the two is 0 (the tree's load, linear or drag), so
 * one plane holds both, signed: LOAD = compliance >= 0 (linear load: bend per unit wind,
 * m / (m/s)) or -drag <= 0 (drag load: bend per squared wind, m / (m/s)^2). Each is read
 * back exactly (boreas_tree_compliance, boreas_tree_drag: a select, no arithmetic), so the
 * step's bits are those of two planes; 4 bytes a template entry less. */
#define BOREAS_TREE_SHAPE_LOAD 14
#define BOREAS_TREE_SHAPE_W2 15         /* bend weight of P2: (2/3)^gamma (P3's is 1) */
/* Storms (trees/wind_load.h). The drag load takes Vogel's factor (|u| VOGEL_SPEED)^VOGEL_B
 * above |u| = 1 / VOGEL_SPEED; the branch breaks once |F| passes BREAK s, and then hangs
 * along HANG / s R |u| u - y (its drag over its weight). Linear load: 0, 0, never, 0. */
#define BOREAS_TREE_SHAPE_VOGEL_B 16     /* Vogel's exponent of this branch, no unit */
#define BOREAS_TREE_SHAPE_VOGEL_SPEED 17 /* 1 / the reference speed, 1 / (m/s) */
#define BOREAS_TREE_SHAPE_BREAK 18       /* |F| at which the base's stress is the wood's
                                            modulus of rupture, m at scale 1 */
#define BOREAS_TREE_SHAPE_HANG 19        /* drag over weight at scale 1, 1 / (m/s)^2 */
/* A BREAK that no bend reaches (the linear load's: it has no stress to compare). */
#define BOREAS_TREE_NEVER_BREAKS 1e30f
/* How far (m at scale 1) a broken branch's bend reaches along its load: far past any
 * segment, so every segment turns along it (eq. 17 keeps their lengths) within
 * segment / reach radians. */
#define BOREAS_TREE_HANG_REACH 1e4f
/* The load at the tip per unit of bend factor, N/m at scale 1 (times the tree's scale):
 * the cantilever's tip stiffness times (1 + w2)^2 (cl/shared/tree_contact.h). */
#define BOREAS_TREE_SHAPE_CONTACT_STIFFNESS 20
/* Where P0 sits in the attachment frame, x y z, m at scale 1 (LOCAL_P1..P3 are in the same
 * frame and include it): 0 but for a trunk standing apart from its tree's base (Arbaro's
 * 0BranchDist), which the wind then bends about its own base. */
#define BOREAS_TREE_SHAPE_LOCAL_P0 21
#define BOREAS_TREE_SHAPE_PLANES 24

/* The two halves of LOAD (above): the compliance where it is positive, the drag where it
 * is negative, else +0 (the bits the two planes held). Macros for any width: where they
 * are used, shared/simd_width.h gives BOREAS_F and BOREAS_SELECT. */
#define boreas_tree_compliance(load) BOREAS_SELECT((BOREAS_F)(0.0f), (load), (load) > 0.0f)
#define boreas_tree_drag(load) BOREAS_SELECT((BOREAS_F)(0.0f), -(load), (load) < 0.0f)

/* A branch's children, as two ranges of local indices (first, count): the generator lays
 * a parent's children out in at most two runs, the next level's branches and the pieces its
 * splits start in its own level (trees/tree_layout.cpp checks it). Ints, static entries;
 * read by tree_step.cl's contact variant to pass its children's contact loads on. */
#define BOREAS_TREE_CHILD_FIRST_A 0
#define BOREAS_TREE_CHILD_COUNT_A 1
#define BOREAS_TREE_CHILD_FIRST_B 2
#define BOREAS_TREE_CHILD_COUNT_B 3
#define BOREAS_TREE_CHILD_PLANES 4

/* A branch's contact load (tree_step.cl's contact variant), ping-pong planes of the trees'
 * own entries: the force the colliders and its children's contact loads put on it, N,
 * world x y z, which its parent takes at the attachment a step later. */
#define BOREAS_TREE_CONTACT_PLANES 3

/* A touched tree of a contact launch (5 ints; the tile's BOREAS_TILE_OBJECT indexes them):
 * its first record row and its colliders, a range of the launch's collider array (each
 * tree's own copies, relative to its base), and its row of the step's places
 * (shared/tree_origin.h). */
#define BOREAS_TREE_TOUCH_RECORD 0
#define BOREAS_TREE_TOUCH_COLLIDER_FIRST 1
#define BOREAS_TREE_TOUCH_COLLIDER_COUNT 2
#define BOREAS_TREE_TOUCH_PUSHED 3 /* 0; the launch writes 1 where a branch touched */
#define BOREAS_TREE_TOUCH_ROW 4
#define BOREAS_TREE_TOUCH_INTS 5

/* A contact record: what one branch pushes one of its tree's colliders with over the
 * step, at row record + local index * collider count + collider (the tree's record and
 * colliders: BOREAS_TREE_TOUCH_*). Floats. */
#define BOREAS_TREE_CONTACT_RECORD_FORCE 0  /* x y z, N, on the collider */
#define BOREAS_TREE_CONTACT_RECORD_TORQUE 3 /* x y z, N m, about the collider's end position */
#define BOREAS_TREE_CONTACT_RECORD_TOUCHING 6 /* 1 where the branch's surface met the collider */
#define BOREAS_TREE_CONTACT_RECORD_FLOATS 8

/* Branch response over one step of dt (host-computed for the current dt): the bend
 * factor F follows its target F* as x = F - F*, u = dF/dt with
 * x' = a x + b u, u' = c x + d u; quasi-static branches have a = b = c = d = 0 and the
 * rest 0 too. The drag load's aerodynamic damping changes the oscillator's damping each
 * step (boreas_damped_step): it needs zeta omega dt, omega dt, dt and omega^2 dt. */
#define BOREAS_TREE_RESPONSE_A 0
#define BOREAS_TREE_RESPONSE_B 1
#define BOREAS_TREE_RESPONSE_C 2
#define BOREAS_TREE_RESPONSE_D 3
#define BOREAS_TREE_RESPONSE_ALPHA_DT 4
#define BOREAS_TREE_RESPONSE_OMEGA_DT 5
#define BOREAS_TREE_RESPONSE_DT 6
#define BOREAS_TREE_RESPONSE_OMEGA2_DT 7
#define BOREAS_TREE_RESPONSE_PLANES 8

/* Response state, ping-pong: F (x y z), whether the branch is broken (0 or 1; once broken
 * it stays so until boreas_tree_heal: carried branches keep it), and dF/dt (x y z). A
 * quasi-static branch's dF/dt is 0 for good (no response moves it), so a batch with no
 * damped template holds the first BOREAS_TREE_MOTION_STILL_PLANES planes only, and no
 * response planes (its step is built with BOREAS_TREE_STILL: trees/tree_batch.h). */
#define BOREAS_TREE_MOTION_F 0
#define BOREAS_TREE_MOTION_BROKEN 3
#define BOREAS_TREE_MOTION_STILL_PLANES 4
#define BOREAS_TREE_MOTION_DF 4
#define BOREAS_TREE_MOTION_PLANES 7

/* Radius functions of the deformer (BoreasBranchRadius, in its field order); the last two,
 * the tip's cap and the beads' phase, came after the records' layout was public, so a
 * record holds them after the broken flag. */
#define BOREAS_TREE_RADIUS_TIP_CAP 9
#define BOREAS_TREE_RADIUS_BULGE_PHASE 10
#define BOREAS_TREE_RADIUS_PLANES 11

/* A branch record (cl/export_records.cl, boreas_cl.h): the state planes, the radius planes
 * but the cap and the phase, the broken flag, the cap, the phase, a zero to a multiple of
 * four floats. */
#define BOREAS_TREE_RECORD_BROKEN (BOREAS_TREE_STATE_PLANES + BOREAS_TREE_RADIUS_TIP_CAP)
#define BOREAS_TREE_RECORD_TIP_CAP (BOREAS_TREE_RECORD_BROKEN + 1)
#define BOREAS_TREE_RECORD_BULGE_PHASE (BOREAS_TREE_RECORD_TIP_CAP + 1)
#define BOREAS_TREE_RECORD_FLOATS 28

/* Leaves: static placement on a last-level branch, two int planes per leaf (the bits:
 * cl/shared/leaf_pack.h, read through boreas_leaf_unpack). */
#define BOREAS_TREE_LEAF_PLACE 0 /* the parent's local entry and v */
#define BOREAS_TREE_LEAF_TURN 1  /* theta around the parent, alpha down, the blade's roll */
#define BOREAS_TREE_LEAF_PLANES 2

/* A leaf instance (a record of cl/tree_leaves.cl, made when read): blade base position,
 * blade axis (unit), blade normal (unit). */
#define BOREAS_TREE_LEAF_OUT_POSITION 0
#define BOREAS_TREE_LEAF_OUT_AXIS 3
#define BOREAS_TREE_LEAF_OUT_NORMAL 6
#define BOREAS_TREE_LEAF_OUT_PLANES 9

/* Deformer output: position, normal, uv. */
#define BOREAS_TREE_VERTEX_POSITION 0
#define BOREAS_TREE_VERTEX_NORMAL 3
#define BOREAS_TREE_VERTEX_UV 6
#define BOREAS_TREE_VERTEX_PLANES 8

#endif
