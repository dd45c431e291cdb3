// boreas: a part's runs as one surface graph, and Dijkstra's geodesic distances over it
// (see surface_graph.h).
#include "mesh_trees/surface_graph.h"

#include <functional>
#include <glm/geometric.hpp>
#include <queue>
#include <unordered_map>
#include <utility>

namespace boreas::impl::hierarchy {

SurfaceGraph surface_graph(const MeshPart& part, const Runs& runs) {
  SurfaceGraph g;
  g.nodes_of_run.resize(runs.count);
  std::vector<int32_t> node_of_vertex(part.vertex_count());
  std::unordered_map<uint64_t, int32_t> node_of_point;
  for (uint32_t v = 0; v < part.vertex_count(); ++v) {
    const uint64_t key = uint64_t(runs.run[v]) << 32 | uint32_t(runs.weld[v]);
    auto [it, inserted] = node_of_point.emplace(key, int32_t(g.position.size()));
    if (inserted) {
      g.position.push_back(position(part, v));
      g.nodes_of_run[runs.run[v]].push_back(it->second);
    }
    node_of_vertex[v] = it->second;
  }
  const size_t nodes = g.position.size();
  std::vector<std::pair<int32_t, int32_t>> edges;
  edges.reserve(part.indices.size());
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      int32_t a = node_of_vertex[part.indices[t + k]];
      int32_t b = node_of_vertex[part.indices[t + (k + 1) % 3]];
      if (a != b) edges.emplace_back(a, b);
    }
  g.first.assign(nodes + 1, 0);
  for (auto [a, b] : edges) ++g.first[a + 1], ++g.first[b + 1];
  for (size_t i = 0; i < nodes; ++i) g.first[i + 1] += g.first[i];
  g.neighbor.resize(g.first[nodes]);
  std::vector<uint32_t> fill(g.first.begin(), g.first.end() - 1);
  for (auto [a, b] : edges) {
    g.neighbor[fill[a]++] = b;
    g.neighbor[fill[b]++] = a;
  }
  return g;
}

// Dijkstra over the edges from source through its run (distance must be infinite on the
// run's nodes); returns the farthest node reached.
int32_t geodesic(const SurfaceGraph& g, int32_t source, std::vector<double>* distance) {
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  (*distance)[source] = 0.0;
  queue.emplace(0.0, source);
  int32_t farthest = source;
  while (!queue.empty()) {
    auto [d, n] = queue.top();
    queue.pop();
    if (d > (*distance)[n]) continue;
    farthest = n;  // popped in order of distance: the last one is the farthest
    for (uint32_t e = g.first[n]; e < g.first[n + 1]; ++e) {
      int32_t m = g.neighbor[e];
      double through = d + glm::distance(g.position[n], g.position[m]);
      if (through < (*distance)[m]) {
        (*distance)[m] = through;
        queue.emplace(through, m);
      }
    }
  }
  return farthest;
}

}  // namespace boreas::impl::hierarchy
