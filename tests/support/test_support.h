// boreas tests: shared helpers — a temporary folder, a runtime on the test device, worlds
// built from the public defaults, and the check that a call fails with a given error.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "boreas/boreas.h"
#include "runtime/runtime.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"
#include "world.h"

namespace boreas::test {

// A world with the given grid (the library's default otherwise) and no waves.
inline std::unique_ptr<impl::World> make_world(const boreas_grid_def* grid = nullptr) {
  boreas_world_def def = boreas_default_world_def();
  if (grid) def.grid = *grid;
  return std::make_unique<impl::World>(def);
}

// A small grid (cheap steps) that nothing forces: its part of the wind stays exactly zero,
// so a world's wind is its sine sum alone.
inline boreas_grid_def calm_grid() {
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -20.0f;
  g.origin[1] = 0.0f;
  g.origin[2] = -20.0f;
  g.cell_size = 10.0f;
  g.resolution[0] = 4;
  g.resolution[1] = 2;
  g.resolution[2] = 4;
  return g;
}

inline boreas_wave steady_wave(float dx, float dz, float amplitude) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = dx;
  w.direction[1] = dz;
  w.amplitude = amplitude;
  w.sharpness = 0.0f;
  return w;
}

// Sets an environment variable for one scope and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) {
      had_ = true;
      old_ = old;
    }
    if (value)
      setenv(name, value, 1);
    else
      unsetenv(name);
  }
  ~ScopedEnv() {
    if (had_)
      setenv(name_.c_str(), old_.c_str(), 1);
    else
      unsetenv(name_.c_str());
  }

 private:
  std::string name_;
  std::string old_;
  bool had_ = false;
};

}  // namespace boreas::test
