// boreas: the meadow's ground — bilinear grids of samples, procedural rolling terrain and
// nutrient noise, and both from pixel arrays the caller gives (Endo et al. sec. 5.2). The
// library reads no image files: that is the caller's (the boreas command uses OpenImageIO),
// so an engine embedding boreas does not inherit an image library's dependencies.
//
// Pixels are stored as the grid's samples, one pixel each (nx = width, nz = height), so
// any resolution works and the bilinear lookup of GroundGrid::sample resamples them. Pixel
// centers sit on the samples: column 0 at x = origin_x, the last column at origin_x +
// size_x, row 0 (the top row of the file) at z = origin_z (the -z edge), the last row at
// origin_z + size_z.

#include "underbrush/terrain.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/tree_random.h"
#include "validation.h"

namespace boreas::impl {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Procedural grids: terrain every 0.25 m (20 samples along the shortest, 5 m wave),
// nutrients every 0.5 m (their patches are meters wide), both at most this many samples a
// side so a large meadow stays a few MB (a 1 km meadow: a sample per meter).
constexpr double kTerrainStep = 0.25;  // m
constexpr double kNutrientStep = 0.5;  // m
constexpr int kMaxProceduralSide = 1024;

// Rolling terrain: this many waves, wavelengths log-uniform in [kMinWave, kMaxWave] m —
// long enough to read as ground rather than bumps, short enough to show on a meadow.
constexpr int kTerrainWaves = 7;
constexpr double kMinWave = 5.0;   // m
constexpr double kMaxWave = 40.0;  // m

// Nutrient value noise: a lattice of random values every kPatch m (the patches) plus a
// finer octave every kDetail m. Blending pulls values toward 0.5, so the sum is stretched
// by kContrast about 0.5 and clamped: patches of bare (0) and rich (1) ground appear.
constexpr double kPatch = 4.0;   // m
constexpr double kDetail = 1.5;  // m
constexpr double kPatchWeight = 0.7;
constexpr double kContrast = 1.6;

// Pixel arrays beyond this many values (1 GB as floats) are refused rather than copied: no
// ground map needs them, and a wrong size would otherwise exhaust memory.
constexpr size_t kMaxImageValues = size_t(BOREAS_IMAGE_MAX_FLOATS);
constexpr int kMaxImageChannels = 16;
// m: no ground rises or falls further than this from the meadow's center (the wind grid's
// origin is within BOREAS_WORLD_MAX_COORDINATE; a height map this tall is a wrong unit,
// not terrain).
constexpr double kMaxGroundOffset = 1e6;

// The purposes random streams are drawn for (tree_random.h).
enum Purpose : uint64_t { kTerrainPurpose = 1, kNutrientPurpose = 2 };

// Where a coordinate falls on one axis of a grid: the two samples around it and the
// fraction between them. `inside` is false where the coordinate was clamped to an edge,
// so the surface is flat along this axis there.
struct AxisLookup {
  int i0 = 0, i1 = 0;
  double t = 0.0;
  double step = 0.0;  // m between samples, 0 for a single sample
  bool inside = false;
};

AxisLookup lookup_axis(double v, double origin, double size, int n) {
  AxisLookup a;
  if (n <= 1 || !(size > 0.0)) return a;
  a.step = size / double(n - 1);
  const double u = (v - origin) / a.step;
  a.inside = u >= 0.0 && u <= double(n - 1);
  const double c = std::isnan(u) ? 0.0 : std::clamp(u, 0.0, double(n - 1));
  a.i0 = std::min(int(c), n - 2);
  a.i1 = a.i0 + 1;
  a.t = c - double(a.i0);
  return a;
}

void check_rect(const GroundRect& rect) {
  const auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(rect.center_x) || !finite(rect.center_y) || !finite(rect.center_z)) {
    std::ostringstream m;
    m << "rect center must be finite (got " << rect.center_x << ", " << rect.center_y << ", "
      << rect.center_z << ")";
    fail_argument(m.str());
  }
  if (!(rect.size_x > 0.0) || !finite(rect.size_x)) {
    fail_argument("rect.size_x must be > 0 and finite (got " + num(rect.size_x) + ")");
  }
  if (!(rect.size_z > 0.0) || !finite(rect.size_z)) {
    fail_argument("rect.size_z must be > 0 and finite (got " + num(rect.size_z) + ")");
  }
}

