// render tests: the SceneError that loading a scene's text throws, for the scene loader's
// tests of mistakes (scene_loader_test, scene_trees_test, scene_underbrush_test,
// scene_forest_test).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "scene/scene_error.h"
#include "scene/scene_loader.h"

namespace boreas::render::testing {

// The SceneError load_scene_text(text, "s.json", base_dir) throws, or a failure when it
// throws none. base_dir as load_scene_text's: "" leaves species files and images relative
// to the working folder.
inline SceneError error_for(const std::string& text, const std::string& base_dir = "") {
  try {
    load_scene_text(text, "s.json", base_dir);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << text;
  return SceneError("", "", "");
}

}  // namespace boreas::render::testing
