// boreas benchmarks: the wind rows, each kernel beside its native twin: the copy kernel
// (the bandwidth yardstick of vs_copy), the sine sum at points and per grid column, and
// the grid step.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bench_harness.h"
#include "native_wind.h"
#include "reference/probe_kernels.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "scene.h"
#include "shared/wind_types.h"
#include "wind/wind_grid.h"

namespace boreas::bench {

namespace {

// Compulsory memory traffic per item, bytes read + written. Reads that hit the cache
// (waves, the grid under the points, a cell's neighbours and its backtrace) are left out,
// so bytes/s is a lower bound to compare with the copy kernel's.
constexpr double kBytesPerCopyItem = 32.0;   // float4 in + float4 out
constexpr double kBytesPerSample = 24.0;     // xyz in + force out
constexpr double kBytesPerSlabColumn = 8.0;  // x and z out
constexpr double kBytesPerGridCell = 32.0;   // x, y, z, solid in and out (4 planes)

constexpr int kSampleSizes[] = {1 << 16, 1 << 20, 1 << 22};
constexpr int kSlabSides[][2] = {{256, 256}, {1024, 1024}, {2048, 2048}};
constexpr int kGridSizes[][3] = {{32, 16, 32}, {64, 32, 64}, {128, 32, 128}};

// Grid steps run before timing, so that the grid holds a developed field.
constexpr int kWarmSteps = 20;

// ---- copy ----

void copy_cl(benchmark::State& state, int n) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Copy : Fixture {
    cl::Kernel kernel;
    cl::Buffer in, out;
  };
  Copy& f = fixture<Copy>("copy/cl/" + std::to_string(n), [&] {
    auto c = std::make_unique<Copy>();
    size_t bytes = size_t(n) * 16;
    c->in = rt->buffer(CL_MEM_READ_ONLY, bytes);
    c->out = rt->buffer(CL_MEM_WRITE_ONLY, bytes);
    BOREAS_CL_CHECK(rt->queue().enqueueFillBuffer(c->in, 1.0f, 0, bytes));
    impl::use_probe_kernels();  // the copy kernel is a probe, not part of the library
    c->kernel = rt->kernel("bandwidth_copy.cl", "boreas_bandwidth_copy");
    return c;
  });
  auto launch = [&] { return impl::launch(*rt, f.kernel, impl::Items(size_t(n)), f.in, f.out); };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_CopyBandwidth", n, kBytesPerCopyItem, launch);
}

void copy_native(benchmark::State& state, int n) {
  struct Copy : Fixture {
    std::vector<float> in, out;
  };
  Copy& f = fixture<Copy>("copy/native/" + std::to_string(n), [&] {
    auto c = std::make_unique<Copy>();
    c->in.assign(size_t(n) * 4, 1.0f);
    c->out.assign(size_t(n) * 4, 0.0f);
    return c;
  });
  native_copy(f.in.data(), f.out.data(), f.in.size());
  time_native(state, "BM_CopyBandwidth", n, kBytesPerCopyItem,
              [&] { native_copy(f.in.data(), f.out.data(), f.in.size()); });
}

// ---- sine sum at points (boreas_wind_sample_points) ----

// The grid under the points: the default world's 64 x 16 x 64 cells with a solid box.
struct SampleScene {
  boreas_grid_def def = scene_grid_def(64, 16, 64);
  std::vector<uint8_t> solids = scene_solids(def);
  std::vector<float> cells = scene_grid_cells(def, solids);
  std::vector<BoreasGpuWave> waves = scene_waves();
  BoreasGpuGrid g = [this] {
    BoreasGpuGrid r = scene_gpu_grid(def);
    for (uint8_t s : solids) r.solid_count += s ? 1 : 0;
    return r;
  }();
};

// width 0: the library's kernel as World::sample builds it, at the device's SIMD width
// (cl/shared/simd_width.h); 1, 8, 16: the same source built at that width (1 is the
// scalar kernel of before issue 22, whose work-item loop PoCL vectorizes itself).
void sine_sum_cl(benchmark::State& state, int n, int width = 0) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Sample : Fixture {
    SampleScene scene;
    cl::Kernel kernel;
    cl::Buffer points, force, waves, grid, phases;
    int wave_slots = 0;
    std::string error;
  };
  const std::string variant = width ? "cl_w" + std::to_string(width) : "cl";
  const std::string width_define = impl::width_define(width);
  const impl::Items items =
      impl::Items(size_t(n)).per_work_item(size_t(width ? width : rt->simd_width()));
  // As World::sample launches it (points and forces as planes).
  auto launch_sample = [&](Sample& s) {
    return impl::launch(*rt, s.kernel, items, s.points, s.force, n, s.waves, s.wave_slots,
                        s.phases, s.grid, s.scene.g);
  };
  Sample& f = fixture<Sample>("sine/" + variant + "/" + std::to_string(n), [&] {
    auto s = std::make_unique<Sample>();
    const SampleScene& sc = s->scene;
    std::vector<float> points = scene_points(n, sc.def);
    DeviceWaves dw = device_waves(sc.waves);
    // As SamplePoints hands them over: relative to the grid's corner, with the waves'
    // phases there.
    std::vector<float> local(points.size());
    const double corner[3] = {sc.g.origin_x, sc.g.origin_y, sc.g.origin_z};
    for (size_t a = 0; a < 3; ++a)
      for (size_t i = 0; i < size_t(n); ++i)
        local[a * size_t(n) + i] = float(double(points[a * size_t(n) + i]) - corner[a]);
    std::vector<float> phases(dw.padded.size(), 0.0f);
    impl::wave_phases_at(dw.padded.data(), int(dw.padded.size()), corner[0], corner[2],
                         phases.data());
    s->phases = upload(*rt, CL_MEM_READ_ONLY, phases.data(), phases.size() * sizeof(float));
    s->points = upload(*rt, CL_MEM_READ_ONLY, local.data(), local.size() * sizeof(float));
    s->force = rt->buffer(CL_MEM_WRITE_ONLY, points.size() * sizeof(float));
    s->waves =
        upload(*rt, CL_MEM_READ_ONLY, dw.padded.data(), dw.padded.size() * sizeof(BoreasGpuWave));
    s->grid = upload(*rt, CL_MEM_READ_ONLY, sc.cells.data(), sc.cells.size() * sizeof(float));
    s->wave_slots = int(dw.padded.size());
    s->kernel =
        rt->kernel("wind_sample_points.cl", "boreas_wind_sample_points", dw.define + width_define);
    // Once: the kernel's result against the native twin's on the same points.
    cl::CommandQueue& q = rt->queue();
    launch_sample(*s);
    std::vector<float> got(points.size()), want(points.size());
    BOREAS_CL_CHECK(
        q.enqueueReadBuffer(s->force, CL_TRUE, 0, got.size() * sizeof(float), got.data()));
    native_sample_points(points.data(), want.data(), n, sc.waves.data(), int(sc.waves.size()),
                         sc.cells.data(), sc.g);
    s->error = disagreement("sine sums", max_difference(got, want));
    return s;
  });
  if (skipped_for(state, f.error)) return;
  auto launch = [&] { return launch_sample(f); };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindSineSum", n, kBytesPerSample, launch);
}

