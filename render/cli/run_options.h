// boreas command: the options of `boreas run` and how they override the scene's "run"
// settings. Command-line values are checked with the same rules as scene values.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "image/animation.h"
#include "scene/scene.h"

namespace boreas::render {

struct RunOptions {
  std::optional<std::string> scene_path;  // unset: the built-in default scene
  std::string out_dir = "out/run";
  std::optional<int> frames;
  std::optional<int> steps_per_frame;
  std::optional<double> dt;
  std::optional<double> height;     // m
  std::optional<std::string> size;  // "WxH" pixels
  std::optional<double> color_max;  // m/s
  std::optional<std::string> device;
  // Mixed into every seed of the scene (scene/scene_seed.h): one scene, many worlds.
  std::optional<uint64_t> seed;
  std::optional<std::string> view;      // "scene" or "slice" (scene: run.view)
  std::string interop = "auto";         // auto, gl_sharing, zero_copy or copy
  std::optional<std::string> textures;  // a folder of leaf and bark maps (render/textures)
  bool exr = false;                     // also write each frame as HDR OpenEXR
  std::string animation = "auto";       // auto, none, gif, webp or mp4
  bool window = false;                  // interactive: a window with an orbit camera
  bool gpu_times = false;               // time the frames' parts on the GPU (render.parts_s)
  bool quiet = false;
};

// The scene's run settings with options applied; throws CliError (exit 1) for a bad
// option, naming it. A color_max of 0 is replaced by auto_color_max(scene).
RunSettings resolve_run_settings(const Scene& scene, const RunOptions& options);

// The animated file `boreas run` writes beside its frames: --animation as asked, checked
// against what this build can write (exit 1 naming what is missing); auto is the first of
// gif, webp and mp4 it can, else none. None with --window, which writes no frames, and
// with the trails view, which writes one picture (asking for one there is an error).
AnimationFormat resolve_animation(const RunOptions& options, ViewMode view = ViewMode::scene);

// "512x384" -> 512, 384; false when text is not two positive integers joined by 'x'.
bool parse_image_size(const std::string& text, int& width, int& height);

// The top of the color map when the scene leaves it open: the waves' amplitudes summed
// plus the strongest primitive or gust, rounded up by nice_ceiling().
float auto_color_max(const Scene& scene);

// The smallest of 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of 10 that is >= v;
// 1 for v <= 0.
float nice_ceiling(float v);

}  // namespace boreas::render
