// boreas command: the CLI11 definition of `boreas info` and `boreas run`, and their help.
#include "cli/command_line.h"

#include <CLI/CLI.hpp>

#include "cli/cli_error.h"

namespace boreas::render {

namespace {

constexpr char kFooter[] =
    "Exit codes: 0 success, 1 bad options or scene file, 2 no OpenCL device (or none matches\n"
    "the request), 3 a failure while running (OpenCL, writing files).\n"
    "BOREAS_DEVICE picks the device when --device and the scene leave it open;\n"
    "BOREAS_CACHE_DIR moves the kernel cache. Scene files: render/SCENES.md.";

// Copies an option into an optional only when it was given.
template <typename T>
void take(const CLI::Option* option, const T& value, std::optional<T>& out) {
  if (option->count() > 0) out = value;
}

}  // namespace

ParseResult parse_command_line(int argc, char** argv) {
  CLI::App app{
      "boreas: OpenCL vegetation-wind physics. Lists devices and films the wind of a scene."};
  app.name("boreas");
  app.footer(kFooter);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("boreas ") + BOREAS_VERSION);

  CLI::App* info =
      app.add_subcommand("info", "List the OpenCL devices and show which one boreas picks.");
  std::string info_device;
  CLI::Option* info_device_option =
      info->add_option("--device", info_device,
                       "Show what this request picks: gpu, cpu, P:D or part of a name")
          ->type_name("REQ");

  CLI::App* run = app.add_subcommand(
      "run",
      "Simulate a scene's wind; write PNG frames of a horizontal slice, a contact sheet and "
      "summary.json.");
  RunOptions options;
  std::string scene_path;
  std::string device;
  std::string size;
  int frames = 0;
  int steps_per_frame = 0;
  double dt = 0.0;
  double height = 0.0;
  double color_max = 0.0;
  CLI::Option* scene_option =
      run->add_option("scene", scene_path,
                      "Scene file (JSON, see render/SCENES.md); the built-in default if omitted")
          ->type_name("FILE");
  run->add_option("--out", options.out_dir, "Output folder")
      ->type_name("DIR")
      ->capture_default_str();
  CLI::Option* frames_option =
      run->add_option("--frames", frames, "Frames to write (scene: run.frames)")->type_name("N");
  CLI::Option* steps_option =
      run->add_option("--steps-per-frame", steps_per_frame,
                      "World steps between frames (scene: run.steps_per_frame)")
          ->type_name("N");
  CLI::Option* dt_option =
      run->add_option("--dt", dt, "Step length in s (scene: run.dt)")->type_name("SECONDS");
  CLI::Option* height_option =
      run->add_option("--height", height, "Height of the slice in m (scene: run.slice_height)")
          ->type_name("METERS");
  CLI::Option* size_option =
      run->add_option("--size", size, "Image size in pixels, e.g. 512x512 (scene: run.image_size)")
          ->type_name("WxH");
  CLI::Option* color_max_option =
      run->add_option("--color-max", color_max,
                      "Speed in m/s at the top of the color map (scene: run.color_max)")
          ->type_name("M/S");
  CLI::Option* device_option =
      run->add_option("--device", device,
                      "Device: gpu, cpu, P:D or part of a name (scene: world.device)")
          ->type_name("REQ");
  run->add_flag("-q,--quiet", options.quiet, "No progress and no result line");

  // CLI11 words a missing or misspelt command as "A subcommand is required" or as an
  // unexpected argument; say what was wrong instead.
  std::string commands;
  bool known = false;
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    commands += (commands.empty() ? "" : " or ") + command->get_name();
    known = known || (argc >= 2 && command->check_name(argv[1]));
  }
  if (argc < 2) {
    report_error("a command is required: " + commands + " (see 'boreas --help')");
    return {std::nullopt, kExitBadInput};
  }
  if (argv[1][0] != '-' && !known) {
    report_error(std::string("unknown command '") + argv[1] + "' (expected " + commands +
                 "; see 'boreas --help')");
    return {std::nullopt, kExitBadInput};
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return {std::nullopt, app.exit(e)};  // --help, --version
    report_error(std::string(e.what()) + " (see 'boreas --help')");
    return {std::nullopt, kExitBadInput};
  }

  CommandLine line;
  if (info->parsed()) {
    line.command = CommandLine::Command::kInfo;
    take(info_device_option, info_device, line.info.device);
    return {line, kExitOk};
  }
  line.command = CommandLine::Command::kRun;
  take(scene_option, scene_path, options.scene_path);
  take(frames_option, frames, options.frames);
  take(steps_option, steps_per_frame, options.steps_per_frame);
  take(dt_option, dt, options.dt);
  take(height_option, height, options.height);
  take(size_option, size, options.size);
  take(color_max_option, color_max, options.color_max);
  take(device_option, device, options.device);
  line.run = options;
  return {line, kExitOk};
}

}  // namespace boreas::render
