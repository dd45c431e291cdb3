// boreas: a grown tree's BlobTree — internodes, junction groups with the offsets of eq. 3,
// 6 and 7, bends, pruning cuts and scars (see blobtree_model.h).
#include "blobtree/blobtree_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "shared/tree_types.h"
#include "trees/tree_layout.h"
#include "trees/tree_params.h"

namespace boreas::impl {
namespace {

using glm::dvec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kIsoFraction = 0.45420201894740647;  // sqrt(1 - (1/2)^(1/3))
// A branch is cut into internodes no shorter than this fraction of its curve's parameter,
// so that children leaving close together share one branching point (a whorl).
constexpr double kMinInternode = 0.02;
// The offsets at an internode's two ends may together take at most this fraction of it.
constexpr double kMaxOffsetFraction = 0.5;
// Where a tip's radius would reach 0, its surface keeps this fraction of the internode's
// base radius (and at least min_radius).
constexpr double kTipFraction = 0.2;
// A cut branch's last internode reaches this many radii past the cut's plane, so the cut
// has a whole cross-section to take off.
constexpr double kCutStub = 2.0;

std::string where(const char* list, size_t i) {
  std::ostringstream s;
  s << list << "[" << i << "]";
  return s.str();
}

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("blobtree: " + what);
}

// A branch's rest curve and radius function.
struct BranchCurve {
  std::array<dvec3, 4> p{};
  const BranchModel* model = nullptr;

