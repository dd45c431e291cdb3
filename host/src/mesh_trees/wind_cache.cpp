// boreas: writes and reads the preprocessed-tree glb (its layout is in wind_cache.h) and
// runs the preprocessing of an imported tree through it.
//
// Both directions share validate(): the writer refuses data that the reader would reject,
// so every file boreas writes reads back. The reader first turns the glTF into a
// PreprocessedTree, checking what only the file can get wrong (types, counts, JSON shapes,
// leaves whose vertices disagree), then validates it like the writer.
#include "mesh_trees/wind_cache.h"

#include <tiny_gltf.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "errors.h"
#include "fnv1a.h"
#include "gltf_building.h"
#include "mesh_trees/model_files.h"

namespace boreas::impl {

namespace {

namespace fs = std::filesystem;

constexpr char kWindExtras[] = "boreas_wind";
constexpr char kTrunkName[] = "trunk";
constexpr char kLeavesName[] = "leaves";
// Indices stored as floats must stay exact (wind_cache.h).
constexpr double kMaxFloatIndex = double(1 << 24);

std::string about(const std::string& path) { return "preprocessed tree '" + path + "': "; }

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
  fail_argument(about(path) + what);
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string hex_key(uint64_t key) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(key));
  return text;
}

// Error messages may span lines (tinygltf's do); a note must not.
std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// ---- checks shared by the writer and the reader ----

void check_finite(const std::string& path, const std::vector<float>& values, const char* what) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      malformed(path, std::string(what) + " value " + std::to_string(i) + " is " +
                          (std::isnan(values[i]) ? "NaN" : "infinite"));
    }
  }
}

template <size_t N>
void check_finite(const std::string& path, const std::array<float, N>& values,
                  const std::string& what) {
  for (float v : values) {
    if (!std::isfinite(v)) malformed(path, what + " is NaN or infinite");
  }
}

void check_size(const std::string& path, size_t size, size_t expected, const char* what,
                const char* per) {
  if (size != expected) {
    malformed(path, std::string(what) + " has " + std::to_string(size) + " values, not " +
                        std::to_string(expected) + " (" + per + ")");
  }
}

void validate_part(const std::string& path, const MeshPart& part, const char* name) {
  const size_t n = part.vertex_count();
  const std::string prefix = name;
  check_size(path, part.positions.size(), 3 * n, (prefix + " positions").c_str(), "3 per vertex");
  check_size(path, part.normals.size(), 3 * n, (prefix + " normals").c_str(), "3 per vertex");
  check_size(path, part.uvs.size(), 2 * n, (prefix + " uvs").c_str(), "2 per vertex");
  if (part.indices.size() % 3 != 0) {
    malformed(path, prefix + " has " + std::to_string(part.indices.size()) +
                        " indices, not a multiple of 3");
  }
  // glTF has no empty accessors, so a part is all there or all absent.
  if ((n == 0) != part.indices.empty()) {
    malformed(path, prefix + " has " + std::to_string(n) + " vertices and " +
                        std::to_string(part.indices.size()) + " indices");
  }
  for (size_t i = 0; i < part.indices.size(); ++i) {
    if (part.indices[i] >= n) {
      malformed(path, prefix + " index " + std::to_string(i) + " is " +
                          std::to_string(part.indices[i]) + ", out of range (" + std::to_string(n) +
                          " vertices)");
    }
  }
  check_finite(path, part.positions, (prefix + " positions").c_str());
  check_finite(path, part.normals, (prefix + " normals").c_str());
  check_finite(path, part.uvs, (prefix + " uvs").c_str());
}

void check_index(const std::string& path, int64_t index, int64_t lo, size_t count,
                 const std::string& what, const char* of) {
  if (index < lo || index >= int64_t(count)) {
    malformed(path, what + " is " + std::to_string(index) + ", out of range (" +
                        std::to_string(count) + " " + of + ")");
  }
}

