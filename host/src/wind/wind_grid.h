// boreas: the force-field grid on the device (Endo et al. sec. 4.1), two buffers in
// ping-pong, updated by cl/wind_grid_step.cl; the scheme is described there.
#pragma once

#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "runtime/runtime.h"
#include "shared/wind_types.h"

namespace boreas::impl {

class WindGrid {
 public:
  WindGrid(Runtime& runtime, const boreas_grid_def& def);

  // What drives the grid in a step. steady: primitives that do not change between steps,
  // kept as a summed field on the device and rebuilt only when steady_version differs from
  // steady_version() (the caller need only fill steady then); varying: gusts at their
  // current strength, evaluated every step.
  struct Forcing {
    std::vector<BoreasGpuForcing> steady;
    uint64_t steady_version = 0;
    std::vector<BoreasGpuForcing> varying;
  };

  // One update over dt seconds with the sine sum of the given device waves (already
  // evaluated at the step's end time). Enqueued, not finished.
  // A grid that was never forced and has no solids is exactly zero and stays so: the
  // kernels are skipped then unless always_run is set (tests use it to check that claim),
  // but for the slab of sine sums where the plants read it (wind_sampling interpolated).
  // wave_slots: BOREAS_WAVE_SLOTS for the buffer's layout (see unrolled_slots).
  // host_waves: the waves buffer's host copy (the slab's phases at the grid's corner).
  void step(double dt, const cl::Buffer& waves, int wave_count, int wave_slots,
            const std::vector<BoreasGpuWave>& host_waves, const Forcing& forcing);

  // Replaces the solid mask (one byte per cell, nonzero = solid). Cells whose state
  // changes start from zero grid wind; solid cells read as zero wind at once.
  void set_solids(const std::vector<uint8_t>& mask);
  const std::vector<uint8_t>& solids() const { return solids_; }

  // A grid that follows the focus (def.follow_focus): moves by whole cells along x and z
  // so that (x, z) is near its middle, once it is more than an eighth of the width (at
  // least a cell) away. The wind where the old and new extents overlap is kept (copied
  // on the device), the new cells start calm and without solids; the steady forcing field
  // is rebuilt at the next step (steady_version() changes). Returns whether it moved: the
  // caller then lays its solids into the new cells (set_solids). Enqueued, not finished.
  bool follow(double x, double z);

  // The grid's cells, 4 floats each (xyz m/s, solid flag), blocking read.
  std::vector<float> read();
  // The device layout: 4 planes of cell_count floats (x, y, z, solid flag). The buffer
  // (current()) holds the step's slab of sine sums after them (wind_types.h).
  std::vector<float> read_planes();

  const boreas_grid_def& def() const { return def_; }
  BoreasGpuGrid gpu() const { return gpu_; }
  const cl::Buffer& current() const { return cells_[current_]; }
  int64_t cell_count() const { return cell_count_; }
  bool active() const { return active_; }
  uint64_t steady_version() const { return steady_version_; }
  void set_always_run(bool on) { always_run_ = on; }

  // Last step's kernel event (for benchmarks' profiling).
  const cl::Event& last_step_event() const { return last_event_; }

 private:
  Runtime& runtime_;
  boreas_grid_def def_;
  // The slab's wave phases at the grid's corner (wind_sine_slab.cl), and their host copy.
  cl::Buffer slab_phases_;
  size_t slab_phase_capacity_ = 0;
  std::vector<float> slab_phases_host_;
  double first_origin_[2];     // x and z where the grid was made, m
  int64_t moved_[2] = {0, 0};  // cells moved since then along x and z (follow)
  BoreasGpuGrid gpu_{};
  int64_t cell_count_ = 0;
  cl::Buffer cells_[2];
  int current_ = 0;
  void build_steady_field(const std::vector<BoreasGpuForcing>& steady);
  void shift_cells(int64_t di, int64_t dk);

  cl::Buffer forcing_;  // varying forcing, padded to its slot count
  size_t forcing_capacity_ = 0;
  cl::Buffer steady_field_;  // 4 planes: summed target x, y, z and coverage maximum
  uint64_t steady_version_ = ~uint64_t(0);
  bool has_steady_ = false;
  std::vector<uint8_t> solids_;
  bool active_ = false;
  bool always_run_ = false;
  cl::Event last_event_;
};

// The device form of a grid definition (no solids yet).
BoreasGpuGrid gpu_grid(const boreas_grid_def& def);

// The per-step constants of the scheme, computed in double (shared with the reference).
BoreasGpuGridStep grid_step_constants(const boreas_grid_def& def, double dt, int forcing_count);

}  // namespace boreas::impl
