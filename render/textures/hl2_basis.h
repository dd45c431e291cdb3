// boreas textures: the "Half-Life 2" basis (McTaggart 2004, used for leaf translucency by
// Kusternig sec. 3.5) and the least-squares projection of a hemisphere intensity onto it.
//
// The basis is three orthonormal directions in tangent space, all 54.7 degrees from +Z and
// 120 degrees apart around it:
//   b0 = (-1/sqrt6,  1/sqrt2, 1/sqrt3),  b1 = (-1/sqrt6, -1/sqrt2, 1/sqrt3),
//   b2 = (sqrt(2/3), 0,       1/sqrt3).
// A shader evaluates the intensity for a unit light direction w (tangent space) as
//   I(w) = c0 dot(w, b0) + c1 dot(w, b1) + c2 dot(w, b2) = dot(w, g),  g = sum_i c_i b_i,
// so three coefficients represent exactly the intensities that are linear in w, and a fit
// is a least-squares problem in g: with M = sum_k w_k w_k^T over the hemisphere samples,
// g = M^-1 sum_k w_k I(w_k) and c_i = dot(b_i, g) (the b_i are orthonormal). M does not
// depend on the intensity, so one fitter serves every texel.
#pragma once

#include <array>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace boreas::render {

using Hl2Coefficients = std::array<double, 3>;

// b0, b1, b2 as above.
const std::array<glm::dvec3, 3>& hl2_basis();

// sum_i c_i dot(w, b_i).
double hl2_evaluate(const Hl2Coefficients& c, const glm::dvec3& w);

// Least-squares projection onto the HL2 basis over a stratified grid of directions on the
// upper hemisphere (z > 0): `rings` bands of equal solid angle (z at the band middles, so
// the samples weigh solid angle uniformly) times `sectors` azimuths.
class Hl2Fitter {
 public:
  explicit Hl2Fitter(int rings = 16, int sectors = 6);

  const std::vector<glm::dvec3>& directions() const { return directions_; }

  // Coefficients minimizing sum_k (I(w_k) - hl2_evaluate(c, w_k))^2, for any callable
  // `double intensity(const glm::dvec3& w)`.
  template <class Intensity>
  Hl2Coefficients fit(Intensity&& intensity) const {
    glm::dvec3 moment(0.0);
    for (const glm::dvec3& w : directions_) moment += w * intensity(w);
    glm::dvec3 c = to_coefficients_ * moment;
    return {c.x, c.y, c.z};
  }

  // Root mean square of I(w_k) - hl2_evaluate(c, w_k) over the samples.
  template <class Intensity>
  double rms_residual(const Hl2Coefficients& c, Intensity&& intensity) const {
    double sum = 0.0;
    for (const glm::dvec3& w : directions_) {
      double e = intensity(w) - hl2_evaluate(c, w);
      sum += e * e;
    }
    return std::sqrt(sum / directions_.size());
  }

 private:
  std::vector<glm::dvec3> directions_;
  glm::dmat3 to_coefficients_;  // B M^-1, B's rows the basis vectors
};

}  // namespace boreas::render
