// boreas command: the CLI11 definition of the commands (info, run, export-mesh, preprocess,
// blobtree) and their help, built once per CommandLineParser.
#include "cli/command_line.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <iostream>

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

// A usage error: "boreas: error: <message>" (cli_error.h's form) and exit code 1.
ParseResult usage_error(std::ostream& err, const std::string& message) {
  err << "boreas: error: " << message << '\n';
  return ParseResult{std::nullopt, kExitBadInput};
}

// The message for a --seed that is not a whole number in range.
std::string bad_seed(const std::string& text) {
  return "--seed: must be a whole number in [0, 18446744073709551615] (got '" + text + "')";
}

}  // namespace

bool parse_seed(const std::string& text, uint64_t& seed) {
  if (text.empty() || text.size() > 20 || text.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  errno = 0;
  unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE) return false;
  seed = uint64_t(value);
  return true;
}

ParseResult parse_command_line(int argc, char** argv) {
  return parse_command_line(argc, argv, std::cout, std::cerr);
}

// The definition, built once: option pointers, and the values CLI11 writes into.
struct CommandLineParser::Impl {
  struct Values {
    std::string info_device;
    RunOptions options;
    std::string scene_path;
    std::string device;
    std::string size;
    int frames = 0;
    int steps_per_frame = 0;
    double dt = 0.0;
    double height = 0.0;
    double color_max = 0.0;
    std::string view;
    std::string textures;
    std::string run_seed;
    ExportOptions export_options;
    std::string export_scene;
    std::string export_device;
    std::string export_seed = "1";
    PreprocessOptions preprocess_options;
    std::string preprocess_seed = "1";
    BlobTreeCommandOptions blob_options;
    std::string blob_device;
    std::string blob_seed = "1";
    AnimationOptions animation_options;
    std::string animation_scene;
    int animation_frames = 0;
    std::string animation_device;
  };
  Values v;
  CLI::App app{
      "boreas: OpenCL vegetation-wind physics. Lists devices, films the wind of a scene and "
      "exports tree meshes, animated or as BlobTree implicit surfaces."};
  CLI::App* info = nullptr;
  CLI::Option* info_device_option = nullptr;
  CLI::App* run = nullptr;
  CLI::Option* scene_option = nullptr;
  CLI::Option* frames_option = nullptr;
  CLI::Option* steps_option = nullptr;
  CLI::Option* dt_option = nullptr;
  CLI::Option* height_option = nullptr;
  CLI::Option* size_option = nullptr;
  CLI::Option* color_max_option = nullptr;
  CLI::Option* device_option = nullptr;
  CLI::Option* view_option = nullptr;
  CLI::Option* textures_option = nullptr;
  CLI::Option* run_seed_option = nullptr;
  CLI::App* export_mesh = nullptr;
  CLI::Option* export_seed_option = nullptr;
  CLI::Option* export_scene_option = nullptr;
  CLI::Option* export_device_option = nullptr;
  CLI::App* preprocess = nullptr;
  CLI::Option* preprocess_seed_option = nullptr;
  CLI::App* blobtree = nullptr;
  CLI::Option* blob_seed_option = nullptr;
  CLI::Option* blob_device_option = nullptr;
  CLI::App* export_animation = nullptr;
  CLI::Option* animation_scene_option = nullptr;
  CLI::Option* animation_frames_option = nullptr;
  CLI::Option* animation_device_option = nullptr;

  Impl();
  ParseResult parse(int argc, char** argv, std::ostream& out, std::ostream& err);

 private:
  // The constructor's steps: one command each (the BlobTree's shape options apart).
  void add_info();
  void add_run();
  void add_export_mesh();
  void add_preprocess();
  void add_blobtree();
  void add_blobtree_shape();
  void add_export_animation();
  // parse()'s steps: what is wrong with the command word, if anything (before CLI11 sees
  // it); the run command's line from the values parsed.
  std::optional<std::string> wrong_command(int argc, char** argv);
  CommandLine run_line();
};

CommandLineParser::Impl::Impl() {
  // The options write into the members of v, which parse() resets.
  app.name("boreas");
  app.footer(kFooter);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("boreas ") + boreas_version());

  add_info();
  add_run();
  add_export_mesh();
  add_export_animation();
  add_preprocess();
  add_blobtree();
}

void CommandLineParser::Impl::add_info() {
  info = app.add_subcommand("info", "List the OpenCL devices and show which one boreas picks.");
  info_device_option =
      info->add_option("--device", v.info_device,
                       "Show what this request picks: gpu, cpu, P:D or part of a name")
          ->type_name("REQ");
}

