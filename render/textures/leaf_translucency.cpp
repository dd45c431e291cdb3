// boreas textures: the back-lit transmitted intensity of a leaf texel and its HL2 fit.
#include "textures/leaf_translucency.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "textures/texture_error.h"

namespace boreas::render {

LeafTranslucency::LeafTranslucency(SlabOptics optics, double refractive_index)
    : slab_(optics), inverse_index_squared_(1.0 / (refractive_index * refractive_index)) {
  if (!(refractive_index >= 1.0) || !std::isfinite(refractive_index)) {
    throw TextureError("LeafTranslucency: refractive_index must be >= 1, got " +
                       std::to_string(refractive_index));
  }
}

double LeafTranslucency::intensity(double d_mm, const glm::dvec3& n, const glm::dvec3& w) const {
  double cos_theta = glm::dot(w, n);
  if (cos_theta <= 0.0) return 0.0;
  double cos_inside = inverse_index_squared_ == 1.0
                          ? cos_theta
                          : std::sqrt(1.0 - (1.0 - cos_theta * cos_theta) * inverse_index_squared_);
  return cos_theta * slab_.transmittance(d_mm / cos_inside);
}

Hl2Coefficients LeafTranslucency::coefficients(const Hl2Fitter& fitter, double d_mm,
                                               const glm::dvec3& n) const {
  return fitter.fit([&](const glm::dvec3& w) { return intensity(d_mm, n, w); });
}

}  // namespace boreas::render
