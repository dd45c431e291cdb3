// boreas: the Weber-Penn tree generator — grows a species into one cubic Bezier per stem
// (Skjermo 2007 sec. 2.1), how each stem attaches to its parent, and the leaves.
//
// The stages, in order:
//   1. The trunk: its length, radius, taper, flare and lobes, and its Bezier.
//   2. Level by level (breadth first): each stem of level n draws its children's maximum
//      length, works out how many children it has (Weber-Penn's counts), spreads them over
//      its branched part and gives each its offset, rotation, down angle, length, radius
//      and Bezier. The children of one parent are appended together, parents in order.
//   3. The leaves, on each stem of the last level, parents in order.
//
// Every random draw comes from a stream keyed by (seed, stem index, purpose) (tree_random.h),
// so a stem's numbers do not depend on what other stems drew. Equations are those of Weber
// and Penn, "Creation and Rendering of Realistic Trees" (1995), as the reference generator
// Arbaro reads them; where they are silent the choice is stated beside it.
//
// Not grown: stem splits (nSegSplits, 0BaseSplits: one Bezier per stem), pruning (PruneRatio),
// and AttractionUp. A stem is grown in its own frame and does not know where "up" is until
// the kernel places it, so the upward turn of levels >= 2 cannot be computed here.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/tree_model.h"
#include "trees/tree_random.h"

namespace boreas::impl {
namespace {

// A tree with more stems than this is refused: no real species gets near it (the weeping
// willow, the largest Weber-Penn tree, has about 27,000), and a mistyped nBranches would
// otherwise exhaust memory. Leaves likewise (the willow: about 270,000).
constexpr size_t kMaxBranches = size_t(1) << 20;
constexpr size_t kMaxLeaves = size_t(1) << 22;
// Children shorter than this fraction of the trunk are not grown (Arbaro drops stems under
// 0.5 mm for the same reason: they are invisible and their own children more so).
constexpr double kMinStemFraction = 1e-4;
// The trunk's size, length and radius factors stay above this fraction of their values
// however large their variations.
constexpr double kMinVariedFraction = 0.1;
// At most this much of a stem, from its base, lies inside its parent and carries nothing.
constexpr double kMaxBaseFraction = 0.5;
// Taper exponent of a cylinder with a rounded tip (nTaper = 2 and the periodic range above).
constexpr double kMaxTaperExponent = 20.0;
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;

// The purposes a stem draws numbers for, one stream each.
enum Purpose : uint64_t { kSelf = 0, kChildLength = 1, kChildren = 2, kLeaves = 3 };

using Vec3 = std::array<double, 3>;

// What the generator keeps per stem beside the model.
struct StemState {
  double offset = 0.0;            // distance of the base from the parent's base, m
  double base_fraction = 0.0;     // the fraction from the base that carries nothing
  double length_child_max = 0.0;  // the children's nLength +- nLengthV, drawn once per parent
};

double clamp(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }

Vec3 add_scaled(const Vec3& a, const Vec3& b, double s) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Rodrigues: v turned by angle (radians) about the unit axis.
Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double d = axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2];
  const Vec3 k = cross(axis, v);
  return {v[0] * c + k[0] * s + axis[0] * d * (1 - c), v[1] * c + k[1] * s + axis[1] * d * (1 - c),
          v[2] * c + k[2] * s + axis[2] * d * (1 - c)};
}

// The stem's radius at the fraction z of its length (around the mean of the lobes): the
// radius functions of tree_model.h.
double radius_at(const BranchModel& b, double z) {
  z = clamp(z, 0.0, 1.0);
  const double taper = std::max(0.0, 1.0 - b.taper_depth * std::pow(z, b.taper_exponent));
  const double flare =
      1.0 + b.flare * (std::pow(100.0, std::max(0.0, 1.0 - 8.0 * z)) - 1.0) / 100.0;
  const double bulges = 1.0 + b.bulge_depth * std::sin(2.0 * kPi * b.bulge_count * z);
  return b.radius * taper * flare * bulges;
}