void check_relief(double relief) {
  if (!(relief >= 0.0) || !std::isfinite(relief)) {
    fail_argument("relief must be >= 0 and finite (got " + num(relief) + ")");
  }
}

// A grid spanning the rectangle, with nx x nz samples.
GroundGrid rect_grid(const GroundRect& rect, int nx, int nz) {
  GroundGrid g;
  g.nx = nx;
  g.nz = nz;
  g.origin_x = rect.center_x - 0.5 * rect.size_x;
  g.origin_z = rect.center_z - 0.5 * rect.size_z;
  g.size_x = rect.size_x;
  g.size_z = rect.size_z;
  return g;
}

// A grid spanning the rectangle with samples about `step` apart, at most
// kMaxProceduralSide a side.
GroundGrid procedural_grid(const GroundRect& rect, double step) {
  const auto side = [step](double size) {
    return int(std::clamp(std::ceil(size / step) + 1.0, 2.0, double(kMaxProceduralSide)));
  };
  return rect_grid(rect, side(rect.size_x), side(rect.size_z));
}

// Uniform in [0, 1) at lattice point (i, k) of one noise layer.
double lattice_value(uint64_t layer_key, int64_t i, int64_t k) {
  const uint64_t h =
      splitmix64_mix(layer_key ^ splitmix64_mix(uint64_t(i) * 0x9e3779b97f4a7c15ull + uint64_t(k)));
  return double(h >> 11) * 0x1.0p-53;
}

// Value noise in [0, 1] at (u, v), in lattice cells: the random lattice values blended
// with the quintic fade, so the surface and its slope are continuous.
double value_noise(uint64_t key, double u, double v) {
  const double fu = std::floor(u), fv = std::floor(v);
  const auto i = int64_t(fu), k = int64_t(fv);
  const auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
  const double a = fade(u - fu), b = fade(v - fv);
  const double v00 = lattice_value(key, i, k), v10 = lattice_value(key, i + 1, k);
  const double v01 = lattice_value(key, i, k + 1), v11 = lattice_value(key, i + 1, k + 1);
  return (1.0 - b) * ((1.0 - a) * v00 + a * v10) + b * ((1.0 - a) * v01 + a * v11);
}

// One layer of value noise with lattice points `cell` m apart. Each layer's lattice is
// turned by its own random angle and shifted, or the patches of all layers would line up
// along x and z and the map would look tiled.
struct NoiseLayer {
  uint64_t key;
  double cos_a, sin_a;      // the lattice's rotation
  double shift_u, shift_v;  // cells
  double cell;              // m

  NoiseLayer(TreeRandom& rng, double cell_size) : key(rng.next_u64()), cell(cell_size) {
    const double angle = 2.0 * kPi * rng.uniform01();
    cos_a = std::cos(angle);
    sin_a = std::sin(angle);
    shift_u = rng.uniform01();
    shift_v = rng.uniform01();
  }
  double at(double x, double z) const {
    return value_noise(key, (cos_a * x + sin_a * z) / cell + shift_u,
                       (cos_a * z - sin_a * x) / cell + shift_v);
  }
};

}  // namespace

double GroundGrid::sample(const std::vector<float>& values, double x, double z) const {
  if (nx < 1 || nz < 1 || values.size() < size_t(nx) * size_t(nz)) return 0.0;
  const AxisLookup ax = lookup_axis(x, origin_x, size_x, nx);
  const AxisLookup az = lookup_axis(z, origin_z, size_z, nz);
  const auto at = [&](int i, int k) { return double(values[size_t(k) * size_t(nx) + size_t(i)]); };
  if (nx == 1 && nz == 1) return at(0, 0);
  if (nx == 1) return (1.0 - az.t) * at(0, az.i0) + az.t * at(0, az.i1);
  if (nz == 1) return (1.0 - ax.t) * at(ax.i0, 0) + ax.t * at(ax.i1, 0);
  const double low = (1.0 - ax.t) * at(ax.i0, az.i0) + ax.t * at(ax.i1, az.i0);
  const double high = (1.0 - ax.t) * at(ax.i0, az.i1) + ax.t * at(ax.i1, az.i1);
  return (1.0 - az.t) * low + az.t * high;
}

double Terrain::height_at(double x, double z) const { return grid.sample(height, x, z); }