  dvec3 point(double v) const {
    double u = 1.0 - v;
    return u * u * u * p[0] + 3.0 * u * u * v * p[1] + 3.0 * u * v * v * p[2] + v * v * v * p[3];
  }
  // Skjermo eq. 2-5 without the lobes (a cone is round): taper, trunk flare, beads, the
  // tip's cap, as the deformer draws them.
  double radius(double v) const { return profile_radius(*model, v); }
};

// One internode before the junction rules: the branch's curve from v0 to v1.
struct Internode {
  int32_t branch = 0;
  double v0 = 0.0, v1 = 0.0;
  dvec3 base{0.0}, top{0.0};
  double r_base = 0.0, r_top = 0.0;
  double s0 = 0.0;            // m along the branch's curve (chords) at the base
  double bend = 0.0;          // rad
  dvec3 bend_reference{0.0};  // the basal internode's axis, for the bend's plane
  double v_scale = 1.0;
  double extend_top = 0.0;  // m past the top (a cut's stub)
};

// Children of one branch that leave at one branching point.
struct Junction {
  double v = 0.0;
  std::vector<int32_t> children;  // branch indices
};

dvec3 any_perpendicular(const dvec3& a) {
  dvec3 ref = std::abs(a.y) < 0.9 ? dvec3(0.0, 1.0, 0.0) : dvec3(1.0, 0.0, 0.0);
  return glm::normalize(glm::cross(a, ref));
}

void check_options(const TreeModel& tree, const BlobTreeOptions& o) {
  if (o.max_level < 0 || o.max_level > 3)
    fail("max_level must be 0..3, not " + std::to_string(o.max_level));
  if (o.segments < 1 || o.segments > 64)
    fail("segments must be 1..64, not " + std::to_string(o.segments));
  // The public def's limits are floats: a float limit converted to double (0.01f, pi/2
  // rounded up) must pass.
  auto finite_in = [](double x, double lo, double hi) {
    return std::isfinite(x) && x >= lo - 1e-7 * (1.0 + std::abs(lo)) &&
           x <= hi + 1e-7 * (1.0 + std::abs(hi));
  };
  if (!finite_in(o.min_radius, 0.0, 1e4)) fail("min_radius must be 0..1e4 m");
  if (!finite_in(o.min_surface, 0.0, 1e4)) fail("min_surface must be 0..1e4 m");
  if (!finite_in(o.pcm_peak, 0.0, 0.45)) fail("pcm_peak must be 0..0.45 (below the iso-value 1/2)");
  if (!finite_in(o.pcm_width, 0.01, 10.0)) fail("pcm_width must be 0.01..10 surface distances");
  if (!finite_in(o.bend_angle, 0.0, kPi / 2.0)) fail("bend_angle must be 0..pi/2 rad");
  const int count = static_cast<int>(tree.branches.size());
  auto check_branch = [&](const std::string& name, int32_t b) {
    if (b < 0 || b >= count)
      fail(name + ".branch: " + std::to_string(b) + " is not a branch of this tree (it has " +
           std::to_string(count) + ", 0 the trunk)");
  };
  for (size_t i = 0; i < o.cuts.size(); ++i) {
    check_branch(where("cuts", i), o.cuts[i].branch);
    if (!finite_in(o.cuts[i].at, 0.01, 1.0))
      fail(where("cuts", i) + ".at must be 0.01..1 along the branch");
  }
  for (size_t i = 0; i < o.scars.size(); ++i) {
    check_branch(where("scars", i), o.scars[i].branch);
    if (o.scars[i].branch == 0)
      fail(where("scars", i) + ".branch: the trunk cannot be lost (cut it instead)");
    if (!finite_in(o.scars[i].stub, 0.01, 1.0))
      fail(where("scars", i) + ".stub must be 0.01..1 of the branch");
    if (!finite_in(o.scars[i].depth, 0.0, 1.0)) fail(where("scars", i) + ".depth must be 0..1");
  }
}

// Rest control points of every branch, placed by the kernels' own geometry.
std::vector<BranchCurve> rest_curves(const TreeModel& tree, const dvec3& position,
                                     double rotation) {
  TreeParams params;
  params.position = {position.x, position.y, position.z};
  params.rotation = rotation;
  TreeLayout layout = tree_layout({TreeLayoutSource{&params, &tree}});
  std::vector<BranchCurve> curves(tree.branches.size());
  for (size_t b = 0; b < tree.branches.size(); ++b) {
    int32_t g = layout.branch_index(0, static_cast<int>(b));
    for (int k = 0; k < 4; ++k) {
      int plane = BOREAS_TREE_STATE_P0 + 3 * k;
      curves[b].p[k] = dvec3(layout.state[size_t(plane) * layout.n + g],
                             layout.state[size_t(plane + 1) * layout.n + g],
                             layout.state[size_t(plane + 2) * layout.n + g]);
    }
    curves[b].model = &tree.branches[b];
  }
  return curves;
}

// A skeleton's internodes by their parents: each one's children, and the roots. Throws
// std::invalid_argument naming an internode that is not after its parent or has no length
// or radius.
struct SkeletonLinks {
  std::vector<std::vector<int32_t>> children;
  std::vector<int32_t> roots;
};

SkeletonLinks skeleton_links(const std::vector<BlobInternode>& skeleton) {
  const size_t count = skeleton.size();
  SkeletonLinks links;
  links.children.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const BlobInternode& n = skeleton[i];
    if (n.parent >= static_cast<int32_t>(i))
      fail("skeleton[" + std::to_string(i) + "].parent must come before it");
    if (!(glm::length(n.top - n.base) > 0.0) || !(n.r_base > 0.0) || !(n.r_top >= 0.0) ||
        !std::isfinite(glm::length(n.top - n.base)))
      fail("skeleton[" + std::to_string(i) + "] needs a positive length and radius");
    if (n.parent < 0)
      links.roots.push_back(static_cast<int32_t>(i));
    else
      links.children[n.parent].push_back(static_cast<int32_t>(i));
  }
  return links;
}

// The offsets of the junction rules: delta_A at each internode's top (positive shortens),
// delta_Bi at each child's base.
struct JunctionOffsets {
  explicit JunctionOffsets(size_t count) : top(count, 0.0), base(count, 0.0) {}
  std::vector<double> top, base;
};

