/* boreas: the OpenCL side of a world, for renderers that draw straight from device buffers
 * (CL-GL interop) instead of reading instances back through the host.
 *
 * A renderer makes its buffers in the world's context (clCreateBuffer, or clCreateFromGLBuffer
 * when the world was created with cl_khr_gl_sharing properties in boreas_world_def), then
 * after each boreas_world_step enqueues the writes below on the world's queue. They only
 * enqueue: the data is in the buffers once the queue has finished the writes (clFinish on
 * the queue, or an event the renderer places after them). Buffers must stay alive until
 * then. Sizes are checked against the buffer's size (CL_MEM_SIZE): a buffer too small is
 * an INVALID_ARGUMENT that names the sizes, and nothing is enqueued.
 *
 * The records are plain floats (a shader reads them as an array of floats or vec4s);
 * positions are world coordinates, or relative to the world's output origin where one is
 * set (boreas_world_set_output_origin), as the getters give them:
 *   branch: BOREAS_BRANCH_RECORD_FLOATS = 28: control points P0..P3 (x y z each), the
 *           vector O the branch's Sloan frame starts from (x y z), then its radius
 *           function: radius (m), taper depth, taper exponent, flare, bulge count, bulge
 *           depth, lobe count, lobe depth, lobe taper (see boreas.h, the deformer), then
 *           1.0 where the branch is broken (boreas_branch.broken) or 0.0, then the tip's
 *           cap (float 25: the radius function's last factor, sqrt(w (2 - w)) with w =
 *           min(1, (1 - v) / cap) where cap > 0, Arbaro's hemispherical end of a stem of
 *           nTaper 1..3; 0: none; a ratio, not scaled with the tree), the bulges' phase
 *           (float 26) and a zero (seven vec4s a record). The bulges are Arbaro's beads of
 *           nTaper 2..3: the factor 1 - depth + depth sqrt(z (2 - z)), z = |x - 2 round(x /
 *           2)| with x = max(1, 2 (count (1 - v) + phase)) (radii from the stem's tip; count
 *           beads along the branch, phase beads from its end to the stem's tip);
 *           in the order of boreas_tree_get_branches (levels in order, children of a
 *           parent contiguous);
 *   leaf:   BOREAS_LEAF_RECORD_FLOATS = 9: blade base position, axis, normal, in the order
 *           of boreas_tree_get_leaves (length, width and branch are static: read them once);
 *   meadow vertex: boreas_meadow_vertex (8 floats), BOREAS_MEADOW_VERTEX_STRIDE per
 *           component, and one int32 strip count per component, as boreas_meadow_get_vertices;
 *   imported tree (boreas_world_add_mesh_tree), in the order of boreas_mesh_tree_get_vertices:
 *           trunk: BOREAS_MESH_TRUNK_VERTEX_FLOATS = 3, the position (its normal and uv do
 *           not change: read them once); leaves: BOREAS_MESH_LEAF_VERTEX_FLOATS = 6, the
 *           position and the normal (leaves turn).
 */
#ifndef BOREAS_CL_H
#define BOREAS_CL_H

#include <stddef.h>

#ifndef CL_TARGET_OPENCL_VERSION
#define CL_TARGET_OPENCL_VERSION 120
#endif
#include <CL/cl.h>

#include "boreas/boreas.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BOREAS_BRANCH_RECORD_FLOATS 28
#define BOREAS_LEAF_RECORD_FLOATS 9
#define BOREAS_MESH_TRUNK_VERTEX_FLOATS 3
#define BOREAS_MESH_LEAF_VERTEX_FLOATS 6

typedef struct boreas_cl_objects {
  cl_context context;     /* the world's; valid while the world lives (not retained) */
  cl_command_queue queue; /* in order; everything the world enqueues goes here */
  cl_device_id device;
} boreas_cl_objects;

BOREAS_API boreas_status boreas_world_get_cl(boreas_world world, boreas_cl_objects* out);

/* Writes the tree's branch records to out, starting at record first_record. */
BOREAS_API boreas_status boreas_tree_enqueue_branch_records(boreas_world world, boreas_tree_id tree,
                                                            cl_mem out, size_t first_record);
/* Makes the tree's leaves from its branches' current state and writes them as records to out,
 * starting at record first_record (leaves are not stored: this is where they are made). */
BOREAS_API boreas_status boreas_tree_enqueue_leaf_records(boreas_world world, boreas_tree_id tree,
                                                          cl_mem out, size_t first_record);
