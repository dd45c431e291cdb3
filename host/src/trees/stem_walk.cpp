// boreas: a Weber-Penn stem walked segment by segment (stem_walk.h). The rules are Arbaro's
// (StemImpl: newDirection, makeClones, split, pruning), in boreas's frame: a stem curves
// about its frame's z axis, turning x toward y (the same way as its down angle), up is +y.
#include "trees/stem_walk.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "trees/tree_model.h"
#include "trees/tree_random.h"

namespace boreas::impl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiansPerDegree = kPi / 180.0;
// Random streams of a stem's walk: its own, and one per clone (kCloneStream + n).
constexpr uint64_t kWalkStream = 5;
constexpr uint64_t kCloneStream = 64;

struct Walker {
  Vec3 position, x, y, z;   // x: the current segment's direction
  double correction = 0.0;  // split correction, degrees per later segment
  TreeRandom rng{0, 0, 0};
  int depth = 0;
  bool clone = false;
  int parent = -1;
  int from = 0;
};

struct Walk {
  const StemWalkInput& in;
  const Species& s;
  const SpeciesLevel& lv;
  double* split_error;
  bool prune_test;
  const StemWalkRoom& room;
  uint64_t clones = 0;
  StemWalk out;
};

void turn(Walker& w, const Vec3& axis, double degrees) {
  const double a = degrees * kRadiansPerDegree, c = std::cos(a), s = std::sin(a);
  w.x = rotate(w.x, axis, c, s);
  w.y = rotate(w.y, axis, c, s);
  w.z = rotate(w.z, axis, c, s);
}

// Declination: the angle between the direction and up, radians.
double declination(const Vec3& x) { return std::acos(std::clamp(dot(x, kUp), -1.0, 1.0)); }

// The direction of segment s > 0 (Arbaro's newDirection): the level's curvature (nCurve over
// CurveRes, or with nCurveBack twice nCurve in the first half and twice nCurveBack in the
// second) plus the split correction; nCurveV / CurveRes about a random axis across the stem
// (a negative nCurveV, Weber-Penn's helix, cannot be a Bezier and is ignored, as Arbaro's
// meshes do); then on levels >= 2 AttractionUp |d sin d| / CurveRes radians toward up (down
// when negative), d the declination. Weber & Penn print AttractionUp d cos(orientation) /
// CurveRes; Arbaro drops the orientation term, which attracts only branches whose frame
// happens to face up, and so do we.
void new_direction(Walk& k, Walker& w, int s) {
  const int n = k.in.segments;
  double delta = k.lv.curve / n;
  if (k.lv.curve_back != 0.0) delta = 2.0 * (s < (n + 1) / 2 ? k.lv.curve : k.lv.curve_back) / n;
  turn(w, w.z, delta + w.correction);
  if (k.lv.curve_v > 0.0) {
    const double random = w.rng.vary(k.lv.curve_v) / n;
    const double axis_angle = kPi * w.rng.uniform_pm1();
    turn(w, w.z * std::cos(axis_angle) + w.y * std::sin(axis_angle), random);
  }
  if (k.in.level >= 2 && k.s.attraction_up != 0.0) {
    const double d = declination(w.x);
    const double up = k.s.attraction_up * std::fabs(d * std::sin(d)) / n;
    const Vec3 axis = cross(w.x, kUp);  // turning x about x cross up moves it toward up
    if (norm(axis) > 1e-12) turn(w, unit(axis), up / kRadiansPerDegree);
  }
}

// Whether the end of segment s is the trunk's base split (0BaseSplits).
bool base_split(const Walk& k, int s) { return k.in.level == 0 && s == 0 && k.s.base_splits > 0; }

// How many clones the end of segment s makes: the trunk's first segment 0BaseSplits, else
// nSegSplits rounded with the level's error carried (Arbaro's makeClones).
int split_count(Walk& k, const Walker& w, int s) {
  int count;
  if (base_split(k, s)) {
    count = k.s.base_splits;
  } else {
    count = int(k.lv.seg_splits + *k.split_error + 0.5);
    *k.split_error -= count - k.lv.seg_splits;
  }
  return w.depth >= kMaxSplitDepth ? 0 : std::max(count, 0);
}