JunctionOffsets junction_offsets(const std::vector<BlobInternode>& skeleton,
                                 const std::vector<std::vector<int32_t>>& children, bool pcm) {
  const size_t count = skeleton.size();
  JunctionOffsets offsets(count);
  std::vector<double>& offset_top = offsets.top;
  std::vector<double>& offset_base = offsets.base;
  for (size_t a = 0; a < count; ++a) {
    const std::vector<int32_t>& kids = children[a];
    if (kids.empty()) continue;
    const BlobInternode& na = skeleton[a];
    const double la = glm::length(na.top - na.base);
    // One child, or a plain blend (no PCM groups): sec. 3.2 keeps the children at P and
    // shortens only A, by eq. 3 for the thickest child's top radius (the one whose
    // overlap with A makes the bulge). Eq. 6-7 go with PCM groups (sec. 3.3).
    if (kids.size() == 1 || !pcm) {
      double r_bt = 0.0;
      for (int32_t k : kids) r_bt = std::max(r_bt, skeleton[k].r_top);
      offset_top[a] = std::min(1.75 * r_bt, kMaxOffsetFraction * la);  // eq. 3
      continue;
    }
    const double ra = na.r_top;
    double rmax = 0.0;
    for (int32_t k : kids) rmax = std::max(rmax, skeleton[k].r_base);
    offset_top[a] = std::min(2.75 * rmax - ra, kMaxOffsetFraction * la);  // eq. 7
    for (int32_t k : kids) {
      const double lb = glm::length(skeleton[k].top - skeleton[k].base);
      offset_base[k] = std::clamp(ra - skeleton[k].r_base, 0.0, kMaxOffsetFraction * lb);  // eq. 6
    }
  }
  return offsets;
}

// Both ends of an internode may be offset (it is a child at its base and a parent at
// its top): together they may take at most kMaxOffsetFraction of it, so no primitive
// collapses to a point.
void limit_offsets(const std::vector<BlobInternode>& skeleton, JunctionOffsets* offsets) {
  std::vector<double>& offset_top = offsets->top;
  std::vector<double>& offset_base = offsets->base;
  for (size_t i = 0; i < skeleton.size(); ++i) {
    const double l = glm::length(skeleton[i].top - skeleton[i].base);
    const double taken = offset_base[i] + std::max(offset_top[i], 0.0);
    if (taken > kMaxOffsetFraction * l) {
      const double shrink = kMaxOffsetFraction * l / taken;
      offset_base[i] *= shrink;
      offset_top[i] *= shrink;
    }
  }
}

// An internode's primitive, its ends moved by its offsets (m; positive shortens it).
BlobPrimitive primitive_of(const BlobInternode& n, double offset_base, double offset_top,
                           int32_t group, bool pcm, const BlobTreeOptions& options) {
  BlobPrimitive p;
  const dvec3 chord_vec = n.top - n.base;
  const dvec3 axis = glm::normalize(chord_vec);
  const double chord = glm::length(chord_vec) - offset_base - offset_top + n.extend_top;
  p.axis = axis;
  p.base = n.base + offset_base * axis;
  // r_t is the surface distance, but a tip keeps a rounded cap (and the grid's
  // resolution); r_b - r_t the skeleton cone (sec. 3.1), never negative.
  p.iso_distance = std::max({n.r_top, options.min_radius, kTipFraction * n.r_base});
  p.iso_distance = std::min(p.iso_distance, std::max(n.r_base, options.min_radius));
  p.iso_distance = std::max(p.iso_distance, options.min_surface);
  p.cone_radius = std::max(0.0, n.r_base - p.iso_distance);
  p.influence = blob_influence(p.iso_distance);
  p.weight = 1.0;
  p.group = group;
  p.pcm = pcm;
  p.pcm_width = options.pcm_width * p.iso_distance;
  p.pcm_peak = options.pcm_peak;
  p.branch = n.branch;
  p.u_direction = any_perpendicular(axis);
  p.v_scale = n.v_scale;
  p.v0 = (n.s0 + offset_base) * n.v_scale;
  p.length = chord;
  if (n.bend > 0.0) {
    const dvec3 away = n.bend_reference - glm::dot(n.bend_reference, axis) * axis;
    if (glm::length(away) > 1e-6) {
      p.bend_direction = -glm::normalize(away);
      p.bend_angle = n.bend;
      // The arc through both ends: rho = chord / (2 sin(angle/2)), length rho * angle.
      p.length = chord * n.bend / (2.0 * std::sin(0.5 * n.bend));
      p.u_direction = p.bend_direction;
    }
  }
  return p;
}

// Which branches are modeled, and how far along: a cut ends its branch at `at`, a scar
// leaves a stub; their children beyond go with them.
struct BranchEnds {
  std::vector<double> end_v;  // where along its curve each branch ends, 0..1
  std::vector<bool> is_scar, is_cut;
};

