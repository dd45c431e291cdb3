// boreas: the wind's load on a generated tree as aerodynamic drag, and the bend it gives
// each branch as a cantilever beam.
//
// Every plant in boreas takes the wind as drag, 1/2 rho C_d A |u| u: the underbrush through
// its parts' drag_area, imported trees through their squared-speed load, and generated
// trees here, so one gust bends a branch, a blade and an imported tree by the same law
// (doubling the wind quadruples each one's load). Skjermo's linear response, bend =
// compliance * wind (tree_params.h), stays as BOREAS_TREE_LOAD_LINEAR.
//
// The loads. A branch catches the wind on its projected area, length times diameter, with
// the drag coefficient of a cylinder in cross flow (1.2 at the Reynolds numbers of
// branches, 1e3..1e5); a leaf on its blade (its outline's area, trees/leaf_area.h, as the light sees it) with 0.5
// (a flat plate across the flow has about 1.2; a fluttering leaf turned into the flow about
// half that). Leaves in a crown shelter one another: a whole tree in a wind tunnel drags
// like its silhouette with C_d about 0.4, far less than the sum of its leaves, and a
// Weber-Penn crown holds several times a real one's leaf area besides. So the leaves'
// drag is scaled down, all alike, until the crown's is its silhouette's (TreeModel::
// crown_area, 0.4), never up. The whole area takes the whole wind whatever the branch's
// direction: the part of the load along a branch does not bend it (eq. 17 turns segments
// only), and a cross-flow refinement (sin^2 of the angle) is not worth a direction per
// branch per step.
//
// The beam. A branch is a cantilever clamped where it leaves its parent (Euler-Bernoulli,
// small deflection) of the species' wood modulus E, loaded by its own area spread along
// it, its leaves where they grow and each branch it carries, with everything that one
// carries, where it attaches (a = v L). So a limb bends under its crown, not under its own
// bark alone. The tip deflects by the integral over x of M(x) (L - x) / (E I(x)), taken
// with the midpoint rule on 16 slices, M the moment of the loads beyond x, I = pi r^4 / 4.
// The radius r(x) is the drawn one (radius times the taper) or, where that is thinner, the
// pipe model's (Shinozaki et al. 1964, the rule that a stem's cross-section follows the leaf
// area it feeds: kHuberValue m^2 of wood per m^2 of leaves beyond x, a typical Huber value):
// Weber-Penn radii are drawn for the eye, and the weeping willow's twigs are a fifth of a
// millimetre thick, which no twig holding ten leaves is. Two branches of one length and
// load differ as beams do: their deflections stand in the ratio of their E r^4.
//
// The deflection is made a bend factor F through eq. 17: for a small F across the branch
// P2 moves by w2 F and P3 by (1 + w2) F, so F = deflection / (1 + w2). Beyond small
// deflections eq. 17 saturates (a segment turns toward the load but never stretches),
// where the beam would stiffen too: that is the model's large-deflection limit.
//
// Reconfiguration. A leafy crown's drag grows slower than U^2 once its leaves fold and its
// twigs streamline: as U^(2+b) with Vogel's exponent b (Vogel 1989, "Drag and
// reconfiguration of broad leaves in high winds", b down to about -1.2 for single leaves
// and clusters; de Langre 2008, "Effects of wind on plants", b -0.5 .. -1.2 over plants and
// trees; Rudnicki, Mitchell and Novak 2004, "Wind tunnel measurements of crown streamlining
// and drag relationships for three conifer species", drag proportional to mass times U,
// b about -1, for conifer crowns). So above a reference speed U_r (the species'
// VogelSpeed) the load takes the factor R = (|u| / U_r)^b, 1 below it, continuous at U_r.
// What a branch carries reconfigures, its own stem does not: the leaves fold and the
// child branches turn into the wind as a crown does (Rudnicki et al.'s crowns lost 36-54 %
// of their frontal area at 20 m/s), while a bare stem in a wind tunnel drags as U^2
// (Tadrist, de Langre et al., a whole cherry tree: its trunk alone quadratic, the tree with
// its leaves far less). A branch whose carried drag is the share phi of others' (leaves,
// children) takes the exponent phi b, the first-order match of (1 - phi) + phi R at U_r: a
// trunk under its crown phi ~0.9, a bare twig 0. One factor per branch keeps its bend and
// its base moment proportional, so the break below is one comparison of the bend.
//
// Breaking. The bending stress at a branch's base is sigma = M r / I = 4 M / (pi r^3), M
// the base moment of the same loads (times R), r the beam's base radius (beam_base_radius);
// along a tapered stem it can be higher (the moment falls linearly toward the loads, r^3
// faster), so the largest along the beam counts. The branch breaks where sigma passes the
// wood's modulus of rupture (WoodRupture: the USDA Forest Products Laboratory's Wood
// Handbook, green wood). As F and sigma share the factor |u|^2 R, the test is |F| > F_break with
// F_break = MOR K / (1/2 rho S), S the stress per dynamic pressure: one float per branch
// (the bend of a damped branch overshoots, and so does its stress). Every length of a tree
// of scale s is s times, so sigma is the same at every scale and F_break is s times:
// a tree's critical wind speed is its species', whatever its size, as Virot et al. (2016,
// "Critical wind speed at which trees break") found (about 42 m/s).
// A broken branch hangs from its parent along the load on it: its drag (times R) plus its
// weight, drag_per_weight the ratio at 1 m/s (green wood 800 kg/m^3; leaves weightless).
// The model keeps one joint per branch, so it breaks (hangs) at its base even where a
// tapered stem is most stressed higher up. A branch whose tip would have to move farther
// than 0.3 of its own length before its base reaches rupture never breaks: past small
// deflections it streamlines into the wind and its base moment stops growing (the
// elastica), so slender twigs and a willow's hanging shoots bend like ropes instead of
// snapping at 5 m/s, as the small-deflection stress would have them (sigma = 3 E r delta /
// L^2 for a tip load: the deflection at rupture is MOR / (3 E) L^2 / r, past 0.3 L for L / r
// above ~150). At 0.3 of its length a cantilever's tip has turned by ~25 degrees, where the
// small-deflection beam, which the stress comes from, starts to overstate the elastica's
// base moment (at half its length, ~40 degrees, by ~15 %). With half the length, a few of
// the oak's and the willow's twigs broke in a 9.4 m/s breeze; with 0.3 none breaks below
// 10.9 m/s (README, "Storms"; 12.6 before the leaves counted their outlines' area).
#pragma once

