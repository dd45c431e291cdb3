// boreas fuzzing: a tree model as Wavefront OBJ (load_tree_model on the file's bytes).
#include "fuzz_input.h"
#include "mesh_trees/model_import.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read([&] {
    (void)boreas::impl::load_tree_model("/nonexistent/fuzz.obj", boreas::fuzz::text_of(data, size),
                                        {});
  });
}
