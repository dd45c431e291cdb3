// boreas: a grown tree — every branch as one cubic Bezier in its own frame plus how it
// attaches to its parent, and the leaves on the last level (Skjermo 2007 sec. 2.1).
//
// A branch's control points are "unpositioned": P0 at the origin, P1 on +x (the first of
// three segments lies along +x), P2 and P3 turned by the species' curvature, no radius;
// a trunk standing apart (0BranchDist) has all four moved by its base's offset.
// The animation kernel places them on the parent every step; see cl/shared/tree_math.h for
// the frame the attachment (v, theta, alpha) describes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "shared/leaf_pack.h"
#include "trees/species.h"

namespace boreas::impl {

struct BranchModel {
  // Unpositioned control points in the attachment frame, m (local[0] is the origin and
  // local[1] = (l1, 0, 0), both moved by a trunk's base where trunks stand apart).
  std::array<std::array<double, 3>, 4> local{};
  int32_t level = 0;    // 0 trunk .. 3
  int32_t parent = -1;  // index in TreeModel::branches, -1 for the trunk
  double v = 0.0;       // where P0 sits on the parent's curve, Bezier parameter 0..1
  double theta = 0.0;   // angle around the parent, radians
  double alpha = 0.0;   // down angle from the parent's axis, radians
  double length = 0.0;  // this branch's length, m (the polygon's length)
  double radius = 0.0;  // base radius, m
  // A Weber-Penn stem that splits (nSegSplits, 0BaseSplits) is several branches: its first
  // piece ends at the split, and the clones and the stem's continuation each start a piece
  // attached at v = 1 of the piece they grow from, one split deeper. Weber-Penn counts the
  // first piece and every clone as a stem, not the continuations.
  int32_t split_depth = 0;   // splits between the stem's base and this piece
  bool clone = false;        // begun as a clone at a split
  double stem_length = 0.0;  // the whole stem's length, m (Weber-Penn's L)
  double stem_from = 0.0;    // where this piece starts along its stem, fraction of stem_length
  // Radius functions of the deformer (Skjermo eq. 2-5): r(v,th) = radius * (1 - taper_depth
  // * v^taper_exponent) * flare(v) * beads(v) * (1 + lobe_depth sin(lobe_count th) (1 - v
  // lobe_taper)) * cap(v); eq. 4's bulges are Arbaro's beads (bead_factor below).
  double taper_depth = 1.0;
  double taper_exponent = 1.0;
  double flare = 0.0;  // trunk only: 1 + flare (100^max(0, 1 - 8v) - 1) / 100
  double bulge_count = 0.0;  // beads along this piece (its length over a bead's, 2 radii)
  double bulge_depth = 0.0;  // the waists' dip, a fraction of the radius (nTaper - 2)
  double bulge_phase = 0.0;  // beads from this piece's end (v = 1) to its stem's tip
  double lobe_count = 0.0;
  double lobe_depth = 0.0;
  double lobe_taper = 1.0;
  // Arbaro's hemispherical tip (nTaper 1..2), its length as a fraction of this piece's: the
  // radius times sqrt(w (2 - w)), w = min(1, (1 - v) / tip_cap) (boreas_tip_cap); 0: none.
  double tip_cap = 0.0;
};

// The tip cap's factor on the radius at v (BranchModel::tip_cap; cl/shared's boreas_tip_cap).
inline double tip_cap_factor(double cap, double v) {
  if (cap <= 0.0) return 1.0;
  const double w = std::min(std::max((1.0 - v) / cap, 0.0), 1.0);
  return std::sqrt(w * (2.0 - w));
}

// The beads' factor on the radius at v (BranchModel::bulge_*; cl/shared's boreas_beads):
// 1 - depth + depth sqrt(z (2 - z)), z the distance in radii from the nearest waist, waists
// every two radii from the stem's tip; 1 over the last radius (the tip cap's).
inline double bead_factor(double count, double depth, double phase, double v) {
  if (depth == 0.0) return 1.0;
  const double x = std::max(2.0 * (count * (1.0 - v) + phase), 1.0);
  const double z = std::fabs(x - 2.0 * std::floor(0.5 * x + 0.5));
  return 1.0 - depth + depth * std::sqrt(z * (2.0 - z));
}

// The beads' mean factor over one bead, for sums over lengths longer than a bead (2 radii):
// a quarter circle's area short of its square, depth (1 - pi / 4).
inline double bead_mean(double depth) { return 1.0 - depth * (1.0 - 0.785398163397448310); }

// A branch's radius at v in [0, 1] as the deformer draws it, around its lobes (their mean,
// 1): radius, taper, flare, beads and the tip's cap (boreas_branch_radius, in double). The
// generator's child radii, the BlobTree's cones and the tests read this one.
inline double profile_radius(const BranchModel& b, double v) {
  const double taper = std::max(
      0.0, 1.0 - b.taper_depth * (b.taper_exponent == 1.0 ? v : std::pow(v, b.taper_exponent)));
  const double flare = b.flare == 0.0 ? 1.0
                                      : 1.0 + b.flare *
                                                  (std::pow(100.0, std::max(0.0, 1.0 - 8.0 * v)) - 1.0) /
                                                  100.0;
  return b.radius * taper * flare * bead_factor(b.bulge_count, b.bulge_depth, b.bulge_phase, v) *
         tip_cap_factor(b.tip_cap, v);
}

// How far a branch's P0 stands from where it attaches, m (|local[0]|): 0 but for a trunk
// standing apart. A bound on a tree's reach from its base adds it to the branch's chain.
inline double base_offset(const BranchModel& b) {
  return std::sqrt(b.local[0][0] * b.local[0][0] + b.local[0][1] * b.local[0][1] +
                   b.local[0][2] * b.local[0][2]);
}

struct LeafModel {
  int32_t parent = 0;   // a last-level branch (piece)
  double v = 0.0;       // Bezier parameter on the parent
  double length = 0.0;  // leaf blade length, m
  double width = 0.0;   // m
  double stem = 0.0;    // petiole length, m: the blade starts this far from the parent's axis
  // Its attachment as the kernels read it, cosine and sine of each angle: theta around the
  // parent, alpha the down angle, roll the blade turned about its axis (LeafBend: its
  // normal is cos(roll) y + sin(roll) z of its attachment frame). Kept as cosines, not
  // angles: a turned leaf's come from vectors, and a forest's leaves are laid out without
  // a libm call.
  double cos_theta = 1.0, sin_theta = 0.0;
  double cos_alpha = 1.0, sin_alpha = 0.0;
  double cos_roll = 1.0, sin_roll = 0.0;