void CommandLineParser::Impl::add_run() {
  run = app.add_subcommand(
      "run",
      "Simulate a scene and film it: PNG frames of the 3D view (OpenGL; or of a horizontal "
      "wind slice with --view slice), a contact sheet and summary.json; or its motion in one "
      "picture (--view trails: trails.png, the first frame with the paths of branch and blade "
      "tips over the run); or watch it with --window.");
  scene_option =
      run->add_option("scene", v.scene_path,
                      "Scene file (JSON, see render/SCENES.md); the built-in default if omitted")
          ->type_name("FILE");
  run->add_option("--out", v.options.out_dir, "Output folder")
      ->type_name("DIR")
      ->capture_default_str();
  frames_option =
      run->add_option("--frames", v.frames, "Frames to write (scene: run.frames)")->type_name("N");
  steps_option = run->add_option("--steps-per-frame", v.steps_per_frame,
                                 "World steps between frames (scene: run.steps_per_frame)")
                     ->type_name("N");
  dt_option =
      run->add_option("--dt", v.dt, "Step length in s (scene: run.dt)")->type_name("SECONDS");
  height_option =
      run->add_option("--height", v.height, "Height of the slice in m (scene: run.slice_height)")
          ->type_name("METERS");
  size_option = run->add_option("--size", v.size,
                                "Image size in pixels, e.g. 512x512 (scene: run.image_size)")
                    ->type_name("WxH");
  color_max_option =
      run->add_option("--color-max", v.color_max,
                      "Speed in m/s at the top of the color map (scene: run.color_max)")
          ->type_name("M/S");
  device_option = run->add_option("--device", v.device,
                                  "Device: gpu, cpu, P:D or part of a name (scene: world.device)")
                      ->type_name("REQ");
  // A string, checked in parse(): CLI11 would wrap -1 around to 2^64 - 1.
  run_seed_option =
      run->add_option("--seed", v.run_seed,
                      "Mixed into every seed of the scene (trees, forests, meadows, emitters, "
                      "imported trees): the same seed makes the same world (0 to 2^64 - 1)")
          ->type_name("N");
  view_option =
      run->add_option("--view", v.view,
                      "scene (3D, OpenGL), slice (wind speed from above), trails (the 3D view's "
                      "first frame with tip paths over the run and crosses where branches broke) or lidar (the 3D view with the "
                      "LiDARs' latest sweeps drawn over it) (scene: run.view)")
          ->type_name("MODE");
  run->add_option("--interop", v.options.interop,
                  "How kernel output reaches OpenGL: auto, gl_sharing, zero_copy or copy")
      ->type_name("HOW")
      ->capture_default_str();
  textures_option =
      run->add_option(
             "--textures", v.textures,
             "Folder with leaf and bark maps (as `boreas` writes them); generated if omitted")
          ->type_name("DIR");
  run->add_option(
         "--animation", v.options.animation,
         "Animated file beside the frames: auto (gif, else webp, else mp4 through ffmpeg), "
         "none, gif, webp or mp4")
      ->type_name("FORMAT")
      ->capture_default_str();
  run->add_flag("--exr", v.options.exr, "Also write each frame as HDR OpenEXR (linear, exposed)");
  run->add_flag("--window", v.options.window,
                "Show the scene in a window: drag or arrow keys orbit, wheel or +/- zoom, "
                "W/S wind stronger/weaker, A/D turn the wind, Esc quits");
  run->add_flag("--gpu-times", v.options.gpu_times,
                "Time each part of a frame on the GPU (summary.json: render.parts_s); the parts "
                "then run one after another, about a tenth slower on llvmpipe");
  run->add_flag("-q,--quiet", v.options.quiet, "No progress and no result line");
}

