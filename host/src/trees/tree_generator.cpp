// boreas: the Weber-Penn tree generator — grows a species into cubic Beziers (Skjermo 2007
// sec. 2.1), how each attaches to its parent, and the leaves.
//
// The stages, in order:
//   1. The trunks: 0Branches of them from the tree's origin, each with its length, radius,
//      taper, flare and lobes, turned by 0Rotate and tilted by 0DownAngle.
//   2. Level by level (breadth first): each stem is walked segment by segment at rest in
//      world space (stem_walk.h: curvature, AttractionUp, splits, the pruning test), and
//      each run of segments between splits becomes one Bezier, a "piece". Then each stem of
//      level n draws its children's maximum length, works out how many children it has
//      (Weber-Penn's counts), spreads them over its branched part and gives each its offset,
//      rotation, down angle, length and radius; a child hangs from the piece its offset
//      falls on.
//   3. The leaves, on the pieces of the last level, turned toward the light by LeafBend.
//
// Every random draw comes from a stream keyed by (seed, stem index, purpose) (tree_random.h),
// so a stem's numbers do not depend on what other stems drew; the one exception is the
// split error, which Arbaro carries from stem to stem of a level and so do we. Equations
// are those of Weber and Penn, "Creation and Rendering of Realistic Trees" (1995), as the
// reference generator Arbaro reads them; where they are silent the choice is stated beside
// it.
//
// Several trunks (0Branches > 1) stand apart as Arbaro stands them (TreeImpl.make): each
// up to 0BranchDist from the tree's origin in a random horizontal direction (metres, not
// scaled by Scale), so a tuft of grass is a clump, not a point. The offset rides in the
// branch's unpositioned P0 (BranchModel::local[0]; BOREAS_TREE_SHAPE_LOCAL_P0 on the
// device), so every reader of the pose sees the trunk where it stands and the wind bends it
// about its own base.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/rest_frame.h"
#include "trees/stem_walk.h"
#include "trees/tree_model.h"
#include "trees/tree_random.h"

