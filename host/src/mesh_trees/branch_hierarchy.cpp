// boreas: branch hierarchy from a trunk mesh's runs of triangles (Kusternig sec. 5.1.1).
//
// The stages, in order:
//   1. Runs (triangle_runs.cpp): positions within the weld tolerance (and a tenth of the edges
//   there) are one
//      point; triangles join through a shared vertex or a shared edge of two welded points,
//      never through one welded point alone. Generated trees start whorled twigs at one
//      point with one radius, so their base rings cross, and taper tips to a point.
//   2. A skeleton per run (branch_skeleton.cpp, over surface_graph.cpp): the geodesic distance over
//   the run's surface from one end
//      slices it into rings however it bends (slicing along one axis cuts a curved limb
//      obliquely and measures radii several times too large); a polyline through those
//      slices' centroids, then slices by the nearest point on it with a circle fit across
//      each, and the smooth curve through the circles' centers. A run whose skeleton would
//      have more surface than its triangles (pieces that are not one tube) has its radii
//      scaled down to match them.
//   3. The hierarchy (here, with touch_index.cpp): the paper orders the runs by diameter and finds,
//   level by level, the
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
#include <cstdint>
#include <glm/geometric.hpp>
#include <numeric>
#include <utility>

#include "errors.h"
#include "mesh_trees/surface_graph.h"
#include "mesh_trees/touch_index.h"
#include "mesh_trees/triangle_runs.h"

namespace boreas::impl {

namespace {

using glm::dvec3;
using hierarchy::find_runs;
using hierarchy::kInfinity;
using hierarchy::make_skeleton;
using hierarchy::position;
using hierarchy::reverse;
using hierarchy::Runs;
using hierarchy::surface_graph;
using hierarchy::SurfaceGraph;
using hierarchy::TouchIndex;

// An end whose radius is this many times the other's is the base: branches taper.
constexpr double kTaperedEnds = 1.25;

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

// A branch per run, with its vertices and skeleton, not yet hung on anything (level -1).
std::vector<MeshBranch> branches_of_runs(const MeshPart& trunk, const Runs& found,
                                         const SurfaceGraph& graph) {
  const int run_count = found.count;
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
  return runs;
}

// The runs by diameter, thickest first (sec. 5.1.1): the stem, then each run hangs on a
// thicker run, so parents always come before their children.
std::vector<int> order_by_diameter(const std::vector<MeshBranch>& runs) {
  std::vector<int> by_diameter(runs.size());
  std::iota(by_diameter.begin(), by_diameter.end(), 0);
  std::stable_sort(by_diameter.begin(), by_diameter.end(), [&](int a, int b) {
    double ra = runs[a].skeleton.max_radius(), rb = runs[b].skeleton.max_radius();
    return ra > rb || (ra == rb && runs[a].skeleton.length() > runs[b].skeleton.length());
  });
  return by_diameter;
}

// Makes the thickest run the stem (its skeleton running up) and hangs every other run, in
// order of diameter, on a thicker one; returns how many touched none (orphans).
int hang_runs(std::vector<MeshBranch>& runs, const std::vector<int>& by_diameter,
              double weld_tolerance) {
  const int run_count = int(runs.size());
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
  return orphans;
}

// The hierarchy of the hung runs: levels in order (the stable sort keeps discovery order
// within a level), parents and each vertex's branch renumbered to match.
MeshHierarchy renumbered(std::vector<MeshBranch> runs, const std::vector<int>& by_diameter,
                         const Runs& found, int orphans) {
  const int run_count = int(runs.size());
  std::vector<int> order = by_diameter;
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
  h.branch_of_vertex.resize(found.run.size());
  for (size_t v = 0; v < found.run.size(); ++v) h.branch_of_vertex[v] = index_of[found.run[v]];
  return h;
}

}  // namespace

MeshHierarchy build_branch_hierarchy(const MeshPart& trunk, double weld_tolerance) {
  if (trunk.triangle_count() == 0)
    fail(BOREAS_ERROR_INVALID_ARGUMENT, "the trunk part has no triangles");
  const Runs found = find_runs(trunk, weld_tolerance);
  std::vector<MeshBranch> runs = branches_of_runs(trunk, found, surface_graph(trunk, found));
  const std::vector<int> by_diameter = order_by_diameter(runs);
  const int orphans = hang_runs(runs, by_diameter, weld_tolerance);
  return renumbered(std::move(runs), by_diameter, found, orphans);
}

}  // namespace boreas::impl