// boreas: what the tree-model readers (obj_reader.cpp, gltf_reader.cpp) share with the
// part selection, the part builder and load_tree_model: small vector math in double, the
// messages' wording, and the readers themselves.
#pragma once

#include <array>
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>
#include <string_view>

#include "mesh_trees/tree_model.h"

namespace boreas::impl::model_import {

class PartSelector;

using Vec3 = std::array<double, 3>;
using Vec2 = std::array<double, 2>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

inline std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

inline std::string trim(std::string_view s) {
  const char* space = " \t\r\n";
  size_t begin = s.find_first_not_of(space);
  if (begin == std::string_view::npos) return {};
  size_t end = s.find_last_not_of(space);
  return std::string(s.substr(begin, end - begin + 1));
}

inline std::string vec_text(const Vec3& v) {
  std::ostringstream out;
  out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return out.str();
}

inline std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// Every message starts with the file, so that a scene with many models says which one failed.
inline std::string about(const std::string& path) { return "tree model '" + path + "': "; }

// Each reader: the file's bytes (OBJ text, or glTF text or binary) into the two parts.
// Throws Error as load_tree_model says.
MeshModel load_obj(const std::string& path, std::string text, const PartSelector& selector);
MeshModel load_gltf(const std::string& path, const std::string& bytes,
                    const PartSelector& selector);

}  // namespace boreas::impl::model_import
