// boreas textures: the HL2 basis vectors and the hemisphere grid of the least-squares fit.
#include "textures/hl2_basis.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <string>

#include "textures/texture_error.h"

namespace boreas::render {

const std::array<glm::dvec3, 3>& hl2_basis() {
  static const std::array<glm::dvec3, 3> basis = {
      glm::dvec3(-1.0 / std::sqrt(6.0), 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)),
      glm::dvec3(-1.0 / std::sqrt(6.0), -1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)),
      glm::dvec3(std::sqrt(2.0 / 3.0), 0.0, 1.0 / std::sqrt(3.0))};
  return basis;
}

double hl2_evaluate(const Hl2Coefficients& c, const glm::dvec3& w) {
  const auto& b = hl2_basis();
  return c[0] * glm::dot(w, b[0]) + c[1] * glm::dot(w, b[1]) + c[2] * glm::dot(w, b[2]);
}

Hl2Fitter::Hl2Fitter(int rings, int sectors) {
  // Fewer than 3 sectors leave M singular (all samples in one plane through +Z).
  if (rings < 1 || sectors < 3) {
    throw TextureError("Hl2Fitter: need rings >= 1 and sectors >= 3, got " + std::to_string(rings) +
                       " and " + std::to_string(sectors));
  }
  const double pi = std::acos(-1.0);
  glm::dmat3 m(0.0);
  directions_.reserve(static_cast<size_t>(rings) * sectors);
  for (int i = 0; i < rings; ++i) {
    double z = (i + 0.5) / rings;
    double r = std::sqrt(1.0 - z * z);
    for (int j = 0; j < sectors; ++j) {
      double phi = 2.0 * pi * (j + 0.5) / sectors;
      glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
      directions_.push_back(w);
      m += glm::outerProduct(w, w);
    }
  }
  // glm matrices are column-major: B's rows are the basis vectors, so B = transpose of the
  // matrix whose columns they are.
  const auto& b = hl2_basis();
  glm::dmat3 rows = glm::transpose(glm::dmat3(b[0], b[1], b[2]));
  to_coefficients_ = rows * glm::inverse(m);
}

}  // namespace boreas::render
