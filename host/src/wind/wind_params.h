// boreas: checked, normalized wind parameters, converted from the public structs.
// Every check names the field and the value, e.g. "waves[2].wavelength must be > 0 (got -1)".
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::impl {

// One sine wave in double precision, direction normalized.
struct WaveParams {
  double dir_x = 1.0;
  double dir_z = 0.0;
  double amplitude = 0.0;   // m/s
  double wavelength = 1.0;  // m
  double speed = 0.0;       // m/s
  double sharpness = 0.0;
  double wavenumber() const;  // 2 pi / wavelength, rad/m
  double phase_rate() const;  // -speed * wavenumber, rad/s: crests move along +D at speed
};

WaveParams checked_wave(const boreas_wave& wave, const std::string& where);
boreas_flow_primitive checked_primitive(const boreas_flow_primitive& p, const std::string& where);
boreas_gust checked_gust(const boreas_gust& g, const std::string& where);
boreas_grid_def checked_grid(const boreas_grid_def& g, const std::string& where);

// Slots a kernel sums over for count items: the next of 0, 1, 2, 4, 8, 16, padded with
// silent items, so its loop unrolls and vectorizes on CPUs; -1 (a plain loop) beyond 16.
int unrolled_slots(int count);

// Pads items with silent ones up to unrolled_slots(items.size()) and returns that count.
template <typename T>
int pad_to_slots(std::vector<T>& items, const T& silent) {
  int slots = unrolled_slots(static_cast<int>(items.size()));
  if (slots > 0) items.resize(static_cast<size_t>(slots), silent);
  return slots;
}

// "#define NAME slots\n" for a kernel build.
std::string slot_define(const char* name, int slots);

}  // namespace boreas::impl