// The exact gradient of the bilinear patch under (x, z): along x it is the slope of the
// cell's x edges blended by the z fraction, and likewise along z. On a grid line the cell
// on the +side is used; beyond the rectangle the clamped surface is flat along that axis.
void Terrain::normal_at(double x, double z, double n[3]) const {
  double dhdx = 0.0, dhdz = 0.0;
  if (grid.nx >= 1 && grid.nz >= 1 && height.size() >= size_t(grid.nx) * size_t(grid.nz)) {
    const AxisLookup ax = lookup_axis(x, grid.origin_x, grid.size_x, grid.nx);
    const AxisLookup az = lookup_axis(z, grid.origin_z, grid.size_z, grid.nz);
    const auto at = [&](int i, int k) {
      return double(height[size_t(k) * size_t(grid.nx) + size_t(i)]);
    };
    if (ax.inside && ax.step > 0.0) {
      const double low = at(ax.i1, az.i0) - at(ax.i0, az.i0);
      const double high = at(ax.i1, az.i1) - at(ax.i0, az.i1);
      dhdx = ((1.0 - az.t) * low + az.t * high) / ax.step;
    }
    if (az.inside && az.step > 0.0) {
      const double low = at(ax.i0, az.i1) - at(ax.i0, az.i0);
      const double high = at(ax.i1, az.i1) - at(ax.i1, az.i0);
      dhdz = ((1.0 - ax.t) * low + ax.t * high) / az.step;
    }
  }
  const double len = std::sqrt(dhdx * dhdx + 1.0 + dhdz * dhdz);
  n[0] = -dhdx / len;
  n[1] = 1.0 / len;
  n[2] = -dhdz / len;
}

double NutrientMaps::at(int channel, double x, double z) const {
  // A channel the maps do not have is an absent nutrient: none of it anywhere.
  if (channel < 0 || channel >= channels || channel >= kMaxNutrients) return 0.0;
  return grid.sample(values[channel], x, z);
}

// h(x, z) = center_y + sum_i a_i sin(k_i . (x - center) + phase_i), with sum_i a_i = relief,
// so |h - center_y| <= relief everywhere, and relief 0 gives exactly center_y.
Terrain procedural_terrain(const GroundRect& rect, double relief, uint64_t seed) {
  check_rect(rect);
  check_relief(relief);
  TreeRandom rng(seed, 0, kTerrainPurpose);
  struct Wave {
    double kx, kz, phase, amplitude;
  };
  Wave waves[kTerrainWaves];
  double weight_sum = 0.0;
  for (Wave& w : waves) {
    const double angle = 2.0 * kPi * rng.uniform01();
    const double wavelength = kMinWave * std::pow(kMaxWave / kMinWave, rng.uniform01());
    const double k = 2.0 * kPi / wavelength;
    w.kx = k * std::cos(angle);
    w.kz = k * std::sin(angle);
    w.phase = 2.0 * kPi * rng.uniform01();
    // Longer waves carry more of the relief, as on real ground; 0.25 keeps short ones visible.
    w.amplitude = (0.25 + rng.uniform01()) * wavelength;
    weight_sum += w.amplitude;
  }
  for (Wave& w : waves) w.amplitude *= relief / weight_sum;

  Terrain t;
  t.grid = procedural_grid(rect, kTerrainStep);
  t.height.assign(size_t(t.grid.nx) * size_t(t.grid.nz), float(rect.center_y));
  if (relief == 0.0) return t;
  const double dx = t.grid.size_x / double(t.grid.nx - 1);
  const double dz = t.grid.size_z / double(t.grid.nz - 1);
  for (int k = 0; k < t.grid.nz; ++k) {
    const double z = -0.5 * rect.size_z + dz * double(k);
    for (int i = 0; i < t.grid.nx; ++i) {
      const double x = -0.5 * rect.size_x + dx * double(i);
      double h = 0.0;
      for (const Wave& w : waves) h += w.amplitude * std::sin(w.kx * x + w.kz * z + w.phase);
      t.height[size_t(k) * size_t(t.grid.nx) + size_t(i)] = float(rect.center_y + h);
    }
  }
  return t;
}