void validate(const std::string& path, const PreprocessedTree& tree) {
  const MeshModel& model = tree.model;
  const MeshTreeData& d = tree.data;
  validate_part(path, model.trunk, kTrunkName);
  validate_part(path, model.leaves, kLeavesName);
  if (model.trunk.vertex_count() == 0) malformed(path, "the trunk has no triangles");

  const size_t branches = d.branches.size();
  if (branches == 0) malformed(path, "there are no branches");
  if (double(branches) > kMaxFloatIndex) malformed(path, "more than 2^24 branches");
  for (size_t i = 0; i < branches; ++i) {
    const MeshTreeBranch& b = d.branches[i];
    const std::string row = "branch " + std::to_string(i);
    // Parents come first (levels in order), which also rules out cycles.
    check_index(path, b.parent, -1, i, row + "'s parent", "branches before it");
    if (b.level < 0) malformed(path, row + "'s level is negative");
    for (int k = 0; k < kMeshTreeLevels; ++k) {
      check_index(path, b.animated_by[k], 0, branches,
                  row + "'s animated_by[" + std::to_string(k) + "]", "branches");
    }
    const std::pair<const std::array<float, 3>*, const char*> vectors[] = {
        {&b.axis, "axis"},     {&b.up, "up"},     {&b.right, "right"},
        {&b.center, "center"}, {&b.base, "base"}, {&b.tip, "tip"}};
    for (const auto& [v, name] : vectors) check_finite(path, *v, row + "'s " + name);
    check_finite(path, std::array<float, 4>{b.phase[0], b.phase[1], b.length, b.radius},
                 row + "'s phase, length or radius");
  }
  if (d.levels < 0) malformed(path, "levels is negative");
  if (d.orphans < 0 || size_t(d.orphans) > branches) {
    malformed(path, "orphans is " + std::to_string(d.orphans) + ", out of range (" +
                        std::to_string(branches) + " branches)");
  }
  check_finite(path, d.longest, "longest");

  const size_t n = model.trunk.vertex_count();
  check_size(path, d.trunk_weights.size(), 4 * n, "trunk weights", "4 per trunk vertex");
  check_size(path, d.trunk_branch.size(), n, "trunk branches", "1 per trunk vertex");
  check_finite(path, d.trunk_weights, "trunk weights");
  for (size_t v = 0; v < n; ++v) {
    check_index(path, d.trunk_branch[v], 0, branches,
                "trunk vertex " + std::to_string(v) + "'s branch", "branches");
  }

  const size_t nl = model.leaves.vertex_count();
  const size_t leaves = d.leaf_branch.size();
  check_size(path, d.leaf_of_vertex.size(), nl, "leaf of vertex", "1 per leaf vertex");
  check_size(path, d.leaf_weights.size(), 4 * leaves, "leaf weights", "4 per leaf");
  check_size(path, d.leaf_petiole.size(), 3 * leaves, "leaf petioles", "3 per leaf");
  check_size(path, d.leaf_axis.size(), 3 * leaves, "leaf axes", "3 per leaf");
  check_size(path, d.leaf_length.size(), leaves, "leaf lengths", "1 per leaf");
  if (double(leaves) > kMaxFloatIndex) malformed(path, "more than 2^24 leaves");
  check_finite(path, d.leaf_weights, "leaf weights");
  check_finite(path, d.leaf_petiole, "leaf petioles");
  check_finite(path, d.leaf_axis, "leaf axes");
  check_finite(path, d.leaf_length, "leaf lengths");
  for (size_t i = 0; i < leaves; ++i) {
    check_index(path, d.leaf_branch[i], 0, branches, "leaf " + std::to_string(i) + "'s branch",
                "branches");
  }
  for (size_t v = 0; v < nl; ++v) {
    check_index(path, d.leaf_of_vertex[v], 0, leaves,
                "leaf vertex " + std::to_string(v) + "'s leaf", "leaves");
  }
}

// ---- writing ----

// Appends data to the model's only buffer as a new view; returns the view's index.
tinygltf::Value json_real(double v) { return tinygltf::Value(v); }
tinygltf::Value json_int(int v) { return tinygltf::Value(v); }

void push_xyz(tinygltf::Value::Array* row, const std::array<float, 3>& v) {
  for (float c : v) row->push_back(json_real(c));
}