void CommandLineParser::Impl::add_export_mesh() {
  export_mesh = app.add_subcommand(
      "export-mesh",
      "Grow one tree in a scene's wind, step to a time and write its branch mesh and leaf quads "
      "as .obj, .ply or .glb (by the extension of --out).");
  export_mesh
      ->add_option("--species", v.export_options.species,
                   "A built-in species or a species file (.xml from Arbaro, or .json)")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  // A string, checked here: CLI11 would wrap -1 around to 2^64 - 1.
  export_seed_option =
      export_mesh
          ->add_option("--seed", v.export_seed,
                       "The same seed grows the same tree (a whole number, 0 to 2^64 - 1)")
          ->type_name("N")
          ->capture_default_str();
  export_mesh
      ->add_option("--time", v.export_options.time,
                   "Simulated seconds before the pose is written (steps of 1/60 s)")
      ->type_name("SECONDS")
      ->capture_default_str();
  export_mesh->add_option("--scale", v.export_options.scale, "Multiplies every length of the tree")
      ->type_name("S")
      ->capture_default_str();
  export_mesh->add_option("--out", v.export_options.out, "Mesh file: .obj, .ply or .glb")
      ->type_name("FILE")
      ->required();
  export_scene_option =
      export_mesh
          ->add_option("--scene", v.export_scene,
                       "Scene whose wind and grid the tree grows in (its own trees are left "
                       "out); the built-in default if omitted")
          ->type_name("FILE");
  export_device_option =
      export_mesh
          ->add_option("--device", v.export_device,
                       "Device: gpu, cpu, P:D or part of a name (scene: world.device)")
          ->type_name("REQ");
  export_mesh->add_flag("-q,--quiet", v.export_options.quiet, "No progress and no result line");
}

void CommandLineParser::Impl::add_export_animation() {
  export_animation = app.add_subcommand(
      "export-animation",
      "Step a scene's trees in its wind at its frame rate and write them as an animated glTF "
      "binary: skinned meshes (one per species and seed), leaves, a key per frame; imported "
      "trees (and with --meadows the meadows) as morph targets.");
  animation_scene_option =
      export_animation->add_option("scene", v.animation_scene, "Scene file; the built-in default if omitted")
          ->type_name("FILE");
  animation_frames_option =
      export_animation->add_option("--frames", v.animation_frames, "Keys written (scene: run.frames)")
          ->type_name("N");
  export_animation->add_option("--out", v.animation_options.out, "Animation file (.glb)")
      ->type_name("FILE")
      ->required();
  export_animation
      ->add_option("--level", v.animation_options.max_level,
                   "Deepest branch level with joints of its own, 0..3 (default 1)")
      ->type_name("L");
  export_animation
      ->add_option("--segments", v.animation_options.segments,
                   "Joints per branch minus one (default 2)")
      ->type_name("N");
  export_animation->add_flag("--no-leaves", v.animation_options.no_leaves, "Branches only");
  export_animation
      ->add_option("--meadows", v.animation_options.meadows,
                   "The scene's meadows: clumps (default: a few baked sway loops per meadow, "
                   "instanced over it), exact (every strip vertex as simulated: large) or none")
      ->type_name("FORM");
  export_animation
      ->add_option("--clumps", v.animation_options.clumps,
                   "Clumps per meadow with --meadows clumps, 1..64 (default 4)")
      ->type_name("N");
  export_animation
      ->add_option("--clump-size", v.animation_options.clump_size,
                   "m: a clump's square cell, 0.1..100 (default 1)")
      ->type_name("M");
  export_animation
      ->add_option("--morph-tolerance", v.animation_options.morph_tolerance,
                   "m: meadows and imported trees within this of boreas's vertices at every key "
                   "(default 0.001)")
      ->type_name("M");
  export_animation
      ->add_option("--warmup", v.animation_options.warmup,
                   "s: the world stepped before the first key, after the bind pose is taken, "
                   "so the keys (and the meadows' loops) start in the wind's sway, 0..600 "
                   "(default 2)")
      ->type_name("SECONDS");
  animation_device_option =
      export_animation
          ->add_option("--device", v.animation_device,
                       "Device: gpu, cpu, P:D or part of a name (scene: world.device)")
          ->type_name("REQ");
  export_animation->add_flag("-q,--quiet", v.animation_options.quiet, "No result line");
}

void CommandLineParser::Impl::add_preprocess() {
  preprocess = app.add_subcommand(
      "preprocess",
      "Find an imported tree model's branch hierarchy and wind weights (Kusternig sec. 5) and "
      "write them with its mesh as binary glTF (vertex attributes _BOREAS_WEIGHTS, "
      "_BOREAS_BRANCH, ...; the branch table in the trunk mesh's extras).");
  preprocess->add_option("model", v.preprocess_options.model, "Tree model: .obj, .gltf or .glb")
      ->type_name("FILE")
      ->required();
  preprocess->add_option("--out", v.preprocess_options.out, "Output file (.glb)")
      ->type_name("FILE")
      ->required();
  preprocess
      ->add_option("--trunk", v.preprocess_options.trunk_part,
                   "Names of the trunk's objects, groups or materials, comma-separated "
                   "(default: trunk,bark,branch,stem,wood)")
      ->type_name("NAMES");
  preprocess
      ->add_option("--leaves", v.preprocess_options.leaves_part,
                   "Names of the leaves' objects, groups or materials (default: "
                   "leaf,leaves,foliage,needle)")
      ->type_name("NAMES");
  preprocess_seed_option =
      preprocess->add_option("--seed", v.preprocess_seed, "Seed of the branches' sway phases")
          ->type_name("N")
          ->capture_default_str();
  preprocess->add_flag("-q,--quiet", v.preprocess_options.quiet, "No result line");
}

