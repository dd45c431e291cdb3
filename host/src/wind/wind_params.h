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
boreas_flow_primitive_def checked_primitive(const boreas_flow_primitive_def& p,
                                            const std::string& where);
boreas_gust_def checked_gust(const boreas_gust_def& g, const std::string& where);
boreas_grid_def checked_grid(const boreas_grid_def& g, const std::string& where);
// A public wave array: where names the array and count_name its count in messages.
std::vector<WaveParams> checked_waves(const boreas_wave* waves, int count, const char* where,
                                      const char* count_name);

}  // namespace boreas::impl
