// boreas command: `boreas blobtree`, which grows a tree, builds its BlobTree (Galbraith et
// al. 2004: implicit junctions with bark ridges and collars, cuts and scars), polygonizes
// it on the device and writes the mesh as PLY, OBJ or binary glTF (by the extension).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace boreas::render {

struct BlobTreeCommandOptions {
  std::string species = "quaking_aspen";  // a built-in name or a species file
  uint64_t seed = 1;
  double scale = 1.0;
  int resolution = 256;  // grid points along the tree's longest side
  std::string out;       // required: .ply, .obj or .glb
  int max_level = 3;
  double min_radius = 0.0;        // m; 0: half a grid cell
  std::string junctions = "pcm";  // pcm or blend
  bool no_offsets = false;
  double ridge = 0.2;
  double ridge_width = 0.5;
  double bend = 0.0;               // rad
  std::vector<std::string> cuts;   // "BRANCH:AT"
  std::vector<std::string> scars;  // "BRANCH:STUB[:DEPTH]"
  std::optional<std::string> device;
  bool quiet = false;
};

// Throws CliError, boreas::Error or MeshWriteError; main() reports them.
int run_blobtree_command(const BlobTreeCommandOptions& options);

}  // namespace boreas::render