BranchEnds branch_ends(size_t count, const BlobTreeOptions& options) {
  BranchEnds e;
  e.end_v.assign(count, 1.0);
  e.is_scar.assign(count, false);
  e.is_cut.assign(count, false);
  for (const BlobCutRequest& c : options.cuts) {
    e.end_v[c.branch] = std::min(e.end_v[c.branch], c.at);
    e.is_cut[c.branch] = true;
  }
  for (const BlobScarRequest& s : options.scars) {
    e.end_v[s.branch] = std::min(e.end_v[s.branch], s.stub);
    e.is_scar[s.branch] = true;
  }
  return e;
}

// Cuts (fig. 12): the plane across the branch at `at`, facing its tip; the cutter's
// ball holds the stub's extension past the plane (2 r) and the surface around it.
std::vector<BlobCut> cutters(const std::vector<BranchCurve>& curves,
                             const BlobTreeOptions& options) {
  std::vector<BlobCut> cuts;
  for (const BlobCutRequest& c : options.cuts) {
    const BranchCurve& curve = curves[c.branch];
    const double v = c.at;
    const double dv = 1e-3;
    dvec3 tangent = curve.point(std::min(1.0, v + dv)) - curve.point(std::max(0.0, v - dv));
    if (glm::length(tangent) < 1e-12) tangent = curve.p[3] - curve.p[0];  // a kinked curve
    const double r = std::max(curve.radius(v), 1e-6);
    const double surface = std::max({r, options.min_radius, options.min_surface});
    BlobCut cut;
    cut.point = curve.point(v);
    cut.normal = glm::normalize(tangent);
    cut.radius = kCutStub * r + 2.5 * surface + r;
    cut.ramp = r;
    cuts.push_back(cut);
  }
  return cuts;
}

// Inside a cutter: a child leaving there would lose its junction and float free.
bool cut_away(const std::vector<BlobCut>& cuts, const dvec3& p) {
  for (const BlobCut& c : cuts)
    if (glm::length(p - c.point) < c.radius && glm::dot(p - c.point, c.normal) > -c.ramp)
      return true;
  return false;
}

// The branches modeled: deep and thick enough, on a kept parent before its end (not past a
// cut, not on a scar's stub).
std::vector<bool> kept_branches(const TreeModel& tree, const std::vector<BranchCurve>& curves,
                                const BranchEnds& ends, const std::vector<BlobCut>& cuts,
                                const BlobTreeOptions& options) {
  const size_t count = tree.branches.size();
  std::vector<bool> kept(count, false);
  for (size_t b = 0; b < count; ++b) {
    const BranchModel& m = tree.branches[b];
    bool ok = m.level <= options.max_level && curves[b].radius(0.0) >= options.min_radius &&
              m.length > 0.0;
    if (ok && m.parent >= 0) {
      ok = kept[m.parent] && !ends.is_scar[m.parent] && m.v <= ends.end_v[m.parent] + 1e-12 &&
           !(ends.is_cut[m.parent] && cut_away(cuts, curves[b].point(0.0)));
    }
    kept[b] = ok;
  }
  return kept;
}

// Each kept branch's branching points: its kept children, clustered along the curve, in
// order along it.
std::vector<std::vector<Junction>> branching_points(const TreeModel& tree,
                                                    const std::vector<bool>& kept) {
  const size_t count = tree.branches.size();
  std::vector<std::vector<Junction>> junctions(count);
  for (size_t b = 1; b < count; ++b) {
    if (!kept[b]) continue;
    int32_t parent = tree.branches[b].parent;
    double v = std::clamp(tree.branches[b].v, kMinInternode, 1.0);
    std::vector<Junction>& list = junctions[parent];
    bool joined = false;
    for (Junction& j : list) {
      if (std::abs(j.v - v) < kMinInternode) {
        j.children.push_back(static_cast<int32_t>(b));
        joined = true;
        break;
      }
    }
    if (!joined) list.push_back(Junction{v, {static_cast<int32_t>(b)}});
  }
  for (size_t b = 0; b < count; ++b) {
    if (!kept[b]) continue;
    std::vector<Junction>& js = junctions[b];
    std::sort(js.begin(), js.end(), [](const Junction& x, const Junction& y) { return x.v < y.v; });
  }
  return junctions;
}