// Weber-Penn's nTaper as the deformer's radius functions. length and radius must be set.
//   nTaper <= 1: a cone cut at 1 - nTaper of the base radius: depth nTaper, exponent 1.
//   1..2: Weber-Penn tapers linearly to (2 - nTaper) r and rounds the tip with a sphere. The
//     profile 1 - z^p with p = nTaper / (2 - nTaper) has the same mean radius (1 - 1/(p + 1) =
//     nTaper / 2); p = 1 at nTaper = 1 (the cone), and p is capped at kMaxTaperExponent (a
//     cylinder with a rounded tip) as nTaper nears 2.
//   2..3: Weber-Penn's periodic taper, a cylinder (unit taper 0) of beads one diameter long
//     whose waists sink by (nTaper - 2) r. Here: the rounded cylinder of nTaper = 2 (so the
//     range is continuous there) with length / (2 r) bulges of depth (nTaper - 2) / 2, the
//     sine with the beads' peak-to-waist swing.
void set_taper(BranchModel& b, double n_taper) {
  n_taper = clamp(n_taper, 0.0, 3.0);
  b.bulge_count = 0.0;
  b.bulge_depth = 0.0;
  if (n_taper <= 1.0) {
    b.taper_depth = n_taper;
    b.taper_exponent = 1.0;
  } else if (n_taper < 2.0) {
    b.taper_depth = 1.0;
    b.taper_exponent = std::min(n_taper / (2.0 - n_taper), kMaxTaperExponent);
  } else {
    b.taper_depth = 1.0;
    b.taper_exponent = kMaxTaperExponent;
    if (n_taper > 2.0 && b.radius > 0.0) {
      b.bulge_count = b.length / (2.0 * b.radius);
      b.bulge_depth = 0.5 * (n_taper - 2.0);
    }
  }
}

// The control polygon: three segments of length / 3 from the origin, the first along +x.
// Weber-Penn turns each of CurveRes segments after the first by nCurve / CurveRes (with
// nCurveBack: 2 nCurve / CurveRes in the first half, 2 nCurveBack / CurveRes in the second);
// here CurveRes is 3, so the second and third segments turn, by nCurve / 3 each or by
// 2 nCurve / 3 then 2 nCurveBack / 3. A positive curve turns toward +y, the same way as the
// down angle (away from the parent's axis), as Weber-Penn's does; negative curves bend
// branches back up. nCurveV adds, per turn, a rotation by +- nCurveV / 3 about a random axis
// across the stem (in its y-z plane), so a stem also bends out of its plane. A negative
// nCurveV (Weber-Penn's helix) cannot be one Bezier and is ignored, as Arbaro does.
void set_curve(BranchModel& b, const SpeciesLevel& lv, TreeRandom& rng) {
  const double segment = b.length / 3.0;
  Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  b.local[0] = {0, 0, 0};
  b.local[1] = {segment, 0, 0};
  for (int joint = 1; joint <= 2; ++joint) {
    double turn = lv.curve / 3.0;
    if (lv.curve_back != 0.0) turn = 2.0 * (joint == 1 ? lv.curve : lv.curve_back) / 3.0;
    const double random_turn = rng.vary(std::max(0.0, lv.curve_v) / 3.0);
    const double axis_angle = kPi * rng.uniform_pm1();
    x = rotate(x, z, turn * kRadiansPerDegree);  // toward +y for a positive turn
    y = cross(z, x);
    const double c = std::cos(axis_angle), sn = std::sin(axis_angle);
    const Vec3 axis{c * z[0] + sn * y[0], c * z[1] + sn * y[1], c * z[2] + sn * y[2]};
    x = rotate(x, axis, random_turn * kRadiansPerDegree);
    y = rotate(y, axis, random_turn * kRadiansPerDegree);
    z = rotate(z, axis, random_turn * kRadiansPerDegree);
    b.local[joint + 1] = add_scaled(b.local[joint], x, segment);
  }
}

// One stem's Bezier and radius functions; its level's curvature and taper.
void shape_stem(BranchModel& b, const SpeciesLevel& lv, TreeRandom& rng) {
  set_curve(b, lv, rng);
  set_taper(b, lv.taper);
}

