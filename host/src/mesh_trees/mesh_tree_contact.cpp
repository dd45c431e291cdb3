// boreas: the host's part of colliders against imported trees (mesh_tree_contact.h).
#include "mesh_trees/mesh_tree_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "shared/mesh_tree_contact_types.h"
#include "shared/mesh_tree_types.h"

namespace boreas::impl {

namespace {

constexpr int kSegments = BOREAS_MESH_TREE_CONTACT_SEGMENTS;
constexpr int kPoints = BOREAS_MESH_TREE_CONTACT_POINTS;
using P3 = std::array<double, 3>;

P3 from(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }
double distance(const P3& a, const P3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// The skeleton as boreas keeps it: base -> center -> tip (model space).
struct Polyline {
  P3 base, center, tip;
  double l1 = 0.0, l2 = 0.0;  // the two pieces' lengths, m

  explicit Polyline(const MeshTreeBranch& b)
      : base(from(b.base)),
        center(from(b.center)),
        tip(from(b.tip)),
        l1(distance(base, center)),
        l2(distance(center, tip)) {}

  // The point a share f of the way along it, by length.
  P3 at(double f) const {
    const double s = f * (l1 + l2);
    const bool first = s <= l1;
    const P3& a = first ? base : center;
    const P3& b = first ? center : tip;
    const double span = first ? l1 : l2;
    const double u = span > 0.0 ? std::clamp((first ? s : s - l1) / span, 0.0, 1.0) : 0.0;
    P3 p;
    for (size_t k = 0; k < 3; ++k) p[k] = a[k] + u * (b[k] - a[k]);
    return p;
  }

  // The share along it of the point nearest p, and p's distance from it.
  void nearest(const P3& p, double* f, double* d) const {
    *d = std::numeric_limits<double>::infinity();
    const P3* ends[2][2] = {{&base, &center}, {&center, &tip}};
    const double before[2] = {0.0, l1}, length[2] = {l1, l2};
    for (int piece = 0; piece < 2; ++piece) {
      const P3& a = *ends[piece][0];
      const P3& b = *ends[piece][1];
      double dot = 0.0;
      for (size_t k = 0; k < 3; ++k) dot += (p[k] - a[k]) * (b[k] - a[k]);
      const double u =
          length[piece] > 0.0 ? std::clamp(dot / (length[piece] * length[piece]), 0.0, 1.0) : 0.0;
      P3 q;
      for (size_t k = 0; k < 3; ++k) q[k] = a[k] + u * (b[k] - a[k]);
      const double r = distance(p, q);
      if (r < *d)
        *d = r, *f = (l1 + l2) > 0.0 ? (before[piece] + u * length[piece]) / (l1 + l2) : 0.0;
    }
  }
};

// Branch j's contact points, model space: at shares 0, 1/S, ..., 1 of its skeleton, each
// with the radius of the cone that holds the branch's vertices nearest it (the branch's own
// radius where none is), and their weights (0..1, not yet raised to the bend exponent).
struct Points {
  std::array<P3, kPoints> point{};
  std::array<double, kPoints> radius{};
  std::array<std::array<double, 4>, kPoints> weight{};
};

Points branch_points(const MeshTreeInstance& tree, size_t j, const std::vector<uint32_t>& verts) {
  const MeshTreeData& d = tree.data;
  const MeshTreeBranch& b = d.branches[j];
  const MeshPart& trunk = tree.model.trunk;
  const Polyline line(b);
  Points s;
  std::array<bool, kPoints> held{};
  for (size_t k = 0; k < size_t(kPoints); ++k) {
    s.point[k] = line.at(double(k) / kSegments);
    s.radius[k] = 0.0;
  }
  for (uint32_t v : verts) {
    const P3 p = {trunk.positions[3 * v], trunk.positions[3 * v + 1], trunk.positions[3 * v + 2]};
    double f = 0.0, r = 0.0;
    line.nearest(p, &f, &r);
    const size_t k = size_t(std::lround(f * kSegments));
    s.radius[k] = std::max(s.radius[k], r);
    held[k] = true;
  }
  // The weights of the levels above the branch's own are its base's: any of its vertices
  // carries them (wind_weights.cpp); its own level's runs along it.
  std::array<double, 4> base{};
  if (!verts.empty())
    for (size_t k = 0; k < 4; ++k) base[k] = d.trunk_weights[4 * size_t(verts[0]) + k];
  for (size_t k = 0; k < size_t(kPoints); ++k) {
    if (!held[k]) s.radius[k] = b.radius;
    s.weight[k] = base;
    if (b.level < kMeshTreeLevels) {
      const double longest = d.longest[size_t(b.level)];
      const double arc = double(k) / kSegments * b.length;
      s.weight[k][size_t(b.level)] = longest > 0.0 ? std::clamp(arc / longest, 0.0, 1.0) : 0.0;
      for (size_t l = size_t(b.level) + 1; l < 4; ++l) s.weight[k][l] = 0.0;
    }
  }
  return s;
}

// The weight of the branch's tip (raised to the bend exponent), kept off 0.
double tip_weight(const MeshTreeInstance& tree, const MeshTreeBranch& b) {
  const double longest = tree.data.longest[size_t(b.level)];
  const double own = longest > 0.0 ? std::clamp(double(b.length) / longest, 0.0, 1.0) : 0.0;
  return std::max(std::pow(own, double(tree.params.bend_exponent)), 1e-3);
}

// 1 / k_a, m/N (cl/shared/mesh_tree_contact.h): the branch's tip as a cantilever of green
// wood, seen through its weight at the tip. 0 for a branch beyond level 3, which animates
// no level and so is never bent itself.
double compliance(const MeshTreeInstance& tree, const MeshTreeBranch& b) {
  if (b.level >= kMeshTreeLevels) return 0.0;
  const double scale = tree.params.scale;
  const double r = std::max(double(b.radius) * scale, 1e-4);
  const double length = std::max(double(b.length) * scale, 1e-3);
  const double inertia = M_PI * r * r * r * r / 4.0;
  const double k_tip = 3.0 * kMeshTreeWoodModulus * inertia / (length * length * length);
  const double w_tip = tip_weight(tree, b);
  return 1.0 / (k_tip * w_tip * w_tip);
}

}  // namespace

void place_contact_table(const MeshTreeInstance& tree, std::vector<float>& planes, size_t stride,
                         size_t first) {
  const MeshTreeData& d = tree.data;
  const MeshTreeParams& params = tree.params;
  std::vector<std::vector<uint32_t>> verts(d.branches.size());
  for (size_t v = 0; v < d.trunk_branch.size(); ++v)
    verts[size_t(d.trunk_branch[v])].push_back(uint32_t(v));
  auto put = [&](int plane, size_t i, double value) {
    planes[size_t(plane) * stride + i] = float(value);
  };
  for (size_t j = 0; j < d.branches.size(); ++j) {
    const size_t i = first + j;
    const MeshTreeBranch& b = d.branches[j];
    const Points s = branch_points(tree, j, verts[j]);
    for (int k = 0; k < kPoints; ++k) {
      const float model[3] = {float(s.point[size_t(k)][0]), float(s.point[size_t(k)][1]),
                              float(s.point[size_t(k)][2])};
      float local[3];  // the tree's own coordinates (TREE_ORIGIN), as its colliders are
      place_local(params, model, local);
      for (int a = 0; a < 3; ++a) put(BOREAS_MESH_TREE_CONTACT_POINT + 3 * k + a, i, local[a]);
      for (int l = 0; l < 4; ++l)
        put(BOREAS_MESH_TREE_CONTACT_WEIGHT + 4 * k + l, i,
            std::pow(s.weight[size_t(k)][size_t(l)], double(params.bend_exponent)));
      put(BOREAS_MESH_TREE_CONTACT_RADIUS + k, i, s.radius[size_t(k)] * params.scale);
    }
    put(BOREAS_MESH_TREE_CONTACT_COMPLIANCE, i, compliance(tree, b));
    const int level = std::min(b.level, kMeshTreeLevels - 1);
    put(BOREAS_MESH_TREE_CONTACT_OMEGA, i, 2.0 * M_PI * params.levels[size_t(level)].frequency);
    // Its tip moves at most half its length (0: a branch past level 3 is never bent).
    put(BOREAS_MESH_TREE_CONTACT_LIMIT, i,
        b.level < kMeshTreeLevels ? 0.5 * b.length * params.scale / tip_weight(tree, b) : 0.0);
  }
}

Bounds mesh_tree_reach(const MeshTreeInstance& tree) {
  const MeshTreeParams& p = tree.params;
  Bounds box;
  box.lo.fill(std::numeric_limits<double>::infinity());
  box.hi.fill(-std::numeric_limits<double>::infinity());
  for (const MeshPart* part : {&tree.model.trunk, &tree.model.leaves})
    for (size_t v = 0; v < part->vertex_count(); ++v) {
      float world[3];
      place_point(p, &part->positions[3 * v], world);
      for (size_t a = 0; a < 3; ++a) {
        box.lo[a] = std::min(box.lo[a], double(world[a]));
        box.hi[a] = std::max(box.hi[a], double(world[a]));
      }
    }
  // Each level moves a vertex by at most its weight (1) times the load times its bend and
  // its sway (the noise's channels stay within about 2); leaves flutter besides. The load
  // follows the drag law without a ceiling (mesh_tree_drag.h): the box holds what it gives
  // in kMeshTreeReachSpeed of wind, past the strongest hurricanes' sustained winds; in a
  // stronger wind a vertex may sway past the box, and a collider there is not tested.
  double sway = p.leaf_flutter;
  for (const boreas_mesh_level_def& l : p.levels) sway += l.bend + 2.0 * l.sway;
  const double margin = mesh_tree_load(tree.drag, kMeshTreeReachSpeed) * sway;
  for (size_t a = 0; a < 3; ++a) {
    box.lo[a] -= margin;
    box.hi[a] += margin;
  }
  return box;
}

}  // namespace boreas::impl
