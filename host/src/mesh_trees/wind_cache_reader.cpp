// boreas: reads the preprocessed-tree glb (its layout is in wind_cache.h). The reader first
// turns the glTF into a PreprocessedTree, checking what only the file can get wrong (types,
// counts, JSON shapes, leaves whose vertices disagree), then validates it like the writer.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "mesh_trees/model_files.h"
#include "mesh_trees/wind_cache.h"
#include "mesh_trees/wind_cache_internal.h"

namespace boreas::impl {

namespace wind_cache {

namespace {

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

  // The leaves part's per-vertex attributes: every vertex of a leaf carries its values.
  struct LeafAttributes {
    std::vector<float> weights, branch, petiole, axis;
  };

  void read_leaves(const tinygltf::Mesh& mesh, PreprocessedTree* out) const {
    const tinygltf::Primitive& p = primitive(mesh, kLeavesName);
    const size_t n = read_part(p, kLeavesName, &out->model.leaves);
    const int vec3 = TINYGLTF_TYPE_VEC3, vec4 = TINYGLTF_TYPE_VEC4, scalar = TINYGLTF_TYPE_SCALAR;
    LeafAttributes a;
    a.weights = attribute(p, kLeavesName, "_BOREAS_WEIGHTS", vec4, n);
    a.branch = attribute(p, kLeavesName, "_BOREAS_BRANCH", scalar, n);
    const std::vector<float> leaf = attribute(p, kLeavesName, "_BOREAS_LEAF", scalar, n);
    a.petiole = attribute(p, kLeavesName, "_BOREAS_PETIOLE", vec3, n);
    a.axis = attribute(p, kLeavesName, "_BOREAS_LEAF_AXIS", vec4, n);
    const std::vector<int32_t> branches = indices_of(a.branch, "leaves _BOREAS_BRANCH");

    MeshTreeData& d = out->data;
    d.leaf_of_vertex = indices_of(leaf, "leaves _BOREAS_LEAF");
    const size_t leaves = leaf_count(d.leaf_of_vertex, n);
    d.leaf_weights.resize(4 * leaves);
    d.leaf_branch.resize(leaves);
    d.leaf_petiole.resize(3 * leaves);
    d.leaf_axis.resize(3 * leaves);
    d.leaf_length.resize(leaves);
    gather_leaves(a, branches, &d);
  }

  // Every leaf has a vertex, so there are at most as many leaves as vertices.
  size_t leaf_count(const std::vector<int32_t>& leaf_of_vertex, size_t n) const {
    size_t leaves = 0;
    for (size_t v = 0; v < n; ++v) {
      if (size_t(leaf_of_vertex[v]) >= n) {
        malformed(path_, "leaves _BOREAS_LEAF element " + std::to_string(v) + " is " +
                             std::to_string(leaf_of_vertex[v]) + ", out of range (" +
                             std::to_string(n) + " leaf vertices)");
      }
      leaves = std::max(leaves, size_t(leaf_of_vertex[v]) + 1);
    }
    return leaves;
  }

  // Each leaf's values from its first vertex; its other vertices must agree, and every
  // leaf must have one.
  void gather_leaves(const LeafAttributes& a, const std::vector<int32_t>& branches,
                     MeshTreeData* d) const {
    const size_t leaves = d->leaf_branch.size();
    std::vector<int64_t> first(leaves, -1);
    for (size_t v = 0; v < d->leaf_of_vertex.size(); ++v) {
      const size_t l = size_t(d->leaf_of_vertex[v]);
      if (first[l] < 0) {
        first[l] = int64_t(v);
        std::copy_n(a.weights.begin() + 4 * v, 4, d->leaf_weights.begin() + 4 * l);
        d->leaf_branch[l] = branches[v];
        std::copy_n(a.petiole.begin() + 3 * v, 3, d->leaf_petiole.begin() + 3 * l);
        std::copy_n(a.axis.begin() + 4 * v, 3, d->leaf_axis.begin() + 3 * l);
        d->leaf_length[l] = a.axis[4 * v + 3];
        continue;
      }
      const size_t f = size_t(first[l]);
      if (const char* differs = differing_attribute(a, v, f)) {
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

  // The first attribute in which vertices v and f differ, or null.
  static const char* differing_attribute(const LeafAttributes& a, size_t v, size_t f) {
    const auto& [weights, branch, petiole, axis] = a;
    const char* differs = nullptr;
    if (!std::equal(weights.begin() + 4 * v, weights.begin() + 4 * v + 4,
                    weights.begin() + 4 * f)) {
      differs = "_BOREAS_WEIGHTS";
    } else if (branch[v] != branch[f]) {
      differs = "_BOREAS_BRANCH";
    } else if (!std::equal(petiole.begin() + 3 * v, petiole.begin() + 3 * v + 3,
                           petiole.begin() + 3 * f)) {
      differs = "_BOREAS_PETIOLE";
    } else if (!std::equal(axis.begin() + 4 * v, axis.begin() + 4 * v + 4, axis.begin() + 4 * f)) {
      differs = "_BOREAS_LEAF_AXIS";
    }
    return differs;
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

}  // namespace wind_cache

bool read_preprocessed_bytes(const std::string& path, const std::string& bytes,
                             PreprocessedTree* out, uint64_t* key) {
  const tinygltf::Model model = wind_cache::load_gltf(path, bytes);
  const tinygltf::Mesh* trunk = nullptr;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    if (mesh.extras.Has(wind_cache::kWindExtras)) {
      trunk = &mesh;
      break;
    }
  }
  if (!trunk) return false;
  PreprocessedTree tree;
  uint64_t file_key = 0;
  wind_cache::CacheReader(path, model).read(*trunk, &tree, &file_key);
  wind_cache::validate(path, tree);
  if (out) *out = std::move(tree);
  if (key) *key = file_key;
  return true;
}

bool read_preprocessed_glb(const std::string& path, PreprocessedTree* out, uint64_t* key) {
  return read_preprocessed_bytes(path, read_file_bytes(path, "preprocessed tree"), out, key);
}

}  // namespace boreas::impl