// The rotation of successive children (or leaves) of one stem, degrees: each turns nRotate
// +- nRotateV past the previous; a negative nRotate alternates sides, +-(180 + nRotate +-
// nRotateV), starting with +.
class RotationAccumulator {
 public:
  double next(const SpeciesLevel& lv, TreeRandom& rng) {
    const double variation = rng.vary(lv.rotate_v);
    if (lv.rotate >= 0.0) {
      angle_ = std::fmod(angle_ + lv.rotate + variation, 360.0);
    } else {
      angle_ = side_ * (180.0 + lv.rotate + variation);
      side_ = -side_;
    }
    if (angle_ < 0.0) angle_ += 360.0;
    return angle_;
  }

 private:
  double angle_ = 0.0;
  double side_ = 1.0;
};

// nDownAngle +- nDownAngleV, degrees; a negative nDownAngleV varies it along the parent
// instead: nDownAngle + nDownAngleV (1 - 2 ShapeRatio0((L - offset) / span)), with span the
// parent's branched length.
double down_angle(const Species& s, const SpeciesLevel& lv, TreeRandom& rng, double parent_length,
                  double offset, double span) {
  const double variation = rng.vary(std::fabs(lv.down_angle_v));
  if (lv.down_angle_v >= 0.0) return lv.down_angle + variation;
  const double ratio = span > 0.0 ? clamp((parent_length - offset) / span, 0.0, 1.0) : 0.0;
  return lv.down_angle + lv.down_angle_v * (1.0 - 2.0 * shape_ratio(s, 0, ratio));
}

std::string describe(const Species& s) {
  return "species '" + s.name + "' (Levels = " + std::to_string(s.levels) + ")";
}

// Weber-Penn's number of children of stem p (README): on the trunk nBranches; on a level-1
// stem N (0.2 + 0.8 (L / L_parent) / nLength_max), nLength_max the length_child_max the
// trunk drew for it; deeper N (1 - 0.5 offset / L_parent). Floored.
double child_count(const Species& s, const TreeModel& tree, const std::vector<StemState>& state,
                   int p) {
  const BranchModel& stem = tree.branches[size_t(p)];
  const double n_max = s.level[size_t(stem.level) + 1].branches;
  double count = n_max;
  if (stem.level == 1) {
    const BranchModel& parent = tree.branches[size_t(stem.parent)];
    const double length_max = state[size_t(stem.parent)].length_child_max;
    if (!(length_max > 0.0) || !(parent.length > 0.0)) return 0.0;
    count = n_max * (0.2 + 0.8 * (stem.length / parent.length) / length_max);
  } else if (stem.level >= 2) {
    const BranchModel& parent = tree.branches[size_t(stem.parent)];
    count = n_max * (1.0 - 0.5 * state[size_t(p)].offset / parent.length);
  }
  if (!(count > 0.0)) return 0.0;  // also NaN
  return std::floor(count);
}

// Draws the maximum length of stem p's children and returns how many it has.
double prepare_children(const Species& s, uint64_t seed, int p, const TreeModel& tree,
                        std::vector<StemState>& state) {
  const SpeciesLevel& lc = s.level[size_t(tree.branches[size_t(p)].level) + 1];
  TreeRandom rng(seed, uint64_t(p), kChildLength);
  state[size_t(p)].length_child_max = std::max(0.0, lc.length + rng.vary(lc.length_v));
  return child_count(s, tree, state, p);
}

