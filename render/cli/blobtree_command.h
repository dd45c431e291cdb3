// boreas command: `boreas blobtree`, which grows a tree, builds its BlobTree (Galbraith et
// al. 2004: implicit junctions with bark ridges and collars, cuts and scars), polygonizes
// it on the device and writes the mesh as PLY, OBJ or binary glTF (by the extension).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

struct BlobTreeCommandOptions {
  std::string species = "quaking_aspen";  // a built-in name or a species file
  uint64_t seed = 1;
  double scale = 1.0;
  // The library's defaults (boreas_default_blobtree_def).
  int resolution = boreas_default_blobtree_def().resolution;  // grid points, longest side
  std::string out;                                            // required: .ply, .obj or .glb
  int max_level = boreas_default_blobtree_def().max_level;
  double min_radius = 0.0;        // m; 0: half a grid cell
  std::string junctions = "pcm";  // pcm or blend
  bool no_offsets = false;
  double ridge = boreas_default_blobtree_def().ridge;
  double ridge_width = boreas_default_blobtree_def().ridge_width;
  double bend = boreas_default_blobtree_def().bend;  // rad
  std::vector<std::string> cuts;                     // "BRANCH:AT"
  std::vector<std::string> scars;                    // "BRANCH:STUB[:DEPTH]"
  std::optional<std::string> device;
  bool quiet = false;
};

// Throws CliError, boreas::Error or MeshWriteError; main() reports them.
int run_blobtree_command(const BlobTreeCommandOptions& options);

}  // namespace boreas::render
