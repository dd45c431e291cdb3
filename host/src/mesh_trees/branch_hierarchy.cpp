// boreas: branch hierarchy from a trunk mesh's runs of triangles (Kusternig sec. 5.1.1).
//
// The stages, in order:
//   1. Runs: positions within the weld tolerance (and a tenth of the edges there) are one
//      point; triangles join through a shared vertex or a shared edge of two welded points,
//      never through one welded point alone. Generated trees start whorled twigs at one
//      point with one radius, so their base rings cross, and taper tips to a point.
//   2. A skeleton per run: the geodesic distance over the run's surface from one end
//      slices it into rings however it bends (slicing along one axis cuts a curved limb
//      obliquely and measures radii several times too large); a polyline through those
//      slices' centroids, then slices by the nearest point on it with a circle fit across
//      each, and the smooth curve through the circles' centers. A run whose skeleton would
//      have more surface than its triangles (pieces that are not one tube) has its radii
//      scaled down to match them.
//   3. The hierarchy: the paper orders the runs by diameter and finds, level by level, the
//      branches that intersect each parent. Intersecting meshes exactly would cost a
//      triangle-triangle test per pair; generated trees (XFrog, NatFX, boreas's own export)
//      start every branch inside or on its parent's surface, so boreas tests whether a
//      branch's end touches a tube (distance to its skeleton within the two radii). Level
//      by level alone is ambiguous at forks: a twig growing from a limb's base also touches
//      the stem. Boreas therefore hangs each run, in order of diameter, on the thicker run
//      whose side its base touches best (distance over the radii); a run that starts on a
//      thicker run's base end is that run's sibling and hangs on its parent. Where nothing
//      is ambiguous that is the level-by-level answer.
#include "mesh_trees/branch_hierarchy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <utility>

#include "errors.h"