void sine_sum_native(benchmark::State& state, int n) {
  struct Sample : Fixture {
    SampleScene scene;
    std::vector<float> points, force;
  };
  Sample& f = fixture<Sample>("sine/native/" + std::to_string(n), [&] {
    auto s = std::make_unique<Sample>();
    s->points = scene_points(n, s->scene.def);
    s->force.assign(s->points.size(), 0.0f);
    return s;
  });
  const SampleScene& sc = f.scene;
  auto run = [&] {
    native_sample_points(f.points.data(), f.force.data(), n, sc.waves.data(), int(sc.waves.size()),
                         sc.cells.data(), sc.g);
  };
  run();
  time_native(state, "BM_WindSineSum", n, kBytesPerSample, run);
}

// ---- sine sum per grid column (boreas_wind_sine_slab): the bare sine sum ----

// width as for sine_sum_cl: 0 the library's kernel at the device's width, else that width
// (`width` neighbouring columns per work-item).
void sine_slab_cl(benchmark::State& state, int nx, int nz, int width = 0) {
  impl::Runtime* rt = runtime_or_skip(state);
  if (!rt) return;
  struct Slab : Fixture {
    cl::Kernel kernel;
    cl::Buffer slab, waves, phases;
    int wave_slots = 0;
    BoreasGpuGrid g{};
    std::string error;
  };
  const int64_t columns = int64_t(nx) * nz;
  const std::string variant = width ? "cl_w" + std::to_string(width) : "cl";
  const std::string width_define = impl::width_define(width);
  // As WindGrid::step launches it.
  const impl::Items items =
      impl::Items(size_t(nx), size_t(nz)).per_work_item(size_t(width ? width : rt->simd_width()));
  auto launch_slab = [&](Slab& s) {
    return impl::launch(*rt, s.kernel, items, s.slab, s.waves, s.wave_slots, s.phases, s.g);
  };
  Slab& f = fixture<Slab>("slab/" + variant + "/" + std::to_string(columns), [&] {
    auto s = std::make_unique<Slab>();
    std::vector<BoreasGpuWave> waves = scene_waves();
    DeviceWaves dw = device_waves(waves);
    s->g = scene_gpu_grid(scene_grid_def(nx, 1, nz));
    const BoreasGpuGrid& g = s->g;
    // The kernel writes the slab after the grid's planes (boreas_grid_slab_offset).
    const size_t offset = size_t(boreas_grid_slab_offset(g));
    s->slab = rt->buffer(CL_MEM_WRITE_ONLY, size_t(boreas_grid_buffer_floats(g)) * sizeof(float));
    s->waves =
        upload(*rt, CL_MEM_READ_ONLY, dw.padded.data(), dw.padded.size() * sizeof(BoreasGpuWave));
    s->wave_slots = int(dw.padded.size());
    std::vector<float> phases(dw.padded.size(), 0.0f);  // at the grid's corner
    impl::wave_phases_at(dw.padded.data(), int(dw.padded.size()), g.origin_x, g.origin_z,
                         phases.data());
    s->phases = upload(*rt, CL_MEM_READ_ONLY, phases.data(), phases.size() * sizeof(float));
    s->kernel = rt->kernel("wind_sine_slab.cl", "boreas_wind_sine_slab", dw.define + width_define);
    cl::CommandQueue& q = rt->queue();
    launch_slab(*s);
    std::vector<float> got(size_t(columns) * 2), want(got.size());
    BOREAS_CL_CHECK(q.enqueueReadBuffer(s->slab, CL_TRUE, offset * sizeof(float),
                                        got.size() * sizeof(float), got.data()));
    native_sine_slab(want.data(), waves.data(), int(waves.size()), g);
    s->error = disagreement("sine slabs", max_difference(got, want));
    return s;
  });
  if (skipped_for(state, f.error)) return;
  auto launch = [&] { return launch_slab(f); };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindSineSlab", columns, kBytesPerSlabColumn, launch);
}

