// boreas command: `boreas export-animation scene.json --frames N --out forest.glb`, which
// builds a scene's world, steps it at the scene's frame rate and writes its trees as an
// animated glTF binary (boreas_world_export_animation): trees skinned, meadows and imported
// trees as morph targets.
#pragma once

#include <optional>
#include <string>

namespace boreas::render {

struct AnimationOptions {
  std::optional<std::string> scene_path;  // unset: the built-in default scene
  std::optional<int> frames;              // keys; unset: the scene's frames
  std::string out;                        // required: .glb
  int max_level = -1;                     // joints down to this branch level; -1: the library's
  int segments = -1;                      // joints per branch minus one; -1: the library's
  bool no_leaves = false;
  std::string meadows = "clumps";         // clumps, exact or none (then not even planted)
  int clumps = 4;                         // per meadow, with meadows "clumps"
  std::optional<float> clump_size;        // m; unset: the library's
  std::optional<float> morph_tolerance;   // m; unset: the library's
  float warmup = 2.0f;                    // s stepped before the first key (README, "Animated glTF")
  std::optional<std::string> device;
  bool quiet = false;
};

// Throws CliError, SceneError or boreas::Error; main() reports them.
int run_animation_command(const AnimationOptions& options);

}  // namespace boreas::render
