// boreas: the shape of a part under a constant load, section by section from the base
// (Endo et al. sec. 3.2, eq. 1), in double precision.
//
// The part lies in its bend plane: u along its unloaded (straight) axis, v toward the load.
// The load is an acceleration a (gravity, and in the tables gravity plus wind and
// colliders per unit mass) at angle theta from +u, acting on every section's mass at its
// middle. Joint j, with the sections below it already fixed and the ones above straight
// along section j-1, turns by alpha_j until the normal components of the load on the part
// above (mass M, center of mass X at arm r from the joint) and of the elastic force
// balance. Reading eq. 1 (the seeds' text is garbled): the elastic force k (X0 - X) acts
// along the chord between X before and after the bend, |X0 - X| = 2 r sin(alpha/2), at
// (180 - alpha)/2 to the arm, so its normal component is k r sin(alpha); the load's is
// M |a| sin(gamma - alpha), gamma the angle from the arm to the load. With k = kappa / r^2
// (component_species.h) the balance kappa sin(alpha) = r M |a| sin(gamma - alpha) gives
//   tan(alpha) = sin(gamma) / (K + cos(gamma)),  K = kappa / (r M |a|),
// which is eq. 1 with its gamma measured from X->P (= pi - ours) and its k (X0 - X) read
// as k r. 0 <= alpha < gamma: a joint never turns past the load.
// Breaking: when the moment the joint must carry, kappa sin(alpha), exceeds the section's
// max_moment, the joint breaks and the part above hangs freely along the load (alpha =
// gamma); a joint broken earlier (`hinge`) has no stiffness at all.
#pragma once

#include <vector>

#include "underbrush/component_species.h"

namespace boreas::impl {

struct BentShape {
  std::vector<double> u, v;    // joints 0..sections (joint 0 at the origin)
  std::vector<double> alpha;   // turn of each joint, rad (signed, toward the load)
  double com_u = 0.0, com_v = 0.0;  // center of mass
  int broke_at = -1;           // first joint that broke under this load, -1 if none
};

// theta: the load's angle from +u, radians (0..pi; the result bends toward +v).
// norm: |a| in m/s^2 (>= 0). hinge: joint broken beforehand, -1 for none.
BentShape bend_under_load(const std::vector<SectionPhysics>& sections, double theta, double norm, int hinge = -1);

// Center of mass of a shape's sections (mass at each section's middle).
void center_of_mass(const std::vector<SectionPhysics>& sections, const std::vector<double>& u,
                    const std::vector<double>& v, double* com_u, double* com_v);

// Distance from the base to the center of mass of the straight part.
double straight_reach(const std::vector<SectionPhysics>& sections);

}  // namespace boreas::impl