void sine_slab_native(benchmark::State& state, int nx, int nz) {
  struct Slab : Fixture {
    std::vector<BoreasGpuWave> waves = scene_waves();
    std::vector<float> slab;
  };
  const int64_t columns = int64_t(nx) * nz;
  Slab& f = fixture<Slab>("slab/native/" + std::to_string(columns), [&] {
    auto s = std::make_unique<Slab>();
    s->slab.assign(size_t(columns) * 2, 0.0f);
    return s;
  });
  const BoreasGpuGrid g = scene_gpu_grid(scene_grid_def(nx, 1, nz));
  auto run = [&] { native_sine_slab(f.slab.data(), f.waves.data(), int(f.waves.size()), g); };
  run();
  time_native(state, "BM_WindSineSlab", columns, kBytesPerSlabColumn, run);
}

// ---- grid step (boreas_wind_grid_step, launched by WindGrid::step with its slab) ----

struct GridScene {
  boreas_grid_def def;
  std::vector<uint8_t> solids;
  impl::WindGrid::Forcing drive;
  std::vector<BoreasGpuWave> waves = scene_waves();
  explicit GridScene(const int size[3])
      : def(scene_grid_def(size[0], size[1], size[2])),
        solids(scene_solids(def)),
        drive(scene_forcing(def)) {}
  int varying_count() const { return int(drive.varying.size()); }
  // The steady field as the native twin builds it (once, like the device's).
  std::vector<float> native_steady_field(const BoreasGpuGrid& g) const {
    std::vector<float> field(size_t(g.nx) * g.ny * g.nz * 4);
    native_forcing_field(field.data(), drive.steady.data(), int(drive.steady.size()), g);
    return field;
  }
};

