// boreas: force-field grid buffers and launches.
#include "wind/wind_grid.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "runtime/kernel_defines.h"
#include "runtime/launch.h"
#include "wind/plant_wind.h"
#include "wind/wind_params.h"

namespace boreas::impl {

BoreasGpuGridStep grid_step_constants(const boreas_grid_def& def, double dt, int forcing_count) {
  double h = def.cell_size;
  BoreasGpuGridStep s{};
  s.dt_over_cell = static_cast<float>(dt / h);
  s.diffusion_mix = static_cast<float>(-std::expm1(-6.0 * def.diffusion * dt / (h * h)));
  s.decay_factor = static_cast<float>(std::exp(-def.decay_rate * dt));
  s.drive_exponent = static_cast<float>(dt / def.response_time / std::log(2.0));
  s.forcing_count = forcing_count;
  return s;
}

BoreasGpuGrid gpu_grid(const boreas_grid_def& def) {
  BoreasGpuGrid g{};
  g.origin_x = def.origin[0];
  g.origin_y = def.origin[1];
  g.origin_z = def.origin[2];
  g.cell_size = def.cell_size;
  g.nx = def.resolution[0];
  g.ny = def.resolution[1];
  g.nz = def.resolution[2];
  g.solid_count = 0;
  g.fade_per_cell = def.edge_fade > 0.0f ? 1.0f / def.edge_fade : 1e30f;
  return g;
}

WindGrid::WindGrid(Runtime& runtime, const boreas_grid_def& def)
    : runtime_(runtime),
      def_(def),
      first_origin_{def.origin[0], def.origin[2]},
      gpu_(gpu_grid(def)) {
  cell_count_ = int64_t(gpu_.nx) * gpu_.ny * gpu_.nz;
  // The 4 planes and the slab of sine sums after them (wind_types.h).
  size_t bytes = static_cast<size_t>(boreas_grid_buffer_floats(gpu_)) * sizeof(float);
  for (cl::Buffer& b : cells_) {
    b = runtime_.buffer(CL_MEM_READ_WRITE, bytes, "wind grid cells");
    BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(b, 0.0f, 0, bytes));
  }
  solids_.assign(static_cast<size_t>(cell_count_), 0);
  BOREAS_CL_CHECK(runtime_.queue().finish());
}

namespace {

// The padding of forcing lists: a primitive that reaches no cell (far away, radius 1 m,
// strength 0): coverage 0, velocity 0.
BoreasGpuForcing silent_forcing() {
  BoreasGpuForcing silent{};
  silent.pos_x = silent.pos_y = silent.pos_z = 1e18f;
  silent.radius = 1.0f;
  silent.dir_x = 1.0f;
  silent.uniform_weight = 1.0f;
  return silent;
}

}  // namespace

void WindGrid::build_steady_field(const std::vector<BoreasGpuForcing>& steady) {
  has_steady_ = !steady.empty();
  if (!has_steady_) return;
  std::vector<BoreasGpuForcing> list = steady;
  int slots = pad_to_slots(list, silent_forcing());
  cl::CommandQueue& q = runtime_.queue();
  if (steady_field_() == nullptr) {
    steady_field_ =
        runtime_.buffer(CL_MEM_READ_WRITE, static_cast<size_t>(cell_count_) * 4 * sizeof(float),
                        "steady forcing field");
  }
  cl::Buffer primitives =
      runtime_.buffer(CL_MEM_READ_ONLY, list.size() * sizeof(BoreasGpuForcing), "flow primitives");
  // Blocking: list is gone when this returns.
  BOREAS_CL_CHECK(q.enqueueWriteBuffer(primitives, CL_TRUE, 0,
                                       list.size() * sizeof(BoreasGpuForcing), list.data()));
  cl::Kernel& kernel = runtime_.kernel("wind_forcing_field.cl", "boreas_wind_forcing_field",
                                       slot_define("BOREAS_FORCING_SLOTS", slots));
  launch(runtime_, kernel, Items(size_t(gpu_.nx), size_t(gpu_.ny), size_t(gpu_.nz)), steady_field_,
         primitives, static_cast<int>(list.size()), gpu_);
}

