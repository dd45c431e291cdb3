// boreas trees: the crown's ambient occlusion (leaf_occlusion.h).
#include "trees/leaf_occlusion.h"

#include <algorithm>
#include <cmath>

#include "runtime/launch.h"

namespace boreas::impl {

LeafDensityGrid leaf_density_grid(const std::vector<boreas_leaf>& leaves) {
  LeafDensityGrid g;
  if (leaves.empty()) {
    g.density.assign(1, 0.0f);
    return g;
  }
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const boreas_leaf& l : leaves) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(l.position[a]));
      hi[a] = std::max(hi[a], double(l.position[a]));
    }
  }
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-3});
  g.cell = longest / kOcclusionVoxels;
  for (int a = 0; a < 3; ++a) {
    g.origin[a] = lo[a] - g.cell;
    g.size[a] = int(std::ceil((hi[a] - lo[a]) / g.cell)) + 2;
  }
  g.density.assign(size_t(g.size[0]) * g.size[1] * g.size[2], 0.0f);
  const double volume = g.cell * g.cell * g.cell;
  for (const boreas_leaf& l : leaves) {
    int i[3];
    for (int a = 0; a < 3; ++a) {
      i[a] = std::clamp(int((double(l.position[a]) - g.origin[a]) / g.cell), 0, g.size[a] - 1);
    }
    g.density[(size_t(i[2]) * g.size[1] + i[1]) * g.size[0] + i[0]] +=
        float(kLeafFill * double(l.length) * double(l.width) / volume);
  }
  return g;
}

std::vector<float> occlusion_directions(int count) {
  // Fibonacci points on the unit disc, lifted to the hemisphere (Malley's method): their
  // density over the hemisphere is proportional to the cosine.
  std::vector<float> d;
  d.reserve(size_t(count) * 3);
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    double r = std::sqrt((k + 0.5) / count), phi = golden * k;
    double x = r * std::cos(phi), z = r * std::sin(phi), y = std::sqrt(std::max(0.0, 1.0 - r * r));
    d.insert(d.end(), {float(x), float(y), float(z)});
  }
  return d;
}

std::vector<float> leaf_occlusion(Runtime& runtime, const std::vector<boreas_leaf>& leaves,
                                  const float transmittance[3]) {
  if (leaves.empty()) return {};
  const LeafDensityGrid g = leaf_density_grid(leaves);
  const std::vector<float> directions = occlusion_directions();
  const size_t voxels = g.density.size();
  std::vector<float> points(leaves.size() * 3);
  for (size_t i = 0; i < leaves.size(); ++i) {
    for (int a = 0; a < 3; ++a) points[3 * i + a] = leaves[i].position[a];
  }
  cl::Buffer density =
      runtime.buffer(CL_MEM_READ_ONLY, voxels * sizeof(float), "leaf density grid");
  cl::Buffer dirs =
      runtime.buffer(CL_MEM_READ_ONLY, directions.size() * sizeof(float), "occlusion directions");
  cl::Buffer occlusion =
      runtime.buffer(CL_MEM_READ_WRITE, voxels * 3 * sizeof(float), "occlusion grid");
  cl::Buffer at = runtime.buffer(CL_MEM_READ_ONLY, points.size() * sizeof(float), "leaf positions");
  cl::Buffer out =
      runtime.buffer(CL_MEM_WRITE_ONLY, points.size() * sizeof(float), "leaf occlusion");
  runtime.upload(density, g.density);
  runtime.upload(dirs, directions);
  runtime.upload(at, points);

  float extinction[3];
  for (int c = 0; c < 3; ++c)
    extinction[c] = float(1.0 - std::clamp(double(transmittance[c]), 0.0, 1.0));
  cl::Kernel& grid = runtime.kernel("leaf_occlusion.cl", "boreas_leaf_occlusion_grid");
  launch(runtime, grid, Items(voxels), density, g.size[0], g.size[1], g.size[2], float(g.cell),
         dirs, int(directions.size() / 3), extinction[0], extinction[1], extinction[2], occlusion);

  cl::Kernel& sample = runtime.kernel("leaf_occlusion.cl", "boreas_leaf_occlusion_leaves");
  launch(runtime, sample, Items(leaves.size()), occlusion, g.size[0], g.size[1], g.size[2],
         float(g.origin[0]), float(g.origin[1]), float(g.origin[2]), float(g.cell), at,
         int(leaves.size()), out);

  std::vector<float> result(points.size());
  runtime.read(out, 0, result.size() * sizeof(float), result.data());
  return result;
}

}  // namespace boreas::impl
