// boreas: force-field grid buffers and launches.
#include "wind/wind_grid.h"

#include <algorithm>
#include <cmath>

#include "errors.h"

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

WindGrid::WindGrid(Runtime& runtime, const boreas_grid_def& def) : runtime_(runtime), def_(def) {
  gpu_.origin_x = def.origin[0];
  gpu_.origin_y = def.origin[1];
  gpu_.origin_z = def.origin[2];
  gpu_.cell_size = def.cell_size;
  gpu_.nx = def.resolution[0];
  gpu_.ny = def.resolution[1];
  gpu_.nz = def.resolution[2];
  gpu_.solid_count = 0;
  cell_count_ = int64_t(gpu_.nx) * gpu_.ny * gpu_.nz;
  size_t bytes = static_cast<size_t>(cell_count_) * 4 * sizeof(float);
  for (cl::Buffer& b : cells_) {
    b = runtime_.buffer(CL_MEM_READ_WRITE, bytes);
    BOREAS_CL_CHECK(runtime_.queue().enqueueFillBuffer(b, 0.0f, 0, bytes));
  }
  slab_ = runtime_.buffer(CL_MEM_READ_WRITE, size_t(gpu_.nx) * gpu_.nz * 2 * sizeof(float));
  slab_kernel_ = runtime_.kernel("wind_sine_slab.cl", "boreas_wind_sine_slab");
  step_kernel_ = runtime_.kernel("wind_grid_step.cl", "boreas_wind_grid_step");
  solids_.assign(static_cast<size_t>(cell_count_), 0);
  BOREAS_CL_CHECK(runtime_.queue().finish());
}

void WindGrid::step(double dt, const cl::Buffer& waves, int wave_count,
                    const std::vector<BoreasGpuForcing>& forcing) {
  if (!forcing.empty()) active_ = true;
  if (!active_ && !always_run_) return;

  cl::CommandQueue& q = runtime_.queue();
  if (forcing.size() > forcing_capacity_ || forcing_() == nullptr) {
    forcing_capacity_ = std::max<size_t>(forcing.size(), 16);
    forcing_ = runtime_.buffer(CL_MEM_READ_ONLY, forcing_capacity_ * sizeof(BoreasGpuForcing));
  }
  if (!forcing.empty()) {
    // Blocking: the caller's vector may be gone before a non-blocking write would read it.
    BOREAS_CL_CHECK(q.enqueueWriteBuffer(forcing_, CL_TRUE, 0,
                                         forcing.size() * sizeof(BoreasGpuForcing), forcing.data()));
  }

  BOREAS_CL_CHECK(slab_kernel_.setArg(0, slab_));
  BOREAS_CL_CHECK(slab_kernel_.setArg(1, waves));
  BOREAS_CL_CHECK(slab_kernel_.setArg(2, wave_count));
  BOREAS_CL_CHECK(slab_kernel_.setArg(3, gpu_));
  BOREAS_CL_CHECK(q.enqueueNDRangeKernel(slab_kernel_, cl::NullRange,
                                         cl::NDRange(size_t(gpu_.nx), size_t(gpu_.nz))));

  BoreasGpuGridStep s = grid_step_constants(def_, dt, static_cast<int>(forcing.size()));
  int next = 1 - current_;
  BOREAS_CL_CHECK(step_kernel_.setArg(0, cells_[current_]));
  BOREAS_CL_CHECK(step_kernel_.setArg(1, cells_[next]));
  BOREAS_CL_CHECK(step_kernel_.setArg(2, slab_));
  BOREAS_CL_CHECK(step_kernel_.setArg(3, forcing_));
  BOREAS_CL_CHECK(step_kernel_.setArg(4, gpu_));
  BOREAS_CL_CHECK(step_kernel_.setArg(5, s));
  BOREAS_CL_CHECK(q.enqueueNDRangeKernel(
      step_kernel_, cl::NullRange, cl::NDRange(size_t(gpu_.nx), size_t(gpu_.ny), size_t(gpu_.nz)),
      cl::NullRange, nullptr, &last_event_));
  current_ = next;
}

std::vector<float> WindGrid::read() {
  std::vector<float> out(static_cast<size_t>(cell_count_) * 4);
  BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(cells_[current_], CL_TRUE, 0,
                                                     out.size() * sizeof(float), out.data()));
  return out;
}

void WindGrid::set_solids(const std::vector<uint8_t>& mask) {
  if (static_cast<int64_t>(mask.size()) != cell_count_)
    fail_argument("solid mask has " + std::to_string(mask.size()) + " cells, the grid has " +
                  std::to_string(cell_count_));
  std::vector<float> cells = read();
  int count = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    uint8_t solid = mask[i] ? 1 : 0;
    count += solid;
    if (solid != solids_[i]) {
      cells[4 * i + 0] = cells[4 * i + 1] = cells[4 * i + 2] = 0.0f;
    }
    cells[4 * i + 3] = solid ? 1.0f : 0.0f;
  }
  BOREAS_CL_CHECK(runtime_.queue().enqueueWriteBuffer(cells_[current_], CL_TRUE, 0,
                                                      cells.size() * sizeof(float), cells.data()));
  solids_.assign(mask.size(), 0);
  for (size_t i = 0; i < mask.size(); ++i) solids_[i] = mask[i] ? 1 : 0;
  gpu_.solid_count = count;
  if (count > 0) active_ = true;
}

}  // namespace boreas::impl
