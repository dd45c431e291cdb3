// boreas: a skeleton per run of triangles (stage 2 of the branch hierarchy, see
// branch_hierarchy.cpp): slices of the geodesic distance from one end, a circle fit across
// each, and the smooth curve through their centers.
#include "mesh_trees/branch_skeleton.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "mesh_trees/surface_graph.h"

namespace boreas::impl {

namespace hierarchy {

namespace {

using glm::dvec3;

// At most this many slices per skeleton, each at least two radii long.
constexpr int kMaxSlices = 16;
// A skeleton whose tube has more than this times the surface of its run's triangles is not
// measuring one tube (a polygon of 4 sides has 0.9 of its circle's perimeter).
constexpr double kMaxSurfaceRatio = 1.5;
// Segments per span of a skeleton's smooth curve.
constexpr int kSubdivisions = 4;

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

}  // namespace

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

void reverse(BranchSkeleton* s) {
  std::reverse(s->nodes.begin(), s->nodes.end());
  std::reverse(s->radii.begin(), s->radii.end());
  update_arc(s);
}

}  // namespace hierarchy

double BranchSkeleton::max_radius() const {
  return radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
}

void BranchSkeleton::nearest(const glm::dvec3& p, double* arc_length, double* distance,
                             double* radius) const {
  *arc_length = 0.0;
  *distance = glm::distance(p, nodes.front());
  *radius = radii.front();
  for (size_t i = 0; i + 1 < nodes.size(); ++i) {
    glm::dvec3 d = nodes[i + 1] - nodes[i];
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

}  // namespace boreas::impl
