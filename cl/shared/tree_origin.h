/* boreas: where a tree stands (issue 40, far from the origin). A tree's state planes hold
 * its branches relative to its base (its root entry's P0 is 0), so its step is the same
 * arithmetic wherever it stands; positions become world positions (or positions relative
 * to the world's output origin) only where they are handed out. Each tree of a batch has
 * a row, its slot's (slot + 1; row 0 is the sink's), in two tables:
 *  - the step's places (tree_step.cl): its base in world coordinates (floats: a def's
 *    position is one) and each wave's phase at it, computed by the host in double for the
 *    step (wind/plant_wind.h, phases_at), so the wind at a branch is sampled relative to
 *    the base as precisely 100 km out as at 0 (wind_sample.h, boreas_wind_sample_local);
 *  - the readers' offsets (export_records.cl, tree_leaves.cl, tree_record_offsets.cl):
 *    base - output origin, computed in double and rounded once, added to every position a
 *    record holds (directions are left as they are).
 * A tile's BOREAS_TILE_OBJECT names the row (step, carry and record tiles; the contact
 * launch's touched trees carry it as BOREAS_TREE_TOUCH_ROW). Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_TREE_ORIGIN_H
#define BOREAS_CL_SHARED_TREE_ORIGIN_H

/* A row of the step's places: the base (x y z), a pad, then wave_count phases (cycles in
 * [0, 1)). */
#define BOREAS_TREE_PLACE_BASE 0
#define BOREAS_TREE_PLACE_PHASES 4
/* A row of the readers' offsets: x y z, a pad. */
#define BOREAS_TREE_OFFSET_FLOATS 4

/* Floats in one row of the step's places. */
#define BOREAS_TREE_PLACE_FLOATS(wave_count) (BOREAS_TREE_PLACE_PHASES + (wave_count))

#ifdef __OPENCL_C_VERSION__
#include "shared/tree_math.h"
#include "shared/wind_sample.h"

/* The wind at a branch's point p (relative to its tree's base), its tree's row of the
 * step's places: boreas_wind_sample_local at the base with the phases there. */
BOREAS_FN void boreas_tree_wind(__global const float* places, int row,
                                __global const BoreasGpuWave* waves, int wave_count,
                                __global const float* grid, const BoreasGpuGrid g, BOREAS_V3 p,
                                BOREAS_V3* wind) {
  __global const float* r = places + (size_t)row * (size_t)BOREAS_TREE_PLACE_FLOATS(wave_count);
  boreas_wind_sample_local(r[BOREAS_TREE_PLACE_BASE], r[BOREAS_TREE_PLACE_BASE + 1],
                           r[BOREAS_TREE_PLACE_BASE + 2], p.x, p.y, p.z, waves, wave_count,
                           r + BOREAS_TREE_PLACE_PHASES, grid, g, &wind->x, &wind->y, &wind->z);
}

/* A reader's offset for its tree's row. */
BOREAS_FN BoreasV3 boreas_tree_offset(__global const float* offsets, int row) {
  __global const float* r = offsets + (size_t)row * BOREAS_TREE_OFFSET_FLOATS;
  return boreas_v3(r[0], r[1], r[2]);
}
#endif

#endif
