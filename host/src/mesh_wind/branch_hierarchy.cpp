// boreas: branch hierarchy from a trunk mesh's runs of triangles (Kusternig sec. 5.1.1).
//
// The paper orders the runs by diameter and finds, level by level, the branches that
// intersect each parent. Intersecting meshes exactly would cost a triangle-triangle test
// per pair; generated trees (XFrog, NatFX, boreas's own export) start every branch inside
// or on its parent's surface, so boreas tests whether a branch's end touches a tube
// (distance to its skeleton within the two radii). Level by level alone is ambiguous at
// forks: a twig growing from a limb's base also touches the stem. Boreas therefore hangs
// each run, in order of diameter, on the thicker run its end touches best (distance over
// the radii); where nothing is ambiguous that is the level-by-level answer.
#include "mesh_wind/branch_hierarchy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "errors.h"

namespace boreas::impl {

namespace {

using glm::dvec3;

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
// of a ring. Slice boundaries split rings wherever a ring's vertices straddle one, and a
// half ring's centroid sits 0.6 radii off the axis. Falls back to the centroid and the
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

// Slices along the principal axis at least two radii wide, so that each slice holds
// whole rings of a tube (a half ring would pull its centroid off the axis); at most 16.
BranchSkeleton make_skeleton(const std::vector<dvec3>& points) {
  BranchSkeleton s;
  dvec3 mean(0.0);
  for (const dvec3& p : points) mean += p;
  mean /= double(points.size());
  dvec3 axis = principal_axis(points, mean);

  std::vector<double> t(points.size());
  double t_min = std::numeric_limits<double>::max(), t_max = -t_min, off_axis = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    t[i] = glm::dot(points[i] - mean, axis);
    t_min = std::min(t_min, t[i]);
    t_max = std::max(t_max, t[i]);
    dvec3 across = points[i] - mean - t[i] * axis;
    off_axis += glm::dot(across, across);
  }
  double radius = std::sqrt(off_axis / double(points.size()));
  double extent = t_max - t_min;
  int slices = radius > 0.0 ? int(std::floor(extent / (2.0 * radius))) : 16;
  slices = std::clamp(slices, 1, 16);

  std::vector<dvec3> sum(slices, dvec3(0.0));
  std::vector<int> count(slices, 0);
  auto slice_of = [&](double ti) {
    int k = extent > 0.0 ? int((ti - t_min) / extent * slices) : 0;
    return std::clamp(k, 0, slices - 1);
  };
  for (size_t i = 0; i < points.size(); ++i) {
    int k = slice_of(t[i]);
    sum[k] += points[i];
    ++count[k];
  }
  std::vector<std::vector<dvec3>> members(slices);
  for (size_t i = 0; i < points.size(); ++i) members[slice_of(t[i])].push_back(points[i]);
  dvec3 e1 =
      glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0)));
  dvec3 e2 = glm::cross(axis, e1);
  for (int k = 0; k < slices; ++k) {
    if (count[k] == 0) continue;
    dvec3 c = sum[k] / double(count[k]);
    double r = 0.0;
    circle_center(members[k], axis, e1, e2, &c, &r);
    s.nodes.push_back(c);
    s.radii.push_back(r);
  }
  // The ends reach the extreme vertices along the axis, through the end slices' centroids.
  dvec3 first = s.nodes.front(), last = s.nodes.back();
  s.nodes.insert(s.nodes.begin(), first + (t_min - glm::dot(first - mean, axis)) * axis);
  s.radii.insert(s.radii.begin(), s.radii.front());
  s.nodes.push_back(last + (t_max - glm::dot(last - mean, axis)) * axis);
  s.radii.push_back(s.radii.back());
  update_arc(&s);
  return s;
}

// How well branch `child`'s end touches `parent`'s tube: below 1 it touches.
double touch_score(const BranchSkeleton& parent, const dvec3& end, double end_radius,
                   double tolerance) {
  double arc, distance, radius;
  parent.nearest(end, &arc, &distance, &radius);
  return distance / (1.1 * (radius + end_radius) + tolerance);
}

