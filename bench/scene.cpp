// boreas: the benchmark scene (see scene.h). Fixed numbers and a fixed seed, so that every
// run and both implementations see the same inputs.
#include "scene.h"

#include <cmath>
#include <utility>

#include "colliders/collider.h"
#include "underbrush/component_species.h"
#include "underbrush/distribution.h"
#include "wind/flow_field.h"
#include "wind/wind_grid.h"

namespace boreas::bench {

std::vector<BoreasGpuWave> scene_waves() {
  // direction (x, z), amplitude m/s, wavelength m, phase (cycles); sharpness 2.5 throughout.
  const float table[4][5] = {{1.0f, 0.0f, 3.0f, 20.0f, 0.3f},
                             {0.6f, 0.8f, 1.5f, 11.0f, 1.1f},
                             {-0.28f, 0.96f, 0.8f, 6.5f, 2.0f},
                             {0.8f, -0.6f, 0.4f, 3.2f, 4.2f}};
  std::vector<BoreasGpuWave> waves;
  for (const auto& row : table) {
    BoreasGpuWave w{};
    w.dir_x = row[0];
    w.dir_z = row[1];
    w.amplitude = row[2];
    w.cycles_per_meter = 1.0f / row[3];
    w.phase_cycles = row[4] / 6.28318530717958648f;
    w.sharpness = 2.5f;
    waves.push_back(w);
  }
  return waves;
}

boreas_grid_def scene_grid_def(int nx, int ny, int nz) {
  boreas_grid_def d = boreas_default_grid_def();
  d.cell_size = 2.0f;
  d.resolution[0] = nx;
  d.resolution[1] = ny;
  d.resolution[2] = nz;
  d.origin[0] = -0.5f * nx * d.cell_size;
  d.origin[1] = 0.0f;
  d.origin[2] = -0.5f * nz * d.cell_size;
  return d;
}

BoreasGpuGrid scene_gpu_grid(const boreas_grid_def& def) { return impl::gpu_grid(def); }

std::vector<uint8_t> scene_solids(const boreas_grid_def& def) {
  const int nx = def.resolution[0], ny = def.resolution[1], nz = def.resolution[2];
  std::vector<uint8_t> mask(size_t(nx) * ny * nz, 0);
  for (int k = nz / 2 - nz / 16; k < nz / 2 + nz / 16; ++k)
    for (int j = 0; j < ny / 4; ++j)
      for (int i = nx / 2 - nx / 16; i < nx / 2 + nx / 16; ++i)
        mask[(size_t(k) * ny + j) * nx + i] = 1;
  return mask;
}

impl::WindGrid::Forcing scene_forcing(const boreas_grid_def& def) {
  // Made through FlowField, as a world makes them, so the device form stays the library's.
  const float half_x = 0.5f * def.resolution[0] * def.cell_size;
  const float height = def.resolution[1] * def.cell_size;
  impl::FlowField field(impl::claim_world_serial());
  boreas_flow_primitive_def source = boreas_default_flow_primitive_def();
  source.type = BOREAS_FLOW_SOURCE;
  source.position[0] = -0.5f * half_x;
  source.position[1] = 0.25f * height;
  source.radius = 0.4f * half_x;
  source.strength = 6.0f;
  field.add_primitive(source, 0.0);
  boreas_flow_primitive_def vortex = boreas_default_flow_primitive_def();
  vortex.type = BOREAS_FLOW_VORTEX;
  vortex.position[0] = 0.5f * half_x;
  vortex.position[1] = 0.5f * height;
  vortex.direction[0] = 0.0f;
  vortex.direction[1] = 1.0f;
  vortex.radius = 0.5f * half_x;
  vortex.strength = 8.0f;
  field.add_primitive(vortex, 0.0);
  boreas_gust_def gust = boreas_default_gust_def();  // a bounded uniform flow, held at its peak
  gust.direction[0] = 0.8f;
  gust.direction[2] = 0.6f;
  gust.center[1] = 0.3f * height;
  gust.center[2] = 0.3f * half_x;
  gust.radius = 0.6f * half_x;
  gust.rise = 0.0f;
  gust.hold = 1e6f;
  field.add_gust(gust, 0.0);
  impl::WindGrid::Forcing drive;
  drive.steady = field.steady();
  drive.steady_version = field.steady_version();
  drive.varying = field.varying(1.0);
  return drive;
}

std::vector<float> scene_grid_cells(const boreas_grid_def& def,
                                    const std::vector<uint8_t>& solids) {
  const int nx = def.resolution[0], ny = def.resolution[1], nz = def.resolution[2];
  const size_t n = size_t(nx) * ny * nz;
  std::vector<float> planes(4 * n);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        size_t c = (size_t(k) * ny + j) * nx + i;
        planes[c] = 2.0f * std::sin(0.21f * i) * std::cos(0.13f * k);
        planes[n + c] = 0.3f * std::sin(0.4f * j + 0.1f * i);
        planes[2 * n + c] = 1.5f * std::cos(0.17f * i + 0.23f * k);
        planes[3 * n + c] = solids[c] ? 1.0f : 0.0f;
      }
  return planes;
}