namespace boreas::impl {

namespace {

using glm::dvec3;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// At most this many slices per skeleton, each at least two radii long.
constexpr int kMaxSlices = 16;
// A skeleton whose tube has more than this times the surface of its run's triangles is not
// measuring one tube (a polygon of 4 sides has 0.9 of its circle's perimeter).
constexpr double kMaxSurfaceRatio = 1.5;
// No weld joins two positions farther apart than this fraction of an edge at either.
constexpr double kWeldEdgeFraction = 0.1;
// Segments per span of a skeleton's smooth curve.
constexpr int kSubdivisions = 4;
// An end whose radius is this many times the other's is the base: branches taper.
constexpr double kTaperedEnds = 1.25;

dvec3 position(const MeshPart& part, uint32_t v) {
  return dvec3(part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]);
}

int find_root(std::vector<int32_t>& parent, int32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

// The principal axis of a point set (power iteration on the covariance), unit; +Y for a
// point set with no extent.
dvec3 principal_axis(const std::vector<dvec3>& points, const dvec3& mean) {
  double c[3][3] = {};
  for (const dvec3& p : points) {
    dvec3 d = p - mean;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[i][j] += d[i] * d[j];
  }
  int widest = 0;
  for (int i = 1; i < 3; ++i)
    if (c[i][i] > c[widest][widest]) widest = i;
  if (!(c[widest][widest] > 0.0)) return dvec3(0.0, 1.0, 0.0);
  dvec3 a(c[0][widest], c[1][widest], c[2][widest]);
  for (int iteration = 0; iteration < 64; ++iteration) {
    dvec3 next(c[0][0] * a.x + c[0][1] * a.y + c[0][2] * a.z,
               c[1][0] * a.x + c[1][1] * a.y + c[1][2] * a.z,
               c[2][0] * a.x + c[2][1] * a.y + c[2][2] * a.z);
    double n = glm::length(next);
    if (!(n > 0.0)) break;
    a = next / n;
  }
  return glm::normalize(a);
}

void update_arc(BranchSkeleton* s) {
  s->arc.assign(s->nodes.size(), 0.0);
  for (size_t i = 1; i < s->nodes.size(); ++i)
    s->arc[i] = s->arc[i - 1] + glm::distance(s->nodes[i - 1], s->nodes[i]);
}

void reverse(BranchSkeleton* s) {
  std::reverse(s->nodes.begin(), s->nodes.end());
  std::reverse(s->radii.begin(), s->radii.end());
  update_arc(s);
}

// The center and radius of a slice of a tube: a least-squares circle (Kasa's fit) through
// the points projected on the plane normal to the axis, which finds the axis from any arc
// of a ring: where a mesh has no gaps between rings for the slice boundaries, they split
// rings, and a half ring's centroid sits 0.6 radii off the axis. Falls back to the centroid and the
// mean distance from it when the fit is degenerate or lands outside the points' spread.
void circle_center(const std::vector<dvec3>& points, const dvec3& axis, const dvec3& e1,
                   const dvec3& e2, dvec3* center, double* radius) {
  dvec3 c0 = *center;
  double spread = 0.0;
  for (const dvec3& p : points) {
    dvec3 d = p - c0;
    spread += glm::length(d - glm::dot(d, axis) * axis);
  }
  spread /= double(points.size());
  *radius = spread;
  if (points.size() < 3 || !(spread > 0.0)) return;
  // Solve for x^2 + y^2 + D x + E y + F = 0 in the plane, coordinates relative to c0 and
  // scaled by the spread for conditioning.
  double m[3][3] = {}, rhs[3] = {};
  for (const dvec3& p : points) {
    double x = glm::dot(p - c0, e1) / spread, y = glm::dot(p - c0, e2) / spread;
    double row[3] = {x, y, 1.0}, b = -(x * x + y * y);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      rhs[i] += row[i] * b;
    }
  }
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (!(std::abs(det) > 1e-9)) return;  // collinear points: no circle
  double sol[3];
  for (int c = 0; c < 3; ++c) {  // Cramer's rule on a 3x3
    double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a[i][j] = j == c ? rhs[i] : m[i][j];
    sol[c] = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
              a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
              a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) /
             det;
  }
  double cx = -0.5 * sol[0], cy = -0.5 * sol[1];
  double r2 = cx * cx + cy * cy - sol[2];
  // A sound arc has its center and radius within a few spreads of the centroid (a third
  // of a ring: about 3); points near a line give a huge circle instead.
  if (!(r2 > 0.0) || std::hypot(cx, cy) > 4.0 || r2 > 16.0) return;
  *center = c0 + spread * (cx * e1 + cy * e2);
  *radius = spread * std::sqrt(r2);
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

struct Runs {
  std::vector<int32_t> weld;  // per vertex, its welded point
  int points = 0;
  std::vector<int32_t> run;  // per vertex, its run
  int count = 0;
};

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

// The runs' surfaces as one graph for geodesic distances: a node per welded point of a
// run (seam duplicates are one node; a point that two runs share is a node in each), an
// edge per triangle edge.
struct SurfaceGraph {
  std::vector<dvec3> position;  // per node, m
  std::vector<std::vector<int32_t>> nodes_of_run;
  std::vector<uint32_t> first;  // node n's edges: neighbor[first[n], first[n + 1])
  std::vector<int32_t> neighbor;
};

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

// Slices a tube at least two radii long (the mean radius from the run's surface area),
// at most kMaxSlices.
int slice_count(double length, double area) {
  double radius = length > 0.0 ? area / (2.0 * M_PI * length) : 0.0;
  // Clamped before the conversion: a ribbon 1e-10 m wide would overflow an int.
  double slices =
      radius > 0.0 ? std::min(std::floor(length / (2.0 * radius)), double(kMaxSlices)) : kMaxSlices;
  return std::clamp(int(slices), 1, kMaxSlices);
}

// Per point its slice of `slices` along `along` (a position along the tube, m). Each
// boundary moves, within half a slice of its even spacing, to the middle of the widest gap
// between the points' values there: a tube mesh's rings are clusters of values, and a
// boundary through a ring would leave two arcs too short to fit a circle to.
std::vector<int> slice_points(const std::vector<double>& along, int slices) {
  std::vector<int> slice(along.size(), 0);
  if (along.empty() || slices < 2) return slice;
  std::vector<double> sorted = along;
  std::sort(sorted.begin(), sorted.end());
  const double lo = sorted.front(), width = (sorted.back() - lo) / slices;
  if (!(width > 0.0)) return slice;
  std::vector<double> boundary(slices - 1);
  size_t i = 0;  // sorted[i] is the first value past the window's start
  for (int j = 1; j < slices; ++j) {
    const double even = lo + j * width, from = even - 0.5 * width, to = even + 0.5 * width;
    while (i < sorted.size() && sorted[i] < from) ++i;
    boundary[j - 1] = even;
    double widest = -1.0;
    // The gaps that overlap the window: from the last value before it to the first after.
    for (size_t k = i > 0 ? i - 1 : 0; k + 1 < sorted.size() && sorted[k] <= to; ++k) {
      double gap = sorted[k + 1] - sorted[k];
      if (gap > widest) {
        widest = gap;
        boundary[j - 1] = std::clamp(0.5 * (sorted[k] + sorted[k + 1]), from, to);
      }
    }
  }
  for (size_t p = 0; p < along.size(); ++p)
    slice[p] = int(std::upper_bound(boundary.begin(), boundary.end(), along[p]) - boundary.begin());
  return slice;
}

// The unit direction of a polyline at an arc length (its segment's), +Y for a point.
dvec3 direction_at(const BranchSkeleton& s, double arc_length) {
  for (size_t i = 0; i + 1 < s.nodes.size(); ++i) {
    dvec3 d = s.nodes[i + 1] - s.nodes[i];
    if (glm::dot(d, d) > 0.0 && (arc_length <= s.arc[i + 1] || i + 2 == s.nodes.size()))
      return glm::normalize(d);
  }
  return dvec3(0.0, 1.0, 0.0);
}

// A first polyline along the run: the centroids of slices of its geodesic distance from
// one end, which follow the tube however it bends. That end is the point farthest from any
// start (a double sweep). A run too short for two slices takes its principal axis.
BranchSkeleton rough_skeleton(const SurfaceGraph& g, const std::vector<int32_t>& nodes, double area,
                              std::vector<double>* distance) {
  for (int32_t n : nodes) (*distance)[n] = kInfinity;
  int32_t end = geodesic(g, nodes.front(), distance);
  for (int32_t n : nodes) (*distance)[n] = kInfinity;
  int32_t other_end = geodesic(g, end, distance);
  std::vector<double> along(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i)  // every node is reached: runs are connected
    along[i] = std::isfinite((*distance)[nodes[i]]) ? (*distance)[nodes[i]] : 0.0;
  const int slices = slice_count((*distance)[other_end], area);
  std::vector<int> slice = slice_points(along, slices);
  std::vector<dvec3> sum(slices, dvec3(0.0));
  std::vector<int> count(slices, 0);
  for (size_t i = 0; i < nodes.size(); ++i) {
    sum[slice[i]] += g.position[nodes[i]];
    ++count[slice[i]];
  }
  BranchSkeleton rough;
  for (int k = 0; k < slices; ++k)
    if (count[k] > 0) rough.nodes.push_back(sum[k] / double(count[k]));
  if (rough.nodes.size() < 2) {
    std::vector<dvec3> points;
    dvec3 mean(0.0);
    for (int32_t n : nodes) points.push_back(g.position[n]), mean += g.position[n];
    mean /= double(points.size());
    dvec3 axis = principal_axis(points, mean);
    double lo = 0.0, hi = 0.0;
    for (const dvec3& p : points) {
      lo = std::min(lo, glm::dot(p - mean, axis));
      hi = std::max(hi, glm::dot(p - mean, axis));
    }
    rough.nodes = {mean + lo * axis, mean + hi * axis};
  }
  rough.radii.assign(rough.nodes.size(), 0.0);
  update_arc(&rough);
  return rough;
}

// A point of the centripetal Catmull-Rom spline through p0..p3 between p1 and p2,
// u in 0..1 (Barry and Goldman's form); the four points must be distinct.
dvec3 catmull_rom(const dvec3& p0, const dvec3& p1, const dvec3& p2, const dvec3& p3, double u) {
  const double t0 = 0.0, t1 = t0 + std::sqrt(glm::distance(p0, p1)),
               t2 = t1 + std::sqrt(glm::distance(p1, p2)),
               t3 = t2 + std::sqrt(glm::distance(p2, p3));
  const double t = t1 + u * (t2 - t1);
  dvec3 a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
  dvec3 a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
  dvec3 a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
  dvec3 b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
  dvec3 b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
  return ((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1);
}

// A point beyond `end` that continues the curve through prev2, prev and end with the same
// turn and the last segment's length (a straight line continues straight).
dvec3 continue_curve(const dvec3& end, const dvec3& prev, const dvec3& prev2) {
  dvec3 last = glm::normalize(end - prev), before = glm::normalize(prev - prev2);
  return end + glm::distance(end, prev) * (2.0 * glm::dot(last, before) * last - before);
}

// The polyline through the slices' centers, refined into the smooth curve through them
// (kSubdivisions segments each). A coarse mesh's rings sample a curved branch a few
// radii apart and its straight segments cut inside the curve: a generator places children
// on the curve, up to a parent's radius and more off the straight segments.
void smooth(BranchSkeleton* s) {
  std::vector<dvec3> nodes;
  std::vector<double> radii;
  for (size_t i = 0; i < s->nodes.size(); ++i)
    if (nodes.empty() || glm::distance(nodes.back(), s->nodes[i]) > 0.0) {
      nodes.push_back(s->nodes[i]);
      radii.push_back(s->radii[i]);
    }
  if (nodes.size() < 3) {
    s->nodes = nodes;
    s->radii = radii;
    return;
  }
  s->nodes = {nodes.front()};
  s->radii = {radii.front()};
  const size_t last = nodes.size() - 1;
  for (size_t i = 0; i < last; ++i) {
    dvec3 before = i > 0 ? nodes[i - 1] : continue_curve(nodes[0], nodes[1], nodes[2]);
    dvec3 after = i + 2 <= last ? nodes[i + 2]
                                : continue_curve(nodes[last], nodes[last - 1], nodes[last - 2]);
    for (int k = 1; k <= kSubdivisions; ++k) {
      double u = double(k) / kSubdivisions;
      s->nodes.push_back(k == kSubdivisions
                             ? nodes[i + 1]
                             : catmull_rom(before, nodes[i], nodes[i + 1], after, u));
      s->radii.push_back(radii[i] + u * (radii[i + 1] - radii[i]));
    }
  }
  update_arc(s);
}

// The skeleton of a run: its points sliced by their nearest point on the rough polyline,
// each slice's center and radius from a circle fit across the polyline there. The ends
// reach the run's extreme points along the end slices' directions.
BranchSkeleton make_skeleton(const SurfaceGraph& g, const std::vector<int32_t>& nodes, double area,
                             std::vector<double>* distance) {
  const BranchSkeleton rough = rough_skeleton(g, nodes, area, distance);
  std::vector<double> along(nodes.size());
  double lo = kInfinity, hi = -kInfinity;
  for (size_t i = 0; i < nodes.size(); ++i) {
    double d, r;
    rough.nearest(g.position[nodes[i]], &along[i], &d, &r);
    lo = std::min(lo, along[i]);
    hi = std::max(hi, along[i]);
  }
  const int slices = slice_count(hi - lo, area);
  const std::vector<int> slice = slice_points(along, slices);
  std::vector<std::vector<dvec3>> members(slices);
  std::vector<double> mean_along(slices, 0.0);
  for (size_t i = 0; i < nodes.size(); ++i) {
    members[slice[i]].push_back(g.position[nodes[i]]);
    mean_along[slice[i]] += along[i];
  }
  BranchSkeleton s;
  std::vector<dvec3> axes;
  std::vector<int> used;
  for (int k = 0; k < slices; ++k) {
    if (members[k].empty()) continue;
    dvec3 c(0.0);
    for (const dvec3& p : members[k]) c += p;
    c /= double(members[k].size());
    dvec3 axis = direction_at(rough, mean_along[k] / double(members[k].size()));
    dvec3 e1 =
        glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0)));
    dvec3 e2 = glm::cross(axis, e1);
    double r = 0.0;
    circle_center(members[k], axis, e1, e2, &c, &r);
    s.nodes.push_back(c);
    s.radii.push_back(r);
    axes.push_back(axis);
    used.push_back(k);
  }
  double before = 0.0, beyond = 0.0;
  for (const dvec3& p : members[used.front()])
    before = std::min(before, glm::dot(p - s.nodes.front(), axes.front()));
  for (const dvec3& p : members[used.back()])
    beyond = std::max(beyond, glm::dot(p - s.nodes.back(), axes.back()));
  smooth(&s);
  s.nodes.insert(s.nodes.begin(), s.nodes.front() + before * axes.front());
  s.radii.insert(s.radii.begin(), s.radii.front());
  s.nodes.push_back(s.nodes.back() + beyond * axes.back());
  s.radii.push_back(s.radii.back());
  update_arc(&s);

  // The tube the skeleton describes against the surface the run has.
  double tube = 0.0;
  for (size_t i = 0; i + 1 < s.nodes.size(); ++i)
    tube += M_PI * (s.radii[i] + s.radii[i + 1]) * (s.arc[i + 1] - s.arc[i]);
  if (tube > kMaxSurfaceRatio * area)
    for (double& r : s.radii) r *= area / tube;
  return s;
}

