// boreas command: the horizontal slice a frame shows. One sample point per pixel center,
// covering the grid's horizontal extent, so the whole frame is one boreas_wind_sample call.
#pragma once

#include <vector>

#include "boreas/boreas.hpp"

namespace boreas::render {

class SliceSampler {
 public:
  // grid: the world's grid; height: the slice's y (m); width x height pixels.
  SliceSampler(const boreas_grid_def& grid, float slice_height, int width, int height);

  // The wind at every pixel now: 3 floats (m/s) per pixel, rows top to bottom, row y at
  // world z = origin.z + (y + 0.5) * meters_per_pixel_z().
  const std::vector<float>& sample(const boreas::World& world);

  float meters_per_pixel_x() const { return meters_per_pixel_x_; }
  float meters_per_pixel_z() const { return meters_per_pixel_z_; }

 private:
  std::vector<float> points_;  // xyz per pixel
  std::vector<float> wind_;    // xyz per pixel
  float meters_per_pixel_x_ = 1.0f;
  float meters_per_pixel_z_ = 1.0f;
};

}  // namespace boreas::render
