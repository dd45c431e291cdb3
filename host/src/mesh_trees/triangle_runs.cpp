// boreas: runs of triangles with positions welded (stage 1 of the branch hierarchy, see
// branch_hierarchy.cpp): a hash grid finds the positions to weld, a union-find the runs.
#include "mesh_trees/triangle_runs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace boreas::impl {

namespace hierarchy {

namespace {

using glm::dvec3;

// No weld joins two positions farther apart than this fraction of an edge at either.
constexpr double kWeldEdgeFraction = 0.1;

int find_root(std::vector<int32_t>& parent, int32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

// Welds positions within weld_tolerance (m) of each other, but never two farther apart
// than kWeldEdgeFraction of the shortest edge at either: a twig thinner than the tolerance
// keeps its rings (a tolerance of 1e-5 of a willow's 20 m is 0.2 mm, and its finest twigs
// are 0.05 mm thick). Per vertex the index of its point, numbered in order of their
// first vertex.
std::vector<int32_t> weld_positions(const MeshPart& part, double weld_tolerance, int* point_count) {
  std::vector<double> reach(part.vertex_count(), weld_tolerance);
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = part.indices[t + k], b = part.indices[t + (k + 1) % 3];
      double edge = glm::distance(position(part, a), position(part, b));
      if (!(edge > 0.0)) continue;
      reach[a] = std::min(reach[a], kWeldEdgeFraction * edge);
      reach[b] = std::min(reach[b], kWeldEdgeFraction * edge);
    }
  // A hash grid of cells one tolerance wide: a vertex's match, if any, lies in its own
  // cell or one of the 26 around it, so the cell boundaries split no pair.
  const double cell = weld_tolerance > 0.0 ? weld_tolerance : 1e-9;
  using Key = std::array<int64_t, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const {
      // Unsigned: the products wrap instead of overflowing for far-off models.
      return size_t(uint64_t(k[0]) * 73856093u ^ uint64_t(k[1]) * 19349663u ^
                    uint64_t(k[2]) * 83492791u);
    }
  };
  std::unordered_map<Key, std::vector<uint32_t>, KeyHash> points_in_cell;  // first vertices
  std::vector<int32_t> weld(part.vertex_count());
  int32_t points = 0;
  for (uint32_t v = 0; v < part.vertex_count(); ++v) {
    const dvec3 p = position(part, v);
    // Clamped well inside int64 so the neighbour offsets below cannot overflow either.
    auto cell_of = [&](double x) { return int64_t(std::clamp(std::floor(x / cell), -4e18, 4e18)); };
    const Key key{cell_of(p.x), cell_of(p.y), cell_of(p.z)};
    int32_t match = -1;
    for (int dx = -1; dx <= 1 && match < 0; ++dx)
      for (int dy = -1; dy <= 1 && match < 0; ++dy)
        for (int dz = -1; dz <= 1 && match < 0; ++dz) {
          auto it = points_in_cell.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (it == points_in_cell.end()) continue;
          for (uint32_t u : it->second)
            if (glm::distance(position(part, u), p) <= std::min(reach[u], reach[v])) {
              match = weld[u];
              break;
            }
        }
    if (match < 0) {
      match = points++;
      points_in_cell[key].push_back(v);
    }
    weld[v] = match;
  }
  *point_count = points;
  return weld;
}

}  // namespace

Runs find_runs(const MeshPart& part, double weld_tolerance) {
  const size_t n = part.vertex_count();
  const size_t triangles = part.triangle_count();
  Runs r;
  r.weld = weld_positions(part, weld_tolerance, &r.points);

  // Triangles join when they share a vertex index (the mesh's own topology) or an edge
  // whose two ends weld to two distinct points (a seam the exporter split). A single
  // coinciding point never joins them, and a collapsed edge is a point.
  std::vector<int32_t> parent(triangles);
  std::iota(parent.begin(), parent.end(), 0);
  auto join = [&](int32_t a, int32_t b) {
    a = find_root(parent, a);
    b = find_root(parent, b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  std::vector<int32_t> triangle_of_vertex(n, -1);
  std::unordered_map<uint64_t, int32_t> triangle_of_edge;
  triangle_of_edge.reserve(3 * triangles);
  for (size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = part.indices[3 * t + k];
      if (triangle_of_vertex[v] < 0)
        triangle_of_vertex[v] = int32_t(t);
      else
        join(triangle_of_vertex[v], int32_t(t));
      const uint32_t a = uint32_t(r.weld[v]);
      const uint32_t b = uint32_t(r.weld[part.indices[3 * t + (k + 1) % 3]]);
      if (a == b) continue;
      const uint64_t edge = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
      auto [it, inserted] = triangle_of_edge.emplace(edge, int32_t(t));
      if (!inserted) join(it->second, int32_t(t));
    }
  }

  // A vertex in no triangle goes with a triangle's vertex at its point, else with the
  // other loose vertices there. Runs are numbered in order of their first vertex.
  std::vector<int32_t> triangle_at_point(r.points, -1);
  for (uint32_t v = 0; v < n; ++v)
    if (triangle_of_vertex[v] >= 0) triangle_at_point[r.weld[v]] = triangle_of_vertex[v];
  std::unordered_map<int64_t, int32_t> run_of_root;  // a triangle, or -1 - a loose point
  r.run.resize(n);
  for (uint32_t v = 0; v < n; ++v) {
    int32_t t = triangle_of_vertex[v] >= 0 ? triangle_of_vertex[v] : triangle_at_point[r.weld[v]];
    int64_t root = t >= 0 ? int64_t(find_root(parent, t)) : -1 - int64_t(r.weld[v]);
    r.run[v] = run_of_root.emplace(root, int32_t(run_of_root.size())).first->second;
  }
  r.count = int(run_of_root.size());
  return r;
}

}  // namespace hierarchy

double default_weld_tolerance(const MeshPart& part) {
  if (part.positions.empty()) return 0.0;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (uint32_t v = 0; v < part.vertex_count(); ++v) {
    lo = glm::min(lo, hierarchy::position(part, v));
    hi = glm::max(hi, hierarchy::position(part, v));
  }
  return 1e-5 * glm::distance(lo, hi);
}

std::vector<int32_t> connected_runs(const MeshPart& part, double weld_tolerance, int* run_count) {
  hierarchy::Runs r = hierarchy::find_runs(part, weld_tolerance);
  *run_count = r.count;
  return std::move(r.run);
}

}  // namespace boreas::impl
