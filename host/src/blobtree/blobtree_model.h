// boreas: a tree as a BlobTree of skeletal implicit cone primitives (Galbraith, MacMurchy
// and Wyvill 2004 sec. 3.1-3.5), in double precision; blobtree_bins packs it into the
// kernels' float planes (cl/shared/blobtree_types.h), and cl/shared/blobtree_field.h
// defines the field it describes.
//
// How a tree becomes primitives:
//  - every branch is cut into internodes at its branching points (where children leave)
//    and at least `segments` places along its curve; each internode is a cone from the
//    curve's point at its base to the point at its top, r_b and r_t the branch's radius
//    there (taper, flare, bulge; the lobes are not round and are left out), the skeleton
//    cone r_b - r_t at the base and 0 at the top, the surface r_t out (sec. 3.1);
//  - a branching point P ends internode A and starts the children B_i: the parent's next
//    internode and every branch leaving there. With one child, A is shortened by
//    delta_A = 1.75 r_Bt (eq. 3). With several, each B_i moves away from P along its axis
//    by delta_Bi = r_A - r_i (eq. 6) and A is shortened by 2.75 max(r_i) - r_A (eq. 7,
//    negative: lengthened past P), and the B_i form a group combined by PCM (eq. 4) that
//    the sum of all groups blends with A (eq. 5). Without PCM (a plain blend, sec. 3.2)
//    the B_i stay at P and A is shortened by eq. 3 for the thickest r_Bt;
//  - a branch whose base radius is below min_radius is left out with its children, and a
//    branch's internodes stop where its radius falls below it (the surface of a tip keeps
//    at least min_radius, a rounded cap: sec. 4 notes the paper's hemispherical tips).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "trees/tree_model.h"

namespace boreas::impl {

struct BlobPrimitive {
  glm::dvec3 base{0.0};
  glm::dvec3 axis{0.0, 1.0, 0.0};  // unit; the chord's direction when bent
  double length = 0.0;             // m, > 0: the skeleton's length (the arc's when bent)
  double cone_radius = 0.0;        // m: skeleton cone radius at the base (r_b - r_t)
  double iso_distance = 0.0;       // m, > 0: surface distance from the skeleton (r_t)
  double influence = 0.0;          // m: R, where the fall-off reaches 0
  double weight = 1.0;             // +1, or -1 for a scar's negative field
  int32_t group = 0;               // junction group; members are contiguous
  bool pcm = false;                // the group combines by PCM (only groups of 2+)
  double pcm_width = 0.0;          // m: w
  double pcm_peak = 0.0;           // M
  // Barr's bend keeping the endpoints (sec. 3.5): the skeleton follows a circular arc of
  // this angle (rad, 0 straight) from base to base + chord * axis, leaving the base turned
  // by half of it towards bend_direction (unit, perpendicular to axis).
  double bend_angle = 0.0;
  glm::dvec3 bend_direction{1.0, 0.0, 0.0};
  // Texture parametrization (sec. 3.6): u = angle around the axis from u_direction (unit,
  // perpendicular to axis; for a bent primitive, measured from the outward normal of the
  // arc) over 2 pi; v = v0 + v_scale * (distance along the skeleton).
  glm::dvec3 u_direction{1.0, 0.0, 0.0};
  double v0 = 0.0;
  double v_scale = 1.0;
  int32_t branch = -1;  // the tree branch it models (-1: not from a branch)

  // The chord: distance from base to the skeleton's end.
  double chord() const;
};

// A pruning cut (sec. 3.4, fig. 12): removes what lies on `normal`'s side of the plane
// through `point` within `radius` of it, leaving a flat face. CSG difference
// min(F, 1 - cutter) with a cutter field that ramps from 0 to 1 over `ramp` across its
// faces.
struct BlobCut {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 1.0, 0.0};  // unit
  double radius = 0.0;
  double ramp = 0.0;  // m, > 0
};

struct BlobModel {
  std::vector<BlobPrimitive> primitives;
  std::vector<BlobCut> cuts;
  // Where F can be non-zero: every primitive's reach. Empty (min > max) with no primitive.
  glm::dvec3 bounds_min{1e300}, bounds_max{-1e300};
  int branches_modeled = 0;  // tree branches that have at least one primitive