void CommandLineParser::Impl::add_blobtree() {
  blobtree = app.add_subcommand(
      "blobtree",
      "Grow one tree and write it as a BlobTree (Galbraith et al. 2004): one implicit surface "
      "with smooth junctions, bark ridges and collars, pruning cuts and scars, polygonized on "
      "the device into a watertight mesh (.ply, .obj or .glb by the extension of --out).");
  blobtree
      ->add_option("--species", v.blob_options.species,
                   "A built-in species or a species file (.xml or .json)")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  blob_seed_option =
      blobtree
          ->add_option("--seed", v.blob_seed, "The same seed grows the same tree (0 to 2^64 - 1)")
          ->type_name("N")
          ->capture_default_str();
  blobtree->add_option("--scale", v.blob_options.scale, "Multiplies every length of the tree")
      ->type_name("S")
      ->capture_default_str();
  blobtree
      ->add_option(
          "--resolution", v.blob_options.resolution,
          "Grid points along the tree's longest side, 16..1024 (256 resolves ~3 cm on a 14 m tree)")
      ->type_name("N")
      ->capture_default_str();
  blobtree->add_option("--out", v.blob_options.out, "Mesh file: .ply, .obj or .glb")
      ->type_name("FILE")
      ->required();
  blobtree
      ->add_option("--max-level", v.blob_options.max_level, "Deepest branch level modeled, 0..3")
      ->type_name("L")
      ->capture_default_str();
  blobtree
      ->add_option("--min-radius", v.blob_options.min_radius,
                   "Branches thinner than this (m) are left out; 0: half a grid cell")
      ->type_name("M")
      ->capture_default_str();
  add_blobtree_shape();
  blob_device_option =
      blobtree->add_option("--device", v.blob_device, "Device: gpu, cpu, P:D or part of a name")
          ->type_name("REQ");
  blobtree->add_flag("-q,--quiet", v.blob_options.quiet, "No progress and no result line");
}

// The BlobTree's junctions, bark ridges, bends, cuts and scars.
void CommandLineParser::Impl::add_blobtree_shape() {
  blobtree
      ->add_option("--junctions", v.blob_options.junctions,
                   "pcm: bark ridges and collars (Precise Contact Modeling); blend: smooth")
      ->type_name("pcm|blend")
      ->capture_default_str();
  blobtree->add_flag(
      "--no-offsets", v.blob_options.no_offsets,
      "Do not shorten and displace internodes at junctions (eq. 3, 6, 7): shows the bulge");
  blobtree
      ->add_option("--ridge", v.blob_options.ridge,
                   "Height of the bark ridges, 0..0.45 field units")
      ->type_name("M")
      ->capture_default_str();
  blobtree
      ->add_option("--ridge-width", v.blob_options.ridge_width,
                   "Width of the bark ridges in branch radii, 0.01..10")
      ->type_name("W")
      ->capture_default_str();
  blobtree
      ->add_option(
          "--bend", v.blob_options.bend,
          "Radians, 0..pi/2: lateral branches bend away from their parent and back (sec. 3.5)")
      ->type_name("RAD")
      ->capture_default_str();
  blobtree
      ->add_option("--cut", v.blob_options.cuts,
                   "Saw a branch off flat: BRANCH:AT, AT 0.01..1 along it (repeatable; branch 0 is "
                   "the trunk)")
      ->type_name("B:AT");
  blobtree
      ->add_option(
          "--scar", v.blob_options.scars,
          "A lost branch: a stub in a hollow, BRANCH:STUB[:DEPTH] (repeatable; STUB 0.01..1 of "
          "its length, DEPTH 0..1, default 0.5)")
      ->type_name("B:S[:D]");
}