// Where an end of a branch (its center and radius) meets another branch's tube: it touches
// when score <= 1 (distance to the skeleton within the two radii, the paper's
// intersection), and it meets the tube's side unless it sits within its own radius of the
// tube's base end. A branch grows out of its parent's side; whorled siblings start at one
// point with one radius, so each lies on the others' base ends, nearer their axes than to
// the parent's.
struct Contact {
  double score = kInfinity;
  bool side = false;
};

Contact contact(const BranchSkeleton& parent, const dvec3& end, double end_radius,
                double tolerance) {
  double arc, distance, radius;
  parent.nearest(end, &arc, &distance, &radius);
  return {distance / (1.1 * (radius + end_radius) + tolerance), arc > end_radius};
}

struct Touch {
  Contact contact;
  int parent = -1;
  bool tip_first = false;  // the child's tip end is the one that touches
};

// Of two contacts: touching beats not touching, then meeting the side beats meeting the
// base end, then the nearer (in radii) wins.
bool better(const Contact& a, const Contact& b) {
  bool a_touches = a.score <= 1.0, b_touches = b.score <= 1.0;
  if (a_touches != b_touches) return a_touches;
  if (a_touches && a.side != b.side) return a.side;
  return a.score < b.score;
}

// An axis-aligned box, m.
struct Box {
  dvec3 lo{kInfinity}, hi{-kInfinity};

