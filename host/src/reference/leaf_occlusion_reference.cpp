// boreas references: the crown's ambient occlusion in double precision.
#include "reference/leaf_occlusion_reference.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl::reference {

std::vector<double> leaf_occlusion(const LeafDensityGrid& g, const std::vector<float>& directions,
                                   const std::vector<float>& projection, double clumping,
                                   const double transmittance[3],
                                   const std::vector<boreas_leaf>& leaves) {
  const int nx = g.size[0], ny = g.size[1], nz = g.size[2];
  const size_t voxels = size_t(nx) * ny * nz;
  const size_t count = directions.size() / 3;
  std::vector<double> occlusion(voxels * 3, 0.0);
  for (int iz = 0; iz < nz; ++iz) {
    for (int iy = 0; iy < ny; ++iy) {
      for (int ix = 0; ix < nx; ++ix) {
        const size_t v = (size_t(iz) * ny + iy) * nx + ix;
        for (size_t d = 0; d < count; ++d) {
          const double dx = directions[3 * d], dy = directions[3 * d + 1],
                       dz = directions[3 * d + 2];
          double depth = 0.0;
          for (double s = 0.25;; s += 0.5) {
            const double x = ix + 0.5 + s * dx, y = iy + 0.5 + s * dy, z = iz + 0.5 + s * dz;
            if (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz) break;
            depth += g.density[(size_t(z) * ny + size_t(y)) * nx + size_t(x)];
          }
          const double tau = clumping * double(projection[d]) * depth * 0.5 * g.cell;
          for (int c = 0; c < 3; ++c)
            occlusion[3 * v + c] += std::exp(-(1.0 - transmittance[c]) * tau) / double(count);
        }
      }
    }
  }
  std::vector<double> out;
  out.reserve(leaves.size() * 3);
  for (const boreas_leaf& l : leaves) {
    const std::array<double, 3> centre = leaf_centre(l);
    double gc[3];
    int i0[3], i1[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
      gc[a] = std::clamp((centre[size_t(a)] - g.origin[a]) / g.cell - 0.5, 0.0,
                         double(g.size[a] - 1));
      i0[a] = std::min(int(gc[a]), std::max(g.size[a] - 2, 0));
      i1[a] = std::min(i0[a] + 1, g.size[a] - 1);
      f[a] = gc[a] - i0[a];
    }
    for (int c = 0; c < 3; ++c) {
      auto at = [&](int x, int y, int z) {
        return occlusion[3 * ((size_t(z) * ny + y) * nx + x) + c];
      };
      auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
      double a = lerp(at(i0[0], i0[1], i0[2]), at(i1[0], i0[1], i0[2]), f[0]);
      double b = lerp(at(i0[0], i1[1], i0[2]), at(i1[0], i1[1], i0[2]), f[0]);
      double d = lerp(at(i0[0], i0[1], i1[2]), at(i1[0], i0[1], i1[2]), f[0]);
      double e = lerp(at(i0[0], i1[1], i1[2]), at(i1[0], i1[1], i1[2]), f[0]);
      out.push_back(lerp(lerp(a, b, f[1]), lerp(d, e, f[1]), f[2]));
    }
  }
  return out;
}

}  // namespace boreas::impl::reference
