// boreas: solid boxes, checked and laid into the grid's cells.
#include "wind/solid_boxes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "validation.h"

namespace boreas::impl {

SolidBox checked_solid_box(const float min[3], const float max[3]) {
  if (!min || !max) fail_argument("solid box min or max is NULL");
  for (int i = 0; i < 3; ++i) {
    check_finite(min[i], "min[" + std::to_string(i) + "]");
    check_finite(max[i], "max[" + std::to_string(i) + "]");
    if (min[i] > max[i])
      fail_argument("solid box min[" + std::to_string(i) + "] = " + std::to_string(min[i]) +
                    " exceeds max[" + std::to_string(i) + "] = " + std::to_string(max[i]));
  }
  return {min[0], min[1], min[2], max[0], max[1], max[2]};
}

void lay_solid_box(const BoreasGpuGrid& g, const SolidBox& box, std::vector<uint8_t>& mask) {
  const double origin[3] = {g.origin_x, g.origin_y, g.origin_z};
  const int n[3] = {g.nx, g.ny, g.nz};
  // The cells whose centers may lie in the box, along each axis: [lo, hi], a cell wider
  // than the rounding could make it (the test per cell below decides).
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const double h = g.cell_size, last = double(n[a] - 1);
    lo[a] = int(std::clamp(std::ceil((box[size_t(a)] - origin[a]) / h - 0.5) - 1.0, 0.0, last));
    hi[a] =
        int(std::clamp(std::floor((box[size_t(a) + 3] - origin[a]) / h - 0.5) + 1.0, -1.0, last));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const double c[3] = {origin[0] + (i + 0.5) * g.cell_size,
                             origin[1] + (j + 0.5) * g.cell_size,
                             origin[2] + (k + 0.5) * g.cell_size};
        bool inside = true;
        for (int a = 0; a < 3; ++a)
          inside = inside && c[a] >= box[size_t(a)] && c[a] <= box[size_t(a) + 3];
        if (inside) mask[(size_t(k) * size_t(g.ny) + size_t(j)) * size_t(g.nx) + size_t(i)] = 1;
      }
}

}  // namespace boreas::impl