// The count children of stem p, appended to the tree (so they are contiguous).
//
// Placement: the branched part of the parent (above BaseSize on the trunk; above the part
// inside its own parent otherwise) is cut into the parent level's CurveRes segments, the
// children shared among them as evenly as integers allow; in a segment with m children the
// j-th sits at (j + 1/2) d +- d/4 with d = nBranchDist / m of the segment (Arbaro's rule:
// nBranchDist 1 spreads them evenly, 0 puts them all at the segment's start, a whorl).
void grow_children(const Species& s, uint64_t seed, int p, int64_t n, TreeModel& tree,
                   std::vector<StemState>& state) {
  if (n <= 0) return;
  const BranchModel parent = tree.branches[size_t(p)];  // a copy: the vector grows below
  const int level = parent.level + 1;
  const SpeciesLevel& lc = s.level[size_t(level)];
  const double length_max = state[size_t(p)].length_child_max;
  TreeRandom rng(seed, uint64_t(p), kChildren);

  const double base = state[size_t(p)].base_fraction;
  const double trunk_length = tree.branches[0].length;
  const int segments = int(clamp(std::round(s.level[size_t(parent.level)].curve_res), 1.0, 1000.0));
  const double branch_dist = clamp(lc.branch_dist, 0.0, 1.0);
  // The span over which a negative nDownAngleV varies: the branched part on the trunk.
  const double down_span = parent.level == 0 ? parent.length * (1.0 - s.base_size) : parent.length;
  RotationAccumulator rotation;

  for (int k = 0; k < segments; ++k) {
    const int64_t m = n * (k + 1) / segments - n * k / segments;
    if (m == 0) continue;
    const double spacing = branch_dist / double(m);
    for (int64_t j = 0; j < m; ++j) {
      const double where = spacing * (double(j) + 0.5) + rng.vary(0.25 * spacing);
      const double fraction = clamp(base + (1.0 - base) * (k + where) / segments, base, 1.0);
      const double offset = fraction * parent.length;
      const double theta = rotation.next(lc, rng);
      const double alpha = down_angle(s, lc, rng, parent.length, offset, down_span);

      // Length: level 1 follows the tree's shape over the branched part of the trunk,
      // (L0 - offset) / (L0 - BaseSize L0) (the README's BaseSize Scale when 0Length is 1;
      // the trunk's own length keeps the ratio in 0..1); deeper levels shorten toward their
      // parent's tip.
      double length;
      if (level == 1) {
        const double ratio = base < 1.0 ? clamp((1.0 - fraction) / (1.0 - base), 0.0, 1.0) : 0.0;
        length = parent.length * length_max * shape_ratio(s, s.shape, ratio);
      } else {
        length = length_max * (parent.length - 0.6 * offset);
      }
      const double radius =
          std::min(parent.radius * std::pow(length / parent.length, s.ratio_power),
                   radius_at(parent, fraction));
      if (!(length > kMinStemFraction * trunk_length) || !(radius > 0.0)) continue;

      BranchModel child;
      child.level = level;
      child.parent = p;
      // The arclength fraction as the Bezier parameter: exact while the polygon is straight
      // (evenly spaced control points), close for the gentle curves of real species.
      child.v = fraction;
      child.theta = theta * kRadiansPerDegree;
      child.alpha = alpha * kRadiansPerDegree;
      child.length = length;
      child.radius = radius;
      TreeRandom self(seed, uint64_t(tree.branches.size()), kSelf);
      shape_stem(child, lc, self);

      StemState st;
      st.offset = offset;
      st.base_fraction = std::min(radius_at(parent, fraction) / length, kMaxBaseFraction);
      tree.branches.push_back(child);
      state.push_back(st);
    }
  }
}

// The block of level parameters that places leaves: min(Levels, 3), as Weber-Penn and
// Arbaro do. When Levels <= 3 that block belongs to no stem; if it is all zero (down angle,
// rotation and their variations) and leaves grow along the stem, it was not given, and
// leaves take 45 +- 0 degrees down and 77 degrees rotation (the leaf block of the Weber-Penn
// tables). Fans (negative Leaves) keep zeros: rush and wheat set them on purpose.
SpeciesLevel leaf_level(const Species& s) {
  const int index = std::min(s.levels, kMaxTreeLevels - 1);
  SpeciesLevel lv = s.level[size_t(index)];
  const bool unused_block = index >= s.levels;
  const bool all_zero =
      lv.down_angle == 0.0 && lv.down_angle_v == 0.0 && lv.rotate == 0.0 && lv.rotate_v == 0.0;
  if (unused_block && all_zero && s.leaves > 0) {
    lv.down_angle = 45.0;
    lv.rotate = 77.0;
  }
  return lv;
}

