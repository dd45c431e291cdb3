// boreas tests and benchmarks: EmbreeWorld's geometries read from their world through the
// public getters, as of its last step (the triangles boreas.h's "Rays" block says a ray
// sees): branch meshes, leaf quads, underbrush strips, imported trees' parts, BlobTrees.
#include <string>

#include "embree_world_impl.h"

namespace boreas::reference {

namespace {

boreas_tree_id tree_of(const EmbreeWorld::Geometry& g) {
  return boreas_tree_id{g.object.index, g.object.generation, g.object.tag};
}
boreas_meadow_id meadow_of(const EmbreeWorld::Geometry& g) {
  return boreas_meadow_id{g.object.index, g.object.generation, g.object.tag};
}
boreas_mesh_tree_id mesh_tree_of(const EmbreeWorld::Geometry& g) {
  return boreas_mesh_tree_id{g.object.index, g.object.generation, g.object.tag};
}

// The positions of boreas_vertex records into a geometry's buffer (and its padding float).
void put_positions(const std::vector<boreas_vertex>& vertices, size_t count,
                   std::vector<float>* out) {
  out->resize(3 * count + 1);
  for (size_t v = 0; v < count; ++v)
    for (int k = 0; k < 3; ++k) (*out)[3 * v + size_t(k)] = vertices[v].position[k];
  out->back() = 0.0f;
}

}  // namespace

void EmbreeWorld::Impl::read(boreas_world world, Geometry& g) {
  switch (g.source) {
    case Source::kTreeBranches: read_branches(world, g); break;
    case Source::kTreeLeaves: read_leaves(world, g); break;
    case Source::kMeadow: read_meadow(world, g); break;
    case Source::kMeshTrunk: read_mesh_part(world, g, BOREAS_MESH_TRUNK); break;
    case Source::kMeshLeaves: read_mesh_part(world, g, BOREAS_MESH_LEAVES); break;
    case Source::kFixed: return;  // add_triangles' and BlobTrees' do not move
  }
  share(g);
}

// Each branch is a (rings + 1) x (sides + 1) grid of its level, 2 rings sides triangles, in
// the order of boreas_tree_get_branches: the triangles' branches follow from the levels.
void EmbreeWorld::Impl::read_branches(boreas_world world, Geometry& g) {
  const boreas_tree_id tree = tree_of(g);
  int vertex_count = 0, index_count = 0;
  check(boreas_tree_get_mesh(world, tree, nullptr, 0, &vertex_count, nullptr, 0, &index_count),
        "boreas_tree_get_mesh (counts)");
  vertices.resize(size_t(vertex_count));
  g.indices.resize(size_t(index_count));
  check(boreas_tree_get_mesh(world, tree, vertices.data(), vertex_count, &vertex_count,
                             g.indices.data(), index_count, &index_count),
        "boreas_tree_get_mesh");
  put_positions(vertices, size_t(vertex_count), &g.positions);
  if (g.parts.size() == size_t(index_count / 3)) return;  // the topology never changes
  int branch_count = 0;
  check(boreas_tree_get_branches(world, tree, nullptr, 0, &branch_count),
        "boreas_tree_get_branches (count)");
  branches.resize(size_t(branch_count));
  check(boreas_tree_get_branches(world, tree, branches.data(), branch_count, &branch_count),
        "boreas_tree_get_branches");
  g.parts.clear();
  int64_t expected_vertices = 0;
  for (int b = 0; b < branch_count; ++b) {
    const boreas_tree_level_def& l = g.levels[size_t(branches[size_t(b)].level)];
    expected_vertices += int64_t(l.rings + 1) * (l.sides + 1);
    g.parts.insert(g.parts.end(), size_t(2 * l.rings * l.sides), b);
  }
  if (expected_vertices != vertex_count || g.parts.size() * 3 != size_t(index_count))
    throw std::runtime_error(
        "EmbreeWorld::add_tree: the tree's mesh has " + std::to_string(vertex_count) +
        " vertices and " + std::to_string(index_count / 3) + " triangles, its levels' rings and "
        "sides make " + std::to_string(expected_vertices) + " and " +
        std::to_string(g.parts.size()) + ": pass the levels the tree was added with");
}

// Each leaf the renderer's quad, corners (u, v) = (0,0), (1,0), (0,1), (1,1), two triangles
// (0, 1, 2), (1, 3, 2) (leaf_uv reads Embree's barycentrics back in this order).
void EmbreeWorld::Impl::read_leaves(boreas_world world, Geometry& g) {
  const boreas_tree_id tree = tree_of(g);
  int count = 0;
  check(boreas_tree_get_leaves(world, tree, nullptr, 0, &count), "boreas_tree_get_leaves (count)");
  leaves.resize(size_t(count));
  check(boreas_tree_get_leaves(world, tree, leaves.data(), count, &count), "boreas_tree_get_leaves");
  g.positions.resize(12 * size_t(count) + 1);
  for (int i = 0; i < count; ++i)
    for (int c = 0; c < 4; ++c)
      leaf_quad_corner(leaves[size_t(i)], float(c & 1), float(c >> 1),
                       &g.positions[12 * size_t(i) + 3 * size_t(c)]);
  g.positions.back() = 0.0f;
  if (g.indices.size() == 6 * size_t(count)) return;
  g.indices.clear();
  for (uint32_t i = 0; i < uint32_t(count); ++i) {
    const uint32_t c = 4 * i;
    g.indices.insert(g.indices.end(), {c, c + 1, c + 2, c + 1, c + 3, c + 2});
  }
}

// Component i's strip starts at vertex i * BOREAS_MEADOW_VERTEX_STRIDE; its triangles are
// (v_k, v_k+1, v_k+2) for k < count - 2 (the vertices past its count are not used).
void EmbreeWorld::Impl::read_meadow(boreas_world world, Geometry& g) {
  const boreas_meadow_id meadow = meadow_of(g);
  int vertex_count = 0;
  check(boreas_meadow_get_vertices(world, meadow, nullptr, nullptr, 0, &vertex_count, nullptr),
        "boreas_meadow_get_vertices (count)");
  const int components = vertex_count / BOREAS_MEADOW_VERTEX_STRIDE;
  meadow_vertices.resize(size_t(vertex_count));
  std::vector<int32_t> counts(static_cast<size_t>(components));
  check(boreas_meadow_get_vertices(world, meadow, nullptr, meadow_vertices.data(), vertex_count,
                                   &vertex_count, counts.data()),
        "boreas_meadow_get_vertices");
  g.positions.resize(3 * size_t(vertex_count) + 1);
  for (size_t v = 0; v < size_t(vertex_count); ++v)
    for (int k = 0; k < 3; ++k) g.positions[3 * v + size_t(k)] = meadow_vertices[v].position[k];
  g.positions.back() = 0.0f;
  if (counts == strip_counts && !g.indices.empty()) return;
  strip_counts = counts;
  g.indices.clear();
  g.parts.clear();
  for (int c = 0; c < components; ++c) {
    const uint32_t first = uint32_t(c) * BOREAS_MEADOW_VERTEX_STRIDE;
    for (int k = 0; k + 2 < counts[size_t(c)]; ++k) {
      const uint32_t v = first + uint32_t(k);
      g.indices.insert(g.indices.end(), {v, v + 1, v + 2});
      g.parts.push_back(c);
    }
  }
}

void EmbreeWorld::Impl::read_mesh_part(boreas_world world, Geometry& g, boreas_mesh_part part) {
  const boreas_mesh_tree_id tree = mesh_tree_of(g);
  int count = 0;
  check(boreas_mesh_tree_get_vertices(world, tree, part, nullptr, 0, &count),
        "boreas_mesh_tree_get_vertices (count)");
  vertices.resize(size_t(count));
  check(boreas_mesh_tree_get_vertices(world, tree, part, vertices.data(), count, &count),
        "boreas_mesh_tree_get_vertices");
  put_positions(vertices, size_t(count), &g.positions);
  if (!g.indices.empty()) return;  // an imported tree's triangles never change
  int index_count = 0;
  check(boreas_mesh_tree_get_indices(world, tree, part, nullptr, 0, &index_count),
        "boreas_mesh_tree_get_indices (count)");
  g.indices.resize(size_t(index_count));
  check(boreas_mesh_tree_get_indices(world, tree, part, g.indices.data(), index_count,
                                     &index_count),
        "boreas_mesh_tree_get_indices");
}

void EmbreeWorld::Impl::read_blobtree(boreas_world world, Geometry& g) {
  int vertex_count = 0, index_count = 0;
  check(boreas_blobtree_get_mesh(world, g.blobtree, nullptr, 0, &vertex_count, nullptr, 0,
                                 &index_count),
        "boreas_blobtree_get_mesh (counts)");
  vertices.resize(size_t(vertex_count));
  g.indices.resize(size_t(index_count));
  check(boreas_blobtree_get_mesh(world, g.blobtree, vertices.data(), vertex_count, &vertex_count,
                                 g.indices.data(), index_count, &index_count),
        "boreas_blobtree_get_mesh");
  put_positions(vertices, size_t(vertex_count), &g.positions);
  share(g);
}

}  // namespace boreas::reference