namespace boreas::impl {
namespace {

// Children shorter than this fraction of the trunk are not grown (Arbaro drops stems under
// 0.5 mm for the same reason: they are invisible and their own children more so).
constexpr double kMinStemFraction = 1e-4;
// The trunk's size, length and radius factors stay above this fraction of their values
// however large their variations.
constexpr double kMinVariedFraction = 0.1;
// At most this much of a stem, from its base, lies inside its parent and carries nothing.
constexpr double kMaxBaseFraction = 0.5;
// Radians: a split piece leaning less than this from its parent's tip tangent continues it
// (the walk's own turns are whole fractions of a degree; rounding leaves ~1e-14).
constexpr double kContinuingAlpha = 1e-9;
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;

// The purposes a stem draws numbers for, one stream each (stem_walk.cpp uses 5 and 64 up).
enum Purpose : uint64_t {
  kSelf = 0,
  kChildLength = 1,
  kChildren = 2,
  kLeaves = 3,
  kTrunks = 4,
  kTrunkBases = 6  // the trunks' places apart (stream 0): draws of their own, so that a
                   // species without 0BranchDist grows as it did before
};

double clamp(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }

// x rounded down, and up with probability its fraction (so counts keep their mean).
int64_t round_by_chance(double x, TreeRandom& rng) {
  const double whole = std::floor(x);
  return int64_t(whole) + (rng.uniform01() < x - whole ? 1 : 0);
}

// The stem's radius at the fraction z of its length (around the mean of the lobes): the
// radius functions of tree_model.h, beads and tip included (Arbaro's stemRadius at the
// child's offset bounds its radius).
double radius_at(const BranchModel& b, double z) { return profile_radius(b, clamp(z, 0.0, 1.0)); }

// Weber-Penn's nTaper as the deformer's radius functions, as Arbaro's stemRadius
// (StemImpl.java) draws it. length and radius must be set; `shape_radius` is Arbaro's
// baseRadius, which sizes the tip and the beads: the radius before 0Scale (Arbaro scales the
// trunk's radius after its profile; the same as radius elsewhere).
//   nTaper <= 1: a cone cut at 1 - nTaper of the base radius: depth nTaper, exponent 1. Exact.
//   1..2: Arbaro tapers linearly to (nTaper - 1) r at the tip (unit taper 2 - nTaper) and
//     rounds the last (nTaper - 1) r of length into a hemisphere. The linear part is exact
//     here (depth 2 - nTaper, exponent 1); the hemisphere is the tip's cap (tip_cap, the
//     tip radius over the length): the linear radius times sqrt(w (2 - w)) over the cap.
//     Arbaro's sphere has the local radius r(z) for its radius, the cap the tip's: they
//     differ by the taper's slope over one tip radius, (2 - nTaper) r_tip / L of r_tip
//     (test_taper_profiles.cpp measures it).
//   2..3: Arbaro's periodic taper: a cylinder of beads one diameter long counted from the
//     tip, whose waists sink by d = nTaper - 2 times r (each bead (1 - d) r + d r sqrt(1 -
//     (x - 1)^2), x in [0, 2] along it in radii), the last radius closed as a hemisphere.
//     Exact here: no taper, the beads as the bulges (boreas_beads: L / 2r of them, depth d,
//     phase 0 at the tip), the hemisphere as the tip's cap (r / L).
void set_taper(BranchModel& b, double n_taper, double shape_radius) {
  n_taper = clamp(n_taper, 0.0, 3.0);
  b.bulge_count = 0.0;
  b.bulge_depth = 0.0;
  b.bulge_phase = 0.0;
  b.taper_exponent = 1.0;
  b.tip_cap = 0.0;
  if (n_taper <= 1.0) {
    b.taper_depth = n_taper;
    return;
  }
  b.taper_depth = std::max(0.0, 2.0 - n_taper);
  if (!(b.length > 0.0) || !(shape_radius > 0.0)) return;
  b.tip_cap = std::min(n_taper - 1.0, 1.0) * shape_radius / b.length;
  if (n_taper > 2.0) {
    b.bulge_count = b.length / (2.0 * shape_radius);
    b.bulge_depth = n_taper - 2.0;
  }
}

// The tip's cap in a piece's own v: the stem's, on the piece that reaches the tip (the last
// piece, and each clone's), 0 on the others. A cap longer than its piece is cut at the
// piece's base (a stem whose last segment is shorter than its tip radius; none in the
// species files), where the radius then steps.
double tip_cap_of_piece(const BranchModel& whole, double z1, double span) {
  if (whole.tip_cap <= 0.0 || z1 < 1.0 || span <= 0.0) return 0.0;
  return std::min(whole.tip_cap / span, 1.0);
}

// A piece's radius functions: the stem's (`whole`) over its fraction [z0, z1]. The taper is
// exact for the first piece (1 - d (z1 v)^e) and for linear tapers; for other exponents
// the piece keeps the exponent and matches the stem's radius at both ends. The flare,
// which reaches an eighth of the stem, is folded into the radius of a later piece as its
// value at z0; bulges keep their length and their place from the stem's tip, lobes fade as
// on the stem.
void piece_radius(const BranchModel& whole, double z0, double z1, BranchModel& b) {
  const double span = z1 - z0;
  const double t0 = 1.0 - whole.taper_depth * std::pow(z0, whole.taper_exponent);
  const double t1 = 1.0 - whole.taper_depth * std::pow(z1, whole.taper_exponent);
  b.taper_exponent = whole.taper_exponent;
  b.flare = 0.0;
  if (z0 <= 0.0) {
    b.radius = whole.radius;
    b.taper_depth = whole.taper_depth * std::pow(span, whole.taper_exponent);
    b.flare = whole.flare;
  } else {
    const double flare =
        1.0 + whole.flare * (std::pow(100.0, std::max(0.0, 1.0 - 8.0 * z0)) - 1.0) / 100.0;
    b.radius = whole.radius * std::max(t0, 0.0) * flare;
    b.taper_depth = t0 > 0.0 ? (whole.taper_exponent == 1.0 ? whole.taper_depth * span / t0
                                                            : 1.0 - std::max(t1, 0.0) / t0)
                             : 1.0;
  }
  b.bulge_count = whole.bulge_count * span;
  b.bulge_depth = whole.bulge_depth;
  b.bulge_phase = whole.bulge_phase + whole.bulge_count * (1.0 - z1);
  b.lobe_count = whole.lobe_count;
  const double fade = 1.0 - z0 * whole.lobe_taper;
  b.lobe_depth = whole.lobe_depth * fade;
  b.lobe_taper = fade > 0.0 ? whole.lobe_taper * span / fade : 0.0;
  b.tip_cap = tip_cap_of_piece(whole, z1, span);
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

// "species 'willow' (willow.json, Levels = 4)".
std::string describe(const Species& s) {
  return "species '" + s.name + "' (" + (s.file.empty() ? "" : s.file + ", ") +
         "Levels = " + std::to_string(s.levels) + ")";
}

// A Weber-Penn stem: what its pieces share.
struct Stem {
  int level = 0;
  int parent = -1;        // parent stem; -1 for a trunk
  int parent_piece = -1;  // the branch its first piece hangs from; -1: the tree's root
  double v = 0.0, theta = 0.0, alpha = 0.0;  // that attachment (radians)
  double offset = 0.0;                       // m from the parent stem's base
  Vec3 base{0.0, 0.0, 0.0};                  // a trunk's base from the tree's origin, m
  double fraction = 0.0;                     // offset / the parent stem's length
  double length = 0.0;                       // Weber-Penn's L
  BranchModel profile;                       // the whole stem's radius functions
  double child_radius = 0.0;                 // Weber-Penn's base radius its children's grow from
  double base_fraction = 0.0;                // the fraction from its base that carries nothing
  double length_child_max = 0.0;             // its children's nLength +- nLengthV, drawn once
  int segments = 1;                          // its level's CurveRes
  StemWalk walk;
  std::vector<int32_t> pieces;  // the branch of each of walk.pieces
};

// A cubic's weights of its three legs at t: B(t) = P0 + sum w_k leg_k.
std::array<double, 3> leg_weights(double t) {
  const double u = 1.0 - t;
  return {1.0 - u * u * u, 3.0 * t * t - 2.0 * t * t * t, t * t * t};
}

// The parameter of the point of the curve of `legs` nearest to q, by Newton steps from t.
double nearest_parameter(const std::array<Vec3, 3>& legs, const Vec3& q, double t) {
  constexpr int kNewtonSteps = 3;
  for (int k = 0; k < kNewtonSteps; ++k) {
    const double u = 1.0 - t;
    const std::array<double, 3> w = leg_weights(t);
    const std::array<double, 3> w1 = {3.0 * u * u, 6.0 * t * u, 3.0 * t * t};
    const std::array<double, 3> w2 = {-6.0 * u, 6.0 - 12.0 * t, 6.0 * t};
    Vec3 b{0.0, 0.0, 0.0}, db{0.0, 0.0, 0.0}, ddb{0.0, 0.0, 0.0};
    for (size_t l = 0; l < 3; ++l) {
      b = b + legs[l] * w[l];
      db = db + legs[l] * w1[l];
      ddb = ddb + legs[l] * w2[l];
    }
    const Vec3 r = b - q;
    const double f = dot(r, db), df = dot(db, db) + dot(r, ddb);
    if (!(df > 0.0)) break;
    t = clamp(t - f / df, 0.0, 1.0);
  }
  return t;
}

// A piece's collapsed control polygon: three legs of a third of its length, the first
// along its first direction (the Bezier's start tangent). A walk of three segments is
// reproduced exactly. A longer walk is fitted (Schneider, "An Algorithm for Automatically
// Fitting Digitized Curves", Graphics Gems 1990, with the legs' lengths held): the other
// two legs' directions are those that bring the curve closest, in least squares, to the
// walk's segment ends. In legs, B(t) = P0 + (1 - (1-t)^3) leg1 + (3t^2 - 2t^3) leg2 + t^3
// leg3, linear in each leg, so with one leg held the best unit direction of the other is
// closed form (against its weighted residuals); alternating, from the middle third's mean
// and the last direction, with each segment end's parameter moved to its nearest point of
// the curve, settles it. Before, the legs were those two directions, whose sum falls short
// of the walk's end on a bent stem: barley's stalks, arching ~100 degrees over 49
// segments, stood 12 % lower than Arbaro's (now +2 %; fitting at t = j / m without moving
// the parameters overshoots by 9 %, keeping the walk's end exactly by 6 %). The price: the
// tip's tangent is no longer the walk's last direction exactly (up to 12 degrees off on a
// stem drooping 90 degrees by AttractionUp; test_weber_penn_rules.cpp measures both).
std::array<Vec3, 3> polygon_directions(const StemPiece& p) {
  const std::vector<Vec3>& d = p.directions;
  if (d.size() == 3) return {d[0], d[1], d[2]};
  const size_t m = d.size();
  Vec3 middle{0.0, 0.0, 0.0};
  for (size_t j = 0; j < m; ++j) {
    const double overlap = std::max(0.0, std::min(double(j) + 1.0, 2.0 * double(m) / 3.0) -
                                             std::max(double(j), double(m) / 3.0));
    middle = middle + d[j] * overlap;
  }
  std::array<Vec3, 3> legs{d.front(), unit(middle), d.back()};
  if (m < 3) return legs;
  // The walk's segment ends in units of a leg (L / 3), and their parameters on the curve.
  std::vector<Vec3> q(m);
  std::vector<double> param(m);
  Vec3 at{0.0, 0.0, 0.0};
  for (size_t j = 0; j < m; ++j) {
    at = at + d[j] * (3.0 / double(m));
    q[j] = at;
    param[j] = double(j + 1) / double(m);
  }
  constexpr int kAlternations = 6;
  constexpr double kTiny = 1e-12;
  for (int it = 0; it < kAlternations; ++it) {
    for (size_t j = 0; j + 1 < m; ++j) param[j] = nearest_parameter(legs, q[j], param[j]);
    for (size_t leg = 1; leg <= 2; ++leg) {
      // Minimize sum |w_j leg + r_j|^2 over a unit leg: leg = -unit(sum w_j r_j).
      Vec3 pull{0.0, 0.0, 0.0};
      for (size_t j = 0; j < m; ++j) {
        const std::array<double, 3> w = leg_weights(param[j]);
        Vec3 r = q[j] * -1.0;
        for (size_t k = 0; k < 3; ++k)
          if (k != leg) r = r + legs[k] * w[k];
        pull = pull + r * w[leg];
      }
      if (norm(pull) > kTiny) legs[leg] = unit(pull) * -1.0;
    }
  }
  return legs;
}

// Where grow_children puts a child on its parent (fraction of the parent's length, offset
// in m), how it leans (theta, alpha, degrees), and its length and radius (m).
struct ChildPlace {
  double fraction = 0.0, offset = 0.0, theta = 0.0, alpha = 0.0, length = 0.0, radius = 0.0;
};

// For each of a stem's segments, the pieces of its walk that cover it.
std::vector<std::vector<int32_t>> segment_cover(const Stem& parent) {
  std::vector<std::vector<int32_t>> cover(static_cast<size_t>(parent.segments));
  for (size_t k = 0; k < parent.walk.pieces.size(); ++k)
    for (int q = parent.walk.pieces[k].first; q < parent.walk.pieces[k].end; ++q)
      cover[size_t(q)].push_back(int32_t(k));
  return cover;
}

class Generator {
 public:
  Generator(const Species& s, uint64_t seed, double scale, const GrowthLimits& limits)
      : s_(s), seed_(seed), scale_(scale), limits_(limits) {}
  TreeModel grow();

 private:
  void grow_trunks();
  void add_stem(Stem stem, const RestFrame& start);
  void place_level(int level, const std::vector<int>& stems);
  double child_count(const Stem& stem) const;
  void grow_children(int p, int64_t n, std::vector<int>& next);
  double child_length(const Stem& parent, double fraction, double offset) const;
  void add_child(int p, const Stem& parent, const StemPiece& piece, const ChildPlace& c,
                 std::vector<int>& next);
  void grow_leaves(const Stem& stem, const SpeciesLevel& lv);
  void bend_leaf(LeafModel& leaf) const;
  void add_leaf(LeafModel leaf);
  double crown_area() const;
  double child_radius(const Stem& parent, double length, double fraction) const;
  const RestCurve& curve_of(int branch) const {
    return branch < 0 ? root_ : curves_[size_t(branch)];
  }

  const Species& s_;
  uint64_t seed_;
  double scale_;
  GrowthLimits limits_;
  size_t pieces_grown_ = 0;     // by the stems so far: the branches they will be when placed
  size_t segments_walked_ = 0;  // by every walk so far, the pruning tests' included
  double tree_size_ = 0.0;
  TreeModel tree_;
  std::vector<Stem> stems_;
  std::vector<RestCurve> curves_;  // each branch at rest
  RestCurve root_ = rest_root();
  std::array<double, kMaxTreeLevels> split_error_{};
};

// A stem walked from `start`, pruned to the envelope first where the species prunes (Arbaro's
// pruning: grow it as a test; while a segment's end leaves the envelope, shorten it to the
// segments before that one, by at least a fifteenth of its length and at most half of it,
// and test again; the final length is the original less PruneRatio of what was cut). Its
// children follow the shortened stem. The radius follows the final length.
void Generator::add_stem(Stem stem, const RestFrame& start) {
  StemWalkInput in;
  in.species = &s_;
  in.level = stem.level;
  in.segments = stem.segments;
  in.start = start;
  in.seed = seed_;
  in.stem = uint64_t(stems_.size());
  in.tree_size = tree_size_;
  double& error = split_error_[size_t(stem.level)];
  const auto room = [&] {
    StemWalkRoom r;
    r.pieces = limits_.branches - std::min(limits_.branches, pieces_grown_);
    r.segments = limits_.segments - std::min(limits_.segments, segments_walked_);
    r.limits = &limits_;
    return r;
  };
  const auto walk = [&](bool prune_test) {
    StemWalk w = walk_stem(in, &error, prune_test, room());
    segments_walked_ += w.segments;
    return w;
  };
  const double min_length = kMinStemFraction * tree_size_;
  if (stem.level >= 1 && s_.prune_ratio > 0.0) {
    const double saved = error, original = stem.length;
    double length = original;
    in.length = length;
    int outside = walk(true).outside;
    while (outside >= 0 && length > 0.001 * tree_size_) {
      error = saved;
      length = std::min(std::max(length / stem.segments * outside, 0.5 * length),
                        length - original / 15.0);
      in.length = length;
      if (length > min_length) outside = walk(true).outside;
    }
    error = saved;
    stem.length = original - (original - length) * s_.prune_ratio;
    if (!(stem.length > min_length)) return;
    stem.profile.radius = child_radius(stems_[size_t(stem.parent)], stem.length, stem.fraction);
    stem.child_radius = stem.profile.radius;
  }
  in.length = stem.length;
  stem.profile.length = stem.length;
  set_taper(stem.profile, s_.level[size_t(stem.level)].taper, stem.child_radius);
  stem.walk = walk(false);
  pieces_grown_ += stem.walk.pieces.size();
  stems_.push_back(std::move(stem));
}

// A trunk's base from the tree's origin, as Arbaro's TreeImpl.make places it: a distance
// var(0BranchDist) (uniform in (-d, d), so |distance| < d) along the horizontal direction
// (sin angle, cos angle) of angle = var(360). Arbaro hands that angle, drawn in degrees'
// range, to Math.sin as radians: over 720 radians the direction is uniform to 1e-3, and so
// it is here. d = 0 (one trunk, or trunks from one point) draws nothing and stands at 0.
Vec3 trunk_base(TreeRandom& rng, double distance) {
  if (!(distance > 0.0)) return {0.0, 0.0, 0.0};
  const double angle = rng.vary(360.0);
  const double d = rng.vary(distance);
  return {d * std::sin(angle), 0.0, d * std::cos(angle)};
}

// A piece's control points and rest curve moved by its stem's base (a trunk standing apart:
// the whole trunk moves, its attachment frame's axes stay), the offset in that frame.
void stand_apart(const RestFrame& f, const Vec3& base, BranchModel& b, std::array<Vec3, 4>& w) {
  if (base[0] == 0.0 && base[1] == 0.0 && base[2] == 0.0) return;
  const Vec3 local = {dot(base, f.x), dot(base, f.y), dot(base, f.z)};
  for (size_t k = 0; k < 4; ++k) {
    w[k] = w[k] + base;
    for (size_t a = 0; a < 3; ++a) b.local[k][a] += local[a];
  }
}

// 1. The trunks: (0Length +- 0LengthV) (Scale +- ScaleV) long, times scale; radius length
//    Ratio 0Scale — Arbaro applies 0Scale to the trunk's own radius only, so its children
//    grow from length Ratio. 0ScaleV is not a factor on the radius: Arbaro jitters each
//    vertex of the trunk's mesh by up to 0ScaleV / (its segment's subsegments) of the radius
//    (SegmentImpl.getSectionPoints), bark roughness. The drawn trunk here is swept from its
//    radius functions, which have no per-vertex term, so the jitter is left out. Some
//    species vary more than the value (shave-grass: Scale 0.5 +- 0.7), where Arbaro grows
//    nothing for a negative draw; a factor below a tenth of its value is drawn again.
//    Several trunks (0Branches) turn by 0Rotate +- 0RotateV around the root and tilt by
//    0DownAngle +- 0DownAngleV, as Arbaro's trunkDirection, and stand apart by up to
//    0BranchDist (trunk_base).
void Generator::grow_trunks() {
  const SpeciesLevel& l0 = s_.level[0];
  TreeRandom rng(seed_, 0, kSelf);
  // A draw below a tenth of the value is drawn again (a few times, then clamped): Arbaro
  // grows nothing for a negative size, so the trees it does grow are these draws.
  const auto varied = [&rng](double value, double variation) {
    double x = value + rng.vary(variation);
    for (int tries = 0; tries < 8 && x < kMinVariedFraction * value; ++tries)
      x = value + rng.vary(variation);
    return std::max(x, kMinVariedFraction * value);
  };
  tree_size_ = varied(s_.scale, s_.scale_v) * scale_;
  const int trunks = int(l0.branches);
  if (trunks < 1) fail_argument(describe(s_) + ": 0Branches must be at least 1 (the trunks)");
  TreeRandom turn(seed_, 0, kTrunks);
  TreeRandom spread(seed_, 0, kTrunkBases);
  RotationAccumulator rotation;
  for (int t = 0; t < trunks; ++t) {
    Stem trunk;
    trunk.segments = int(clamp(std::round(l0.curve_res), 1.0, 1000.0));
    trunk.length = varied(l0.length, l0.length_v) * tree_size_;
    trunk.child_radius = trunk.length * s_.ratio;
    trunk.profile.radius = trunk.child_radius * s_.trunk_scale;
    if (!std::isfinite(trunk.length) || !(trunk.length > 0.0) ||
        !std::isfinite(trunk.profile.radius) || !(trunk.profile.radius > 0.0)) {
      fail_argument(describe(s_) + ": the trunk grew " + std::to_string(trunk.length) +
                    " m long and " + std::to_string(trunk.profile.radius) +
                    " m thick; Scale, 0Length, Ratio and 0Scale must be positive");
    }
    trunk.profile.flare = s_.flare;
    trunk.profile.lobe_count = s_.lobes;
    trunk.profile.lobe_depth = s_.lobe_depth;
    trunk.profile.lobe_taper = 1.0;
    trunk.base_fraction = clamp(s_.base_size, 0.0, 1.0);
    trunk.theta = rotation.next(l0, turn) * kRadiansPerDegree;
    trunk.alpha = (l0.down_angle + turn.vary(l0.down_angle_v)) * kRadiansPerDegree;
    trunk.base = trunk_base(spread, l0.branch_dist * scale_);
    RestFrame start = rest_attach(root_, 0.0, trunk.theta, trunk.alpha);
    start.origin = start.origin + trunk.base;
    add_stem(trunk, start);
  }
}

// The pieces of the given stems (all of one level) as branches: in order of split depth
// (one step tier each), each depth in order of the parents, so the children of one parent
// are contiguous and a piece comes after the piece it grows from.
void Generator::place_level(int level, const std::vector<int>& stem_ids) {
  struct Ref {
    int stem, piece;
  };
  std::vector<std::vector<Ref>> by_depth;
  for (int id : stem_ids) {
    Stem& stem = stems_[size_t(id)];
    stem.pieces.assign(stem.walk.pieces.size(), -1);
    for (int k = 0; k < int(stem.walk.pieces.size()); ++k) {
      const int depth = stem.walk.pieces[size_t(k)].depth;
      if (int(by_depth.size()) <= depth) by_depth.resize(size_t(depth) + 1);
      by_depth[size_t(depth)].push_back({id, k});
    }
  }
  for (std::vector<Ref>& tier : by_depth) {
    if (tier.empty()) continue;
    const auto parent_of = [&](const Ref& r) {
      const Stem& stem = stems_[size_t(r.stem)];
      const StemPiece& piece = stem.walk.pieces[size_t(r.piece)];
      return piece.parent < 0 ? stem.parent_piece : stem.pieces[size_t(piece.parent)];
    };
    std::stable_sort(tier.begin(), tier.end(),
                     [&](const Ref& a, const Ref& b) { return parent_of(a) < parent_of(b); });
    tree_.tier_begin.push_back(int32_t(tree_.branches.size()));
    tree_.tier_level.push_back(level);
    for (const Ref& r : tier) {
      Stem& stem = stems_[size_t(r.stem)];
      const StemPiece& piece = stem.walk.pieces[size_t(r.piece)];
      const int parent = parent_of(r);
      BranchModel b;
      b.level = level;
      b.parent = parent;
      b.split_depth = piece.depth;
      b.clone = piece.clone;
      b.stem_length = stem.length;
      b.stem_from = double(piece.first) / stem.segments;
      b.length = stem.length * double(piece.end - piece.first) / stem.segments;
      piece_radius(stem.profile, b.stem_from, double(piece.end) / stem.segments, b);
      const std::array<Vec3, 3> d = polygon_directions(piece);
      if (piece.parent < 0) {
        b.v = stem.v;
        b.theta = stem.theta;
        b.alpha = stem.alpha;
      } else {  // a split: on the tip of the piece it grows from, along its first direction
        b.v = 1.0;
        rest_attach_angles(rest_point(curve_of(parent), 1.0), d[0], &b.theta, &b.alpha);
        // The continuing stem keeps its heading (stem_walk.cpp, split), so its first
        // direction is its parent's tip tangent and alpha is rounding (~1e-14): theta, the
        // side it leans to, is then atan2 of rounding, and it rolls the piece's frame (O is
        // the attachment's y) and every child and leaf placed around the piece by that
        // arbitrary angle. Such a piece takes its parent's frame at the tip instead (theta
        // and alpha 0: S and T carry on), as Arbaro's continuing stem keeps its own.
        if (b.alpha < kContinuingAlpha) b.theta = b.alpha = 0.0;
      }
      const RestFrame f = rest_attach(curve_of(parent), b.v, b.theta, b.alpha);
      const double third = b.length / 3.0;
      const Vec3 w1 = rest_place(f, {third, 0.0, 0.0});
      const Vec3 w2 = w1 + d[1] * third;
      const Vec3 w3 = w2 + d[2] * third;
      b.local[1] = {third, 0.0, 0.0};
      b.local[2] = rest_local(f, w2);
      b.local[3] = rest_local(f, w3);
      std::array<Vec3, 4> w = {f.origin, w1, w2, w3};
      if (piece.parent < 0) stand_apart(f, stem.base, b, w);
      const RestCurve c = rest_curve(w, f.y);
      stem.pieces[size_t(r.piece)] = int32_t(tree_.branches.size());
      tree_.branches.push_back(b);
      curves_.push_back(c);
    }
  }
}

// A child's base radius: Weber-Penn's parent radius (L / L_parent)^RatioPower, at most the
// parent's radius where it grows.
double Generator::child_radius(const Stem& parent, double length, double fraction) const {
  return std::min(parent.child_radius * std::pow(length / parent.length, s_.ratio_power),
                  radius_at(parent.profile, fraction));
}

// Weber-Penn's number of children of a stem (README): on the trunk nBranches; on a level-1
// stem N (0.2 + 0.8 (L / L_parent) / nLength_max), nLength_max the length_child_max the
// trunk drew for it; deeper N (1 - 0.5 offset / L_parent). Floored.
double Generator::child_count(const Stem& stem) const {
  const double n_max = s_.level[size_t(stem.level) + 1].branches;
  double count = n_max;
  if (stem.level == 1) {
    const Stem& parent = stems_[size_t(stem.parent)];
    if (!(parent.length_child_max > 0.0) || !(parent.length > 0.0)) return 0.0;
    count = n_max * (0.2 + 0.8 * (stem.length / parent.length) / parent.length_child_max);
  } else if (stem.level >= 2) {
    count = n_max * (1.0 - 0.5 * stem.fraction);
  }
  if (!(count > 0.0)) return 0.0;  // also NaN
  return std::floor(count);
}

// The n children of stem p, as stems of the next level (appended to `next`).
//
// Placement (Arbaro's makeSubstems): each of the stem's CurveRes segments carries its share
// of the children on its branched part (above BaseSize on the trunk; above the part inside
// its own parent otherwise); in a segment whose branched part is a fraction b of it, with m
// children, the j-th sits at (j + 1/2) d +- d/4 from the part's start, d = b nBranchDist / m
// (nBranchDist 1 spreads them evenly, 0 puts them all at its start, a whorl). A child hangs
// from the piece its offset falls on; where a split made several, they take turns (Arbaro
// divides a split stem's children per segment among its clones). The rounding error starts
// at zero on each stem (Arbaro carries it from stem to stem of a level; per stem keeps a
// stem's children independent of the others).
void Generator::grow_children(int p, int64_t n, std::vector<int>& next) {
  if (n <= 0) return;
  const Stem parent = stems_[size_t(p)];  // a copy: add_stem grows stems_
  const int level = parent.level + 1;
  const SpeciesLevel& lc = s_.level[size_t(level)];
  TreeRandom rng(seed_, uint64_t(p), kChildren);
  const double base = parent.base_fraction;
  const int segments = parent.segments;
  const double branch_dist = clamp(lc.branch_dist, 0.0, 1.0);
  // The span over which a negative nDownAngleV varies: the branched part on the trunk.
  const double down_span = parent.level == 0 ? parent.length * (1.0 - s_.base_size) : parent.length;
  const std::vector<std::vector<int32_t>> cover = segment_cover(parent);
  std::vector<size_t> turns(size_t(segments), 0);
  RotationAccumulator rotation;

  // Per segment of the stem: n / CurveRes children (on the trunk n / CurveRes / (1 -
  // BaseSize) over the part of each segment above BaseSize), rounded with the error carried
  // to the next segment, so the stem has n in all.
  const double per_segment = double(n) / segments / (parent.level == 0 ? 1.0 - base : 1.0);
  double error = 0.0;
  for (int k = 0; k < segments; ++k) {
    const double start = clamp(base * segments - k, 0.0, 1.0);  // of the segment, bare
    if (start >= 1.0) continue;
    const double rate = parent.level == 0 ? per_segment * (1.0 - start) : per_segment;
    const int64_t m = int64_t(rate + error + 0.5);
    error -= double(m) - rate;
    if (m <= 0) continue;
    const double spacing = (1.0 - start) / double(m) * branch_dist;
    for (int64_t j = 0; j < m; ++j) {
      ChildPlace c;
      const double where = start + spacing * (double(j) + 0.5) + rng.vary(0.25 * spacing);
      c.fraction = clamp((k + where) / segments, base, 1.0);
      c.offset = c.fraction * parent.length;
      c.theta = rotation.next(lc, rng);
      c.alpha = down_angle(s_, lc, rng, parent.length, c.offset, down_span);
      c.length = child_length(parent, c.fraction, c.offset);
      c.radius = child_radius(parent, c.length, c.fraction);
      if (!(c.length > kMinStemFraction * tree_size_) || !(c.radius > 0.0)) continue;

      // The piece the offset falls on, and where on it.
      const int q = std::min(int(c.fraction * segments), segments - 1);
      const std::vector<int32_t>& pieces = cover[size_t(q)];
      const StemPiece& piece =
          parent.walk.pieces[size_t(pieces[turns[size_t(q)]++ % pieces.size()])];
      add_child(p, parent, piece, c, next);
    }
  }
}

// Length: level 1 follows the tree's shape over the branched part of the trunk,
// (L0 - offset) / (L0 - BaseSize L0) (the README's BaseSize Scale when 0Length is 1;
// the trunk's own length keeps the ratio in 0..1); deeper levels shorten toward their
// parent's tip.
double Generator::child_length(const Stem& parent, double fraction, double offset) const {
  const int level = parent.level + 1;
  const double base = parent.base_fraction;
  double length;
  if (level == 1) {
    const double ratio = base < 1.0 ? clamp((1.0 - fraction) / (1.0 - base), 0.0, 1.0) : 0.0;
    length = parent.length * parent.length_child_max * shape_ratio(s_, s_.shape, ratio);
  } else {
    length = parent.length_child_max * (parent.length - 0.6 * offset);
  }
  return length;
}

// The child placed at c on `piece` of stem p (parent), added as a stem of the next level
// (its index appended to `next` when it grew).
void Generator::add_child(int p, const Stem& parent, const StemPiece& piece, const ChildPlace& c,
                          std::vector<int>& next) {
  const int level = parent.level + 1;
  const SpeciesLevel& lc = s_.level[size_t(level)];
  const int segments = parent.segments;
  const size_t piece_index = size_t(&piece - parent.walk.pieces.data());
  Stem child;
  child.level = level;
  child.parent = p;
  child.parent_piece = parent.pieces[piece_index];
  // The arclength fraction as the Bezier parameter: exact while the polygon is straight
  // (evenly spaced control points), close for the gentle curves of real species.
  child.v =
      clamp((c.fraction * segments - piece.first) / double(piece.end - piece.first), 0.0, 1.0);
  child.theta = c.theta * kRadiansPerDegree;
  child.alpha = c.alpha * kRadiansPerDegree;
  child.offset = c.offset;
  child.fraction = c.fraction;
  child.length = c.length;
  child.segments = int(clamp(std::round(lc.curve_res), 1.0, 1000.0));
  child.profile.radius = c.radius;
  child.child_radius = c.radius;
  child.base_fraction =
      std::min(radius_at(parent.profile, c.fraction) / c.length, kMaxBaseFraction);
  const size_t before = stems_.size();
  add_stem(child, rest_attach(curve_of(child.parent_piece), child.v, child.theta, child.alpha));
  if (stems_.size() > before) next.push_back(int(before));
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

// The leaves of a last-level stem: |Leaves| ShapeRatio(offset / L_parent, LeafDistrib)
// LeafQuality of them.
//   Leaves > 0: each piece's share rounded up with the fraction's probability, spread along
//     its part above the stem's base part like children (jitter +- half a spacing), each
//     turned by the leaf block's rotation and down angle. The share is by segments, as
//     Arbaro gives every segment of the stem and of each clone leavesPerSegment = count /
//     CurveRes (a clone inherits it undivided; the base part only moves the first
//     segment's leaves up); sharing by the length above the base part gave clones, which
//     have none, 1 / (1 - base) too many (desert_bush: +4.6 % leaves).
//   Leaves < 0: Weber-Penn's fan at each tip (v = 1 of each last piece: clones grow their
//     own, as in Arbaro), the count rounded to the nearest whole as Arbaro rounds it:
//     leaves spread in a plane through the stem by nRotate / count apart (+- nRotateV /
//     count), each tilted out of it by the down angle; that direction is
//     stored as its angle from the stem (alpha) and azimuth (theta).
// Size: Weber-Penn's LeafScale / sqrt(LeafQuality) (fewer, larger leaves keep the area), times
// scale; width LeafScaleX of that, petiole LeafStemLen of it.
double expected_leaves(const Species& s, double fraction) {
  const double expected = std::fabs(double(s.leaves)) *
                          shape_ratio(s, s.leaf_distrib, clamp(fraction, 0.0, 1.0)) *
                          s.leaf_quality;
  return expected > 0.0 ? expected : 0.0;  // also NaN
}

// LeafBend, as Arbaro's setLeafOrientation (LeafImpl.java): the leaf turns toward the light
// by the fraction LeafBend, first about the vertical (its normal's azimuth toward the azimuth
// of the leaf's base from the trunk: out of the crown), then about its own x axis (normal x
// leaf axis, Arbaro's local rotx) by LeafBend times the normal's angle from the vertical,
// which turns the normal toward the leaf's axis. The turned axis is stored as the
// attachment's angles and the normal as the blade's roll about that axis. Arbaro leaves the
// azimuth difference unwrapped; it is wrapped here so a leaf turns the short way round.
void Generator::bend_leaf(LeafModel& leaf) const {
  if (s_.leaf_bend == 0.0) return;
  const RestPoint at = rest_point(curve_of(leaf.parent), leaf.v);
  const RestFrame f =
      rest_attach(at, {leaf.cos_theta, leaf.sin_theta, leaf.cos_alpha, leaf.sin_alpha});
  Vec3 axis = f.x, normal = f.y;
  const Vec3 position = f.origin;
  // The turn from the normal's azimuth to the position's, in (-pi, pi]: the angle between
  // their horizontal parts.
  // (None for a leaf on the trunk's axis or a normal within 1e-9 of vertical, whose
  // azimuths are not defined.)
  const double x = position[0] * normal[0] + position[2] * normal[2];
  const double y = position[0] * normal[2] - position[2] * normal[0];
  if (position[0] * position[0] + position[2] * position[2] > 0.0 &&
      normal[0] * normal[0] + normal[2] * normal[2] > 1e-18) {
    const double turn = s_.leaf_bend * std::atan2(y, x);
    const double c = std::cos(turn), sn = std::sin(turn);
    axis = rotate(axis, kUp, c, sn);
    normal = rotate(normal, kUp, c, sn);
  }
  // About the leaf's own x axis: the normal turns toward the axis, the axis away from it.
  const double up = s_.leaf_bend * std::acos(clamp(dot(normal, kUp), -1.0, 1.0));
  const double c = std::cos(up), sn = std::sin(up);
  const Vec3 turned_normal = normal * c + axis * sn;
  axis = axis * c - normal * sn;
  normal = turned_normal;
  RestAngles turned;
  const RestFrame g = rest_attach_along(at, axis, &turned);
  leaf.cos_theta = turned.cos_theta;
  leaf.sin_theta = turned.sin_theta;
  leaf.cos_alpha = turned.cos_alpha;
  leaf.sin_alpha = turned.sin_alpha;
  // The normal lies in the turned frame's y-z plane (both turns keep it perpendicular to
  // the axis): its two components there are the roll's cosine and sine.
  const double ny = dot(normal, g.y), nz = dot(normal, g.z), n = std::sqrt(ny * ny + nz * nz);
  if (n > 0.0) {
    leaf.cos_roll = ny / n;
    leaf.sin_roll = nz / n;
  }
}

void Generator::add_leaf(LeafModel leaf) {
  bend_leaf(leaf);
  tree_.leaves.push_back(leaf);
}

void Generator::grow_leaves(const Stem& stem, const SpeciesLevel& lv) {
  TreeRandom rng(seed_, uint64_t(&stem - stems_.data()), kLeaves);
  const double expected = expected_leaves(s_, stem.fraction);
  LeafModel leaf;
  leaf.length = s_.leaf_scale / std::sqrt(s_.leaf_quality) * scale_;
  leaf.width = leaf.length * s_.leaf_scale_x;
  leaf.stem = leaf.length * s_.leaf_stem_len;
  const double base = stem.base_fraction;
  const double n = stem.segments;
  RotationAccumulator rotation;
  for (size_t k = 0; k < stem.walk.pieces.size(); ++k) {
    const StemPiece& piece = stem.walk.pieces[k];
    leaf.parent = stem.pieces[k];
    if (s_.leaves > 0) {
      const double z0 = std::max(piece.first / n, base), z1 = piece.end / n;
      if (!(z1 > z0)) continue;
      const double share = expected * double(piece.end - piece.first) / n;
      const int64_t count = round_by_chance(share, rng);
      const double spacing = 1.0 / double(std::max<int64_t>(count, 1));
      for (int64_t i = 0; i < count; ++i) {
        const double where = spacing * (double(i) + 0.5) + rng.vary(0.5 * spacing);
        const double fraction = clamp(z0 + (z1 - z0) * where, z0, z1);
        leaf.v = clamp((fraction - piece.first / n) / ((piece.end - piece.first) / n), 0.0, 1.0);
        leaf.set_theta(rotation.next(lv, rng) * kRadiansPerDegree);
        leaf.set_alpha(down_angle(s_, lv, rng, stem.length, fraction * stem.length, stem.length) *
                       kRadiansPerDegree);
        add_leaf(leaf);
      }
      continue;
    }
    if (piece.end != stem.segments) continue;
    // Arbaro rounds a fan's count to the nearest whole ((int)(leaves + 0.5)), not by chance:
    // a rush's 0.5 to 1 leaf per stem is one leaf on every stem.
    const int64_t count = int64_t(expected + 0.5);
    if (count == 0) continue;
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
      // The direction (cos d sin b, -sin d, cos d cos b) with the stem along the last axis:
      // alpha its angle from the stem, theta its azimuth around it.
      const double along = clamp(std::cos(d) * std::cos(b), -1.0, 1.0);
      leaf.cos_alpha = along;
      leaf.sin_alpha = std::sqrt(1.0 - along * along);
      const double x = std::cos(d) * std::sin(b), y = -std::sin(d), r = std::sqrt(x * x + y * y);
      leaf.cos_theta = r > 0.0 ? x / r : 1.0;
      leaf.sin_theta = r > 0.0 ? y / r : 0.0;
      add_leaf(leaf);
    }
  }
}

TreeModel Generator::grow() {
  if (!std::isfinite(scale_) || !(scale_ > 0.0)) {
    fail_argument("grow_tree: scale must be a positive finite number, got " +
                  std::to_string(scale_) + " for species '" + s_.name + "'");
  }
  if (s_.levels < 1 || s_.levels > kMaxTreeLevels) {
    fail_argument(describe(s_) + ": Levels must be 1.." + std::to_string(kMaxTreeLevels));
  }
  // Arbaro refuses a split without an angle (Params.prepare: "nSplitAngle may not be 0"):
  // its clones would grow inside the stem they split from.
  for (int n = 0; n < s_.levels; ++n) {
    const SpeciesLevel& lv = s_.level[size_t(n)];
    if (lv.seg_splits > 0.0 && lv.split_angle == 0.0) {
      const std::string l = std::to_string(n);
      fail_argument(describe(s_) + ": " + l + "SegSplits is " + param_text(lv.seg_splits) +
                    " but " + l + "SplitAngle is 0; a stem that splits needs a split angle " +
                    "(Arbaro refuses it too)");
    }
  }
  tree_.species = s_.name;
  tree_.wood_modulus = s_.wood_modulus * 1e9;
  tree_.wood_rupture = s_.wood_rupture * 1e6;
  tree_.vogel_exponent = s_.vogel_exponent;
  tree_.vogel_speed = s_.vogel_speed;
  tree_.leaf_area_index = s_.leaf_area_index;
  tree_.clumping = s_.clumping;
  grow_trunks();
  std::vector<int> level_stems;
  for (int id = 0; id < int(stems_.size()); ++id) level_stems.push_back(id);

  // 2. The stems, breadth first.
  for (int n = 0; n < kMaxTreeLevels; ++n) {
    tree_.level_begin[size_t(n)] = int32_t(tree_.branches.size());
    place_level(n, level_stems);
    if (int32_t(tree_.branches.size()) > tree_.level_begin[size_t(n)]) tree_.levels = n + 1;
    std::vector<int> next;
    if (n + 1 < s_.levels) {
      // Every count first, so an exploding species fails before it fills memory.
      std::vector<int64_t> counts(level_stems.size());
      double total = double(tree_.branches.size());
      for (size_t i = 0; i < level_stems.size(); ++i) {
        Stem& stem = stems_[size_t(level_stems[i])];
        const SpeciesLevel& lc = s_.level[size_t(n) + 1];
        TreeRandom rng(seed_, uint64_t(level_stems[i]), kChildLength);
        stem.length_child_max = std::max(0.0, lc.length + rng.vary(lc.length_v));
        const double count = child_count(stem);
        total += count;
        if (total > double(limits_.branches)) {
          const std::string child = std::to_string(n + 1);
          fail_argument(describe(s_) + " grows more than " + std::to_string(limits_.branches) +
                        " branches, the most one tree may have (at level " + child + "); lower " +
                        child + "Branches (" + param_text(lc.branches) + ") or Levels");
        }
        counts[i] = int64_t(count);
      }
      for (size_t i = 0; i < level_stems.size(); ++i)
        grow_children(level_stems[i], counts[i], next);
    }
    level_stems = std::move(next);
  }
  tree_.level_begin[kMaxTreeLevels] = int32_t(tree_.branches.size());
  tree_.tier_begin.push_back(int32_t(tree_.branches.size()));

  // 3. The leaves, on the last level (a one-level tree has none: Weber-Penn's trunk carries
  //    no leaves), grouped by the piece they grow on.
  if (s_.leaves != 0 && s_.levels >= 2) {
    const SpeciesLevel lv = leaf_level(s_);
    const int last = s_.levels - 1;
    double bound = 0.0;  // each piece rounds its expected count up at most
    for (const Stem& stem : stems_) {
      if (stem.level == last)
        bound += (std::ceil(expected_leaves(s_, stem.fraction)) + 1.0) * double(stem.pieces.size());
    }
    if (bound > double(limits_.leaves)) {
      fail_argument(describe(s_) + " grows more than " + std::to_string(limits_.leaves) +
                    " leaves, the most one tree may have; lower Leaves (" + param_text(s_.leaves) +
                    "), LeafQuality (" + param_text(s_.leaf_quality) + ") or " +
                    std::to_string(last) + "Branches");
    }
    tree_.leaves.reserve(size_t(bound));
    for (const Stem& stem : stems_)
      if (stem.level == last) grow_leaves(stem, lv);
    const auto by_parent = [](const LeafModel& a, const LeafModel& b) {
      return a.parent < b.parent;
    };
    if (!std::is_sorted(tree_.leaves.begin(), tree_.leaves.end(), by_parent))  // splits only
      std::stable_sort(tree_.leaves.begin(), tree_.leaves.end(), by_parent);
  }
  tree_.crown_area = crown_area();
  return std::move(tree_);
}

// The crown seen from the side as an ellipse: as wide as twice the distance from the
// trunk's axis that 90 % of the last level's control points stay within, as tall as the
// heights between their 5th and 95th percentiles (a few stray twigs do not make a crown).
double Generator::crown_area() const {
  std::vector<double> reach, height;
  for (int b = tree_.level_begin[size_t(tree_.levels - 1)]; b < int(tree_.branches.size()); ++b) {
    for (const Vec3& p : curve_of(b).p) {
      reach.push_back(std::sqrt(p[0] * p[0] + p[2] * p[2]));
      height.push_back(p[1]);
    }
  }
  if (reach.empty()) return 0.0;
  auto percentile = [](std::vector<double>& v, double q) {
    auto at = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), at, v.end());
    return *at;
  };
  const double width = 2.0 * percentile(reach, 0.9);
  const double tall = percentile(height, 0.95) - percentile(height, 0.05);
  return kPi / 4.0 * width * tall;
}

}  // namespace

TreeModel grow_tree(const Species& s, uint64_t seed, double scale, const GrowthLimits& limits) {
  return Generator(s, seed, scale, limits).grow();
}

}  // namespace boreas::impl
