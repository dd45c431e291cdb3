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
 * The records are plain floats (a shader reads them as an array of floats or vec4s):
 *   branch: BOREAS_BRANCH_RECORD_FLOATS = 28: control points P0..P3 (x y z each), the
 *           vector O the branch's Sloan frame starts from (x y z), then its radius
 *           function: radius (m), taper depth, taper exponent, flare, bulge count, bulge
 *           depth, lobe count, lobe depth, lobe taper (see boreas.h, the deformer), then
 *           1.0 where the branch is broken (boreas_branch.broken) or 0.0, and three zeros
 *           (seven vec4s a record);
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