// The leaves of last-level stem p: |Leaves| ShapeRatio(offset / L_parent, LeafDistrib)
// LeafQuality of them, the fraction rounded up with that probability.
//   Leaves > 0: spread along the stem above its base part like children (one segment, jitter
//     +- half a spacing), each turned by the leaf block's rotation and down angle.
//   Leaves < 0: Weber-Penn's fan at the stem's tip (v = 1): leaves spread in a plane through
//     the stem by nRotate / count apart (+- nRotateV / count), each tilted out of it by the
//     down angle; that direction is stored as its angle from the stem (alpha) and azimuth
//     (theta).
// Size: Weber-Penn's LeafScale / sqrt(LeafQuality) (fewer, larger leaves keep the area), times
// scale; width LeafScaleX of that, petiole LeafStemLen of it.
double expected_leaves(const Species& s, const BranchModel& stem) {
  const double expected = std::fabs(double(s.leaves)) *
                          shape_ratio(s, s.leaf_distrib, clamp(stem.v, 0.0, 1.0)) * s.leaf_quality;
  return expected > 0.0 ? expected : 0.0;  // also NaN
}

void grow_leaves(const Species& s, uint64_t seed, double scale, int p, const SpeciesLevel& lv,
                 TreeModel& tree, const std::vector<StemState>& state) {
  const BranchModel& stem = tree.branches[size_t(p)];
  TreeRandom rng(seed, uint64_t(p), kLeaves);
  const double expected = expected_leaves(s, stem);
  const double whole = std::floor(expected);
  const int64_t count = int64_t(whole) + (rng.uniform01() < expected - whole ? 1 : 0);
  if (count == 0) return;

  LeafModel leaf;
  leaf.parent = p;
  leaf.length = s.leaf_scale / std::sqrt(s.leaf_quality) * scale;
  leaf.width = leaf.length * s.leaf_scale_x;
  leaf.stem = leaf.length * s.leaf_stem_len;

  if (s.leaves > 0) {
    const double base = state[size_t(p)].base_fraction;
    const double spacing = 1.0 / double(count);
    RotationAccumulator rotation;
    for (int64_t i = 0; i < count; ++i) {
      const double where = spacing * (double(i) + 0.5) + rng.vary(0.5 * spacing);
      leaf.v = clamp(base + (1.0 - base) * where, base, 1.0);
      leaf.theta = rotation.next(lv, rng) * kRadiansPerDegree;
      leaf.alpha = down_angle(s, lv, rng, stem.length, leaf.v * stem.length, stem.length) *
                   kRadiansPerDegree;
      tree.leaves.push_back(leaf);
    }
    return;
  }
  const double step = lv.rotate / double(count);
  const double step_v = lv.rotate_v / double(count);
  leaf.v = 1.0;
  // Odd counts put one leaf in the middle, the rest in pairs either side.
  const double first = count % 2 == 1 ? step : 0.5 * step;
  for (int64_t i = 0; i < count; ++i) {
    double spread = 0.0;
    if (count % 2 == 1 && i == 0) {
      spread = 0.0;
    } else {
      const int64_t pair = count % 2 == 1 ? (i - 1) / 2 : i / 2;
      const double side = (count % 2 == 1 ? (i - 1) % 2 : i % 2) == 0 ? 1.0 : -1.0;
      spread = side * (first + double(pair) * step + rng.vary(step_v));
    }
    const double tilt = lv.down_angle + rng.vary(lv.down_angle_v);
    const double b = spread * kRadiansPerDegree, d = tilt * kRadiansPerDegree;
    // The direction (cos d sin b, -sin d, cos d cos b) with the stem along the last axis.
    leaf.alpha = std::acos(clamp(std::cos(d) * std::cos(b), -1.0, 1.0));
    double theta = std::atan2(-std::sin(d), std::cos(d) * std::sin(b));
    if (theta < 0.0) theta += 2.0 * kPi;
    leaf.theta = theta;
    tree.leaves.push_back(leaf);
  }
}

}  // namespace