  void add(const Box& o) {
    lo = glm::min(lo, o.lo);
    hi = glm::max(hi, o.hi);
  }
  bool near(const dvec3& p, double margin) const {
    return glm::all(glm::greaterThanEqual(p, lo - dvec3(margin))) &&
           glm::all(glm::lessThanEqual(p, hi + dvec3(margin)));
  }
};

// The runs' tubes grown by the distance at which they touch, in a bounding volume
// hierarchy: the runs that an end may touch, without a test against every thicker run.
class TouchIndex {
 public:
  TouchIndex(const std::vector<MeshBranch>& runs, double tolerance) {
    boxes_.resize(runs.size());
    for (size_t r = 0; r < runs.size(); ++r) {
      const BranchSkeleton& s = runs[r].skeleton;
      double grow = 1.1 * s.max_radius() + tolerance;
      for (const dvec3& p : s.nodes) boxes_[r].add({p - dvec3(grow), p + dvec3(grow)});
    }
    items_.resize(runs.size());
    std::iota(items_.begin(), items_.end(), 0);
    if (!items_.empty()) build(0, int(items_.size()));
  }

  // Calls f(run) for each run whose grown box lies within margin of p.
  template <class F>
  void near(const dvec3& p, double margin, F f) const {
    if (nodes_.empty()) return;
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& n = nodes_[stack.back()];
      stack.pop_back();
      if (!n.box.near(p, margin)) continue;
      if (n.left < 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if (boxes_[items_[i]].near(p, margin)) f(items_[i]);
      } else {
        stack.push_back(n.left);
        stack.push_back(n.right);
      }
    }
  }

 private:
  struct Node {
    Box box;
    int first = 0, count = 0;   // its items
    int left = -1, right = -1;  // its children; -1 for a leaf
  };

  // A node over items [first, first + count), split at the median of their boxes' centers
  // on the axis they spread most along; returns its index.
  int build(int first, int count) {
    const int index = int(nodes_.size());
    nodes_.emplace_back();
    Box box, centers;
    for (int i = first; i < first + count; ++i) {
      const Box& b = boxes_[items_[i]];
      box.add(b);
      dvec3 c = 0.5 * (b.lo + b.hi);
      centers.add({c, c});
    }
    nodes_[index].box = box;
    nodes_[index].first = first;
    nodes_[index].count = count;
    if (count <= 4) return index;
    const dvec3 extent = centers.hi - centers.lo;
    const int axis =
        extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
    const int half = count / 2;
    std::nth_element(items_.begin() + first, items_.begin() + first + half,
                     items_.begin() + first + count, [&](int a, int b) {
                       return boxes_[a].lo[axis] + boxes_[a].hi[axis] <
                              boxes_[b].lo[axis] + boxes_[b].hi[axis];
                     });
    const int left = build(first, half);
    const int right = build(first + half, count - half);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  std::vector<Box> boxes_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
};

