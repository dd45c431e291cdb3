// boreas textures: Kubelka-Munk reflectance and transmittance of a thin slab, and its
// inversion from a measured reflectance and transmittance.
#include "textures/thin_slab.h"

#include <cmath>
#include <string>

#include "textures/texture_error.h"

namespace boreas::render {
KubelkaMunkSlab::KubelkaMunkSlab(SlabOptics optics)
    : k_(optics.absorption_per_mm),
      s_(optics.scattering_per_mm),
      beta_(std::sqrt(optics.absorption_per_mm *
                      (optics.absorption_per_mm + 2.0 * optics.scattering_per_mm))),
      a_(beta_ > 0.0 ? (s_ + k_) / beta_ : 0.0) {
  if (!(k_ >= 0.0) || !(s_ >= 0.0) || !std::isfinite(k_) || !std::isfinite(s_)) {
    throw TextureError("KubelkaMunkSlab: K and S must be finite and >= 0, got K = " +
                       std::to_string(k_) + " /mm, S = " + std::to_string(s_) + " /mm");
  }
}

double KubelkaMunkSlab::reflectance(double d_mm) const {
  double y = beta_ * d_mm;
  return s_ * d_mm * sinhc(y) * transmittance(d_mm);
}

SlabOptics slab_optics_from_measurement(double r, double t, double d_mm) {
  if (!(r > 0.0) || !(t > 0.0) || !(r + t < 1.0) || !(d_mm > 0.0)) {
    throw TextureError(
        "slab_optics_from_measurement: need r > 0, t > 0, r + t < 1 and d > 0, got r = " +
        std::to_string(r) + ", t = " + std::to_string(t) + ", d = " + std::to_string(d_mm) + " mm");
  }
  double a = (1.0 + r * r - t * t) / (2.0 * r);
  double b = std::sqrt(a * a - 1.0);
  double s = std::log((1.0 - r * (a - b)) / t) / (b * d_mm);
  return SlabOptics{s * (a - 1.0), s};
}

LeafOptics default_leaf_optics() {
  // slab_optics_from_measurement(kReferenceReflectance[c], kReferenceTransmittance[c],
  // kReferenceLaminaMm), written out so the numbers can be read (a test checks them).
  LeafOptics optics;
  optics.rgb[0] = SlabOptics{11.702242, 2.554765};
  optics.rgb[1] = SlabOptics{7.414173, 3.152285};
  optics.rgb[2] = SlabOptics{17.506322, 2.157340};
  return optics;
}

}  // namespace boreas::render