GroundPixels checked_ground_pixels(const boreas_image& image, const std::string& field) {
  GroundPixels p;
  if (!image.pixels) {
    if (image.width != 0 || image.height != 0 || image.channels != 0) {
      fail_argument(field + ".pixels is NULL but its size is " + std::to_string(image.width) +
                    " x " + std::to_string(image.height) + " x " + std::to_string(image.channels) +
                    " (all zero means none)");
    }
    return p;
  }
  if (image.width < 1 || image.height < 1) {
    fail_argument(field + " must be at least 1 x 1 pixels (got " + std::to_string(image.width) +
                  " x " + std::to_string(image.height) + ")");
  }
  check_count(image.channels, 1, kMaxImageChannels, field + ".channels");
  const size_t values = size_t(image.width) * size_t(image.height) * size_t(image.channels);
  if (values > kMaxImageValues) {
    fail_argument(field + ": " + std::to_string(image.width) + " x " +
                  std::to_string(image.height) + " x " + std::to_string(image.channels) +
                  " values is more than the " + std::to_string(kMaxImageValues) +
                  " a ground map may have");
  }
  for (size_t i = 0; i < values; ++i) {
    if (!std::isfinite(image.pixels[i])) {
      const size_t pixel = i / size_t(image.channels);
      fail_argument(field + ": pixel (" + std::to_string(pixel % size_t(image.width)) + ", " +
                    std::to_string(pixel / size_t(image.width)) + ") channel " +
                    std::to_string(i % size_t(image.channels)) + " is not a finite number");
    }
  }
  p.width = image.width;
  p.height = image.height;
  p.channels = image.channels;
  p.data.assign(image.pixels, image.pixels + values);
  return p;
}

Terrain pixel_terrain(const GroundRect& rect, double relief, const GroundPixels& p) {
  check_rect(rect);
  check_relief(relief);
  if (p.empty()) fail_argument("pixel_terrain: no pixels");
  Terrain t;
  t.grid = rect_grid(rect, p.width, p.height);
  t.height.resize(size_t(p.width) * size_t(p.height));
  for (size_t s = 0; s < t.height.size(); ++s) {
    const double offset = relief * double(p.data[s * size_t(p.channels)]);
    if (!(std::abs(offset) <= kMaxGroundOffset)) {
      fail_argument("meadow_def.terrain: pixel (" + std::to_string(s % size_t(p.width)) + ", " +
                    std::to_string(s / size_t(p.width)) + ") puts the ground " + num(offset) +
                    " m from the meadow's center; at most " + num(kMaxGroundOffset));
    }
    t.height[s] = float(rect.center_y + offset);
  }
  return t;
}

NutrientMaps procedural_nutrients(const GroundRect& rect, uint64_t seed) {
  check_rect(rect);
  NutrientMaps m;
  m.grid = procedural_grid(rect, kNutrientStep);
  m.channels = kMaxNutrients;
  const double dx = m.grid.size_x / double(m.grid.nx - 1);
  const double dz = m.grid.size_z / double(m.grid.nz - 1);
  for (int c = 0; c < kMaxNutrients; ++c) {
    // Two layers per channel, drawn from a stream keyed by (seed, channel), so the channels
    // are independent patterns.
    TreeRandom rng(seed, uint64_t(c), kNutrientPurpose);
    const NoiseLayer patch(rng, kPatch), detail(rng, kDetail);
    std::vector<float>& v = m.values[c];
    v.resize(size_t(m.grid.nx) * size_t(m.grid.nz));
    for (int k = 0; k < m.grid.nz; ++k) {
      const double z = dz * double(k);
      for (int i = 0; i < m.grid.nx; ++i) {
        const double x = dx * double(i);
        const double n = kPatchWeight * patch.at(x, z) + (1.0 - kPatchWeight) * detail.at(x, z);
        const double stretched = 0.5 + kContrast * (n - 0.5);
        v[size_t(k) * size_t(m.grid.nx) + size_t(i)] = float(std::clamp(stretched, 0.0, 1.0));
      }
    }
  }
  return m;
}

NutrientMaps pixel_nutrients(const GroundRect& rect, const GroundPixels& p) {
  check_rect(rect);
  if (p.empty()) fail_argument("pixel_nutrients: no pixels");
  NutrientMaps m;
  m.grid = rect_grid(rect, p.width, p.height);
  m.channels = std::min(p.channels, kMaxNutrients);
  const size_t count = size_t(p.width) * size_t(p.height);
  for (int c = 0; c < m.channels; ++c) {
    m.values[c].resize(count);
    // Float pixels may stray outside [0, 1]; a concentration cannot.
    for (size_t s = 0; s < count; ++s) {
      m.values[c][s] = std::clamp(p.data[s * size_t(p.channels) + size_t(c)], 0.0f, 1.0f);
    }
  }
  return m;
}

}  // namespace boreas::impl