// The best touch of the child's base on the runs thicker than it (rank below its own).
// A child whose ends differ in radius by kTaperedEnds or more has its base at the thicker
// end; otherwise either end may be the base.
Touch best_touch(const std::vector<MeshBranch>& runs, const TouchIndex& index,
                 const std::vector<int>& by_diameter, const std::vector<int>& rank, int child,
                 double tolerance) {
  const BranchSkeleton& s = runs[child].skeleton;
  const double r_base = s.radii.front(), r_tip = s.radii.back();
  const bool base_known = r_base >= kTaperedEnds * r_tip || r_tip >= kTaperedEnds * r_base;
  const bool ends[2] = {!base_known || r_base >= r_tip, !base_known || r_tip > r_base};
  Touch best;
  auto consider = [&](int p, bool tip) {
    const dvec3& end = tip ? s.nodes.back() : s.nodes.front();
    Contact c = contact(runs[p].skeleton, end, tip ? r_tip : r_base, tolerance);
    if (better(c, best.contact)) best = {c, p, tip};
  };
  for (int tip = 0; tip < 2; ++tip) {
    if (!ends[tip]) continue;
    index.near(tip ? s.nodes.back() : s.nodes.front(), 1.1 * (tip ? r_tip : r_base), [&](int p) {
      if (rank[p] < rank[child]) consider(p, tip);
    });
  }
  // Touching none, it hangs on the nearest.
  if (best.contact.score > 1.0)
    for (int i = 0; i < rank[child]; ++i)
      for (int tip = 0; tip < 2; ++tip)
        if (ends[tip]) consider(by_diameter[i], tip);
  return best;
}

