// boreas: the wind at points the caller names (boreas_wind_sample), evaluated on the
// device by cl/wind_sample_points.cl with the same math the plants use.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/runtime.h"
#include "wind/plant_wind.h"

namespace boreas::impl {

class SamplePoints {
 public:
  explicit SamplePoints(Runtime& runtime) : runtime_(runtime) {}

  // The wind at count points (xyz packed) into force_xyz, blocking, read as `wind` says
  // (exact unless wind.interpolated). Checks every point before anything runs.
  void sample(const PlantWind& wind, const float* xyz, int count, float* force_xyz);

 private:
  Runtime& runtime_;
  // Device points and results, grown to the largest call (kept: sampling is per frame).
  cl::Buffer points_;
  cl::Buffer results_;
  size_t capacity_ = 0;
  std::vector<float> planar_;  // host staging for the kernel's planar layout
  // The waves' phases at the grid's corner (wind_sample_points.cl).
  cl::Buffer phases_;
  size_t phase_capacity_ = 0;
  std::vector<float> phases_host_;
};

}  // namespace boreas::impl