ParseResult CommandLineParser::Impl::parse(int argc, char** argv, std::ostream& out,
                                           std::ostream& err) {
  // Every value back to its default and every option unparsed: one parse leaves nothing
  // for the next.
  v = Values{};
  app.clear();
  if (std::optional<std::string> wrong = wrong_command(argc, argv)) return usage_error(err, *wrong);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return {std::nullopt, app.exit(e, out, err)};  // --help, --version
    return usage_error(err, std::string(e.what()) + " (see 'boreas --help')");
  }

  CommandLine line;
  if (export_mesh->parsed()) {
    line.command = CommandLine::Command::kExportMesh;
    take(export_scene_option, v.export_scene, v.export_options.scene_path);
    take(export_device_option, v.export_device, v.export_options.device);
    if (export_seed_option->count() > 0 && !parse_seed(v.export_seed, v.export_options.seed)) {
      return usage_error(err, bad_seed(v.export_seed));
    }
    line.export_mesh = v.export_options;
    return {line, kExitOk};
  }
  if (export_animation->parsed()) {
    line.command = CommandLine::Command::kExportAnimation;
    take(animation_scene_option, v.animation_scene, v.animation_options.scene_path);
    take(animation_frames_option, v.animation_frames, v.animation_options.frames);
    take(animation_device_option, v.animation_device, v.animation_options.device);
    line.export_animation = v.animation_options;
    return {line, kExitOk};
  }
  if (blobtree->parsed()) {
    line.command = CommandLine::Command::kBlobTree;
    take(blob_device_option, v.blob_device, v.blob_options.device);
    if (blob_seed_option->count() > 0 && !parse_seed(v.blob_seed, v.blob_options.seed)) {
      return usage_error(err, bad_seed(v.blob_seed));
    }
    line.blobtree = v.blob_options;
    return {line, kExitOk};
  }
  if (preprocess->parsed()) {
    line.command = CommandLine::Command::kPreprocess;
    if (preprocess_seed_option->count() > 0 &&
        !parse_seed(v.preprocess_seed, v.preprocess_options.seed)) {
      return usage_error(err, bad_seed(v.preprocess_seed));
    }
    line.preprocess = v.preprocess_options;
    return {line, kExitOk};
  }
  if (info->parsed()) {
    line.command = CommandLine::Command::kInfo;
    take(info_device_option, v.info_device, line.info.device);
    return {line, kExitOk};
  }
  CommandLine line_run = run_line();
  if (run_seed_option->count() > 0) {
    uint64_t seed = 0;
    if (!parse_seed(v.run_seed, seed)) return usage_error(err, bad_seed(v.run_seed));
    line_run.run.seed = seed;
  }
  return {line_run, kExitOk};
}

std::optional<std::string> CommandLineParser::Impl::wrong_command(int argc, char** argv) {
  // CLI11 words a missing or misspelt command as "A subcommand is required" or as an
  // unexpected argument; say what was wrong instead.
  std::vector<std::string> names;
  bool known = false;
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    names.push_back(command->get_name());
    known = known || (argc >= 2 && command->check_name(argv[1]));
  }
  std::string commands;  // "info, run or export-mesh"
  for (size_t i = 0; i < names.size(); ++i) {
    commands += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  if (argc < 2) {
    return "a command is required: " + commands + " (see 'boreas --help')";
  }
  if (argv[1][0] != '-' && !known) {
    return std::string("unknown command '") + argv[1] + "' (expected " + commands +
           "; see 'boreas --help')";
  }
  return std::nullopt;
}

CommandLine CommandLineParser::Impl::run_line() {
  CommandLine line;
  line.command = CommandLine::Command::kRun;
  take(scene_option, v.scene_path, v.options.scene_path);
  take(frames_option, v.frames, v.options.frames);
  take(steps_option, v.steps_per_frame, v.options.steps_per_frame);
  take(dt_option, v.dt, v.options.dt);
  take(height_option, v.height, v.options.height);
  take(size_option, v.size, v.options.size);
  take(color_max_option, v.color_max, v.options.color_max);
  take(device_option, v.device, v.options.device);
  take(view_option, v.view, v.options.view);
  take(textures_option, v.textures, v.options.textures);
  line.run = v.options;
  return line;
}

CommandLineParser::CommandLineParser() : impl_(std::make_unique<Impl>()) {}
CommandLineParser::~CommandLineParser() = default;

ParseResult CommandLineParser::parse(int argc, char** argv, std::ostream& out, std::ostream& err) {
  return impl_->parse(argc, argv, out, err);
}

ParseResult parse_command_line(int argc, char** argv, std::ostream& out, std::ostream& err) {
  return CommandLineParser().parse(argc, argv, out, err);
}

}  // namespace boreas::render