void attach(std::vector<MeshBranch>& runs, int child, const Touch& touch, bool orphan) {
  MeshBranch& c = runs[child];
  if (touch.tip_first) reverse(&c.skeleton);
  c.parent = touch.parent;
  c.level = runs[touch.parent].level + 1;
  c.orphan = orphan;
  double distance, radius;
  runs[touch.parent].skeleton.nearest(c.skeleton.nodes.front(), &c.attach_arc, &distance, &radius);
}

}  // namespace

double BranchSkeleton::max_radius() const {
  return radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
}

void BranchSkeleton::nearest(const dvec3& p, double* arc_length, double* distance,
                             double* radius) const {
  *arc_length = 0.0;
  *distance = glm::distance(p, nodes.front());
  *radius = radii.front();
  for (size_t i = 0; i + 1 < nodes.size(); ++i) {
    dvec3 d = nodes[i + 1] - nodes[i];
    double len2 = glm::dot(d, d);
    double u = len2 > 0.0 ? std::clamp(glm::dot(p - nodes[i], d) / len2, 0.0, 1.0) : 0.0;
    double dist = glm::distance(p, nodes[i] + u * d);
    if (dist < *distance) {
      *distance = dist;
      *arc_length = arc[i] + u * (arc[i + 1] - arc[i]);
      *radius = radii[i] + u * (radii[i + 1] - radii[i]);
    }
  }
}

double default_weld_tolerance(const MeshPart& part) {
  if (part.positions.empty()) return 0.0;
  dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (uint32_t v = 0; v < part.vertex_count(); ++v) {
    lo = glm::min(lo, position(part, v));
    hi = glm::max(hi, position(part, v));
  }
  return 1e-5 * glm::distance(lo, hi);
}