// width_one: on a runtime whose kernels are built at SIMD width 1 (before issue 22).
void grid_step_cl(benchmark::State& state, const int size[3], bool width_one = false) {
  impl::Runtime* rt = width_one ? width_one_runtime_or_skip(state) : runtime_or_skip(state);
  if (!rt) return;
  struct Grid : Fixture {
    GridScene scene;
    DeviceWaves waves;
    std::unique_ptr<impl::WindGrid> grid;
    cl::Buffer wave_buffer;
    std::string error;
    explicit Grid(const int size[3]) : scene(size), waves(device_waves(scene.waves)) {}
    void step() {
      grid->step(kStepSeconds, wave_buffer, int(waves.padded.size()), waves.slots, waves.padded,
                 scene.drive);
    }
  };
  const int64_t cells = int64_t(size[0]) * size[1] * size[2];
  Grid& f = fixture<Grid>(
      std::string(width_one ? "grid/cl_w1/" : "grid/cl/") + std::to_string(cells), [&] {
        auto s = std::make_unique<Grid>(size);
        const GridScene& sc = s->scene;
        s->grid = std::make_unique<impl::WindGrid>(*rt, sc.def);
        s->grid->set_always_run(true);
        s->grid->set_solids(sc.solids);
        s->wave_buffer = upload(*rt, CL_MEM_READ_ONLY, s->waves.padded.data(),
                                s->waves.padded.size() * sizeof(BoreasGpuWave));
        for (int i = 0; i < kWarmSteps; ++i) s->step();
        // Once: one step of the kernel against the native twin from the same grid.
        std::vector<float> before = s->grid->read_planes();
        s->step();
        std::vector<float> got = s->grid->read_planes();
        BoreasGpuGrid g = s->grid->gpu();
        std::vector<float> slab(size_t(g.nx) * g.nz * 2), want(before.size());
        native_sine_slab(slab.data(), sc.waves.data(), int(sc.waves.size()), g);
        std::vector<float> steady = sc.native_steady_field(g);
        native_grid_step(before.data(), want.data(), slab.data(), steady.data(),
                         sc.drive.varying.data(), sc.varying_count(), g,
                         impl::grid_step_constants(sc.def, kStepSeconds, sc.varying_count()));
        s->error = disagreement("grid steps", max_difference(got, want));
        return s;
      });
  if (skipped_for(state, f.error)) return;
  auto launch = [&] {
    f.step();
    return f.grid->last_step_event();
  };
  warm_up(*rt, launch);
  time_cl(state, *rt, "BM_WindGridStep", cells, kBytesPerGridCell, launch);
}

