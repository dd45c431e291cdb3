// render tests: small scenes for the end-to-end tests, 64 m square grids drawn at one pixel
// per meter so pixel positions are easy to reason about.
#pragma once

#include <string>

namespace boreas::render::testing {

// Grid x, z in [-32, 32] m, y in [0, 16] m; 2 frames of 64x64 pixels unless changed.
inline std::string scene_json(const std::string& wind, int frames = 2, int size = 64) {
  return R"({
  "name": "tiny",
  "world": {"grid": {"origin": [-32, 0, -32], "cell_size": 2, "resolution": [32, 8, 32]}},
  "wind": )" +
         wind + R"(,
  "run": {"frames": )" +
         std::to_string(frames) + R"(, "steps_per_frame": 2, "dt": 0.05,
          "slice_height": 2, "image_size": [)" +
         std::to_string(size) + ", " + std::to_string(size) + R"(], "color_max": 8}
})";
}

// A steady 4 m/s wind (sharpness 0) with a 16 m box in the middle: x, z in [-8, 8] m,
// which is pixels [24, 40) in a 64x64 frame.
inline std::string obstacle_scene() {
  return scene_json(R"({
    "waves": [{"direction": [1, 0.5], "amplitude": 4, "wavelength": 30, "speed": 0, "sharpness": 0}],
    "obstacles": [{"min": [-8, 0, -8], "max": [8, 6, 8]}]
  })");
}

// Moving, sharp-crested waves: the slice changes from frame to frame.
inline std::string moving_scene() {
  return scene_json(R"({
    "waves": [{"direction": [1, 0], "amplitude": 5, "wavelength": 20, "speed": 10, "sharpness": 2},
              {"direction": [0, 1], "amplitude": 3, "wavelength": 13, "speed": 7, "sharpness": 1}]
  })");
}

// No wind at all.
inline std::string calm_scene() { return scene_json("{}"); }

// scene_json() with a "trees" array (JSON) and frames of size x size pixels.
inline std::string scene_with_trees(const std::string& wind, const std::string& trees,
                                    int size = 64) {
  std::string text = scene_json(wind, 2, size);
  size_t run = text.rfind(",\n  \"run\"");
  return text.substr(0, run) + ",\n  \"trees\": " + trees + text.substr(run);
}

// scene_json() with more top-level members (JSON text such as "\"meadows\": [...]") and
// frames of size x size pixels.
inline std::string scene_with(const std::string& wind, const std::string& members, int frames = 2,
                              int size = 64) {
  std::string text = scene_json(wind, frames, size);
  size_t run = text.rfind(",\n  \"run\"");
  return text.substr(0, run) + ",\n  " + members + text.substr(run);
}

// A 16 m meadow of the default mix in the middle of the tiny grid: pixels [24, 40) of a
// 64x64 frame.
inline std::string middle_meadow() {
  return R"("meadows": [{"center": [0, 0, 0], "size": [16, 16], "density": 40, "seed_points": 1024}])";
}

// A ball of radius 0.5 m rolling along +x at 4 m/s through the middle meadow, from x = -6 m.
inline std::string rolling_ball() {
  return R"("colliders": [{"center": [-6, 0.5, 0], "radius": 0.5, "velocity": [4, 0, 0]}])";
}

// A quaking aspen in the middle of the tiny grid.
inline std::string aspen_in_the_middle() {
  return R"([{"species": "quaking_aspen", "position": [0, 0, 0], "seed": 4}])";
}

// Strong moving waves and a gust: the trees sway.
inline std::string gusty_wind() {
  return R"({
    "waves": [{"direction": [1, 0], "amplitude": 9, "wavelength": 30, "speed": 12, "sharpness": 2}],
    "gusts": [{"direction": [1, 0, 0.3], "strength": 10, "delay": 0, "rise": 0.1, "hold": 1, "fall": 1}]
  })";
}

// A species file whose line 5 is out of range: Levels must be 1..4.
inline std::string bad_species_json() {
  return "{\n  \"format\": \"boreas-species-1\",\n  \"name\": \"bad\",\n  \"params\": {\n"
         "    \"Levels\": 9\n  }\n}\n";
}

}  // namespace boreas::render::testing