std::vector<int32_t> connected_runs(const MeshPart& part, double weld_tolerance, int* run_count) {
  Runs r = find_runs(part, weld_tolerance);
  *run_count = r.count;
  return std::move(r.run);
}

MeshHierarchy build_branch_hierarchy(const MeshPart& trunk, double weld_tolerance) {
  if (trunk.triangle_count() == 0)
    fail(BOREAS_ERROR_INVALID_ARGUMENT, "the trunk part has no triangles");
  const Runs found = find_runs(trunk, weld_tolerance);
  const int run_count = found.count;
  const SurfaceGraph graph = surface_graph(trunk, found);

  std::vector<double> area(run_count, 0.0);  // m^2
  for (size_t t = 0; t + 2 < trunk.indices.size(); t += 3) {
    dvec3 a = position(trunk, trunk.indices[t]), b = position(trunk, trunk.indices[t + 1]),
          c = position(trunk, trunk.indices[t + 2]);
    area[found.run[trunk.indices[t]]] += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  std::vector<MeshBranch> runs(run_count);
  for (uint32_t v = 0; v < trunk.vertex_count(); ++v) runs[found.run[v]].vertices.push_back(v);
  std::vector<double> distance(graph.position.size(), kInfinity);
  for (int r = 0; r < run_count; ++r) {
    runs[r].skeleton = make_skeleton(graph, graph.nodes_of_run[r], area[r], &distance);
    runs[r].level = -1;
  }

  // By diameter, thickest first (sec. 5.1.1): the stem, then each run hangs on a thicker
  // run, so parents always come before their children.
  std::vector<int> by_diameter(run_count);
  std::iota(by_diameter.begin(), by_diameter.end(), 0);
  std::stable_sort(by_diameter.begin(), by_diameter.end(), [&](int a, int b) {
    double ra = runs[a].skeleton.max_radius(), rb = runs[b].skeleton.max_radius();
    return ra > rb || (ra == rb && runs[a].skeleton.length() > runs[b].skeleton.length());
  });
  const int stem = by_diameter[0];
  if (runs[stem].skeleton.nodes.front().y > runs[stem].skeleton.nodes.back().y)
    reverse(&runs[stem].skeleton);
  runs[stem].level = 0;

  const double tolerance = std::max(weld_tolerance, 1e-9);
  std::vector<int> rank(run_count);
  for (int i = 0; i < run_count; ++i) rank[by_diameter[i]] = i;
  const TouchIndex index(runs, tolerance);
  int orphans = 0;
  for (int i = 1; i < run_count; ++i) {
    int c = by_diameter[i];
    Touch touch = best_touch(runs, index, by_diameter, rank, c, tolerance);
    // A run that touches no thicker run (a floating piece) hangs on the nearest one.
    bool orphan = touch.contact.score > 1.0;
    // One that starts on a thicker run's base end is its sibling (a whorl, or a fork at
    // the parent's tip): it hangs on that run's parent, which a coarse parent's straight
    // segments may have left just out of reach.
    if (!orphan && !touch.contact.side && touch.parent >= 0 && runs[touch.parent].parent >= 0)
      touch.parent = runs[touch.parent].parent;
    // No score at all (a NaN position a caller let through): the stem takes it.
    if (touch.parent < 0) touch.parent = stem, orphan = true;
    attach(runs, c, touch, orphan);
    orphans += orphan ? 1 : 0;
  }
  std::vector<int> order = by_diameter;

  // Renumber levels in order (the stable sort keeps discovery order within a level).
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return runs[a].level < runs[b].level; });
  std::vector<int> index_of(run_count);
  for (int i = 0; i < run_count; ++i) index_of[order[i]] = i;
  MeshHierarchy h;
  h.orphans = orphans;
  h.branches.reserve(run_count);
  for (int r : order) {
    MeshBranch b = std::move(runs[r]);
    if (b.parent >= 0) b.parent = index_of[b.parent];
    h.levels = std::max(h.levels, b.level + 1);
    h.branches.push_back(std::move(b));
  }
  h.branch_of_vertex.resize(trunk.vertex_count());
  for (uint32_t v = 0; v < trunk.vertex_count(); ++v)
    h.branch_of_vertex[v] = index_of[found.run[v]];
  return h;
}

}  // namespace boreas::impl