tinygltf::Value wind_extras(const MeshTreeData& d, uint64_t key) {
  tinygltf::Value::Array branches;
  for (const MeshTreeBranch& b : d.branches) {
    tinygltf::Value::Array row{json_int(b.parent), json_int(b.level)};
    for (int32_t a : b.animated_by) row.push_back(json_int(a));
    row.push_back(json_real(b.phase[0]));
    row.push_back(json_real(b.phase[1]));
    for (const auto* v : {&b.axis, &b.up, &b.right, &b.center, &b.base, &b.tip}) push_xyz(&row, *v);
    row.push_back(json_real(b.length));
    row.push_back(json_real(b.radius));
    row.push_back(json_int(b.orphan ? 1 : 0));
    branches.emplace_back(std::move(row));
  }
  tinygltf::Value::Array longest;
  for (float l : d.longest) longest.push_back(json_real(l));
  tinygltf::Value::Object wind{{"version", json_int(kWindCacheVersion)},
                               {"key", tinygltf::Value(hex_key(key))},
                               {"levels", json_int(d.levels)},
                               {"orphans", json_int(d.orphans)},
                               {"longest", tinygltf::Value(std::move(longest))},
                               {"branches", tinygltf::Value(std::move(branches))}};
  return tinygltf::Value(tinygltf::Value::Object{{kWindExtras, tinygltf::Value(std::move(wind))}});
}

std::string glb_bytes(const PreprocessedTree& tree, uint64_t key) {
  const MeshPart& trunk = tree.model.trunk;
  const MeshPart& leaves = tree.model.leaves;
  const MeshTreeData& d = tree.data;
  int bark = 0, leaf = 0;
  tinygltf::Model model = gltf::new_tree_model("boreas (preprocessed tree)", &bark, &leaf);

  const size_t n = trunk.vertex_count();
  std::vector<float> branch(n);
  for (size_t v = 0; v < n; ++v) branch[v] = float(d.trunk_branch[v]);
  // add_floats grows the accessors, not the meshes: the reference stays valid.
  tinygltf::Mesh& trunk_mesh = model.meshes[size_t(gltf::add_triangle_mesh(
      model, trunk.positions, trunk.normals, trunk.uvs, trunk.indices, kTrunkName, bark))];
  std::map<std::string, int>& trunk_attributes = trunk_mesh.primitives[0].attributes;
  trunk_attributes["_BOREAS_WEIGHTS"] =
      gltf::add_floats(model, d.trunk_weights, TINYGLTF_TYPE_VEC4, n);
  trunk_attributes["_BOREAS_BRANCH"] = gltf::add_floats(model, branch, TINYGLTF_TYPE_SCALAR, n);
  trunk_mesh.extras = wind_extras(d, key);

  const size_t nl = leaves.vertex_count();
  if (nl > 0) {
    // The per-leaf data repeated on each of the leaf's vertices, for engines that read
    // vertex attributes only.
    std::vector<float> weights(4 * nl), branches(nl), index(nl), petiole(3 * nl), axis(4 * nl);
    for (size_t v = 0; v < nl; ++v) {
      const size_t l = size_t(d.leaf_of_vertex[v]);
      std::copy_n(d.leaf_weights.begin() + 4 * l, 4, weights.begin() + 4 * v);
      branches[v] = float(d.leaf_branch[l]);
      index[v] = float(l);
      std::copy_n(d.leaf_petiole.begin() + 3 * l, 3, petiole.begin() + 3 * v);
      std::copy_n(d.leaf_axis.begin() + 3 * l, 3, axis.begin() + 4 * v);
      axis[4 * v + 3] = d.leaf_length[l];
    }
    std::map<std::string, int>& attributes =
        model
            .meshes[size_t(gltf::add_triangle_mesh(model, leaves.positions, leaves.normals,
                                                   leaves.uvs, leaves.indices, kLeavesName, leaf))]
            .primitives[0]
            .attributes;
    attributes["_BOREAS_WEIGHTS"] = gltf::add_floats(model, weights, TINYGLTF_TYPE_VEC4, nl);
    attributes["_BOREAS_BRANCH"] = gltf::add_floats(model, branches, TINYGLTF_TYPE_SCALAR, nl);
    attributes["_BOREAS_LEAF"] = gltf::add_floats(model, index, TINYGLTF_TYPE_SCALAR, nl);
    attributes["_BOREAS_PETIOLE"] = gltf::add_floats(model, petiole, TINYGLTF_TYPE_VEC3, nl);
    attributes["_BOREAS_LEAF_AXIS"] = gltf::add_floats(model, axis, TINYGLTF_TYPE_VEC4, nl);
  }

  std::string bytes;
  if (!gltf::glb_bytes(model, &bytes))
    fail(BOREAS_ERROR_INTERNAL, "tinygltf could not serialize the preprocessed tree");
  return bytes;
}

