// boreas tests: the topology of an indexed triangle mesh — is it watertight, manifold and
// consistently oriented — by counting how each undirected edge is used and whether the
// triangles around each vertex form one fan.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace boreas::test {

// Degenerate triangles are counted and otherwise left out: they add no edges, links or
// faces (but their vertices count as referenced).
struct MeshTopology {
  int64_t vertices = 0;  // referenced by at least one triangle
  int64_t triangles = 0;
  int64_t edges = 0;                 // distinct undirected edges
  int64_t boundary_edges = 0;        // used by one triangle (a hole)
  int64_t nonmanifold_edges = 0;     // used by three or more triangles
  int64_t misoriented_edges = 0;     // used by two triangles in the same direction
  int64_t degenerate_triangles = 0;  // a repeated index
  int64_t nonmanifold_vertices = 0;  // its link is not one path (open fan) or one cycle (disc)
  int64_t unused_vertices = 0;       // of vertex_count, referenced by none
  int64_t components = 0;            // of non-degenerate triangles, through shared edges
  int64_t euler = 0;                 // V - E + F, F without the degenerate triangles

  bool watertight() const { return boundary_edges == 0 && nonmanifold_edges == 0; }
  bool manifold() const {
    return nonmanifold_edges == 0 && misoriented_edges == 0 && degenerate_triangles == 0 &&
           nonmanifold_vertices == 0;
  }
};

namespace topology_detail {

// Union-find with path halving and the lower index as root: fast enough without ranks.
inline uint32_t find_root(std::vector<uint32_t>& parent, uint32_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

inline void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

// Is the link of a vertex (the far edge b-c of each triangle around it) one path or one
// cycle: connected, no node of degree above 2? `link` holds the pairs; it is reordered.
inline bool link_is_one_fan(std::vector<uint64_t>& link, std::vector<uint32_t>& nodes,
                            std::vector<uint32_t>& parent) {
  nodes.clear();
  for (uint64_t e : link) {
    nodes.push_back(uint32_t(e >> 32));
    nodes.push_back(uint32_t(e));
  }
  std::sort(nodes.begin(), nodes.end());
  // Every node appears once per link edge at it: more than twice is a fork.
  for (size_t i = 0; i + 2 < nodes.size(); ++i)
    if (nodes[i] == nodes[i + 2]) return false;
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  parent.resize(nodes.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto slot = [&](uint32_t v) {
    return uint32_t(std::lower_bound(nodes.begin(), nodes.end(), v) - nodes.begin());
  };
  size_t groups = nodes.size();
  for (uint64_t e : link) {
    const uint32_t a = find_root(parent, slot(uint32_t(e >> 32)));
    const uint32_t b = find_root(parent, slot(uint32_t(e)));
    if (a != b) {
      unite(parent, a, b);
      --groups;
    }
  }
  return groups == 1;
}

}  // namespace topology_detail

// indices: three per triangle, each < vertex_count. The triangles around each vertex are
// gathered by a counting sort and every edge is counted at its lower vertex, so the work is
// linear apart from tiny per-vertex sorts: a few million triangles take well under a second.
inline MeshTopology mesh_topology(const std::vector<uint32_t>& indices, int64_t vertex_count) {
  using namespace topology_detail;
  MeshTopology t;
  const size_t tri_count = indices.size() / 3;
  t.triangles = int64_t(tri_count);

  std::vector<uint8_t> referenced(size_t(vertex_count), 0);
  std::vector<uint8_t> degenerate(tri_count, 0);
  std::vector<size_t> first(size_t(vertex_count) + 1, 0);
  for (size_t f = 0; f < tri_count; ++f) {
    const uint32_t a = indices[3 * f], b = indices[3 * f + 1], c = indices[3 * f + 2];
    referenced[a] = referenced[b] = referenced[c] = 1;
    if (a == b || b == c || c == a) {
      degenerate[f] = 1;
      ++t.degenerate_triangles;
      continue;
    }
    ++first[a + 1];
    ++first[b + 1];
    ++first[c + 1];
  }
  t.vertices = std::count(referenced.begin(), referenced.end(), uint8_t(1));
  t.unused_vertices = vertex_count - t.vertices;
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<uint32_t> around(first.back());
  {
    std::vector<size_t> next(first.begin(), first.end() - 1);
    for (size_t f = 0; f < tri_count; ++f)
      if (!degenerate[f])
        for (int k = 0; k < 3; ++k) around[next[indices[3 * f + k]]++] = uint32_t(f);
  }

  // Per vertex v: the edges to higher neighbours (so each edge is seen once), with the
  // triangles using them and in which direction, and v's link.
  struct Use {
    uint32_t other;
    uint32_t triangle;
    bool forward;  // the triangle runs the edge from its lower vertex to its higher
  };
  std::vector<Use> uses;
  std::vector<uint64_t> link;
  std::vector<uint32_t> nodes, link_parent;
  std::vector<uint32_t> parent(tri_count);
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t v = 0; v < size_t(vertex_count); ++v) {
    if (first[v] == first[v + 1]) continue;
    uses.clear();
    link.clear();
    for (size_t i = first[v]; i < first[v + 1]; ++i) {
      const uint32_t f = around[i];
      int k = 0;
      while (indices[3 * f + k] != v) ++k;
      const uint32_t next = indices[3 * f + (k + 1) % 3], prev = indices[3 * f + (k + 2) % 3];
      link.push_back(uint64_t(std::min(next, prev)) << 32 | std::max(next, prev));
      if (next > v) uses.push_back({next, f, true});
      if (prev > v) uses.push_back({prev, f, false});
    }
    std::sort(uses.begin(), uses.end(),
              [](const Use& a, const Use& b) { return a.other < b.other; });
    for (size_t i = 0; i < uses.size();) {
      size_t j = i;
      int forward = 0;
      for (; j < uses.size() && uses[j].other == uses[i].other; ++j) {
        forward += uses[j].forward;
        unite(parent, uses[i].triangle, uses[j].triangle);
      }
      const size_t n = j - i;
      ++t.edges;
      if (n == 1) ++t.boundary_edges;
      if (n >= 3) ++t.nonmanifold_edges;
      if (n == 2 && forward != 1) ++t.misoriented_edges;
      i = j;
    }
    if (!link_is_one_fan(link, nodes, link_parent)) ++t.nonmanifold_vertices;
  }
  for (size_t f = 0; f < tri_count; ++f)
    if (!degenerate[f] && find_root(parent, uint32_t(f)) == f) ++t.components;
  t.euler = t.vertices - t.edges + (t.triangles - t.degenerate_triangles);
  return t;
}

}  // namespace boreas::test
