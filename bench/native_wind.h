// boreas: native C++ twins of the hot kernels, the yardstick boreas_bench compares the
// OpenCL kernels with. The kernels' own float math (the C++ builds of cl/shared/
// wind_sample.h and flow_primitives.h, fast_math.h polynomials included) in loops written
// the way a tuned CPU version would be: OpenMP threads over rows, SIMD over x.
#pragma once

#include <cstddef>

#include "shared/wind_types.h"

namespace boreas::bench {

// out[i] = in[i] for count floats (the twin of cl/bandwidth_copy.cl).
void native_copy(const float* in, float* out, size_t count);

// Layouts as on the device: the grid is 4 planes of nx*ny*nz floats (x, y, z wind, solid
// flag), then (where the plants interpolate) the slab: 2 planes of nx*nz floats (sine sum
// x, then z; boreas_grid_slab_offset); points and forces 3 planes of count floats (x, then
// y, then z).

// cl/wind_sample_points.cl: the wind (sine sum + trilinear grid, zero in solids) at count
// points.
void native_sample_points(const float* points, float* force, int count, const BoreasGpuWave* waves,
                          int wave_count, const float* grid, const BoreasGpuGrid& g);

// The same for n <= kNativeWindBlock points given as three arrays (px, py, pz), results in
// (fx, fy, fz); one thread. For twins of kernels that sample the wind (trees).
// interpolated: the sine sum as wind_sampling interpolated reads it (BOREAS_WIND_INTERPOLATED:
// bilinear in the slab after the grid's planes, exact beyond the column centers).
constexpr int kNativeWindBlock = 256;
void native_wind_block(const float* px, const float* py, const float* pz, int n,
                       const BoreasGpuWave* waves, int wave_count, const float* grid,
                       const BoreasGpuGrid& g, float* fx, float* fy, float* fz,
                       bool interpolated = false);

// cl/wind_sine_slab.cl: the sine sum at every column center.
void native_sine_slab(float* slab, const BoreasGpuWave* waves, int wave_count,
                      const BoreasGpuGrid& g);

// cl/wind_forcing_field.cl: the steady primitives' summed target and coverage maximum per
// cell, 4 planes (built once, when the primitives change, as a world does).
void native_forcing_field(float* field, const BoreasGpuForcing* steady, int count,
                          const BoreasGpuGrid& g);

// cl/wind_grid_step.cl: one grid update from in to out, with the slab of native_sine_slab,
// the steady field of native_forcing_field (nullptr for none) and varying_count gusts.
void native_grid_step(const float* in, float* out, const float* slab, const float* steady,
                      const BoreasGpuForcing* varying, int varying_count, const BoreasGpuGrid& g,
                      const BoreasGpuGridStep& s);

// Threads the OpenMP loops use (for the report).
int native_thread_count();

}  // namespace boreas::bench
