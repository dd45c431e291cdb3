// boreas: the preprocessing of an imported tree with its cache: the key that tells whether
// a cache was made from this model, and preprocess_tree, which reads the cache, or computes
// the tree and writes it (the glb's writer and reader are wind_cache_writer.cpp and
// wind_cache_reader.cpp).
#include "mesh_trees/wind_cache.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>

#include "errors.h"
#include "fnv1a.h"
#include "mesh_trees/model_files.h"
#include "mesh_trees/wind_cache_internal.h"

namespace boreas::impl {

namespace {

namespace fs = std::filesystem;

using wind_cache::one_line;

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

}  // namespace

uint64_t preprocess_key_of(const std::string& bytes, const ModelPartSelection& selection,
                           uint64_t seed) {
  Fnv1a64 hash;
  hash.add(bytes.data(), bytes.size());
  hash.add_u64(uint64_t(bytes.size()));
  hash.add_string(selection.trunk);
  hash.add_string(selection.leaves);
  hash.add_u64(seed);
  hash.add_u64(kWindCacheVersion);
  return hash.value();
}

uint64_t preprocess_key(const std::string& model_path, const ModelPartSelection& selection,
                        uint64_t seed) {
  return preprocess_key_of(read_file_bytes(model_path, "tree model"), selection, seed);
}

PreprocessedTree preprocess_tree(const std::string& path, const ModelPartSelection& selection,
                                 uint64_t seed, bool use_cache, bool* from_cache,
                                 std::string* cache_note) {
  if (from_cache) *from_cache = false;
  if (cache_note) cache_note->clear();
  auto note = [&](const std::string& s) {
    if (cache_note) *cache_note = one_line(*cache_note + (cache_note->empty() ? "" : "; ") + s);
  };

  const std::string bytes = read_file_bytes(path, "tree model");
  const uint64_t key = preprocess_key_of(bytes, selection, seed);
  const std::string extension = lowercase(fs::path(path).extension().string());
  if (extension == ".glb" || extension == ".gltf") {
    PreprocessedTree tree;
    if (read_preprocessed_bytes(path, bytes, &tree, nullptr)) {
      if (from_cache) *from_cache = true;
      tree.key = key;
      return tree;
    }
  }

  const std::string cache_path = path + ".boreas.glb";
  if (use_cache) {
    std::error_code ec;
    if (fs::exists(cache_path, ec)) {
      try {
        PreprocessedTree tree;
        uint64_t cached_key = 0;
        if (!read_preprocessed_glb(cache_path, &tree, &cached_key)) {
          note("ignored the wind cache '" + cache_path + "': it holds no boreas_wind data");
        } else if (cached_key == key) {
          if (from_cache) *from_cache = true;
          tree.key = key;
          return tree;
        }
      } catch (const Error& e) {
        note(std::string("ignored a corrupt or unreadable wind cache: ") + e.what());
      }
    }
  }

  PreprocessedTree tree;
  tree.model = load_tree_model(path, bytes, selection);
  tree.data = compute_mesh_tree(tree.model, seed);
  tree.key = key;
  if (use_cache) {
    try {
      write_preprocessed_glb(cache_path, tree, key);
    } catch (const Error& e) {
      note(std::string("the wind cache was not saved (the model is preprocessed again on every "
                       "load): ") +
           e.what());
    }
  }
  return tree;
}

}  // namespace boreas::impl
