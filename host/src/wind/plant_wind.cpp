// boreas: the kernel defines of the wind the plants read.
#include "wind/plant_wind.h"

#include <cmath>

#include "runtime/kernel_defines.h"

namespace boreas::impl {

std::string PlantWind::defines() const {
  return slot_define("BOREAS_WAVE_SLOTS", wave_slots) +
         (interpolated ? slot_define("BOREAS_WIND_INTERPOLATED", 1) : std::string());
}

void PlantWind::phases_at(double x, double z, float* out) const {
  wave_phases_at(host_waves->data(), wave_count, x, z, out);
}

void wave_phases_at(const BoreasGpuWave* waves, int count, double x, double z, float* out) {
  // The wave's float direction and wavenumber, as the kernel multiplies them, so that the
  // phase at a point relative to the origin adds up to the world point's phase.
  for (int i = 0; i < count; ++i) {
    const BoreasGpuWave& w = waves[i];
    const double u = double(w.phase_cycles) +
                     (double(w.dir_x) * x + double(w.dir_z) * z) * double(w.cycles_per_meter);
    const float f = float(u - std::floor(u));
    out[i] = f < 1.0f ? f : 0.0f;  // a value just below 1 may round up to it
  }
}

}  // namespace boreas::impl