// Where a branch is split, 0 .. end_v: at its branching points and at `segments` even steps
// (dropped where a branching point is near).
std::vector<double> internode_splits(const std::vector<Junction>& js, double end_v, int segments) {
  std::vector<double> splits;
  for (const Junction& j : js)
    if (j.v < end_v - 1e-12) splits.push_back(j.v);
  for (int k = 1; k < segments; ++k) {
    double v = end_v * double(k) / segments;
    bool near = false;
    for (double s : splits) near = near || std::abs(s - v) < 0.5 / segments;
    if (!near) splits.push_back(v);
  }
  std::sort(splits.begin(), splits.end());
  splits.insert(splits.begin(), 0.0);
  splits.push_back(end_v);
  return splits;
}

// A branch's internodes between its splits, ending where its radius falls below
// min_radius.
std::vector<Internode> branch_internodes(const BranchCurve& c, size_t b,
                                         const std::vector<double>& splits, double min_radius) {
  std::vector<Internode> list;
  const double v_scale = 1.0 / (2.0 * kPi * std::max(c.radius(0.0), 1e-6));
  double s = 0.0;
  for (size_t k = 0; k + 1 < splits.size(); ++k) {
    Internode n;
    n.branch = static_cast<int32_t>(b);
    n.v0 = splits[k];
    n.v1 = splits[k + 1];
    if (n.v1 - n.v0 < 1e-9) continue;
    n.base = c.point(n.v0);
    n.top = c.point(n.v1);
    n.r_base = c.radius(n.v0);
    n.r_top = c.radius(n.v1);
    n.s0 = s;
    n.v_scale = v_scale;
    s += glm::length(n.top - n.base);
    if (glm::length(n.top - n.base) < 1e-9) continue;
    if (n.r_base < min_radius || n.r_base <= 0.0) break;
    list.push_back(n);
  }
  return list;
}

// Internodes of every kept branch: split at its branching points and at `segments`
// even steps, ending where its radius falls below min_radius or at a cut or scar.
std::vector<std::vector<Internode>> internodes_of(
    const std::vector<BranchCurve>& curves, const BranchEnds& ends, const std::vector<bool>& kept,
    const std::vector<std::vector<Junction>>& junctions, const BlobTreeOptions& options) {
  const size_t count = curves.size();
  std::vector<std::vector<Internode>> internodes(count);
  for (size_t b = 0; b < count; ++b) {
    if (!kept[b]) continue;
    // A scar's stub is one internode: split into `segments`, its pieces would be shorter
    // than the offsets at their ends.
    const int segments = ends.is_scar[b] ? 1 : options.segments;
    const std::vector<double> splits = internode_splits(junctions[b], ends.end_v[b], segments);
    internodes[b] = branch_internodes(curves[b], b, splits, options.min_radius);
    // A cut leaves a stub that reaches past the cut's plane, so the cut has a whole cross
    // section to take off.
    if (ends.is_cut[b] && !internodes[b].empty())
      internodes[b].back().extend_top = kCutStub * curves[b].radius(ends.end_v[b]);
  }
  return internodes;
}

// Bends (sec. 3.5): a lateral branch's first internode, in the plane of its axis and its
// parent's, turned away from the parent's axis at its base.
void bend_first_internodes(const TreeModel& tree, double bend_angle,
                           std::vector<std::vector<Internode>>* internodes) {
  std::vector<std::vector<Internode>>& all = *internodes;
  for (size_t b = 1; b < tree.branches.size(); ++b) {
    if (all[b].empty()) continue;
    int32_t parent = tree.branches[b].parent;
    const std::vector<Internode>& ps = all[parent];
    const Internode* basal = nullptr;
    for (const Internode& n : ps)
      if (n.v1 <= tree.branches[b].v + kMinInternode) basal = &n;
    if (!basal && !ps.empty()) basal = &ps.front();
    if (!basal) continue;
    all[b].front().bend = bend_angle;
    all[b].front().bend_reference = glm::normalize(basal->top - basal->base);
  }
}

// The skeleton index of the internode a branch's first internode starts at: its parent's
// internode ending at the branching point it leaves from; -1 where the parent stopped short
// of it (too thin there).
int32_t attachment(const TreeModel& tree, const std::vector<std::vector<Junction>>& junctions,
                   const std::vector<std::vector<Internode>>& internodes,
                   const std::vector<std::vector<int32_t>>& index_of, size_t b) {
  int32_t parent = -1;
  const int32_t pb = tree.branches[b].parent;
  const double v = std::clamp(tree.branches[b].v, kMinInternode, 1.0);
  for (size_t k = 0; k < internodes[pb].size() && parent < 0; ++k) {
    for (const Junction& j : junctions[pb])
      if (std::abs(internodes[pb][k].v1 - j.v) < 1e-12 && std::abs(j.v - v) < kMinInternode &&
          std::find(j.children.begin(), j.children.end(), int32_t(b)) != j.children.end())
        parent = index_of[pb].empty() ? -1 : index_of[pb][k];
  }
  return parent;
}

