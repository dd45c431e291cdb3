// boreas: eq. 1, section by section (see rest_shape.h for the reading).
#include "underbrush/rest_shape.h"

#include <cmath>

namespace boreas::impl {

void center_of_mass(const std::vector<SectionPhysics>& sections, const std::vector<double>& u,
                    const std::vector<double>& v, double* com_u, double* com_v) {
  double m = 0.0, su = 0.0, sv = 0.0;
  for (size_t j = 0; j < sections.size(); ++j) {
    m += sections[j].mass;
    su += sections[j].mass * 0.5 * (u[j] + u[j + 1]);
    sv += sections[j].mass * 0.5 * (v[j] + v[j + 1]);
  }
  *com_u = m > 0.0 ? su / m : 0.0;
  *com_v = m > 0.0 ? sv / m : 0.0;
}

double straight_reach(const std::vector<SectionPhysics>& sections) {
  double m = 0.0, s = 0.0, along = 0.0;
  for (const SectionPhysics& sec : sections) {
    m += sec.mass;
    s += sec.mass * (along + 0.5 * sec.length);
    along += sec.length;
  }
  return m > 0.0 ? s / m : 0.0;
}

BentShape bend_under_load(const std::vector<SectionPhysics>& sections, double theta, double norm, int hinge) {
  const size_t n = sections.size();
  BentShape out;
  out.u.assign(n + 1, 0.0);
  out.v.assign(n + 1, 0.0);
  out.alpha.assign(n, 0.0);
  double load_u = std::cos(theta), load_v = std::sin(theta);
  double phi = 0.0;  // direction of the sections not yet fixed
  for (size_t j = 0; j < n; ++j) {
    // The part above joint j: straight along phi from the joint.
    double m = 0.0, s = 0.0, along = 0.0;
    for (size_t k = j; k < n; ++k) {
      m += sections[k].mass;
      s += sections[k].mass * (along + 0.5 * sections[k].length);
      along += sections[k].length;
    }
    double r = m > 0.0 ? s / m : 0.0;
    // gamma: signed angle from the arm (along phi) to the load, in (-pi, pi].
    double gamma = std::atan2(std::cos(phi) * load_v - std::sin(phi) * load_u,
                              std::cos(phi) * load_u + std::sin(phi) * load_v);
    double sg = std::fabs(gamma);
    double alpha = 0.0;
    // Only the broken joint turns freely; the joints above it stay elastic (the part
    // hanging from it is already aligned with the load, so they barely turn).
    bool free_joint = static_cast<int>(j) == hinge;
    if (norm > 0.0 && r > 0.0) {
      if (free_joint) {
        alpha = sg;
      } else {
        double K = sections[j].stiffness / (r * m * norm);
        alpha = std::atan2(std::sin(sg), K + std::cos(sg));
        if (out.broke_at < 0 && sections[j].stiffness * std::sin(alpha) > sections[j].max_moment) {
          out.broke_at = static_cast<int>(j);  // it cannot hold the part above: that
          alpha = sg;                          // hangs along the load
        }
      }
    }
    alpha = std::copysign(alpha, gamma);
    out.alpha[j] = alpha;
    phi += alpha;
    out.u[j + 1] = out.u[j] + sections[j].length * std::cos(phi);
    out.v[j + 1] = out.v[j] + sections[j].length * std::sin(phi);
  }
  center_of_mass(sections, out.u, out.v, &out.com_u, &out.com_v);
  return out;
}

}  // namespace boreas::impl
