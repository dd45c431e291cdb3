/* boreas: structs the wind kernels and the host share. Compiles as OpenCL C and as C++;
 * the host static_asserts every size and offset (host/src/wind/gpu_layout.cpp), so the two
 * sides cannot drift. Only 4-byte scalars: no float3/float4, whose alignment differs. */
#ifndef BOREAS_CL_SHARED_WIND_TYPES_H
#define BOREAS_CL_SHARED_WIND_TYPES_H

#include "shared/simd_width.h"

/* One wave of the sine sum, as the kernels see it at the current step: the host folds
 * the blend weight into the amplitude and reduces the time's phase to one cycle in double,
 * so the kernels never see a large time. Phases are in cycles (turns), not radians, so
 * that the kernel can reduce any position's phase to one cycle before the sine. */
typedef struct BoreasGpuWave {
  float dir_x;            /* unit direction on the ground plane */
  float dir_z;
  float amplitude;        /* m/s, blend weight included */
  float cycles_per_meter; /* 1 / wavelength */
  float phase_cycles;     /* t phi / (2 pi) reduced to [0, 1) */
  float sharpness;        /* k >= 0 */
  float pad0;
  float pad1;
} BoreasGpuWave;
/* The wave's size and its phase_cycles' place, in floats (a list of phases read with a
 * stride: wind_sample.h). */
#define BOREAS_WAVE_FLOATS 8
#define BOREAS_WAVE_PHASE_WORD 4

/* The force-field grid: cell (i, j, k) covers origin + [i, i+1) * cell_size along x, and
 * likewise j along y (up) and k along z. Cells are numbered x fastest, then y, then z,
 * and stored as 4 planes of nx*ny*nz floats: the grid's part of the wind along x, y, z
 * (m/s), then 1 in solid cells, else 0.
 * Why planes and why the origin's components interleaved with the counts: x, y, z values
 * side by side in memory invite LLVM's SLP vectorizer to pack them into one vector, and a
 * vector value in the work-item loop stops PoCL from vectorizing across work-items. */
typedef struct BoreasGpuGrid {
  float origin_x;
  int nx;
  float origin_y;
  int ny;
  float origin_z;
  int nz;
  float cell_size; /* m */
  int solid_count; /* cells marked solid */
  /* 1 / boreas_grid_def.edge_fade, per cell: the grid's wind fades to zero over that many
   * cells beyond its sides; 1e30 stops it at the sides (edge_fade 0). */
  float fade_per_cell;
  int pad0;
} BoreasGpuGrid;

/* The grid's buffer holds, after its 4 planes, the slab: the sine sum at the center of
 * every column (i, k), at x = origin_x + (i + 1/2) cell_size and likewise z, as 2 planes
 * of nx*nz floats (x, then z). wind_sine_slab.cl writes it each step into the buffer the
 * grid step writes, which reads it from there; with wind_sampling interpolated the plants'
 * kernels read it too (wind_sample.h). In floats from the buffer's start, and in all. */
BOREAS_FN int boreas_grid_slab_offset(BoreasGpuGrid g) { return 4 * g.nx * g.ny * g.nz; }
BOREAS_FN int boreas_grid_buffer_floats(BoreasGpuGrid g) {
  return boreas_grid_slab_offset(g) + 2 * g.nx * g.nz;
}

/* One flow primitive or gust, evaluated by the host for the current step (lifetime and
 * gust envelope already folded into strength). The kind is given as three weights
 * rather than a type code, so the kernel sums all three shapes with no branch:
 * uniform (1, 0, 0), source (0, 1, 0), sink (0, -1, 0), vortex (0, 0, 1). */
typedef struct BoreasGpuForcing {
  /* Components interleaved, not x, y, z in a row: see BoreasGpuGrid for why. */
  float pos_x;    /* m */
  float dir_x;    /* unit direction (uniform) or axis (vortex) */
  float pos_y;
  float dir_y;
  float pos_z;
  float dir_z;
  float radius;   /* m; 0 = unbounded (uniform only) */
  float strength; /* m/s; negative reverses */
  float uniform_weight;
  float radial_weight;
  float swirl_weight;
  float pad0;
} BoreasGpuForcing;

/* Per-step constants of the grid update, computed by the host in double. */
typedef struct BoreasGpuGridStep {
  float dt_over_cell;   /* dt / cell_size, s/m: backtrace length per unit velocity */
  float diffusion_mix;  /* 1 - exp(-6 nu dt / h^2) */
  float decay_factor;   /* exp(-decay_rate dt) */
  float drive_exponent; /* dt / response_time * log2(e): drive = 1 - 2^(-coverage * this) */
  int forcing_count;
  int pad0;
  int pad1;
  int pad2;
} BoreasGpuGridStep;

#endif
