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

// Limits of the scene's arrays.
constexpr int kMaxTrees = 1024;

// A tree the world grows (the scene's "trees" array). def holds the library's defaults
// with the scene's values; def.species is left null and set from species when the tree is
// added, so a Scene can be copied freely.
struct SceneTree {
  // A built-in species name, or a species file (.xml or .json) with a relative path
  // already resolved against the scene file's folder.
  std::string species;
  boreas_tree_def def = boreas_default_tree_def();
};

struct Scene {
  std::string name = "unnamed";
  std::string source;  // the file, for errors raised once the world is built
  std::string description;
  std::optional<std::string> device;  // unset: the best device (or BOREAS_DEVICE)
  boreas_grid_def grid = boreas_default_grid_def();
  std::vector<boreas_wave> waves;
  std::vector<boreas_flow_primitive> primitives;
  std::vector<boreas_gust> gusts;
  std::vector<SolidBox> obstacles;
  std::vector<SceneTree> trees;
  RunSettings run;
};

}  // namespace boreas::render
