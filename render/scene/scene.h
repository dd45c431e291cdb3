// boreas scenes: what a scene file describes, as plain structs the loader fills in and the
// boreas command turns into a world. Units and defaults are listed in render/SCENES.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// An axis-aligned obstacle; every grid cell whose center lies inside becomes solid.
struct SolidBox {
  float min[3] = {0.0f, 0.0f, 0.0f};  // m
  float max[3] = {0.0f, 0.0f, 0.0f};  // m
};

// Limits of the run settings, shared by the scene loader and the command line.
constexpr int kMaxFrames = 100000;
constexpr int kMaxStepsPerFrame = 100000;
constexpr double kMaxDt = 3600.0;    // s, the library's bound on one step
constexpr int kMinImageSide = 16;    // pixels
constexpr int kMaxImageSide = 4096;  // pixels; a 4096x4096 frame already takes ~600 MB

// How `boreas run` films the scene; command-line options override these.
struct RunSettings {
  int frames = 24;
  int steps_per_frame = 4;
  float dt = 1.0f / 24.0f;    // s per step
  float slice_height = 2.0f;  // m; the loader puts it 2 m above the grid floor unless given
  int image_width = 384;      // pixels
  int image_height = 384;     // pixels
  float color_max = 0.0f;     // m/s at the top of the color map; 0 picks it from the scene
};

struct Scene {
  std::string name = "unnamed";
  std::string description;
  std::optional<std::string> device;  // unset: the best device (or BOREAS_DEVICE)
  boreas_grid_def grid = boreas_default_grid_def();
  std::vector<boreas_wave> waves;
  std::vector<boreas_flow_primitive> primitives;
  std::vector<boreas_gust> gusts;
  std::vector<SolidBox> obstacles;
  RunSettings run;
};

}  // namespace boreas::render
