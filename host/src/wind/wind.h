// boreas: the wind of a world, one object: the sine-sum wave sets and their blends, the
// force-field grid with its flow primitives, gusts and solids, and sampling at points. It
// hands the plants what their kernels read (plants()).
//
// Its part of a world's step (stages 1-5 of world.h), enqueued by enqueue_step:
//  1. expired primitives and gusts are removed, faded wave sets dropped (on copies);
//  2. the waves' device copy is rewritten for the step's end time;
//  3. a grid that follows the focus moves when the focus has left its middle (its wind
//     copied where the extents overlap, solid boxes laid into the new cells); when a flow
//     primitive came or went, or the grid moved, the steady forcing field is rebuilt;
//  4-5. the grid steps (the slab of sine sums per column, then the cells: wind_grid.h).
// The copies become the wind's state at commit(), once the device has finished the whole
// step; after a failure rollback() puts the waves' device copy back.
//
// Every change checks all its arguments before it changes anything.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "boreas/boreas.h"
#include "runtime/runtime.h"
#include "wind/flow_field.h"
#include "wind/plant_wind.h"
#include "wind/sample_points.h"
#include "wind/solid_boxes.h"
#include "wind/wave_buffer.h"
#include "wind/wave_layers.h"
#include "wind/wind_grid.h"
#include "wind/wind_params.h"

namespace boreas::impl {

// A world def's wind, checked (names world_def.grid and world_def.waves[i] in errors).
struct WindSettings {
  boreas_grid_def grid{};
  std::vector<WaveParams> waves;
};
WindSettings checked_wind_settings(const boreas_world_def& def);

class Wind {
 public:
  // world_serial: the world's number, in every id the wind issues (slot_map.h).
  Wind(Runtime& runtime, const WindSettings& settings, uint32_t world_serial);

  // Changes at world time `now` (s).
  void set_waves(const boreas_wave* waves, int count, float blend_seconds, double now);
  boreas_primitive_id add_primitive(const boreas_flow_primitive_def& p, double now);
  boreas_gust_id add_gust(const boreas_gust_def& g, double now);
  void remove(boreas_primitive_id id) { flow_.remove(id); }
  void remove(boreas_gust_id id) { flow_.remove(id); }
  void add_solid_box(const float min[3], const float max[3]);
  void set_solid_mask(const uint8_t* mask, int64_t count);
  // The solid boxes as given (boreas_wind_add_solid_box), in the order added.
  const std::vector<SolidBox>& solid_boxes() const { return solid_boxes_; }

  // The step from time t - dt to t (the stages above), enqueued; focus: the world's focus
  // points (xyz packed), the first of which a following grid follows.
  void enqueue_step(double dt, double t, const std::vector<double>& focus);
  void commit();
  // After a failed step: the waves' device copy as committed, at the committed time `now`.
  void rollback(double now) noexcept;

  // What the plants' kernels read, for the step just enqueued (or the last one).
  PlantWind plants() const;

  // The wind at count points (xyz packed), blocking, exact (boreas_wind_sample).
  // as_plants: as the plants' kernels read it (grid.wind_sampling), for tests. That reads
  // the last step's slab: right only between a step and the next set_waves, and all zero
  // (the sine sums missing) before the first step.
  void sample(const float* xyz, int count, float* force_xyz, bool as_plants = false);

  WindGrid& grid() { return *grid_; }
  const WindGrid& grid() const { return *grid_; }
  const WaveLayers& wave_layers() const { return waves_; }

 private:
  // Lays every solid box into the grid's cells again (after the grid moved).
  void relay_solid_boxes();

  std::unique_ptr<WindGrid> grid_;
  WaveLayers waves_;
  WaveBuffer wave_buffer_;
  FlowField flow_;
  // Solid boxes as given, for a grid that moves; cleared by set_solid_mask.
  std::vector<SolidBox> solid_boxes_;
  SamplePoints sample_points_;
  // The step's copies, until commit.
  struct Pending {
    FlowField flow;
    WaveLayers waves;
  };
  std::optional<Pending> pending_;
};

}  // namespace boreas::impl
