// boreas command: `boreas export-mesh`, which grows one tree in a scene's wind, steps the
// world to a time and writes the tree's branch mesh and leaf quads as OBJ, PLY or glTF
// binary (.glb), chosen by the output file's extension.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace boreas::render {

struct ExportOptions {
  std::string species = "quaking_aspen";  // a built-in name or a species file
  uint64_t seed = 1;
  double time = 0.0;  // s: the pose written is the one at this time
  double scale = 1.0;
  std::string out;                        // required: .obj, .ply or .glb
  std::optional<std::string> scene_path;  // unset: the built-in default scene
  std::optional<std::string> device;
  bool quiet = false;
};

// The fixed step export-mesh advances the world by (the last step is shortened to land on
// the requested time).
constexpr double kExportStep = 1.0 / 60.0;  // s
constexpr double kMaxExportTime = 1e5;      // s

// Throws CliError, SceneError, boreas::Error or MeshWriteError; main() reports them.
int run_export_command(const ExportOptions& options);

}  // namespace boreas::render