// Arbaro's split (StemImpl.split): each piece draws the split angle nSplitAngle +-
// nSplitAngleV less its declination, and its later segments turn back by that angle over the
// remaining ones. A clone (spread > 0) turns away by the angle about its own z axis first,
// then diverges about the vertical: evenly around for base splits, else by 20 + 0.75 (30 +
// |declination - 90|) ((v + 1) / 2)^2 degrees to a random side. The continuing stem (spread
// 0) keeps its heading and takes only the correction: Arbaro computes its turn too, but
// `trf = split(trf, 0, ...)` at the end of makeClones only reassigns a local (a
// Transformation is immutable), so the turn is lost and the stem bends away from its clones
// over its remaining segments. Forks are lopsided, and species files were tuned that way.
void split(Walk& k, Walker& w, double spread, int s) {
  const int remaining = k.in.segments - s - 1;
  const double d = declination(w.x) / kRadiansPerDegree;
  const double angle = std::max(0.0, k.lv.split_angle + w.rng.vary(k.lv.split_angle_v) - d);
  w.correction -= angle / remaining;
  if (spread > 0.0) {
    turn(w, w.z, angle);
    double diverge;
    if (base_split(k, s)) {
      diverge = spread + w.rng.vary(k.lv.split_angle_v);
    } else {
      const double v = w.rng.vary(1.0);
      diverge = 20.0 + 0.75 * (30.0 + std::fabs(d - 90.0)) * std::pow((v + 1.0) / 2.0, 2.0);
      if (w.rng.vary(1.0) >= 0.0) diverge = -diverge;
    }
    turn(w, kUp, diverge);
  }
}

void add_piece(Walk& k, StemPiece&& piece) {
  if (k.out.pieces.size() >= k.room.pieces) {
    const std::string n = std::to_string(k.in.level);
    fail_argument(
        species_label(k.s) + " grows more than " + std::to_string(k.room.limits->branches) +
        " branches, the most one tree may have (splitting at level " + n + "); lower " + n +
        "SegSplits (" + param_text(k.lv.seg_splits) + ")" +
        (k.in.level == 0 ? ", 0BaseSplits (" + param_text(k.s.base_splits) + ")" : std::string()) +
        " or " + n + "Branches");
  }
  k.out.pieces.push_back(std::move(piece));
}

// Counts a segment walked; past the tree's room the species is refused before the walk
// (or the tree's other stems) can take minutes.
void count_segment(Walk& k) {
  if (++k.out.segments > k.room.segments) {
    const std::string n = std::to_string(k.in.level);
    fail_argument(species_label(k.s) + " walks more than " +
                  std::to_string(k.room.limits->segments) +
                  " stem segments, the most one tree may (at level " + n + ", " +
                  std::to_string(k.in.segments) + " per stem); lower " + n + "CurveRes, " + n +
                  "Branches or Levels");
  }
}

// One path from segment w.from to the stem's end; clones walk their own paths first (Arbaro's
// order, which the carried split error depends on). Returns the prune test's segment or -1.
int walk_path(Walk& k, Walker w) {
  const int n = k.in.segments;
  const double segment_length = k.in.length / n;
  StemPiece piece;
  piece.depth = w.depth;
  piece.clone = w.clone;
  piece.parent = w.parent;
  piece.first = w.from;
  for (int s = w.from; s < n; ++s) {
    count_segment(k);
    if (s > 0) new_direction(k, w, s);
    piece.directions.push_back(w.x);
    w.position = w.position + w.x * segment_length;
    if (k.prune_test && !inside_envelope(k.s, k.in.tree_size, w.position)) return s;
    if (s == n - 1) break;
    const int clones = split_count(k, w, s);
    if (clones == 0) continue;
    piece.end = s + 1;
    const int ended = int(k.out.pieces.size());
    add_piece(k, std::move(piece));
    const double spread = 360.0 / (clones + 1);
    for (int i = 0; i < clones; ++i) {
      Walker clone = w;
      clone.rng = TreeRandom(k.in.seed, k.in.stem, kCloneStream + k.clones++);
      split(k, clone, spread * (i + 1), s);
      clone.depth = w.depth + 1;
      clone.clone = true;
      clone.parent = ended;
      clone.from = s + 1;
      const int outside = walk_path(k, clone);
      if (outside >= 0) return outside;
    }
    split(k, w, 0.0, s);
    ++w.depth;
    w.clone = false;
    piece = StemPiece{};
    piece.depth = w.depth;
    piece.parent = ended;
    piece.first = s + 1;
  }
  piece.end = n;
  add_piece(k, std::move(piece));
  return -1;
}

}  // namespace

bool inside_envelope(const Species& s, double tree_size, const Vec3& p) {
  const double r = std::sqrt(p[0] * p[0] + p[2] * p[2]);
  const double bare = tree_size * (1.0 - s.base_size);
  const double ratio = bare > 0.0 ? (tree_size - p[1]) / bare : -1.0;
  return r / tree_size < s.prune_width * shape_ratio(s, 8, ratio);
}

StemWalk walk_stem(const StemWalkInput& in, double* split_error, bool prune_test,
                   const StemWalkRoom& room) {
  const Species& s = *in.species;
  Walk k{in, s, s.level[size_t(in.level)], split_error, prune_test, room, 0, {}};
  Walker w;
  w.position = in.start.origin;
  w.x = in.start.x;
  w.y = in.start.y;
  w.z = in.start.z;
  w.rng = TreeRandom(in.seed, in.stem, kWalkStream);
  k.out.outside = walk_path(k, w);
  return std::move(k.out);
}

}  // namespace boreas::impl