/* ---------------------------------------------------------------------------------------
 * A forest's records in one call per frame: boreas_world_enqueue_tree_records.
 *
 * Given a view, one call enqueues the records of every tree the view sees, culled and
 * packed on the device, with the counts a renderer draws from written into an indirect
 * buffer, so nothing is read back and nothing is done per tree on the host. A call is a
 * fixed number of kernel launches, whatever the number of trees: for each stepping mode in
 * use (and each chunk of it, where a world passes the device's largest allocation), at most
 * six: the cull with the offsets and counts, the derived branches' poses (where some are
 * derived), the settled branches' poses (where some are settled), the branch records, the
 * leaf records, and the settled poses undone; a world with no trees, one.
 *  - Culling: a tree is drawn unless its bounding sphere (about its base: nothing of it
 *    reaches farther, however it bends) lies wholly outside one of the view's planes; a
 *    tree straddling a plane is drawn.
 *  - Detail by distance: a drawn tree keeps a share of its leaves as the stochastic
 *    simplification of aggregate detail does per leaf (Cook, Halstead, Planck and Ryu):
 *    a leaf of the tree's mean area A at distance d (the eye to the tree's base) covers
 *    A / (d pixel_angle)^2 pixels; below resolved_pixels the tree keeps that share of its
 *    leaves (at least min_keep, at least one leaf), chosen by a fixed permutation of its
 *    leaves (the range record's stride), and each kept leaf's record has its axis
 *    lengthened by f = sqrt(leaves / kept): a renderer draws it f times longer and wider,
 *    so the leaves' total area, the crown's coverage, stays. A tree that keeps all its
 *    leaves writes the same records, bit for bit, as boreas_tree_enqueue_branch_records
 *    and _leaf_records (axis of unit length).
 *  - Impostors: a drawn tree at least impostor_distance from the eye writes no branch or
 *    leaf records, but one impostor record.
 *  - Order: the trees of default (lagged) mode first, then exact mode's; within a mode,
 *    in the order of the world's internal slots: fixed for a given sequence of adds and
 *    removes (the same world built the same way writes the same bytes), not the order of
 *    the ids. Each drawn tree's range record names it.
 *  - Buffers (all required, in the world's context): the record buffers hold as many
 *    records as fit in their size (CL_MEM_SIZE); what does not fit is not written: the
 *    trees drawn are written in order up to the first whose branch, leaf or range records
 *    would pass the end, the impostors up to the end. The indirect buffer's commands count
 *    what was written, and its NEEDED words what the view asked for (grow the buffers to
 *    those and call again next frame). The indirect buffer must hold
 *    BOREAS_TREE_INDIRECT_UINTS words: smaller, or a NULL buffer, or a view field out of
 *    range (NaN, a plane with a zero normal and a d below 0) is INVALID_ARGUMENT naming it,
 *    and nothing is enqueued.
 *
 * Records:
 *  branch: BOREAS_BRANCH_RECORD_FLOATS, as above; a drawn tree's in the order of
 *          boreas_tree_get_branches;
 *  leaf:   BOREAS_LEAF_RECORD_FLOATS, as above, the axis times the leaf's size factor f;
 *          record m of a tree's range is its leaf (m * stride) mod leaves in the order of
 *          boreas_tree_get_leaves (stride 1 where it keeps them all);
 *  impostor (floats): [0..2] the tree's base (m), [3] its scale, [4] its rotation about +y
 *          (rad), [5] its template (boreas_tree_get_template) as a float, [6..8] its
 *          trunk's tip's displacement from rest (m: its first piece's tip; the sway),
 *          [9..11] 0;
 *  range (int32), one per drawn tree: its boreas_tree_id's index and generation, its
 *          first branch record and count, its first leaf record and count, its leaves at
 *          full detail, the leaf stride above;
 *  indirect (uint32): three GL DrawArraysIndirect commands (count, instanceCount, first,
 *          baseInstance) for branches, leaves and impostors: count the view's
 *          vertices_per_* (what a renderer draws per record), instanceCount the records
 *          written, first and baseInstance 0; then the ranges written and three zeros; then
 *          the records the view needed: branches, leaves, impostors, ranges. */
#define BOREAS_TREE_IMPOSTOR_RECORD_FLOATS 12
#define BOREAS_TREE_RANGE_RECORD_INTS 8
#define BOREAS_TREE_INDIRECT_UINTS 20
/* Word offsets in the indirect buffer. */
#define BOREAS_TREE_INDIRECT_BRANCH_COMMAND 0
#define BOREAS_TREE_INDIRECT_LEAF_COMMAND 4
#define BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND 8
#define BOREAS_TREE_INDIRECT_RANGES_WRITTEN 12
#define BOREAS_TREE_INDIRECT_NEEDED 16

typedef struct boreas_tree_view_def {
  float eye[3]; /* m: the camera; distances for detail and impostors are from here.
                   Default 0, 0, 0 */
  /* The view's planes, (nx, ny, nz, d) each: a point p is inside where n . p + d >= 0 for
   * all six (n need not be unit length; each plane is normalized). A plane with n = 0
   * and d >= 0 is no plane. Default: six such (every tree drawn). */
  float planes[6][4];
  /* rad: the angle a pixel spans (vertically), for the leaves' detail; 0: every drawn
   * tree keeps all its leaves. Default 0 */
  float pixel_angle;
  /* pixels: a leaf that covers fewer is thinned (a 3 x 3-pixel leaf: its outline is no
   * longer resolved). Default 9 */
  float resolved_pixels;
  /* The least share of its leaves a drawn tree keeps, in (0, 1]. Default 0.05 */
  float min_keep;
  /* m: trees this far or farther are impostors; 0: none. Default 0 */
  float impostor_distance;
  /* The indirect commands' vertex counts per record (count): branch, leaf, impostor, each
   * >= 0. Default 0, 4, 4 (a renderer that draws branches per level sets its own count) */
  int vertices_per_branch;
  int vertices_per_leaf;
  int vertices_per_impostor;
} boreas_tree_view_def;

