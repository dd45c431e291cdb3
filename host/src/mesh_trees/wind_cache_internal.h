// boreas: what the preprocessed-tree glb's writer (wind_cache_writer.cpp), reader
// (wind_cache_reader.cpp) and driver (wind_cache.cpp) share: the file's names, the messages'
// wording, and validate(), which both directions apply (wind_cache_validate.cpp).
#pragma once

#include <algorithm>
#include <string>

#include "errors.h"
#include "mesh_trees/wind_cache.h"

namespace boreas::impl::wind_cache {

constexpr char kWindExtras[] = "boreas_wind";
constexpr char kTrunkName[] = "trunk";
constexpr char kLeavesName[] = "leaves";
// Indices stored as floats must stay exact (wind_cache.h).
constexpr double kMaxFloatIndex = double(1 << 24);

inline std::string about(const std::string& path) { return "preprocessed tree '" + path + "': "; }

[[noreturn]] inline void malformed(const std::string& path, const std::string& what) {
  fail_argument(about(path) + what);
}

// Error messages may span lines (tinygltf's do); a note must not.
inline std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Throws Error (INVALID_ARGUMENT, naming path) unless the tree is one that the reader
// accepts: sizes that fit the model, indices in range, no NaN or infinite value. The writer
// refuses what the reader would reject, so every file boreas writes reads back.
void validate(const std::string& path, const PreprocessedTree& tree);

}  // namespace boreas::impl::wind_cache