void grid_step_native(benchmark::State& state, const int size[3]) {
  struct Grid : Fixture {
    GridScene scene;
    BoreasGpuGrid g{};
    BoreasGpuGridStep constants{};
    std::vector<float> cells[2];
    std::vector<float> slab;
    std::vector<float> steady;
    int current = 0;
    explicit Grid(const int size[3]) : scene(size) {}
    void step() {
      native_sine_slab(slab.data(), scene.waves.data(), int(scene.waves.size()), g);
      native_grid_step(cells[current].data(), cells[1 - current].data(), slab.data(), steady.data(),
                       scene.drive.varying.data(), scene.varying_count(), g, constants);
      current = 1 - current;
    }
  };
  const int64_t cells = int64_t(size[0]) * size[1] * size[2];
  Grid& f = fixture<Grid>("grid/native/" + std::to_string(cells), [&] {
    auto s = std::make_unique<Grid>(size);
    s->g = scene_gpu_grid(s->scene.def);
    const size_t n = size_t(cells);
    s->cells[0].assign(4 * n, 0.0f);
    for (size_t c = 0; c < n; ++c) {
      s->cells[0][3 * n + c] = s->scene.solids[c] ? 1.0f : 0.0f;
      s->g.solid_count += s->scene.solids[c] ? 1 : 0;
    }
    s->cells[1] = s->cells[0];
    s->slab.assign(size_t(s->g.nx) * s->g.nz * 2, 0.0f);
    s->constants = impl::grid_step_constants(s->scene.def, kStepSeconds, s->scene.varying_count());
    s->steady = s->scene.native_steady_field(s->g);
    for (int i = 0; i < kWarmSteps; ++i) s->step();
    return s;
  });
  time_native(state, "BM_WindGridStep", cells, kBytesPerGridCell, [&] { f.step(); });
}

}  // namespace

void register_wind_benchmarks() {
  for (int n : kCopySizes) {
    add("BM_CopyBandwidth/native/" + std::to_string(n), [n](auto& s) { copy_native(s, n); });
    add("BM_CopyBandwidth/cl/" + std::to_string(n), [n](auto& s) { copy_cl(s, n); });
  }
  for (int n : kSampleSizes) {
    add("BM_WindSineSum/native/" + std::to_string(n), [n](auto& s) { sine_sum_native(s, n); });
    add("BM_WindSineSum/cl/" + std::to_string(n), [n](auto& s) { sine_sum_cl(s, n); });
    add("BM_WindSineSum/cl_w1/" + std::to_string(n), [n](auto& s) { sine_sum_cl(s, n, 1); });
    add("BM_WindSineSum/cl_w8/" + std::to_string(n), [n](auto& s) { sine_sum_cl(s, n, 8); });
  }
  for (const auto& side : kSlabSides) {
    const int nx = side[0], nz = side[1];
    const std::string columns = std::to_string(int64_t(nx) * nz);
    add("BM_WindSineSlab/native/" + columns, [=](auto& s) { sine_slab_native(s, nx, nz); });
    add("BM_WindSineSlab/cl/" + columns, [=](auto& s) { sine_slab_cl(s, nx, nz); });
    add("BM_WindSineSlab/cl_w1/" + columns, [=](auto& s) { sine_slab_cl(s, nx, nz, 1); });
    add("BM_WindSineSlab/cl_w8/" + columns, [=](auto& s) { sine_slab_cl(s, nx, nz, 8); });
  }
  for (const auto& size : kGridSizes) {
    const std::string cells = std::to_string(int64_t(size[0]) * size[1] * size[2]);
    add("BM_WindGridStep/native/" + cells, [&size](auto& s) { grid_step_native(s, size); });
    add("BM_WindGridStep/cl/" + cells, [&size](auto& s) { grid_step_cl(s, size); });
    add("BM_WindGridStep/cl_w1/" + cells, [&size](auto& s) { grid_step_cl(s, size, true); });
  }
}

}  // namespace boreas::bench