// Through a temporary file in the same folder and a rename, which replaces the old file at
// once: a process reading the cache meanwhile sees the old file or the new, never half.
void write_file_replacing(const std::string& path, const std::string& bytes) {
  static std::atomic<unsigned> counter{0};
  const std::string temp =
      path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
  std::ofstream out(temp, std::ios::binary | std::ios::trunc);
  if (!out) {
    fail(BOREAS_ERROR_IO, "cannot write " + about(path) + "cannot create '" + temp + "' (" +
                              std::strerror(errno) + ")");
  }
  out.write(bytes.data(), std::streamsize(bytes.size()));
  out.close();
  std::error_code ec;
  if (!out) {
    fs::remove(temp, ec);
    fail(BOREAS_ERROR_IO, "cannot write " + about(path) + "writing '" + temp + "' failed");
  }
  fs::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    fail(BOREAS_ERROR_IO, "cannot write " + about(path) + ec.message());
  }
}

// ---- reading ----

tinygltf::Model load_gltf(const std::string& path, const std::string& bytes) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
    malformed(path, "larger than 4 GiB, more than tinygltf reads");
  }

  tinygltf::Model model;
  std::string error;
  const bool ok = parse_gltf(bytes, path, &model, &error);
  if (!ok) {
    malformed(path, "not a readable glTF file (tinygltf: " +
                        (error.empty() ? std::string("no reason given") : one_line(error)) + ")");
  }
  return model;
}

// Turns the glTF into a PreprocessedTree, checking what validate() cannot see.
class CacheReader {
 public:
  CacheReader(const std::string& path, const tinygltf::Model& model)
      : path_(path), model_(model), accessors_(model, about(path)) {}

  void read(const tinygltf::Mesh& trunk_mesh, PreprocessedTree* out, uint64_t* key) {
    const tinygltf::Primitive& trunk = primitive(trunk_mesh, kTrunkName);
    const size_t n = read_part(trunk, kTrunkName, &out->model.trunk);
    MeshTreeData& d = out->data;
    d.trunk_weights = attribute(trunk, kTrunkName, "_BOREAS_WEIGHTS", TINYGLTF_TYPE_VEC4, n);
    d.trunk_branch =
        indices_of(attribute(trunk, kTrunkName, "_BOREAS_BRANCH", TINYGLTF_TYPE_SCALAR, n),
                   "trunk _BOREAS_BRANCH");
    read_extras(trunk_mesh.extras.Get(kWindExtras), &d, key);
    for (const tinygltf::Mesh& mesh : model_.meshes) {
      if (mesh.name == kLeavesName && &mesh != &trunk_mesh) {
        read_leaves(mesh, out);
        break;
      }
    }
  }

