// boreas fuzzing: a tree model as glTF 2.0, binary (an input starting "glTF") or JSON
// (load_tree_model on the file's bytes). The file lies in a folder that does not exist, so
// an external buffer is a missing file, never one of this machine's.
#include <cstring>

#include "fuzz_input.h"
#include "mesh_trees/model_import.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  return boreas::fuzz::refused_or_read([&] {
    (void)boreas::impl::load_tree_model(binary ? "/nonexistent/fuzz.glb" : "/nonexistent/fuzz.gltf",
                                        boreas::fuzz::text_of(data, size), {});
  });
}
