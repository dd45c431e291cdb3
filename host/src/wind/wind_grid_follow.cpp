// boreas: a grid that follows the focus (boreas_grid_def.follow_focus): moved by whole
// cells, its wind kept where the old and new extents overlap.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "wind/wind_grid.h"

namespace boreas::impl {

bool WindGrid::follow(double x, double z) {
  const double h = def_.cell_size;
  // The focus's offset from the middle, in cells, and the whole cells to move by.
  auto move_for = [h](double p, double origin, int n) -> int64_t {
    const double off = (p - origin) / h - 0.5 * n;
    const double threshold = std::max(1.0, n / 8.0);
    if (!(std::fabs(off) > threshold)) return 0;  // also for a focus whose offset is NaN
    return int64_t(std::llround(off));
  };
  const int64_t di = move_for(x, gpu_.origin_x, gpu_.nx);
  const int64_t dk = move_for(z, gpu_.origin_z, gpu_.nz);
  if (di == 0 && dk == 0) return false;
  if (active_) shift_cells(di, dk);
  // The origin from where the grid began, in double: no drift however often it moves.
  moved_[0] += di;
  moved_[1] += dk;
  def_.origin[0] = float(first_origin_[0] + double(moved_[0]) * h);
  def_.origin[2] = float(first_origin_[1] + double(moved_[1]) * h);
  gpu_.origin_x = def_.origin[0];
  gpu_.origin_z = def_.origin[2];
  // The steady primitives are laid into the new cells at the next step.
  steady_version_ = ~uint64_t(0);
  return true;
}

// The cells' values move by (-di, -dk) cells into the other buffer of the pair, which is
// cleared first; cells that come in from outside stay zero. One rectangle copy per plane.
void WindGrid::shift_cells(int64_t di, int64_t dk) {
  cl::CommandQueue& q = runtime_.queue();
  const int next = 1 - current_;
  const size_t bytes = static_cast<size_t>(cell_count_) * 4 * sizeof(float);
  BOREAS_CL_CHECK(q.enqueueFillBuffer(cells_[next], 0.0f, 0, bytes));
  const int64_t keep_x = int64_t(gpu_.nx) - std::llabs(di);
  const int64_t keep_z = int64_t(gpu_.nz) - std::llabs(dk);
  const size_t nx = size_t(gpu_.nx), ny = size_t(gpu_.ny), nz = size_t(gpu_.nz);
  const size_t row = nx * sizeof(float), slice = row * ny;
  if (keep_x > 0 && keep_z > 0) {
    for (size_t plane = 0; plane < 4; ++plane) {
      // Planes are nz slices each: a plane's slice k is slice plane * nz + k of the buffer.
      cl::array<size_t, 3> from = {size_t(std::max<int64_t>(di, 0)) * sizeof(float), 0,
                                   plane * nz + size_t(std::max<int64_t>(dk, 0))};
      cl::array<size_t, 3> to = {size_t(std::max<int64_t>(-di, 0)) * sizeof(float), 0,
                                 plane * nz + size_t(std::max<int64_t>(-dk, 0))};
      cl::array<size_t, 3> region = {size_t(keep_x) * sizeof(float), ny, size_t(keep_z)};
      BOREAS_CL_CHECK(q.enqueueCopyBufferRect(cells_[current_], cells_[next], from, to, region, row,
                                              slice, row, slice));
    }
  }
  current_ = next;
  // The host's mask moves alike; the cells that come in are open until the caller lays
  // its solids into them.
  std::vector<uint8_t> moved(solids_.size(), 0);
  int count = 0;
  for (size_t k = 0; k < nz; ++k)
    for (size_t j = 0; j < ny; ++j)
      for (size_t i = 0; i < nx; ++i) {
        const int64_t si = int64_t(i) + di, sk = int64_t(k) + dk;
        if (si < 0 || sk < 0 || si >= int64_t(nx) || sk >= int64_t(nz)) continue;
        const uint8_t v = solids_[(size_t(sk) * ny + j) * nx + size_t(si)];
        moved[(k * ny + j) * nx + i] = v;
        count += v;
      }
  solids_ = std::move(moved);
  gpu_.solid_count = count;
}

}  // namespace boreas::impl
