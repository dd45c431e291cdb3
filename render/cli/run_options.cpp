// boreas command: run settings from the scene, overridden by options, checked.
#include "cli/run_options.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "cli/cli_error.h"
#include "scene/scene_loader.h"

namespace boreas::render {

namespace {

[[noreturn]] void bad_option(const std::string& option, const std::string& rule, double got) {
  throw CliError(kExitBadInput, option + ": must be " + rule + " (got " + cli_number(got) + ")");
}

// The lidar view draws the scene's LiDARs' sweeps over the frames it writes.
void check_lidar_view(const Scene& scene, const RunOptions& options, ViewMode view) {
  if (view != ViewMode::lidar) return;
  bool has_lidar = false;
  for (const SceneSensor& s : scene.sensors) has_lidar |= s.type == SceneSensor::Type::lidar;
  if (!has_lidar) {
    throw CliError(kExitBadInput, "--view lidar: the scene has no LiDAR to draw (add one to its "
                                  "\"sensors\", type \"lidar\")");
  }
  if (options.window) {
    throw CliError(kExitBadInput, "--window: only with --view scene; lidar writes its frames");
  }
}

}  // namespace

AnimationFormat resolve_animation(const RunOptions& options, ViewMode view) {
  const std::string& choice = options.animation;
  if (choice == "auto") {
    return options.window || view == ViewMode::trails ? AnimationFormat::none
                                                      : best_animation_format();
  }
  AnimationFormat format = AnimationFormat::none;
  for (AnimationFormat f :
       {AnimationFormat::none, AnimationFormat::gif, AnimationFormat::webp, AnimationFormat::mp4}) {
    if (choice == animation_format_name(f)) format = f;
  }
  if (format == AnimationFormat::none && choice != "none") {
    throw CliError(kExitBadInput,
                   "--animation: expected auto, none, gif, webp or mp4 (got '" + choice + "')");
  }
  if (format == AnimationFormat::none) return format;
  if (options.window)
    throw CliError(kExitBadInput, "--animation: not with --window, which writes no frames");
  if (view == ViewMode::trails)
    throw CliError(kExitBadInput, "--animation: not with --view trails, which writes one picture");
  if (!can_write_animation(format)) {
    throw CliError(kExitBadInput,
                   format == AnimationFormat::mp4
                       ? "--animation mp4: needs the ffmpeg command (Debian package ffmpeg), and "
                         "none is on PATH"
                       : "--animation " + choice + ": this build's OpenImageIO writes only still " +
                             (format == AnimationFormat::gif ? "GIF" : "WebP") + " images");
  }
  return format;
}

bool parse_image_size(const std::string& text, int& width, int& height) {
  size_t x = text.find_first_of("xX");
  if (x == std::string::npos || x == 0 || x + 1 >= text.size()) return false;
  std::string w = text.substr(0, x);
  std::string h = text.substr(x + 1);
  auto digits = [](const std::string& s) {
    return s.size() <= 6 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  if (!digits(w) || !digits(h)) return false;
  width = std::stoi(w);
  height = std::stoi(h);
  return width > 0 && height > 0;
}

float nice_ceiling(float v) {
  if (!(v > 0.0f)) return 1.0f;
  float power = std::pow(10.0f, std::floor(std::log10(v)));
  for (float step : {1.0f, 1.2f, 1.5f, 2.0f, 2.5f, 3.0f, 4.0f, 5.0f, 6.0f, 8.0f, 10.0f}) {
    if (step * power >= v * (1.0f - 1e-6f)) return step * power;
  }
  return 10.0f * power;
}

float auto_color_max(const Scene& scene) {
  float waves = 0.0f;
  for (const boreas_wave& w : scene.waves) waves += w.amplitude;
  float strongest = 0.0f;
  for (const boreas_flow_primitive_def& p : scene.primitives) {
    strongest = std::max(strongest, std::fabs(p.strength));
  }
  for (const boreas_gust_def& g : scene.gusts)
    strongest = std::max(strongest, std::fabs(g.strength));
  // A calm scene still needs a scale; 1 m/s keeps zero at the bottom color.
  return nice_ceiling(std::max(waves + strongest, 1.0f));
}

RunSettings resolve_run_settings(const Scene& scene, const RunOptions& options) {
  RunSettings run = scene.run;
  if (options.frames) {
    if (*options.frames < 1 || *options.frames > kMaxFrames) {
      bad_option("--frames", "in [1, " + cli_number(kMaxFrames) + "]", *options.frames);
    }
    run.frames = *options.frames;
  }
  if (options.steps_per_frame) {
    if (*options.steps_per_frame < 1 || *options.steps_per_frame > kMaxStepsPerFrame) {
      bad_option("--steps-per-frame", "in [1, " + cli_number(kMaxStepsPerFrame) + "]",
                 *options.steps_per_frame);
    }
    run.steps_per_frame = *options.steps_per_frame;
  }
  if (options.dt) {
    // Checked as the float the world steps with: a dt that rounds to 0 would fail mid-run.
    if (!(float(*options.dt) > 0.0f && *options.dt <= BOREAS_STEP_MAX_SECONDS)) {
      bad_option("--dt", "in (0, " + cli_number(BOREAS_STEP_MAX_SECONDS) + "]", *options.dt);
    }
    run.dt = float(*options.dt);
  }
  if (options.height) {
    std::string rule = check_slice_height(scene.grid, *options.height);
    if (!rule.empty())
      bad_option("--height", rule + " m, the grid's vertical extent", *options.height);
    run.slice_height = float(*options.height);
  }
  if (options.size) {
    int w = 0;
    int h = 0;
    if (!parse_image_size(*options.size, w, h)) {
      throw CliError(kExitBadInput, "--size: expected WIDTHxHEIGHT in pixels, e.g. 512x384 (got '" +
                                        *options.size + "')");
    }
    std::string sides =
        "at least " + cli_number(kMinImageSide) + " and at most " + cli_number(kMaxImageSide) + " pixels ";
    if (w < kMinImageSide || w > kMaxImageSide) bad_option("--size", sides + "wide", w);
    if (h < kMinImageSide || h > kMaxImageSide) bad_option("--size", sides + "high", h);
    run.image_width = w;
    run.image_height = h;
  }
  if (options.color_max) {
    if (!(*options.color_max > 0.0 && *options.color_max <= 1e6)) {
      bad_option("--color-max", "in (0, 1e6] m/s", *options.color_max);
    }
    run.color_max = float(*options.color_max);
  }
  if (!(run.color_max > 0.0f)) run.color_max = auto_color_max(scene);
  if (options.view) {
    if (*options.view == "scene") {
      run.view = ViewMode::scene;
    } else if (*options.view == "slice") {
      run.view = ViewMode::slice;
    } else if (*options.view == "trails") {
      run.view = ViewMode::trails;
    } else if (*options.view == "lidar") {
      run.view = ViewMode::lidar;
    } else {
      throw CliError(kExitBadInput, "--view: expected scene, slice, trails or lidar (got '" +
                                        *options.view + "')");
    }
  }
  check_lidar_view(scene, options, run.view);
  static const char* const kInterop[] = {"auto", "gl_sharing", "zero_copy", "copy"};
  if (std::find(std::begin(kInterop), std::end(kInterop), options.interop) == std::end(kInterop)) {
    throw CliError(kExitBadInput, "--interop: expected auto, gl_sharing, zero_copy or copy (got '" +
                                      options.interop + "')");
  }
  if ((options.window || options.exr || options.textures) && run.view == ViewMode::slice) {
    throw CliError(kExitBadInput, std::string(options.window ? "--window" : options.exr ? "--exr" : "--textures") +
                                      ": only with the 3D view (--view scene), not the slice");
  }
  if ((options.window || options.exr) && run.view == ViewMode::trails) {
    throw CliError(kExitBadInput, std::string(options.window ? "--window" : "--exr") +
                                      ": only with --view scene; trails writes one picture");
  }
  return run;
}

}  // namespace boreas::render