// The skeleton: every internode with the one whose top it starts at. A branch whose
// parent stopped short of its branching point is left out with its children (its
// internodes cleared).
std::vector<BlobInternode> link_skeleton(const TreeModel& tree,
                                         const std::vector<std::vector<Junction>>& junctions,
                                         std::vector<std::vector<Internode>>* internodes) {
  std::vector<BlobInternode> skeleton;
  std::vector<std::vector<int32_t>> index_of(internodes->size());
  for (size_t b = 0; b < internodes->size(); ++b) {
    std::vector<Internode>& list = (*internodes)[b];
    int32_t parent = -1;
    if (b > 0 && !list.empty()) {
      parent = attachment(tree, junctions, *internodes, index_of, b);
      if (parent < 0) list.clear();
    }
    for (size_t k = 0; k < list.size(); ++k) {
      const Internode& n = list[k];
      BlobInternode s;
      s.base = n.base;
      s.top = n.top;
      s.r_base = n.r_base;
      s.r_top = n.r_top;
      s.parent = k == 0 ? parent : static_cast<int32_t>(skeleton.size()) - 1;
      s.branch = n.branch;
      s.s0 = n.s0;
      s.v_scale = n.v_scale;
      s.bend = n.bend;
      s.bend_reference = n.bend_reference;
      s.extend_top = n.extend_top;
      index_of[b].push_back(static_cast<int32_t>(skeleton.size()));
      skeleton.push_back(s);
    }
  }
  return skeleton;
}

// Scars (sec. 3.4, fig. 13): a negative field where the lost branch left its parent,
// summed with everything, around the stub.
void add_scars(const TreeModel& tree, const std::vector<BranchCurve>& curves,
               const std::vector<std::vector<Internode>>& internodes,
               const BlobTreeOptions& options, BlobModel* model) {
  int32_t group_id = model->primitives.empty() ? 0 : model->primitives.back().group + 1;
  for (const BlobScarRequest& s : options.scars) {
    if (internodes[s.branch].empty()) continue;
    const Internode& stub = internodes[s.branch].front();
    const int32_t parent = tree.branches[s.branch].parent;
    const double r_parent = curves[parent].radius(tree.branches[s.branch].v);
    // The hollow is in the bark around the stub, not in the wood: the negative skeleton
    // runs along the stub's axis from its surface distance below the parent's bark out to
    // the bark.
    BlobPrimitive p;
    p.axis = glm::normalize(stub.top - stub.base);
    // At most 0.3 of the parent's radius: its reach (2.2 times that) then ends short of
    // the parent's axis, so a scar the size of its parent hollows the bark without
    // severing the wood.
    p.iso_distance =
        std::min(1.5 * std::max({stub.r_base, options.min_surface, 1e-6}), 0.3 * r_parent);
    p.iso_distance = std::max(p.iso_distance, 1e-6);
    p.base = stub.base + std::max(0.0, r_parent - p.iso_distance) * p.axis;
    p.length = std::max(std::min(p.iso_distance, r_parent), 1e-6);
    p.cone_radius = 0.0;
    p.influence = blob_influence(p.iso_distance);
    p.weight = -s.depth;
    p.group = group_id++;
    p.u_direction = any_perpendicular(p.axis);
    p.branch = -1;
    model->primitives.push_back(p);
  }
}

}  // namespace

double BlobPrimitive::chord() const {
  if (bend_angle <= 0.0) return length;
  double rho = length / bend_angle;
  return 2.0 * rho * std::sin(0.5 * bend_angle);
}

double blob_influence(double iso_distance) { return iso_distance / kIsoFraction; }

double blob_reach(const BlobPrimitive& p, double group_max_width) {
  return p.cone_radius + std::max(p.influence, p.iso_distance + group_max_width);
}

