// boreas: the checks that the preprocessed-tree glb's writer and reader share (see
// wind_cache_internal.h): what the data must be for the file to read back.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh_trees/wind_cache_internal.h"

namespace boreas::impl::wind_cache {

namespace {

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

// The branch table: parents before children, links in range, every value finite; the
// counts that come with it.
void validate_branches(const std::string& path, const MeshTreeData& d) {
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
}

// Per trunk vertex: four finite weights and a branch in range.
void validate_trunk_data(const std::string& path, const MeshPart& trunk, const MeshTreeData& d) {
  const size_t branches = d.branches.size();
  const size_t n = trunk.vertex_count();
  check_size(path, d.trunk_weights.size(), 4 * n, "trunk weights", "4 per trunk vertex");
  check_size(path, d.trunk_branch.size(), n, "trunk branches", "1 per trunk vertex");
  check_finite(path, d.trunk_weights, "trunk weights");
  for (size_t v = 0; v < n; ++v) {
    check_index(path, d.trunk_branch[v], 0, branches,
                "trunk vertex " + std::to_string(v) + "'s branch", "branches");
  }
}

// Per leaf: weights, petiole, axis and length, finite, and a branch in range; per leaf
// vertex, a leaf in range.
void validate_leaf_data(const std::string& path, const MeshPart& leaf_part, const MeshTreeData& d) {
  const size_t branches = d.branches.size();
  const size_t nl = leaf_part.vertex_count();
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

}  // namespace

void validate(const std::string& path, const PreprocessedTree& tree) {
  const MeshModel& model = tree.model;
  const MeshTreeData& d = tree.data;
  validate_part(path, model.trunk, kTrunkName);
  validate_part(path, model.leaves, kLeavesName);
  if (model.trunk.vertex_count() == 0) malformed(path, "the trunk has no triangles");
  validate_branches(path, d);
  validate_trunk_data(path, model.trunk, d);
  validate_leaf_data(path, model.leaves, d);
}

}  // namespace boreas::impl::wind_cache
