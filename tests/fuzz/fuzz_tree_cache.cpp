// boreas fuzzing: a preprocessed imported tree, the `.boreas.glb` cache that boreas writes
// beside a model and reads back instead of preprocessing it again (read_preprocessed_bytes,
// binary or text glTF). The file lies in a folder that does not exist, so a buffer it
// names is a missing file, never one of this machine's.
#include "fuzz_input.h"
#include "mesh_trees/wind_cache.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read([&] {
    boreas::impl::PreprocessedTree tree;
    uint64_t key = 0;
    (void)boreas::impl::read_preprocessed_bytes("/nonexistent/fuzz.obj.boreas.glb",
                                                boreas::fuzz::text_of(data, size), &tree, &key);
  });
}
