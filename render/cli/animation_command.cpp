// boreas command: `boreas export-animation`. The options are checked before the scene is
// built; the library checks the rest (its errors name the field) before its first step.
#include "cli/animation_command.h"

#include <filesystem>
#include <iostream>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"
#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {

int run_animation_command(const AnimationOptions& options) {
  if (std::filesystem::path(options.out).extension() != ".glb")
    throw CliError(kExitBadInput, "--out must name a .glb file (got '" + options.out + "')");
  Scene scene = options.scene_path ? load_scene_file(*options.scene_path) : load_default_scene();
  // Meadows as clumps by default: exactly, their strips' motion is most of a file (the
  // default scene's four are 313 MB at 20 keys, bench/RESULTS.md); none: not planted.
  if (options.meadows != "clumps" && options.meadows != "exact" && options.meadows != "none")
    throw CliError(kExitBadInput, "--meadows must be clumps, exact or none (got '" + options.meadows + "')");
  if (options.meadows == "clumps" && (options.clumps < 1 || options.clumps > BOREAS_ANIMATION_MAX_CLUMPS))
    throw CliError(kExitBadInput, "--clumps must be 1.." + std::to_string(BOREAS_ANIMATION_MAX_CLUMPS) +
                                      " (got " + std::to_string(options.clumps) + ")");
  if (options.meadows == "none") scene.meadows.clear();
  boreas_animation_def def = boreas_default_animation_def();
  if (options.meadows == "clumps") def.meadow_clumps = options.clumps;
  if (options.clump_size) def.clump_size = *options.clump_size;
  def.frames = options.frames.value_or(scene.run.frames);
  def.steps_per_frame = scene.run.steps_per_frame;
  def.frame_time = scene.run.dt * float(scene.run.steps_per_frame);  // the scene's frame rate
  if (options.max_level >= 0) def.skin.max_level = options.max_level;
  if (options.segments >= 0) def.skin.segments = options.segments;
  def.leaves = options.no_leaves ? 0 : 1;
  if (def.frames < 1 || def.frames > BOREAS_ANIMATION_MAX_FRAMES)
    throw CliError(kExitBadInput, "--frames must be 1.." +
                                      std::to_string(BOREAS_ANIMATION_MAX_FRAMES) + " (got " +
                                      std::to_string(def.frames) + ")");

  if (options.morph_tolerance) def.morph_tolerance = *options.morph_tolerance;
  // Keys from a sway, not from the first bend out of rest (which a clump's loop would
  // have to undo); the library checks the range.
  def.warmup = options.warmup;

  SceneIds ids;
  boreas::World world = make_world(scene, options.device, &ids);
  def.meadows = ids.meadows.data();
  def.meadow_count = int(ids.meadows.size());
  def.mesh_trees = ids.mesh_trees.data();
  def.mesh_tree_count = int(ids.mesh_trees.size());
  const std::filesystem::path parent = std::filesystem::path(options.out).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  world.export_animation(ids.trees, options.out, def);
  if (!options.quiet)
    std::cout << "wrote " << options.out << ": " << ids.trees.size() << " trees, "
              << ids.meadows.size() << " meadows, " << ids.mesh_trees.size() << " imported trees, " << def.frames
              << " keys at " << 1.0 / def.frame_time << " frames/s, "
              << std::filesystem::file_size(options.out) << " bytes\n";
  return kExitOk;
}

}  // namespace boreas::render