  // Recomputes bounds_min/max from the primitives.
  void update_bounds();
};

// One internode of a skeleton, what the junction rules take: a tree's branches cut at
// their branching points, or any skeleton made by hand.
struct BlobInternode {
  glm::dvec3 base{0.0}, top{0.0};
  double r_base = 0.0, r_top = 0.0;  // m
  int32_t parent = -1;   // the internode whose top this one starts at (-1: a root); parents
                         // come before their children
  int32_t branch = -1;   // the tree branch it belongs to
  double s0 = 0.0;       // m along its branch at the base (texture v)
  double v_scale = 1.0;  // texture v per metre
  double bend = 0.0;     // rad (sec. 3.5): see BlobTreeOptions::bend_angle
  glm::dvec3 bend_reference{0.0};  // the basal axis the bend turns away from
  double extend_top = 0.0;         // m: the skeleton reaches this far past `top`
};

// What a pruning cut or a scar is placed on.
struct BlobCutRequest {
  int32_t branch = 0;  // index in the tree's branch list (boreas_tree_get_branches order)
  double at = 0.5;     // where along the branch, 0..1 of its curve's parameter
};
struct BlobScarRequest {
  int32_t branch = 0;  // the branch that was lost
  double stub = 0.1;   // the stub left, as a fraction of the branch's length (0..1)
  double depth = 0.5;  // the negative field's strength relative to the branch: 0..1
};

struct BlobTreeOptions {
  int max_level = 3;         // deepest branch level modeled (0 trunk .. 3)
  int segments = 4;          // at least this many internodes per branch along its curve
  double min_radius = 0.0;   // m: thinner branches are left out (see above)
  double min_surface = 0.0;  // m: no surface lies closer than this to its skeleton, so
                             // thin branches stay whole tubes on a grid (not beads)
  bool offsets = true;       // the delta_A / delta_Bi offsets (eq. 3, 6, 7)
  bool pcm = true;           // children of a branching point combine by PCM (else summed)
  double pcm_peak = 0.2;     // M: the ridge's height in field units (Gascuel's alpha times
                             // the largest compression, which is at most 1/2 here)
  double pcm_width = 0.5;    // w as a multiple of the member's own surface distance
  double bend_angle = 0.0;   // rad: bend every lateral branch's first internode (sec. 3.5)
  std::vector<BlobCutRequest> cuts;
  std::vector<BlobScarRequest> scars;
};

// Builds the BlobTree of a grown tree standing at `position`, turned by `rotation` rad about
// the up axis (its rest pose). Throws std::invalid_argument naming the option or the
// branch that is wrong.
BlobModel build_blobtree(const TreeModel& tree, const glm::dvec3& position,
                         const BlobTreeOptions& options, double rotation = 0.0);

// The primitives of a skeleton by the junction rules: every root alone, then for each
// internode with children a group of them (eq. 3, 6, 7 offsets; PCM when options.pcm and
// two or more). Only options.offsets, pcm, pcm_peak, pcm_width, min_radius and
// min_surface are used.
// Throws std::invalid_argument naming the internode that is wrong.
BlobModel blob_model_of(const std::vector<BlobInternode>& skeleton, const BlobTreeOptions& options);

// A primitive's radius of influence for a surface distance: iso / 0.4542.
double blob_influence(double iso_distance);

// How far from its skeleton a primitive can change F (its fall-off, and its PCM
// expansion of the other members of its group, whose widths are given).
double blob_reach(const BlobPrimitive& p, double group_max_width);

// Each primitive's group's widest PCM propagation region (0 outside PCM groups), by
// primitive: what blob_reach takes.
std::vector<double> blob_group_widths(const BlobModel& model);

// The box around a primitive's skeleton (its ends, and an arc's bulge) grown by `grow` m.
void blob_skeleton_box(const BlobPrimitive& p, double grow, glm::dvec3* lo, glm::dvec3* hi);

}  // namespace boreas::impl
