// boreas fuzzing: writes the seeds of fuzz_tree_cache, preprocessed trees as boreas writes
// them beside a model: each model given is preprocessed (preprocess_tree, without the
// cache) and written with write_preprocessed_glb to OUT_DIR/<model's name>.boreas.glb; the
// first is also written as text glTF (buffers inline), which the reader takes as well.
//   make_tree_cache_seeds OUT_DIR MODEL...
#include <tiny_gltf.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "errors.h"
#include "mesh_trees/model_files.h"
#include "mesh_trees/wind_cache.h"

namespace {

namespace fs = std::filesystem;
using namespace boreas::impl;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The binary cache at glb_path again as text glTF, its buffer a data URI.
void write_as_text(const std::string& glb_path, const std::string& gltf_path) {
  tinygltf::Model model;
  std::string error;
  if (!parse_gltf(read_bytes(glb_path), glb_path, &model, &error))
    fail_argument("cannot read back " + glb_path + ": " + error);
  std::ofstream out(gltf_path, std::ios::binary);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, false))
    fail_argument("cannot write " + gltf_path);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: make_tree_cache_seeds OUT_DIR MODEL...\n");
    return 2;
  }
  try {
    const fs::path out_dir = argv[1];
    fs::create_directories(out_dir);
    for (int i = 2; i < argc; ++i) {
      const std::string model = argv[i];
      const PreprocessedTree tree =
          preprocess_tree(model, ModelPartSelection{}, 1, false, nullptr, nullptr);
      const std::string name = fs::path(model).filename().string();
      const std::string glb = (out_dir / (name + ".boreas.glb")).string();
      write_preprocessed_glb(glb, tree, tree.key);
      std::printf("%s\n", glb.c_str());
      if (i == 2) {
        const std::string gltf = (out_dir / (name + ".boreas.gltf")).string();
        write_as_text(glb, gltf);
        std::printf("%s\n", gltf.c_str());
      }
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "make_tree_cache_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