std::vector<float> scene_points(int count, const boreas_grid_def& def) {
  // xorshift32: fixed, fast, and the same on every platform.
  uint32_t state = 0x9e3779b9u;
  auto next = [&state] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return (state >> 8) * (1.0f / 16777216.0f);  // [0, 1)
  };
  const size_t n = size_t(count);
  std::vector<float> planes(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a)
      planes[a * n + i] = def.origin[a] + next() * def.resolution[a] * def.cell_size;
  return planes;
}

namespace {

// The first `count` components of a meadow: its planes cut to stride count. Parents come
// before their children, so every parent index stays valid.
impl::Meadow cut_meadow(impl::Meadow m, int count) {
  const size_t from = size_t(m.count), to = size_t(count);
  auto cut = [&](auto& planes, int plane_count) {
    auto out = planes;
    out.resize(size_t(plane_count) * to);
    for (size_t k = 0; k < size_t(plane_count); ++k)
      for (size_t c = 0; c < to; ++c) out[k * to + c] = planes[k * from + c];
    planes = std::move(out);
  };
  cut(m.frame, BOREAS_UB_FRAME_PLANES);
  cut(m.index, BOREAS_UB_INDEX_PLANES);
  cut(m.rest_state, BOREAS_UB_STATE_PLANES);
  m.species_of.resize(to);
  m.plant_of.resize(to);
  m.count = count;
  return m;
}

}  // namespace

impl::Meadow scene_meadow(int components) {
  impl::MeadowParams params;
  params.species.push_back(impl::load_component_species("meadow_grass"));
  params.weights.push_back(1.0);
  const int per_tuft = params.species[0].components_per_plant();
  const int tufts = (components + per_tuft - 1) / per_tuft;
  const int side = int(std::ceil(std::sqrt(double(tufts))));
  std::vector<impl::Planting> plantings;
  for (int t = 0; t < tufts; ++t) {
    impl::Planting p{};
    p.position[0] = float((t % side - 0.5 * (side - 1)) * kMeadowSpacing);
    p.position[2] = float((t / side - 0.5 * (side - 1)) * kMeadowSpacing);
    p.normal[1] = 1.0f;
    p.kind = 0;
    p.seed = 7u + uint32_t(t);
    plantings.push_back(p);
  }
  return cut_meadow(impl::meadow_from_plantings(std::move(params), plantings), components);
}

impl::StepColliders scene_step_colliders() {
  // A football and a larger ball on the ground, still: center (m), radius (m).
  const float balls[2][4] = {{-1.0f, 0.11f, 0.5f, 0.11f}, {1.5f, 0.3f, -2.0f, 0.3f}};
  impl::StepColliders out;
  out.dt = kStepSeconds;
  for (const auto& b : balls) {
    impl::Collider c;
    c.def = boreas_default_collider_def();
    for (int a = 0; a < 3; ++a) c.def.pose.position[a] = b[a];
    c.def.radius = b[3];
    out.add(c);
  }
  return out;
}

std::vector<BoreasGpuCollider> scene_colliders() { return scene_step_colliders().gpu; }

}  // namespace boreas::bench