TreeModel grow_tree(const Species& s, uint64_t seed, double scale) {
  if (!std::isfinite(scale) || !(scale > 0.0)) {
    fail_argument("grow_tree: scale must be a positive finite number, got " +
                  std::to_string(scale) + " for species '" + s.name + "'");
  }
  if (s.levels < 1 || s.levels > kMaxTreeLevels) {
    fail_argument(describe(s) + ": Levels must be 1.." + std::to_string(kMaxTreeLevels));
  }
  TreeModel tree;
  tree.species = s.name;
  std::vector<StemState> state;

  // 1. The trunk: (0Length +- 0LengthV) (Scale +- ScaleV) long, times scale; radius
  //    length Ratio (0Scale +- 0ScaleV) (Weber & Penn: 0Scale scales the trunk's radius only).
  //    Some species vary more than the value (shave-grass: Scale 0.5 +- 0.7), where Arbaro
  //    grows nothing for a negative draw; each factor is kept above a tenth of its value.
  const SpeciesLevel& l0 = s.level[0];
  TreeRandom rng(seed, 0, kSelf);
  const auto varied = [&rng](double value, double variation) {
    return std::max(value + rng.vary(variation), kMinVariedFraction * value);
  };
  const double tree_size = varied(s.scale, s.scale_v) * scale;
  BranchModel trunk;
  trunk.length = varied(l0.length, l0.length_v) * tree_size;
  trunk.radius = trunk.length * s.ratio * varied(s.trunk_scale, s.trunk_scale_v);
  if (!std::isfinite(trunk.length) || !(trunk.length > 0.0) || !std::isfinite(trunk.radius) ||
      !(trunk.radius > 0.0)) {
    fail_argument(describe(s) + ": the trunk grew " + std::to_string(trunk.length) +
                  " m long and " + std::to_string(trunk.radius) +
                  " m thick; Scale, 0Length, Ratio and 0Scale must be positive");
  }
  trunk.flare = s.flare;
  trunk.lobe_count = s.lobes;
  trunk.lobe_depth = s.lobe_depth;
  trunk.lobe_taper = 1.0;
  shape_stem(trunk, l0, rng);
  tree.branches.push_back(trunk);
  StemState trunk_state;
  trunk_state.base_fraction = clamp(s.base_size, 0.0, 1.0);
  state.push_back(trunk_state);

  // 2. The stems, breadth first.
  tree.level_begin[0] = 0;
  for (int n = 0; n < kMaxTreeLevels; ++n) {
    const int32_t begin = tree.level_begin[size_t(n)];
    const int32_t end = int32_t(tree.branches.size());
    tree.level_begin[size_t(n) + 1] = end;
    if (end > begin) tree.levels = n + 1;
    if (n + 1 >= s.levels) continue;
    // Every count first, so an exploding species fails before it fills memory.
    std::vector<int64_t> counts(size_t(end - begin));
    double total = double(end);
    for (int32_t p = begin; p < end; ++p) {
      const double count = prepare_children(s, seed, p, tree, state);
      total += count;
      if (total > double(kMaxBranches)) {
        fail_argument(describe(s) + " grows more than " + std::to_string(kMaxBranches) +
                      " branches (at level " + std::to_string(n + 1) +
                      "); lower nBranches or Levels");
      }
      counts[size_t(p - begin)] = int64_t(count);
    }
    for (int32_t p = begin; p < end; ++p)
      grow_children(s, seed, p, counts[size_t(p - begin)], tree, state);
  }

  // 3. The leaves, on the last level (a one-level tree has none: Weber-Penn's trunk carries
  //    no leaves).
  if (s.leaves != 0 && s.levels >= 2) {
    const SpeciesLevel lv = leaf_level(s);
    const int last = s.levels - 1;
    double bound = 0.0;  // each stem rounds its expected count up at most
    for (int32_t p = tree.level_begin[size_t(last)]; p < tree.level_begin[size_t(last) + 1]; ++p)
      bound += std::ceil(expected_leaves(s, tree.branches[size_t(p)]));
    if (bound > double(kMaxLeaves)) {
      fail_argument(describe(s) + " grows more than " + std::to_string(kMaxLeaves) +
                    " leaves; lower Leaves or LeafQuality");
    }
    tree.leaves.reserve(size_t(bound));
    for (int32_t p = tree.level_begin[size_t(last)]; p < tree.level_begin[size_t(last) + 1]; ++p)
      grow_leaves(s, seed, scale, p, lv, tree, state);
  }
  return tree;
}

}  // namespace boreas::impl