  void set_theta(double a) { cos_theta = std::cos(a), sin_theta = std::sin(a); }
  void set_alpha(double a) { cos_alpha = std::cos(a), sin_alpha = std::sin(a); }
  double theta() const { return std::atan2(sin_theta, cos_theta); }
  double alpha() const { return std::atan2(sin_alpha, cos_alpha); }
};

struct TreeModel {
  std::string species;
  double wood_modulus = 7e9;  // Pa: the species' green wood (WoodModulus), for the wind's load
  double wood_rupture = 40e6;  // Pa: its modulus of rupture (WoodRupture), where branches break
  double vogel_exponent = -0.8;  // the crown's reconfiguration (VogelExponent, VogelSpeed m/s)
  double vogel_speed = 8.0;
  double leaf_area_index = 4.0;  // the light's calibration (LeafAreaIndex, Clumping)
  double clumping = 0.8;
  // m^2: the crown's silhouette at rest seen from the side (an ellipse over the last level's
  // extent), for the leaves' sheltering (trees/wind_load.h); 0 where not known.
  double crown_area = 0.0;
  // Levels in order; within a level, the children of one parent are contiguous, in the
  // order of their parents. branches[0] is the trunk.
  std::vector<BranchModel> branches;
  std::vector<LeafModel> leaves;  // grouped by parent, parents in order
  int levels = 0;                 // stem levels present (1..4)
  // branches of level n are [level_begin[n], level_begin[n + 1]).
  std::array<int32_t, kMaxTreeLevels + 1> level_begin{};
  // Step tiers: a level's pieces in order of split depth, so a piece comes after the piece
  // it grows from (exact stepping and carrying place a branch on its parent's new state).
  // Tier k is [tier_begin[k], tier_begin[k + 1]), of level tier_level[k]; levels in order.
  std::vector<int32_t> tier_begin;  // tiers + 1 entries
  std::vector<int32_t> tier_level;
  int tiers() const { return int(tier_level.size()); }

