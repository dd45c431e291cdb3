// boreas textures: light that passes a leaf from its back side, as a function of direction,
// and its HL2 coefficients (Kusternig sec. 3.5.1).
//
// Light enters through the upper surface, which has the perturbed normal n from the normal
// map, and leaves through the lower one; w is the unit direction from the texel towards the
// light in tangent space (z > 0). One set serves both sides: for a tangent-space light
// vector L on either side, a shader uses w = (L.x, L.y, |L.z|). The light enters at
// cos(theta) = dot(w, n), crosses the slab of the texel's thickness d along
// d / cos(theta_in), and the slab lets T(d / cos(theta_in)) of it through (Kubelka-Munk in
// the green band, thin_slab.h), so the transmitted intensity is
//   I(w) = cos(theta) T(d / cos(theta_in))   for cos(theta) > 0, else 0 (the light grazes or
//          comes from behind the tilted facet: a bulge shadows it),
// with theta_in = theta (no refraction, the default) or Snell's angle inside a leaf of index
// refractive_index. The HL2 coefficients are the least-squares fit of I over the hemisphere
// (hl2_basis.h), in the fixed tangent-space basis the shader uses with the tangent-space
// light vector; the perturbed normal enters through I, which tilts the fitted lobe, so veins
// and bulges show in the coefficients as well as through their thickness.
//
// Combining with the translucency color map (RGB transmittance at normal incidence): the
// coefficients already hold the green transmittance, so translucent radiance is
// E * I_hl2(w) * color / color.g for a per-channel result without counting the thickness
// twice; the paper's plain product E * I_hl2(w) * color darkens thick parts once more.
#pragma once

#include <glm/vec3.hpp>

#include "textures/hl2_basis.h"
#include "textures/thin_slab.h"

namespace boreas::render {

class LeafTranslucency {
 public:
  // refractive_index 1 is the plain d / cos(theta) path; about 1.45 (cuticle and cell walls)
  // bends the light towards the normal inside, which shortens grazing paths.
  explicit LeafTranslucency(SlabOptics optics, double refractive_index = 1.0);

  // I(w) above, for thickness d_mm and unit normal n; w is a unit vector.
  double intensity(double d_mm, const glm::dvec3& n, const glm::dvec3& w) const;

  Hl2Coefficients coefficients(const Hl2Fitter& fitter, double d_mm, const glm::dvec3& n) const;

 private:
  KubelkaMunkSlab slab_;
  double inverse_index_squared_;
};

}  // namespace boreas::render