 private:
  const tinygltf::Primitive& primitive(const tinygltf::Mesh& mesh, const char* part) const {
    if (mesh.primitives.size() != 1) {
      malformed(path_, std::string("the ") + part + " mesh has " +
                           std::to_string(mesh.primitives.size()) + " primitives, not 1");
    }
    const tinygltf::Primitive& p = mesh.primitives[0];
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES) {
      malformed(path_, std::string("the ") + part + " primitive's mode is " +
                           std::to_string(p.mode) + ", not TRIANGLES");
    }
    return p;
  }

  // The cache writes FLOAT only: anything else was not written by boreas.
  std::vector<float> floats(int index, int type, const std::string& what) const {
    if (index >= 0 && size_t(index) < model_.accessors.size()) {
      const tinygltf::Accessor& a = model_.accessors[size_t(index)];
      if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != type) {
        malformed(path_, what + " is not " + type_name(type) + " FLOAT");
      }
    }
    const std::vector<double> read = accessors_.floats(index, what, type);
    const std::vector<float> values(read.begin(), read.end());  // exact: they were floats
    const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(type)));
    for (size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i])) {
        malformed(path_, what + " element " + std::to_string(i / components) + " is " +
                             (std::isnan(values[i]) ? "NaN" : "infinite"));
      }
    }
    return values;
  }

  std::vector<uint32_t> indices(int index, const std::string& what) const {
    if (index < 0) malformed(path_, what + " are missing");
    return accessors_.indices(index, what);
  }

  static std::string type_name(int type) {
    switch (type) {
      case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
      case TINYGLTF_TYPE_VEC2:
        return "VEC2";
      case TINYGLTF_TYPE_VEC3:
        return "VEC3";
      default:
        return "VEC4";
    }
  }

  // The attribute's values, which must number `count` elements (POSITION's).
  std::vector<float> attribute(const tinygltf::Primitive& p, const char* part, const char* name,
                               int type, size_t count) const {
    const std::string what = std::string(part) + " " + name;
    auto it = p.attributes.find(name);
    if (it == p.attributes.end())
      malformed(path_, "the " + std::string(part) + " mesh has no " + name);
    std::vector<float> values = floats(it->second, type, what);
    const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(type)));
    if (values.size() != count * components) {
      malformed(path_, what + " has " + std::to_string(values.size() / components) +
                           " elements, POSITION " + std::to_string(count));
    }
    return values;
  }

  size_t read_part(const tinygltf::Primitive& p, const char* part, MeshPart* out) const {
    auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end())
      malformed(path_, std::string("the ") + part + " mesh has no POSITION");
    out->positions = floats(position->second, TINYGLTF_TYPE_VEC3, std::string(part) + " POSITION");
    const size_t n = out->positions.size() / 3;
    out->normals = attribute(p, part, "NORMAL", TINYGLTF_TYPE_VEC3, n);
    out->uvs = attribute(p, part, "TEXCOORD_0", TINYGLTF_TYPE_VEC2, n);
    out->indices = indices(p.indices, std::string(part) + " indices");
    return n;
  }

  // Indices stored as floats (wind_cache.h): whole numbers, exact in a float.
  std::vector<int32_t> indices_of(const std::vector<float>& values, const std::string& what) const {
    std::vector<int32_t> out(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
      const float v = values[i];
      if (v != std::floor(v) || v < 0.0f || double(v) > kMaxFloatIndex) {
        malformed(path_, what + " element " + std::to_string(i) + " is " + std::to_string(v) +
                             ", not an index");
      }
      out[i] = int32_t(v);
    }
    return out;
  }

  void read_leaves(const tinygltf::Mesh& mesh, PreprocessedTree* out) const {
    const tinygltf::Primitive& p = primitive(mesh, kLeavesName);
    const size_t n = read_part(p, kLeavesName, &out->model.leaves);
    const int vec3 = TINYGLTF_TYPE_VEC3, vec4 = TINYGLTF_TYPE_VEC4, scalar = TINYGLTF_TYPE_SCALAR;
    const std::vector<float> weights = attribute(p, kLeavesName, "_BOREAS_WEIGHTS", vec4, n);
    const std::vector<float> branch = attribute(p, kLeavesName, "_BOREAS_BRANCH", scalar, n);
    const std::vector<float> leaf = attribute(p, kLeavesName, "_BOREAS_LEAF", scalar, n);
    const std::vector<float> petiole = attribute(p, kLeavesName, "_BOREAS_PETIOLE", vec3, n);
    const std::vector<float> axis = attribute(p, kLeavesName, "_BOREAS_LEAF_AXIS", vec4, n);
    const std::vector<int32_t> branches = indices_of(branch, "leaves _BOREAS_BRANCH");

    MeshTreeData& d = out->data;
    d.leaf_of_vertex = indices_of(leaf, "leaves _BOREAS_LEAF");
    // Every leaf has a vertex, so there are at most as many leaves as vertices.
    size_t leaves = 0;
    for (size_t v = 0; v < n; ++v) {
      if (size_t(d.leaf_of_vertex[v]) >= n) {
        malformed(path_, "leaves _BOREAS_LEAF element " + std::to_string(v) + " is " +
                             std::to_string(d.leaf_of_vertex[v]) + ", out of range (" +
                             std::to_string(n) + " leaf vertices)");
      }
      leaves = std::max(leaves, size_t(d.leaf_of_vertex[v]) + 1);
    }
    d.leaf_weights.resize(4 * leaves);
    d.leaf_branch.resize(leaves);
    d.leaf_petiole.resize(3 * leaves);
    d.leaf_axis.resize(3 * leaves);
    d.leaf_length.resize(leaves);
    std::vector<int64_t> first(leaves, -1);
    for (size_t v = 0; v < n; ++v) {
      const size_t l = size_t(d.leaf_of_vertex[v]);
      if (first[l] < 0) {
        first[l] = int64_t(v);
        std::copy_n(weights.begin() + 4 * v, 4, d.leaf_weights.begin() + 4 * l);
        d.leaf_branch[l] = branches[v];
        std::copy_n(petiole.begin() + 3 * v, 3, d.leaf_petiole.begin() + 3 * l);
        std::copy_n(axis.begin() + 4 * v, 3, d.leaf_axis.begin() + 3 * l);
        d.leaf_length[l] = axis[4 * v + 3];
        continue;
      }
      const size_t f = size_t(first[l]);
      const char* differs = nullptr;
      if (!std::equal(weights.begin() + 4 * v, weights.begin() + 4 * v + 4,
                      weights.begin() + 4 * f)) {
        differs = "_BOREAS_WEIGHTS";
      } else if (branch[v] != branch[f]) {
        differs = "_BOREAS_BRANCH";
      } else if (!std::equal(petiole.begin() + 3 * v, petiole.begin() + 3 * v + 3,
                             petiole.begin() + 3 * f)) {
        differs = "_BOREAS_PETIOLE";
      } else if (!std::equal(axis.begin() + 4 * v, axis.begin() + 4 * v + 4,
                             axis.begin() + 4 * f)) {
        differs = "_BOREAS_LEAF_AXIS";
      }
      if (differs) {
        malformed(path_, std::string("leaves vertices ") + std::to_string(f) + " and " +
                             std::to_string(v) + " of leaf " + std::to_string(l) +
                             " have different " + differs);
      }
    }
    for (size_t l = 0; l < leaves; ++l) {
      if (first[l] < 0) {
        malformed(path_, "leaf " + std::to_string(l) + " has no vertices (_BOREAS_LEAF skips it)");
      }
    }
  }

  // ---- the "boreas_wind" extras ----

  double number(const tinygltf::Value& v, const std::string& what) const {
    if (!v.IsNumber()) malformed(path_, "boreas_wind " + what + " is missing or not a number");
    return v.GetNumberAsDouble();
  }

  float real(const tinygltf::Value& v, const std::string& what) const {
    const float f = float(number(v, what));
    if (!std::isfinite(f)) malformed(path_, "boreas_wind " + what + " is not a finite float");
    return f;
  }

  int32_t integer(const tinygltf::Value& v, const std::string& what) const {
    const double d = number(v, what);
    if (d != std::floor(d) || d < std::numeric_limits<int32_t>::min() ||
        d > std::numeric_limits<int32_t>::max()) {
      malformed(path_, "boreas_wind " + what + " is " + std::to_string(d) + ", not an integer");
    }
    return int32_t(d);
  }

  const tinygltf::Value& array(const tinygltf::Value& v, size_t size,
                               const std::string& what) const {
    // tinygltf drops nulls from arrays (and JSON writes NaN as null), so a NaN shows as a
    // short array.
    if (!v.IsArray() || (size > 0 && v.ArrayLen() != size)) {
      malformed(path_, "boreas_wind " + what + " is not an array of " + std::to_string(size) +
                           (v.IsArray() ? " (it has " + std::to_string(v.ArrayLen()) + ")" : ""));
    }
    return v;
  }

  void read_extras(const tinygltf::Value& wind, MeshTreeData* d, uint64_t* key) const {
    if (!wind.IsObject()) malformed(path_, "boreas_wind is not an object");
    const int version = integer(wind.Get("version"), "version");
    if (version != kWindCacheVersion) {
      malformed(path_, "boreas_wind version " + std::to_string(version) + ", this boreas reads " +
                           std::to_string(kWindCacheVersion) + " (preprocess the model again)");
    }
    const tinygltf::Value& key_value = wind.Get("key");
    const std::string text = key_value.IsString() ? key_value.Get<std::string>() : std::string();
    if (text.size() != 16 ||
        text.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
      malformed(path_, "boreas_wind key is not 16 hex digits");
    }
    *key = std::stoull(text, nullptr, 16);
    d->levels = integer(wind.Get("levels"), "levels");
    d->orphans = integer(wind.Get("orphans"), "orphans");
    const tinygltf::Value& longest = array(wind.Get("longest"), kMeshTreeLevels, "longest");
    for (int k = 0; k < kMeshTreeLevels; ++k) d->longest[k] = real(longest.Get(k), "longest");
    const tinygltf::Value& rows = wind.Get("branches");
    if (!rows.IsArray()) malformed(path_, "boreas_wind branches is missing or not an array");
    d->branches.resize(rows.ArrayLen());
    for (size_t i = 0; i < rows.ArrayLen(); ++i) {
      const std::string name = "branch " + std::to_string(i);
      const tinygltf::Value& row = array(rows.Get(int(i)), kWindCacheColumns, name);
      int c = 0;
      auto next_int = [&] {
        const int k = c++;
        return integer(row.Get(k), name + " column " + std::to_string(k));
      };
      auto next_real = [&] {
        const int k = c++;
        return real(row.Get(k), name + " column " + std::to_string(k));
      };
      MeshTreeBranch& b = d->branches[i];
      b.parent = next_int();
      b.level = next_int();
      for (int32_t& a : b.animated_by) a = next_int();
      for (float& p : b.phase) p = next_real();
      for (auto* v : {&b.axis, &b.up, &b.right, &b.center, &b.base, &b.tip}) {
        for (float& x : *v) x = next_real();
      }
      b.length = next_real();
      b.radius = next_real();
      const int orphan = next_int();
      if (orphan != 0 && orphan != 1) malformed(path_, name + "'s orphan column is not 0 or 1");
      b.orphan = orphan == 1;
    }
  }

  const std::string& path_;
  const tinygltf::Model& model_;
  GltfAccessors accessors_;
};

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

void write_preprocessed_glb(const std::string& path, const PreprocessedTree& tree, uint64_t key) {
  try {
    validate(path, tree);
  } catch (const Error& e) {
    fail_argument(std::string("cannot write ") + e.what());
  }
  write_file_replacing(path, glb_bytes(tree, key));
}

bool read_preprocessed_bytes(const std::string& path, const std::string& bytes,
                             PreprocessedTree* out, uint64_t* key) {
  const tinygltf::Model model = load_gltf(path, bytes);
  const tinygltf::Mesh* trunk = nullptr;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    if (mesh.extras.Has(kWindExtras)) {
      trunk = &mesh;
      break;
    }
  }
  if (!trunk) return false;
  PreprocessedTree tree;
  uint64_t file_key = 0;
  CacheReader(path, model).read(*trunk, &tree, &file_key);
  validate(path, tree);
  if (out) *out = std::move(tree);
  if (key) *key = file_key;
  return true;
}

bool read_preprocessed_glb(const std::string& path, PreprocessedTree* out, uint64_t* key) {
  return read_preprocessed_bytes(path, read_file_bytes(path, "preprocessed tree"), out, key);
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