std::vector<double> blob_group_widths(const BlobModel& model) {
  const std::vector<BlobPrimitive>& prims = model.primitives;
  std::vector<double> width(prims.size(), 0.0);
  size_t i = 0;
  while (i < prims.size()) {
    size_t e = i + 1;
    while (e < prims.size() && prims[e].group == prims[i].group) ++e;
    double w = 0.0;
    for (size_t k = i; k < e; ++k)
      if (prims[k].pcm) w = std::max(w, prims[k].pcm_width);
    for (size_t k = i; k < e; ++k) width[k] = w;
    i = e;
  }
  return width;
}

void blob_skeleton_box(const BlobPrimitive& p, double grow, dvec3* lo, dvec3* hi) {
  const dvec3 top = p.base + p.chord() * p.axis;
  const double bulge =
      p.bend_angle > 0.0 ? (p.length / p.bend_angle) * (1.0 - std::cos(0.5 * p.bend_angle)) : 0.0;
  *lo = glm::min(p.base, top) - dvec3(grow + bulge);
  *hi = glm::max(p.base, top) + dvec3(grow + bulge);
}

void BlobModel::update_bounds() {
  bounds_min = dvec3(1e300);
  bounds_max = dvec3(-1e300);
  const std::vector<double> widths = blob_group_widths(*this);
  for (size_t i = 0; i < primitives.size(); ++i) {
    dvec3 lo, hi;
    blob_skeleton_box(primitives[i], blob_reach(primitives[i], widths[i]), &lo, &hi);
    bounds_min = glm::min(bounds_min, lo);
    bounds_max = glm::max(bounds_max, hi);
  }
}

BlobModel blob_model_of(const std::vector<BlobInternode>& skeleton,
                        const BlobTreeOptions& options) {
  const SkeletonLinks links = skeleton_links(skeleton);
  JunctionOffsets offsets(skeleton.size());
  if (options.offsets) offsets = junction_offsets(skeleton, links.children, options.pcm);
  limit_offsets(skeleton, &offsets);

  // Groups in order: each root alone, then each internode's children.
  std::vector<std::vector<int32_t>> groups;
  for (int32_t r : links.roots) groups.push_back({r});
  for (size_t a = 0; a < skeleton.size(); ++a)
    if (!links.children[a].empty()) groups.push_back(links.children[a]);

  BlobModel model;
  std::vector<int32_t> branches;
  int32_t group_id = 0;
  for (const std::vector<int32_t>& members : groups) {
    const bool pcm = options.pcm && members.size() > 1;
    for (int32_t i : members) {
      const BlobInternode& n = skeleton[i];
      model.primitives.push_back(
          primitive_of(n, offsets.base[i], offsets.top[i], group_id, pcm, options));
      if (n.branch >= 0) branches.push_back(n.branch);
    }
    ++group_id;
  }
  std::sort(branches.begin(), branches.end());
  model.branches_modeled =
      static_cast<int>(std::unique(branches.begin(), branches.end()) - branches.begin());
  model.update_bounds();
  return model;
}

BlobModel build_blobtree(const TreeModel& tree, const dvec3& position,
                         const BlobTreeOptions& options, double rotation) {
  check_options(tree, options);
  if (tree.branches.empty()) fail("the tree has no branches");
  const std::vector<BranchCurve> curves = rest_curves(tree, position, rotation);
  const BranchEnds ends = branch_ends(tree.branches.size(), options);
  const std::vector<BlobCut> cuts = cutters(curves, options);
  const std::vector<bool> kept = kept_branches(tree, curves, ends, cuts, options);
  const std::vector<std::vector<Junction>> junctions = branching_points(tree, kept);
  std::vector<std::vector<Internode>> internodes =
      internodes_of(curves, ends, kept, junctions, options);
  if (options.bend_angle > 0.0) bend_first_internodes(tree, options.bend_angle, &internodes);
  const std::vector<BlobInternode> skeleton = link_skeleton(tree, junctions, &internodes);

  BlobModel model = blob_model_of(skeleton, options);
  add_scars(tree, curves, internodes, options, &model);
  // A cut whose branch is left out cuts nothing.
  for (size_t i = 0; i < options.cuts.size(); ++i)
    if (!internodes[options.cuts[i].branch].empty()) model.cuts.push_back(cuts[i]);
  model.update_bounds();
  return model;
}

}  // namespace boreas::impl
