// boreas scenes: loading and validating scene files. Everything is checked here, before a
// world exists, so a bad file never leaves a half-built world behind.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace boreas::render {

// Parses and validates scene JSON; source names it in errors. Relative paths of species
// files and meadow images are resolved against base_dir ("" leaves them relative to the
// working folder). A run seed (`boreas run --seed`) is mixed into every seed of the scene,
// a forest's before it plants its trees (scene_seed.h). Throws SceneError.
Scene load_scene_text(const std::string& text, const std::string& source,
                      const std::string& base_dir = "", const SceneLimits& limits = {},
                      std::optional<uint64_t> run_seed = std::nullopt);

// Reads path and loads it; errors name the path as given, and relative species files and
// images are found next to it.
Scene load_scene_file(const std::string& path, std::optional<uint64_t> run_seed = std::nullopt);

// The scene built into the boreas command (render/scenes/default.json).
Scene load_default_scene(std::optional<uint64_t> run_seed = std::nullopt);
const std::string& default_scene_text();

// The slice height must lie within the grid's vertical extent; returns the rule's text
// ("in [0, 32]") when it does not, "" when it does. Shared with the command-line checks.
std::string check_slice_height(const boreas_grid_def& grid, double height);

}  // namespace boreas::render