BOREAS_API boreas_tree_view_def boreas_default_tree_view_def(void);

/* Sets view's eye, planes and pixel_angle (its other fields kept) from a camera as an engine
 * keeps it: at eye (m), looking along forward, up the way up points (any length, not
 * parallel to forward), a perspective projection of vertical_fov (rad, in (0, pi)), aspect
 * (width / height, > 0), near_m and far_m (m, 0 < near_m < far_m) onto a viewport
 * viewport_height pixels high (>= 1). The planes are the frustum's, in the order of a GL
 * view-projection's rows (left, right, bottom, top, near, far), computed in double and
 * normalized; pixel_angle is the angle a pixel spans at the image's centre,
 * 2 tan(vertical_fov / 2) / viewport_height (set it to 0 for every drawn tree whole).
 * Refused, naming the argument and leaving view as it was, for a NULL pointer, a value
 * not finite or out of its range, or a pixel spanning 1 rad or more. */
BOREAS_API boreas_status boreas_set_tree_view_camera(boreas_tree_view_def* view, const float eye[3],
                                                     const float forward[3], const float up[3],
                                                     float vertical_fov, float aspect, float near_m,
                                                     float far_m, int viewport_height);

/* The caller's buffers of one call (cl_mem in the world's context; see above). */
typedef struct boreas_tree_record_buffers {
  cl_mem branches;  /* branch records */
  cl_mem leaves;    /* leaf records */
  cl_mem impostors; /* impostor records */
  cl_mem ranges;    /* range records */
  cl_mem indirect;  /* BOREAS_TREE_INDIRECT_UINTS uint32 */
} boreas_tree_record_buffers;

/* Enqueues the records of every tree the view sees into the buffers (see above). */
BOREAS_API boreas_status boreas_world_enqueue_tree_records(boreas_world world,
                                                           const boreas_tree_view_def* view,
                                                           const boreas_tree_record_buffers* out);

/* Writes the meadow's strips as boreas_meadow_get_vertices gives them (camera NULL: full
 * detail): component i's strip to vertices starting at vertex (first_component + i) *
 * BOREAS_MEADOW_VERTEX_STRIDE, its count to strip_counts at first_component + i. */
BOREAS_API boreas_status boreas_meadow_enqueue_vertices(boreas_world world, boreas_meadow_id meadow,
                                                        const float camera[3], cl_mem vertices,
                                                        cl_mem strip_counts,
                                                        size_t first_component);
/* Writes the imported tree's part (BOREAS_MESH_TRUNK or BOREAS_MESH_LEAVES) as of the last
 * step to out, starting at vertex first_vertex. */
BOREAS_API boreas_status boreas_mesh_tree_enqueue_vertices(boreas_world world,
                                                           boreas_mesh_tree_id tree,
                                                           boreas_mesh_part part, cl_mem out,
                                                           size_t first_vertex);

/* The same for any list of meadows or imported trees in ONE launch, for an engine drawing
 * many (one call per frame instead of one per object): meadow k's component i to component
 * slot first_components[k] + i, tree k's vertex j to vertex first_vertices[k] + j. Refused,
 * with nothing enqueued, for count < 0, a NULL array with count > 0, an id that is not live,
 * a range past a buffer's end or two objects' ranges that overlap, naming the entry
 * ("meadows[3]: ...", "trees[0] ... and trees[2] ... overlap"). */
BOREAS_API boreas_status boreas_world_enqueue_meadow_vertices(
    boreas_world world, const boreas_meadow_id* meadows, const size_t* first_components, int count,
    const float camera[3], cl_mem vertices, cl_mem strip_counts);
BOREAS_API boreas_status boreas_world_enqueue_mesh_tree_vertices(
    boreas_world world, const boreas_mesh_tree_id* trees, const size_t* first_vertices, int count,
    boreas_mesh_part part, cl_mem out);

/* Casts count rays read from `rays` (boreas_ray records of BOREAS_RAY_RECORD_FLOATS floats,
 * from record first_ray) and writes their hits to `hits` (boreas_hit records of
 * BOREAS_HIT_RECORD_WORDS 4-byte words, from record first_hit), as boreas_world_cast_rays
 * does, without the rays or hits passing through the host. The rays are checked on the
 * device first, and their reach (the box they span) read back with the check's verdict
 * (a few bytes: the call waits for it); a bad ray is refused naming its index, and nothing
 * is enqueued. */
#define BOREAS_RAY_RECORD_FLOATS 7
#define BOREAS_HIT_RECORD_WORDS 12
BOREAS_API boreas_status boreas_world_enqueue_cast_rays(boreas_world world, cl_mem rays,
                                                        size_t first_ray, int count, cl_mem hits,
                                                        size_t first_hit);

#ifdef __cplusplus
}
#endif

#endif
