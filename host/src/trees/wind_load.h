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
// branches, 1e3..1e5); a leaf on its blade (an ellipse, length x width x pi/4) with 0.5
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
// area it feeds: 1e-4 m^2 of wood per m^2 of leaves beyond x, a typical Huber value):
// Weber-Penn radii are drawn for the eye, and the weeping willow's twigs are a fifth of a
// millimetre thick, which no twig holding ten leaves is. Two branches of one length and
// load differ as beams do: their deflections stand in the ratio of their E r^4.
//
// The deflection is made a bend factor F through eq. 17: for a small F across the branch
// P2 moves by w2 F and P3 by (1 + w2) F, so F = deflection / (1 + w2). Beyond small
// deflections eq. 17 saturates (a segment turns toward the load but never stretches),
// where the beam would stiffen too: that is the model's large-deflection limit.
#pragma once

#include <vector>

#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "wind/air.h"

namespace boreas::impl {

inline constexpr double kWoodDragCoefficient = 1.2;   // a cylinder in cross flow
inline constexpr double kLeafDragCoefficient = 0.5;   // a fluttering leaf, per blade area
inline constexpr double kCrownDragCoefficient = 0.4;  // a whole crown, per silhouette area
inline constexpr double kHuberValue = 1e-4;           // m^2 of wood per m^2 of leaves beyond
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

}  // namespace boreas::impl