  // A world keeps a template's model packed once the device holds its blocks
  // (trees/tree_templates.h): the leaves (nine tenths of an aspen's model: 22,000 of them)
  // and the branches (232 bytes each) are dropped, and grown again from species and seed
  // (grow_tree is a pure function of both) for the few readers that need every field: a
  // new template block of the model, the rays, BlobTree. What the rest read stays: the
  // levels and tiers above, the branch getter's fields of each branch, the leaves' count
  // and the size every leaf of a grown tree shares. (The rest pose that adds and heal place
  // comes from the device's copy of the template block: TreeBatch::template_rest.)
  struct Packed {
    struct Branch {
      int32_t parent = -1;
      float v = 0.0f;                     // float(BranchModel::v)
      double radius = 0.0, length = 0.0;  // m, as BranchModel's
    };
    std::vector<Branch> branches;
    int32_t leaf_count = 0;
    double leaf_length = 0.0, leaf_width = 0.0;  // m, as LeafModel's
    std::shared_ptr<const Species> species;      // what grows it again, at scale 1
    uint64_t seed = 0;
  };
  std::shared_ptr<const Packed> packed;  // null while `branches` and `leaves` hold them
  int32_t branch_count() const {
    return packed ? int32_t(packed->branches.size()) : int32_t(branches.size());
  }
  int32_t leaf_count() const { return packed ? packed->leaf_count : int32_t(leaves.size()); }
};

// Splits deeper than this inside one level are not grown (the clone stays with its stem):
// step tiers are launched one after another, and no Weber-Penn species comes near it (the
// weeping willow's level 1, 16 segments at 0.2 splits each, reaches about 3).
inline constexpr int kMaxSplitDepth = 7;
inline constexpr int kMaxTreeTiers = kMaxTreeLevels * (kMaxSplitDepth + 1);

// The most one tree may grow. A species asking for more is refused with Error
// (INVALID_ARGUMENT) naming the species, its file, the parameter to lower and the limit,
// before the memory or the time is spent: a level's branches and the leaves are counted
// before they grow, splits and segments as they are walked. The defaults are far above
// every real species (the weeping willow, the largest, grows 28,215 branches and 249,900
// leaves and walks 70,395 stem segments; host/species/README.md) and keep a tree within
// about a gigabyte and a few seconds; the fuzzer passes smaller ones, so that each input
// grows in milliseconds.
struct GrowthLimits {
  // Pieces: stems and the clones their splits make. One less than 2^20, so that a tree's
  // entries (its root and branches) fit a packed leaf's parent field (leaf_pack.h).
  size_t branches = (size_t(1) << BOREAS_LEAF_ENTRY_BITS) - 1;
  size_t leaves = size_t(1) << 22;
  // Stem segments walked (each stem's nCurveRes, each clone's rest of them, and the walks
  // of the pruning test): the work of a tree, and the directions it keeps while growing.
  size_t segments = size_t(1) << 23;
};

// Grows a tree: deterministic for (species, seed, scale); the same on every machine (the
// random stream is boreas's own, not std's distributions). scale multiplies every length.
TreeModel grow_tree(const Species& species, uint64_t seed, double scale = 1.0,
                    const GrowthLimits& limits = {});

}  // namespace boreas::impl
