// boreas: writes the preprocessed-tree glb (its layout is in wind_cache.h), through the
// glTF building helpers, after validate() has accepted the data.
#include <tiny_gltf.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "boreas_gltf/gltf_building.h"
#include "errors.h"
#include "mesh_trees/wind_cache.h"
#include "mesh_trees/wind_cache_internal.h"

namespace boreas::impl {

namespace wind_cache {

namespace {

namespace fs = std::filesystem;

std::string hex_key(uint64_t key) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(key));
  return text;
}

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

}  // namespace

}  // namespace wind_cache

void write_preprocessed_glb(const std::string& path, const PreprocessedTree& tree, uint64_t key) {
  try {
    wind_cache::validate(path, tree);
  } catch (const Error& e) {
    fail_argument(std::string("cannot write ") + e.what());
  }
  wind_cache::write_file_replacing(path, wind_cache::glb_bytes(tree, key));
}

}  // namespace boreas::impl
