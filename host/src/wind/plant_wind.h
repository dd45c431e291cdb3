// boreas: the wind as the plants' step kernels read it (cl/shared/wind_sample.h): the
// device waves of the step, the grid's current buffer and layout, and how to sample them.
#pragma once

#include <string>
#include <vector>

#include "runtime/cl_check.h"
#include "shared/wind_types.h"

namespace boreas::impl {

// Handed by the wind (Wind::plants) to trees, imported trees and underbrush each step;
// valid until the wind's next change.
struct PlantWind {
  const cl::Buffer* waves = nullptr;
  int wave_count = 0;  // waves in the buffer, padding included
  int wave_slots = 0;  // BOREAS_WAVE_SLOTS of the buffer's layout (unrolled_slots)
  const cl::Buffer* grid = nullptr;
  BoreasGpuGrid grid_layout{};
  bool interpolated = false;  // wind_sampling interpolated: the sine sums from the grid's slab
  const std::vector<BoreasGpuWave>* host_waves = nullptr;  // the buffer's waves, host copy
  // The defines of a kernel that samples this wind (cl/shared/wind_sample.h).
  std::string defines() const;
  // Every wave's phase at the point (x, z) of the ground, m, in cycles reduced to [0, 1),
  // computed in double: what boreas_wind_sample_local (cl/shared/wind_sample.h) reads for
  // points given relative to an origin there. Writes wave_count floats.
  void phases_at(double x, double z, float* out) const;
};

// The same for the first `count` of `waves`.
void wave_phases_at(const BoreasGpuWave* waves, int count, double x, double z, float* out);

}  // namespace boreas::impl
