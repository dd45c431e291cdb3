// boreas: the wind's changes, its part of a step, and what it hands the plants.
#include "wind/wind.h"

#include <cmath>
#include <string>

#include "errors.h"

namespace boreas::impl {

WindSettings checked_wind_settings(const boreas_world_def& def) {
  WindSettings s;
  s.grid = checked_grid(def.grid, "world_def.grid");
  s.waves = checked_waves(def.waves, def.wave_count, "world_def.waves", "world_def.wave_count");
  return s;
}

Wind::Wind(Runtime& runtime, const WindSettings& settings, uint32_t world_serial)
    : grid_(std::make_unique<WindGrid>(runtime, settings.grid)),
      wave_buffer_(runtime),
      flow_(world_serial),
      sample_points_(runtime) {
  waves_.set(settings.waves, 0.0, 0.0);
  wave_buffer_.upload(waves_, 0.0);
}

void Wind::set_waves(const boreas_wave* waves, int count, float blend_seconds, double now) {
  if (!std::isfinite(blend_seconds) || blend_seconds < 0.0f)
    fail_argument("blend_seconds must be finite and >= 0 (got " + std::to_string(blend_seconds) +
                  ")");
  std::vector<WaveParams> checked = checked_waves(waves, count, "waves", "count");
  WaveLayers next = waves_;
  next.set(std::move(checked), blend_seconds, now);
  try {
    wave_buffer_.upload(next, now);
  } catch (...) {
    rollback(now);
    throw;
  }
  waves_ = std::move(next);
}

boreas_primitive_id Wind::add_primitive(const boreas_flow_primitive_def& p, double now) {
  return flow_.add_primitive(checked_primitive(p, "primitive"), now);
}

boreas_gust_id Wind::add_gust(const boreas_gust_def& g, double now) {
  return flow_.add_gust(checked_gust(g, "gust"), now);
}

void Wind::add_solid_box(const float min[3], const float max[3]) {
  const SolidBox box = checked_solid_box(min, max);
  std::vector<uint8_t> mask = grid_->solids();
  lay_solid_box(grid_->gpu(), box, mask);
  solid_boxes_.reserve(solid_boxes_.size() + 1);  // a failure below leaves the list as it was
  grid_->set_solids(mask);
  solid_boxes_.push_back(box);
}

void Wind::set_solid_mask(const uint8_t* mask, int64_t count) {
  if (mask == nullptr && count == 0) {
    grid_->set_solids(std::vector<uint8_t>(static_cast<size_t>(grid_->cell_count()), 0));
    solid_boxes_.clear();
    return;
  }
  if (grid_->def().follow_focus)
    fail_argument(
        "the grid follows the focus (grid.follow_focus): its solids must be boxes "
        "(boreas_wind_add_solid_box), since a cell mask has no place once the grid "
        "moves; only NULL with count 0 (clear) is taken");
  if (mask == nullptr) fail_argument("solid mask is NULL with count > 0");
  if (count != grid_->cell_count())
    fail_argument("solid mask count must equal the grid's cell count " +
                  std::to_string(grid_->cell_count()) + " (got " + std::to_string(count) + ")");
  grid_->set_solids(std::vector<uint8_t>(mask, mask + count));
  solid_boxes_.clear();
}

void Wind::relay_solid_boxes() {
  std::vector<uint8_t> mask = grid_->solids();
  for (const SolidBox& box : solid_boxes_) lay_solid_box(grid_->gpu(), box, mask);
  if (mask != grid_->solids()) grid_->set_solids(mask);
}

void Wind::enqueue_step(double dt, double t, const std::vector<double>& focus) {
  pending_.emplace(Pending{flow_, waves_});
  FlowField& flow = pending_->flow;
  flow.expire(t);
  pending_->waves.prune(t);
  wave_buffer_.upload(pending_->waves, t);
  if (grid_->def().follow_focus && !focus.empty() && grid_->follow(focus[0], focus[2]))
    relay_solid_boxes();
  WindGrid::Forcing forcing;
  forcing.steady_version = flow.steady_version();
  // The primitives are copied only when they changed; the grid keeps their field.
  if (forcing.steady_version != grid_->steady_version()) forcing.steady = flow.steady();
  forcing.varying = flow.varying(t);
  grid_->step(dt, wave_buffer_.buffer(), wave_buffer_.count(), wave_buffer_.slots(),
              wave_buffer_.waves(), forcing);
}

void Wind::commit() {
  if (!pending_) return;
  flow_ = std::move(pending_->flow);
  waves_ = std::move(pending_->waves);
  pending_.reset();
}

void Wind::rollback(double now) noexcept {
  pending_.reset();
  try {
    wave_buffer_.upload(waves_, now);
  } catch (...) {
    // Best effort: the device is failing already, and the caller gets the first error.
  }
}

PlantWind Wind::plants() const {
  PlantWind wind;
  wind.waves = &wave_buffer_.buffer();
  wind.wave_count = wave_buffer_.count();
  wind.wave_slots = wave_buffer_.slots();
  wind.host_waves = &wave_buffer_.waves();
  wind.grid = &grid_->current();
  wind.grid_layout = grid_->gpu();
  wind.interpolated = grid_->def().wind_sampling == BOREAS_WIND_SAMPLING_INTERPOLATED;
  return wind;
}

void Wind::sample(const float* xyz, int count, float* force_xyz, bool as_plants) {
  // Exact (boreas_wind_sample), or as the plants' kernels sample it where as_plants.
  PlantWind wind = plants();
  wind.interpolated = wind.interpolated && as_plants;
  sample_points_.sample(wind, xyz, count, force_xyz);
}

}  // namespace boreas::impl
