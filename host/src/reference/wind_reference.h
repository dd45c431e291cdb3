// boreas: double-precision host references of the wind kernels. Tests compare the
// float32 kernels against these; they follow the same equations and order of stages,
// written plainly and without any approximation.
#pragma once

#include <array>
#include <vector>

#include "boreas/boreas.h"
#include "shared/wind_types.h"
#include "wind/wave_layers.h"

namespace boreas::impl::reference {

using Vec3 = std::array<double, 3>;

// Sine sum of every layer at (x, z) and time t, weights included (x and z components).
std::array<double, 2> sine_sum(const WaveLayers& layers, double x, double z, double t);

// Sine sum of one plain wave set at time t.
std::array<double, 2> sine_sum(const std::vector<WaveParams>& waves, double x, double z, double t);

// The grid in double: cells as (x, y, z, solid) like the device, x fastest.
struct Grid {
  BoreasGpuGrid g{};
  std::vector<std::array<double, 4>> cells;
  size_t index(int i, int j, int k) const { return (size_t(k) * g.ny + j) * g.nx + i; }
  Vec3 trilinear(Vec3 cell_coords) const;  // as boreas_grid_trilinear
};

// One step of cl/wind_grid_step.cl in double. sine_at(x, z) gives the sine sum at the step's
// end time; forcing as the device gets it.
template <typename SineAt>
void grid_step(Grid& grid, const boreas_grid_def& def, double dt, SineAt sine_at,
               const std::vector<BoreasGpuForcing>& forcing);

// Velocity and coverage of one primitive at offset r (as the kernel).
Vec3 flow_velocity(const BoreasGpuForcing& f, const Vec3& r, double* coverage);

}  // namespace boreas::impl::reference

#include "reference/wind_reference_grid.inl"