void WindGrid::step(double dt, const cl::Buffer& waves, int wave_count, int wave_slots,
                    const std::vector<BoreasGpuWave>& host_waves, const Forcing& drive) {
  if (drive.steady_version != steady_version_) {
    build_steady_field(drive.steady);
    steady_version_ = drive.steady_version;
  }
  if (has_steady_ || !drive.varying.empty()) active_ = true;
  const size_t w = static_cast<size_t>(runtime_.simd_width());
  cl::CommandQueue& q = runtime_.queue();
  // The sine sums per column, into the tail of the buffer that is current after the step.
  auto enqueue_slab = [&](const cl::Buffer& into) {
    // The waves' phases at the grid's corner, in double (wind_sine_slab.cl).
    slab_phases_host_.assign(size_t(std::max(wave_count, 1)), 0.0f);
    wave_phases_at(host_waves.data(), std::min(wave_count, int(host_waves.size())), gpu_.origin_x,
                   gpu_.origin_z, slab_phases_host_.data());
    if (slab_phases_host_.size() > slab_phase_capacity_ || slab_phases_() == nullptr) {
      const size_t capacity = std::max<size_t>(slab_phases_host_.size(), 16);
      slab_phases_ = runtime_.buffer(CL_MEM_READ_ONLY, capacity * sizeof(float), "slab phases");
      slab_phase_capacity_ = capacity;
    }
    BOREAS_CL_CHECK(q.enqueueWriteBuffer(slab_phases_, CL_TRUE, 0,
                                         slab_phases_host_.size() * sizeof(float),
                                         slab_phases_host_.data()));
    cl::Kernel& kernel = runtime_.kernel("wind_sine_slab.cl", "boreas_wind_sine_slab",
                                         slot_define("BOREAS_WAVE_SLOTS", wave_slots));
    // One work-item per simd_width() neighbouring columns of a row (wind_sine_slab.cl).
    launch(runtime_, kernel, Items(size_t(gpu_.nx), size_t(gpu_.nz)).per_work_item(w), into, waves,
           wave_count, slab_phases_, gpu_);
  };
  if (!active_ && !always_run_) {
    // An idle grid stays zero; the plants still read the slab when they interpolate.
    if (def_.wind_sampling == BOREAS_WIND_SAMPLING_INTERPOLATED) enqueue_slab(cells_[current_]);
    return;
  }

  std::vector<BoreasGpuForcing> forcing = drive.varying;
  int forcing_slots = pad_to_slots(forcing, silent_forcing());

  if (forcing.size() > forcing_capacity_ || forcing_() == nullptr) {
    // The capacity changes only once the buffer is there: a refused allocation keeps both.
    const size_t capacity = std::max<size_t>(forcing.size(), 16);
    forcing_ =
        runtime_.buffer(CL_MEM_READ_ONLY, capacity * sizeof(BoreasGpuForcing), "grid forcing");
    forcing_capacity_ = capacity;
  }
  if (!forcing.empty()) {
    // Blocking: the vector is gone before a non-blocking write would read it.
    BOREAS_CL_CHECK(q.enqueueWriteBuffer(
        forcing_, CL_TRUE, 0, forcing.size() * sizeof(BoreasGpuForcing), forcing.data()));
  }
  // The kernel takes a buffer argument either way; without steady primitives it is unread.
  const cl::Buffer& steady = has_steady_ ? steady_field_ : forcing_;

  cl::Kernel& step_kernel =
      runtime_.kernel("wind_grid_step.cl", "boreas_wind_grid_step",
                      slot_define("BOREAS_STEADY_FORCING", has_steady_ ? 1 : 0) +
                          slot_define("BOREAS_FORCING_SLOTS", forcing_slots) +
                          slot_define("BOREAS_GRID_SOLIDS", gpu_.solid_count > 0 ? 1 : 0));
  int next = 1 - current_;
  // The step reads the slab from its output buffer's tail.
  enqueue_slab(cells_[next]);
  BoreasGpuGridStep s = grid_step_constants(def_, dt, static_cast<int>(forcing.size()));
  // One work-item per simd_width() neighbouring cells of a row (wind_grid_step.cl).
  last_event_ = launch(runtime_, step_kernel,
                       Items(size_t(gpu_.nx), size_t(gpu_.ny), size_t(gpu_.nz)).per_work_item(w),
                       cells_[current_], cells_[next], forcing_, steady, gpu_, s);
  current_ = next;
}

std::vector<float> WindGrid::read_planes() {
  std::vector<float> planes(static_cast<size_t>(cell_count_) * 4);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(cells_[current_], CL_TRUE, 0,
                                                     planes.size() * sizeof(float), planes.data()));
  return planes;
}

std::vector<float> WindGrid::read() {
  std::vector<float> planes = read_planes();
  std::vector<float> out(planes.size());
  size_t n = static_cast<size_t>(cell_count_);
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 4; ++a) out[4 * i + a] = planes[a * n + i];
  return out;
}

void WindGrid::set_solids(const std::vector<uint8_t>& mask) {
  if (static_cast<int64_t>(mask.size()) != cell_count_)
    fail_argument("solid mask has " + std::to_string(mask.size()) + " cells, the grid has " +
                  std::to_string(cell_count_));
  std::vector<float> planes = read_planes();
  size_t n = static_cast<size_t>(cell_count_);
  int count = 0;
  for (size_t i = 0; i < n; ++i) {
    uint8_t solid = mask[i] ? 1 : 0;
    count += solid;
    if (solid != solids_[i]) planes[i] = planes[n + i] = planes[2 * n + i] = 0.0f;
    planes[3 * n + i] = solid ? 1.0f : 0.0f;
  }
  BOREAS_CL_CHECK(runtime_.queue().enqueueWriteBuffer(
      cells_[current_], CL_TRUE, 0, planes.size() * sizeof(float), planes.data()));
  for (size_t i = 0; i < n; ++i) solids_[i] = mask[i] ? 1 : 0;
  gpu_.solid_count = count;
  if (count > 0) active_ = true;
}

}  // namespace boreas::impl
