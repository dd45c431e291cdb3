// boreas: the kernel defines of the wind the plants read.
#include "wind/plant_wind.h"

#include "runtime/kernel_defines.h"

namespace boreas::impl {

std::string PlantWind::defines() const {
  return slot_define("BOREAS_WAVE_SLOTS", wave_slots) +
         (interpolated ? slot_define("BOREAS_WIND_INTERPOLATED", 1) : std::string());
}

}  // namespace boreas::impl
