// boreas trees: the crown's ambient occlusion (leaf_occlusion.h).
#include "trees/leaf_occlusion.h"

#include <algorithm>
#include <cmath>

#include "runtime/launch.h"
#include "trees/leaf_area.h"

namespace boreas::impl {

std::array<double, 3> leaf_centre(const boreas_leaf& l) {
  std::array<double, 3> c{};
  for (int a = 0; a < 3; ++a) c[size_t(a)] = double(l.position[a]) + 0.5 * double(l.length) * l.axis[a];
  return c;
}

double crown_projection(const std::vector<boreas_leaf>& leaves) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const boreas_leaf& l : leaves) {
    const std::array<double, 3> c = leaf_centre(l);
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], c[size_t(2 * k)]);  // x, then z
      hi[k] = std::max(hi[k], c[size_t(2 * k)]);
    }
  }
  if (leaves.empty()) return 0.0;
  return 3.14159265358979323846 / 4.0 * (hi[0] - lo[0]) * (hi[1] - lo[1]);
}

double leaf_area_scale(const std::vector<boreas_leaf>& leaves, const CrownLight& light) {
  if (light.leaf_area_index <= 0.0) return 1.0;
  double area = 0.0;
  for (const boreas_leaf& l : leaves) area += leaf_area(l.length, l.width, light.outline);
  const double target = light.leaf_area_index * crown_projection(leaves);
  return area > target && target > 0.0 ? target / area : 1.0;
}

LeafDensityGrid leaf_density_grid(const std::vector<boreas_leaf>& leaves,
                                  const CrownLight& light) {
  LeafDensityGrid g;
  if (leaves.empty()) {
    g.density.assign(1, 0.0f);
    return g;
  }
  std::vector<std::array<double, 3>> centres(leaves.size());
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (size_t i = 0; i < leaves.size(); ++i) {
    centres[i] = leaf_centre(leaves[i]);
    for (size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], centres[i][a]);
      hi[a] = std::max(hi[a], centres[i][a]);
    }
  }
  const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-3});
  g.cell = longest / kOcclusionVoxels;
  for (size_t a = 0; a < 3; ++a) {
    g.origin[a] = lo[a] - g.cell;
    g.size[a] = int(std::ceil((hi[a] - lo[a]) / g.cell)) + 2;
  }
  g.density.assign(size_t(g.size[0]) * g.size[1] * g.size[2], 0.0f);
  const double per_volume = leaf_area_scale(leaves, light) / (g.cell * g.cell * g.cell);
  for (size_t n = 0; n < leaves.size(); ++n) {
    int i[3];
    for (size_t a = 0; a < 3; ++a)
      i[a] = std::clamp(int((centres[n][a] - g.origin[a]) / g.cell), 0, g.size[a] - 1);
    g.density[(size_t(i[2]) * g.size[1] + i[1]) * g.size[0] + i[0]] +=
        float(leaf_area(leaves[n].length, leaves[n].width, light.outline) * per_volume);
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

std::vector<float> leaf_projection(const std::vector<boreas_leaf>& leaves,
                                   const std::vector<float>& directions, int outline) {
  const size_t count = directions.size() / 3;
  std::vector<double> sum(count, 0.0);
  double area = 0.0;
  for (const boreas_leaf& l : leaves) {
    const double a = leaf_area(l.length, l.width, outline);
    const double n[3] = {l.normal[0], l.normal[1], l.normal[2]};
    const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(norm > 0.0)) continue;  // a leaf without a normal has no orientation to count
    area += a;
    for (size_t d = 0; d < count; ++d) {
      const double dot = n[0] * directions[3 * d] + n[1] * directions[3 * d + 1] +
                         n[2] * directions[3 * d + 2];
      sum[d] += a * std::abs(dot) / norm;
    }
  }
  std::vector<float> g(count, 0.5f);  // no oriented leaf: the spherical distribution's
  if (area > 0.0)
    for (size_t d = 0; d < count; ++d) g[d] = float(sum[d] / area);
  return g;
}

std::vector<float> leaf_occlusion(Runtime& runtime, const std::vector<boreas_leaf>& leaves,
                                  const float transmittance[3], const CrownLight& light) {
  if (leaves.empty()) return {};
  const LeafDensityGrid g = leaf_density_grid(leaves, light);
  const std::vector<float> directions = occlusion_directions();
  const std::vector<float> projection = leaf_projection(leaves, directions, light.outline);
  const size_t voxels = g.density.size();
  std::vector<float> points(leaves.size() * 3);
  for (size_t i = 0; i < leaves.size(); ++i) {
    const std::array<double, 3> c = leaf_centre(leaves[i]);
    for (size_t a = 0; a < 3; ++a) points[3 * i + a] = float(c[a]);
  }
  cl::Buffer density =
      runtime.buffer(CL_MEM_READ_ONLY, voxels * sizeof(float), "leaf density grid");
  cl::Buffer dirs =
      runtime.buffer(CL_MEM_READ_ONLY, directions.size() * sizeof(float), "occlusion directions");
  cl::Buffer proj =
      runtime.buffer(CL_MEM_READ_ONLY, projection.size() * sizeof(float), "leaf projection");
  cl::Buffer occlusion =
      runtime.buffer(CL_MEM_READ_WRITE, voxels * 3 * sizeof(float), "occlusion grid");
  cl::Buffer at = runtime.buffer(CL_MEM_READ_ONLY, points.size() * sizeof(float), "leaf centres");
  cl::Buffer out =
      runtime.buffer(CL_MEM_WRITE_ONLY, points.size() * sizeof(float), "leaf occlusion");
  runtime.upload(density, g.density);
  runtime.upload(dirs, directions);
  runtime.upload(proj, projection);
  runtime.upload(at, points);

  float extinction[3];
  for (int c = 0; c < 3; ++c)
    extinction[c] = float(1.0 - std::clamp(double(transmittance[c]), 0.0, 1.0));
  cl::Kernel& grid = runtime.kernel("leaf_occlusion.cl", "boreas_leaf_occlusion_grid");
  launch(runtime, grid, Items(voxels), density, g.size[0], g.size[1], g.size[2], float(g.cell),
         dirs, proj, int(directions.size() / 3), float(light.clumping), extinction[0],
         extinction[1], extinction[2], occlusion);

  cl::Kernel& sample = runtime.kernel("leaf_occlusion.cl", "boreas_leaf_occlusion_leaves");
  launch(runtime, sample, Items(leaves.size()), occlusion, g.size[0], g.size[1], g.size[2],
         float(g.origin[0]), float(g.origin[1]), float(g.origin[2]), float(g.cell), at,
         int(leaves.size()), out);

  std::vector<float> result(points.size());
  runtime.read(out, 0, result.size() * sizeof(float), result.data());
  return result;
}

}  // namespace boreas::impl