#include <vector>

#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "wind/air.h"

namespace boreas::impl {

inline constexpr double kWoodDragCoefficient = 1.2;   // a cylinder in cross flow
inline constexpr double kLeafDragCoefficient = 0.5;   // a fluttering leaf, per blade area
inline constexpr double kCrownDragCoefficient = 0.4;  // a whole crown, per silhouette area
// m^2 of wood per m^2 of leaves beyond (the blade's area, leaf_area.h): 1.25e-4 since the
// blades count their outlines' area (0.51-0.78 of length x width) instead of the ellipse's
// pi/4, so that the twigs keep about the strength 1e-4 gave with the ellipse (README,
// "Storms": the lowest break speeds moved by under 20 %).
inline constexpr double kHuberValue = 1.25e-4;
inline constexpr double kGreenWoodDensity = 800.0;    // kg/m^3, for the natural frequency

// The factor (0, 1] every leaf's drag takes in this crown (sheltering, above).
double leaf_shelter(const TreeModel& m);

// The tip deflection per unit dynamic pressure (1/2 rho |u|^2) of every branch of `m` as
// a cantilever, m / Pa, with the species' modulus times the level's stiffness.
std::vector<double> deflection_per_pressure(const TreeModel& m, const TreeParams& params);

// The tip stiffness of every branch of `m` as that cantilever (the same slices and radii):
// the load at its tip per metre of the tip's deflection, N/m, at scale 1. A tree of scale s
// has it s times (L^3 / I goes as s^-1). Colliders push branches against it
// (cl/shared/tree_contact.h).
std::vector<double> tip_stiffness(const TreeModel& m, const TreeParams& params);

// The radius each branch of `m` has as a beam at its base: the drawn one, or the pipe
// model's for all the leaf area it carries where that is thicker. The natural frequency
// takes it too (tree_params.h), so a twig drawn a hundredth of a millimetre thick does not
// swing once a minute.
std::vector<double> beam_base_radius(const TreeModel& m);

// The bend factor per squared wind speed of every branch of the template (scale 1):
// F* = K |u| u, K in m / (m/s)^2. A tree of scale s bends with K s: every length s times
// (areas s^2, moments s^3, I s^4), and the pipe model's radius s times with the leaf
// area's square root.
std::vector<double> drag_compliance(const TreeModel& m, const TreeParams& params);

// Vogel's factor R = (max(speed, reference) / reference)^exponent (above).
double reconfiguration(double speed, double exponent, double reference_speed);

// The share (0..1) of the drag each branch carries that is not its own stem's (its leaves
// and children: the part that reconfigures, above).
std::vector<double> reconfiguring_share(const TreeModel& m);

// The bending moment at each branch's base per unit dynamic pressure, N m / Pa = m^3, and
// the stress there per unit dynamic pressure, 4 M / (pi r^3) with r the beam's base radius
// (no unit: Pa / Pa).
std::vector<double> base_moment_per_pressure(const TreeModel& m);
std::vector<double> base_stress_per_pressure(const TreeModel& m);
// The largest stress per unit dynamic pressure along each branch: its base's, or higher up
// a tapered stem where the moment falls slower than r^3 (the beam of
// deflection_per_pressure, slice by slice). What break_bend compares.
std::vector<double> peak_stress_per_pressure(const TreeModel& m);

// The bend factor magnitude (m, scale 1) at which each branch's base stress reaches the
// species' modulus of rupture, or kNeverBreaks where that bend would move the tip farther
// than the branch's length (above).
inline constexpr double kNeverBreaks = 1e30;  // BOREAS_TREE_NEVER_BREAKS
inline constexpr double kBreakReach = 0.3;    // of the branch's length (above)
std::vector<double> break_bend(const TreeModel& m, const TreeParams& params);

// Drag over weight of each branch with all it carries, in 1 / (m/s)^2: 1/2 rho C_d A /
// (m g). A broken branch hangs along drag_per_weight R |u| u - y (above).
std::vector<double> drag_per_weight(const TreeModel& m);

}  // namespace boreas::impl
