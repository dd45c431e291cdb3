// boreas command: slice sample points and the one sampling call per frame.
#include "cli/slice_sampler.h"

namespace boreas::render {

SliceSampler::SliceSampler(const boreas_grid_def& grid, float slice_height, int width, int height) {
  meters_per_pixel_x_ = grid.cell_size * float(grid.resolution[0]) / float(width);
  meters_per_pixel_z_ = grid.cell_size * float(grid.resolution[2]) / float(height);
  points_.resize(size_t(width) * size_t(height) * 3);
  wind_.resize(points_.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float* p = &points_[(size_t(y) * size_t(width) + size_t(x)) * 3];
      p[0] = grid.origin[0] + (float(x) + 0.5f) * meters_per_pixel_x_;
      p[1] = slice_height;
      p[2] = grid.origin[2] + (float(y) + 0.5f) * meters_per_pixel_z_;
    }
  }
}

const std::vector<float>& SliceSampler::sample(const boreas::World& world) {
  // The C call, not World::sample(), to fill the same buffer every frame.
  boreas::check(
      boreas_wind_sample(world.handle(), points_.data(), int(points_.size() / 3), wind_.data()));
  return wind_;
}

}  // namespace boreas::render
