/* boreas: structs the wind kernels and the host share. Compiles as OpenCL C and as C++;
 * the host static_asserts every size and offset (host/src/wind/gpu_layout.cpp), so the two
 * sides cannot drift. Only 4-byte scalars: no float3/float4, whose alignment differs. */
#ifndef BOREAS_CL_SHARED_WIND_TYPES_H
#define BOREAS_CL_SHARED_WIND_TYPES_H

/* Kinds of flow primitive (Wejchert-Haumann). Must equal boreas_flow_type in boreas.h. */
#define BOREAS_GPU_FLOW_UNIFORM 0
#define BOREAS_GPU_FLOW_SOURCE 1
#define BOREAS_GPU_FLOW_SINK 2
#define BOREAS_GPU_FLOW_VORTEX 3

/* One wave of the sine sum, as the kernels see it at the current step: the host folds
 * the blend weight into the amplitude and reduces t * phi modulo 2 pi in double, so the
 * kernels never see a large time. */
typedef struct BoreasGpuWave {
  float dir_x;      /* unit direction on the ground plane */
  float dir_z;
  float amplitude;  /* m/s, blend weight included */
  float wavenumber; /* w = 2 pi / wavelength, rad/m */
  float phase;      /* t * phi mod 2 pi, rad */
  float sharpness;  /* k >= 0 */
  float pad0;
  float pad1;
} BoreasGpuWave;

/* The force-field grid: cell (i, j, k) covers origin + [i, i+1) * cell_size along x, and
 * likewise j along y (up) and k along z. Cells are stored x fastest, then y, then z, as
 * float4: xyz the grid's part of the wind (m/s), w = 1 in solid cells, else 0. */
typedef struct BoreasGpuGrid {
  float origin_x;
  float origin_y;
  float origin_z;
  float cell_size; /* m */
  int nx;
  int ny;
  int nz;
  int solid_count; /* 0 lets kernels skip obstacle handling */
} BoreasGpuGrid;

/* One flow primitive or gust, evaluated by the host for the current step (lifetime and
 * gust envelope already folded into strength). */
typedef struct BoreasGpuForcing {
  float pos_x;    /* m */
  float pos_y;
  float pos_z;
  float radius;   /* m; 0 = unbounded (uniform only) */
  float dir_x;    /* unit direction (uniform) or axis (vortex) */
  float dir_y;
  float dir_z;
  float strength; /* m/s; negative reverses */
  int type;       /* BOREAS_GPU_FLOW_* */
  int pad0;
  int pad1;
  int pad2;
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
