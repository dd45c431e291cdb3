// boreas command: `boreas preprocess MODEL --out FILE.glb`, which finds an imported tree's
// branch hierarchy and wind weights and writes them with the mesh as binary glTF.
#pragma once

#include <cstdint>
#include <string>

namespace boreas::render {

struct PreprocessOptions {
  std::string model;       // .obj, .gltf or .glb
  std::string out;         // .glb
  std::string trunk_part;  // empty: the library's default names
  std::string leaves_part;
  uint64_t seed = 1;
  bool quiet = false;
};

// Throws CliError or boreas::Error; main() reports them.
int run_preprocess_command(const PreprocessOptions& options);

}  // namespace boreas::render
