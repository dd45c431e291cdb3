// boreas tests: shared helpers — a temporary folder, a runtime on the test device, worlds
// built from the public defaults, the bytes a world moves and a vector's raw bytes, and the
// check that a call fails with a given error.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

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

// The default grid resized to nx x ny x nz cells of `cell` m, centred on the origin in x
// and z, from y = 0 up.
inline boreas_grid_def centered_grid(int nx, int ny, int nz, float cell) {
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -0.5f * float(nx) * cell;
  g.origin[1] = 0.0f;
  g.origin[2] = -0.5f * float(nz) * cell;
  g.cell_size = cell;
  g.resolution[0] = nx;
  g.resolution[1] = ny;
  g.resolution[2] = nz;
  return g;
}

// A small grid (cheap steps) that nothing forces: its part of the wind stays exactly zero,
// so a world's wind is its sine sum alone.
inline boreas_grid_def calm_grid() { return centered_grid(4, 2, 4, 10.0f); }

// A vortex about the vertical through the origin (4 m/s at `radius`): a steady primitive,
// so the world's grid is stepped.
inline void add_vortex(impl::World& world, float radius) {
  boreas_flow_primitive_def v = boreas_default_flow_primitive_def();
  v.type = BOREAS_FLOW_VORTEX;
  v.direction[1] = 1.0f;
  v.radius = radius;
  v.strength = 4.0f;
  world.wind().add_primitive(v, world.time());
}

// A strong travelling wave across the ground, off the x axis: 9 m/s, 25 m long, 7 m/s,
// sharpness 2 (trees bend visibly within a second).
inline boreas_wave windy_wave() {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = 1.0f;
  w.direction[1] = 0.4f;
  w.amplitude = 9.0f;
  w.wavelength = 25.0f;
  w.speed = 7.0f;
  w.sharpness = 2.0f;
  return w;
}

inline boreas_wave steady_wave(float dx, float dz, float amplitude) {
  boreas_wave w = boreas_default_wave();
  w.direction[0] = dx;
  w.direction[1] = dz;
  w.amplitude = amplitude;
  w.sharpness = 0.0f;
  return w;
}

// A world on calm_grid() whose definition holds this one wave: its wind is that wave alone.
inline std::unique_ptr<impl::World> make_world_with_wave(const boreas_wave& wave) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = calm_grid();
  def.waves = &wave;
  def.wave_count = 1;
  return std::make_unique<impl::World>(def);
}

// The bytes the world's runtime has moved between host and device so far (uploaded and read
// back; copies on the device are left out): counters that machine noise cannot blur.
inline uint64_t transfer_bytes(impl::World& world) {
  const impl::Runtime::Traffic& t = world.runtime().traffic();
  return t.uploaded + t.read_back;
}

// A vector's raw bytes, for comparisons bit for bit.
template <typename T>
std::vector<unsigned char> bytes_of(const std::vector<T>& v) {
  std::vector<unsigned char> out(v.size() * sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), v.data(), out.size());
  return out;
}

// Everything a generated tree shows, branches then leaves, as raw bytes.
inline std::vector<unsigned char> tree_bytes(impl::World& world, boreas_tree_id id) {
  std::vector<unsigned char> out = bytes_of(world.tree_branches(id));
  std::vector<unsigned char> leaves = bytes_of(world.tree_leaves(id));
  out.insert(out.end(), leaves.begin(), leaves.end());
  return out;
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
