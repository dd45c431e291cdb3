// boreas: meadows and imported trees gathered for the animated glTF (morph_export.h).
#include "export/morph_export.h"

#include <cmath>

#include "errors.h"
#include "export/meadow_strips.h"
#include "world.h"

namespace boreas::impl {
namespace {

constexpr size_t kPieceMaxVertices = 65535;

template <typename Id, typename F>
void check_ids(const std::vector<Id>& ids, const char* name, F get) {
  for (size_t i = 0; i < ids.size(); ++i) {
    try {
      get(ids[i]);
    } catch (const Error& e) {
      fail(e.status(), std::string(name) + "[" + std::to_string(i) + "]: " + e.what());
    }
  }
}

}  // namespace

MorphGather::MorphGather(World& world, const std::vector<boreas_meadow_id>& meadows,
                         const std::vector<boreas_mesh_tree_id>& mesh_trees, const ClumpParams& clumps,
                         gltf::ForestAnimation* a)
    : world_(world), a_(a) {
  check_ids(meadows, "meadows", [&](boreas_meadow_id id) { world_.meadow(id); });
  check_ids(mesh_trees, "mesh_trees", [&](boreas_mesh_tree_id id) { world_.mesh_tree(id); });
  for (size_t i = 0; i < meadows.size(); ++i) {
    if (clumps.clumps > 0)
      clumps_.emplace_back(world_, meadows[i], i, clumps, a_);
    else
      add_meadow(meadows[i], i);
  }
  for (size_t i = 0; i < mesh_trees.size(); ++i) add_mesh_tree(mesh_trees[i], i);
}

// The meadow's pieces: whole components while the strips fit 16-bit indices, each a base
// at the world position of its first vertex (double), colored by the components' parts.
void MorphGather::add_meadow(boreas_meadow_id id, size_t index) {
  std::vector<float> vertices;
  std::vector<int32_t> counts;
  world_.meadow_vertices(id, nullptr, &vertices, &counts);
  const std::vector<boreas_component> components = world_.meadow_components(id);
  std::map<std::pair<int32_t, int32_t>, std::array<float, 3>> colors;
  for (const boreas_meadow_part& p : world_.meadow_parts(id))
    colors[{p.species, p.part}] = {linear(p.color[0]), linear(p.color[1]), linear(p.color[2])};
  const std::array<double, 3>& origin = world_.output_origin();
  MeadowCopies copies{id, {}};
  size_t c = 0;
  while (c < counts.size()) {
    gltf::MorphBase base;
    base.name = "meadow" + std::to_string(index) + "_piece" + std::to_string(copies.pieces.size());
    base.leaf_material = true;
    gltf::MorphedMesh copy;
    copy.name = base.name;
    copy.base = int(a_->morph_bases.size());
    const float* first = &vertices[c * BOREAS_MEADOW_VERTEX_STRIDE * kMeadowFloats];
    for (size_t k = 0; k < 3; ++k) copy.position[k] = origin[k] + double(first[k]);
    MeadowPiece piece{a_->morphed.size(), c, c};
    for (; c < counts.size() && base.vertex_count() + size_t(counts[c]) <= kPieceMaxVertices; ++c) {
      const std::array<float, 3> color = colors[{components[c].species, components[c].part}];
      strip_triangles(uint32_t(base.vertex_count()), uint32_t(counts[c]), &base.indices);
      for (int32_t v = 0; v < counts[c]; ++v) {
        const float* x = &vertices[(c * BOREAS_MEADOW_VERTEX_STRIDE + size_t(v)) * kMeadowFloats];
        for (size_t k = 0; k < 3; ++k) base.positions.push_back(float(double(x[k]) - double(first[k])));
        base.normals.insert(base.normals.end(), x + 3, x + 6);
        base.colors.insert(base.colors.end(), color.begin(), color.end());
      }
    }
    piece.end = c;
    a_->morph_bases.push_back(std::move(base));
    a_->morphed.push_back(std::move(copy));
    copies.pieces.push_back(piece);
  }
  meadows_.push_back(std::move(copies));
}

// The tree's trunk and leaves, on its model's bases (its file and parts, at rest).
void MorphGather::add_mesh_tree(boreas_mesh_tree_id id, size_t index) {
  const MeshTreeInstance& tree = world_.mesh_tree(id);
  const MeshTreeParams& p = tree.params;
  for (const boreas_mesh_part part : {BOREAS_MESH_TRUNK, BOREAS_MESH_LEAVES}) {
    const MeshPart& mesh = part == BOREAS_MESH_TRUNK ? tree.model.trunk : tree.model.leaves;
    if (mesh.vertex_count() == 0) continue;
    const char* part_name = part == BOREAS_MESH_TRUNK ? "trunk" : "leaves";
    const std::string key = p.model + "\n" + p.trunk_part + "\n" + p.leaves_part + "\n" + part_name;
    auto [it, added] = model_bases_.emplace(key, int(a_->morph_bases.size()));
    if (added) {
      gltf::MorphBase base;
      base.name = "mesh_model" + std::to_string(model_bases_.size() - 1) + "_" + part_name;
      base.positions = mesh.positions;
      base.normals = mesh.normals;
      base.indices = mesh.indices;
      base.leaf_material = part == BOREAS_MESH_LEAVES;
      a_->morph_bases.push_back(std::move(base));
    }
    gltf::MorphedMesh copy;
    copy.name = "mesh_tree" + std::to_string(index) + "_" + part_name;
    copy.base = it->second;
    for (size_t k = 0; k < 3; ++k) copy.position[k] = double(p.position[k]);
    copy.rotation = p.yaw;
    copy.scale = p.scale;
    trees_.push_back({id, part, a_->morphed.size()});
    a_->morphed.push_back(std::move(copy));
  }
}

void MorphGather::search_key() {
  for (MeadowClumps& c : clumps_) c.key();
}

void MorphGather::finish(int frames) {
  for (MeadowClumps& c : clumps_) c.close_loops(size_t(frames));
}

void MorphGather::key() {
  const std::array<double, 3>& origin = world_.output_origin();
  for (MeadowClumps& c : clumps_) c.key();
  for (const MeadowCopies& m : meadows_) {
    std::vector<float> vertices;
    std::vector<int32_t> counts;
    world_.meadow_vertices(m.id, nullptr, &vertices, &counts);
    for (const MeadowPiece& piece : m.pieces) {
      gltf::MorphedMesh& copy = a_->morphed[piece.copy];
      std::vector<float> key;
      for (size_t c = piece.first; c < piece.end; ++c)
        for (int32_t v = 0; v < counts[c]; ++v) {
          const float* x = &vertices[(c * BOREAS_MEADOW_VERTEX_STRIDE + size_t(v)) * kMeadowFloats];
          for (size_t k = 0; k < 3; ++k) key.push_back(float(origin[k] + double(x[k]) - copy.position[k]));
        }
      copy.keys.push_back(std::move(key));
    }
  }
  // World to the model's space: R_y(-yaw) (x - position) / scale (place_point undone).
  for (const TreeCopy& t : trees_) {
    gltf::MorphedMesh& copy = a_->morphed[t.copy];
    const double c = std::cos(copy.rotation), s = std::sin(copy.rotation), k = 1.0 / copy.scale;
    std::vector<float> key;
    for (const boreas_vertex& v : world_.mesh_tree_vertices(t.id, t.part)) {
      const double x = origin[0] + v.position[0] - copy.position[0], y = origin[1] + v.position[1] - copy.position[1],
                   z = origin[2] + v.position[2] - copy.position[2];
      key.insert(key.end(), {float(k * (c * x - s * z)), float(k * y), float(k * (s * x + c * z))});
    }
    if (key.size() != a_->morph_bases[size_t(copy.base)].positions.size())
      fail(BOREAS_ERROR_INTERNAL, copy.name + ": the world's vertices are not its model's");
    copy.keys.push_back(std::move(key));
  }
}

}  // namespace boreas::impl