struct Touch {
  double score = std::numeric_limits<double>::max();
  int parent = -1;
  bool tip_first = false;  // the child's tip end is the one that touches
};

Touch best_touch(const std::vector<MeshBranch>& runs, const std::vector<int>& candidates,
                 const MeshBranch& child, double tolerance) {
  Touch best;
  const BranchSkeleton& s = child.skeleton;
  for (int p : candidates) {
    double base = touch_score(runs[p].skeleton, s.nodes.front(), s.radii.front(), tolerance);
    double tip = touch_score(runs[p].skeleton, s.nodes.back(), s.radii.back(), tolerance);
    double score = std::min(base, tip);
    if (score < best.score) best = {score, p, tip < base};
  }
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
  const size_t n = part.vertex_count();
  // Weld: vertices in the same cell of a grid of weld_tolerance are one point. Exporters'
  // seam duplicates are bit-identical copies, so the cell boundary never splits them.
  double cell = weld_tolerance > 0.0 ? weld_tolerance : 1e-9;
  struct CellHash {
    size_t operator()(const std::array<int64_t, 3>& k) const {
      return size_t(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  std::unordered_map<std::array<int64_t, 3>, int32_t, CellHash> welded;
  std::vector<int32_t> weld(n);
  for (uint32_t v = 0; v < n; ++v) {
    dvec3 p = position(part, v) / cell;
    std::array<int64_t, 3> key{int64_t(std::floor(p.x)), int64_t(std::floor(p.y)),
                               int64_t(std::floor(p.z))};
    weld[v] = welded.emplace(key, int32_t(welded.size())).first->second;
  }
  std::vector<int32_t> parent(welded.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    int a = find_root(parent, weld[part.indices[t]]);
    for (int k = 1; k < 3; ++k) {
      int b = find_root(parent, weld[part.indices[t + k]]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::unordered_map<int32_t, int32_t> run_of_root;
  std::vector<int32_t> run(n);
  for (uint32_t v = 0; v < n; ++v)
    run[v] =
        run_of_root.emplace(find_root(parent, weld[v]), int32_t(run_of_root.size())).first->second;
  *run_count = int(run_of_root.size());
  return run;
}

MeshHierarchy build_branch_hierarchy(const MeshPart& trunk, double weld_tolerance) {
  if (trunk.triangle_count() == 0)
    fail(BOREAS_ERROR_INVALID_ARGUMENT, "the trunk part has no triangles");
  int run_count = 0;
  std::vector<int32_t> run = connected_runs(trunk, weld_tolerance, &run_count);

  std::vector<MeshBranch> runs(run_count);
  for (uint32_t v = 0; v < trunk.vertex_count(); ++v) runs[run[v]].vertices.push_back(v);
  for (MeshBranch& b : runs) {
    std::vector<dvec3> points;
    points.reserve(b.vertices.size());
    for (uint32_t v : b.vertices) points.push_back(position(trunk, v));
    b.skeleton = make_skeleton(points);
    b.level = -1;
  }

  // By diameter, thickest first (sec. 5.1.1): the stem, then each run hangs on the
  // thicker run it touches best, so parents always come before their children.
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
  int orphans = 0;
  std::vector<int> thicker{stem};
  for (int i = 1; i < run_count; ++i) {
    int c = by_diameter[i];
    Touch touch = best_touch(runs, thicker, runs[c], tolerance);
    // A run that touches no thicker run (a floating piece) hangs on the nearest one.
    bool orphan = touch.score > 1.0;
    attach(runs, c, touch, orphan);
    orphans += orphan ? 1 : 0;
    thicker.push_back(c);
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
  for (uint32_t v = 0; v < trunk.vertex_count(); ++v) h.branch_of_vertex[v] = index_of[run[v]];
  return h;
}

}  // namespace boreas::impl
