// boreas tests: a small windy world through the public C API only (for tests that link
// the shared library, as an engine would).
#pragma once

#include "boreas/boreas.h"

namespace boreas::test {

// A world on a coarse 8 x 4 x 8 grid with one default sine wave of `amplitude` m/s. On a
// failure *out stays NULL and boreas_last_error says why.
inline boreas_status create_small_windy_world(boreas_world* out,
                                              float amplitude = boreas_default_wave().amplitude) {
  boreas_world_def def = boreas_default_world_def();
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 4;
  boreas_status s = boreas_world_create(&def, out);
  if (s != BOREAS_OK) return s;
  boreas_wave wave = boreas_default_wave();
  wave.amplitude = amplitude;
  s = boreas_wind_set_waves(*out, &wave, 1, 0.0f);
  if (s != BOREAS_OK) {
    boreas_world_destroy(*out);
    *out = nullptr;
  }
  return s;
}

}  // namespace boreas::test
