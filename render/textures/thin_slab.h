// boreas textures: the leaf as a thin Kubelka-Munk slab, which gives its reflectance
// (albedo), its transmittance at normal incidence (translucency color) and the transmitted
// intensity that the HL2 coefficients are fitted to.
//
// The model. A leaf is a slab of thickness d (mm) that absorbs (K, 1/mm) and scatters (S,
// 1/mm) diffuse light, with no reflecting background. Kubelka-Munk's two-flux solution
// (Kubelka 1948, "New contributions to the optics of intensely light-scattering materials",
// JOSA 38:448) gives
//   T = b / (a sinh(b S d) + b cosh(b S d)),   R = sinh(b S d) / (a sinh(b S d) + b cosh(b S d)),
//   a = 1 + K/S,  b = sqrt(a^2 - 1).
// With beta = b S = sqrt(K (K + 2 S)) and y = beta d this is
//   T = 1 / ((S + K) d sinhc(y) + cosh(y)),   R = S d sinhc(y) T,   sinhc(y) = sinh(y) / y,
// which is the form computed here: it stays finite for K = 0 (T = 1 / (1 + S d)) and S = 0
// (T = exp(-K d)). The same per-channel K and S hold over the whole leaf (Kusternig sec. 3.5.1
// makes the same assumption); veins differ only in thickness.
//
// The constants (default_leaf_optics) are not fitted to one species: they are K and S that
// reproduce, for a 0.2 mm lamina, a typical green broadleaf in the three sRGB bands:
//   R = (0.090, 0.150, 0.055): the ColorChecker "Foliage" patch (sRGB 87, 108, 67, McCamy et
//     al. 1976), which was made to match the reflectance spectrum of leaves;
//   T = (0.060, 0.130, 0.020): leaf transmittance is about as large as reflectance in the
//     visible and peaks near 550 nm at 0.1-0.2, falling below 0.05 in the chlorophyll bands
//     around 450 and 670 nm (Woolley 1971, Plant Physiol. 47:656; Gates et al. 1965, Appl.
//     Opt. 4:11). The red band keeps more than the blue because it takes in 580-620 nm,
//     where chlorophyll absorbs little.
// Inverting Kubelka-Munk for these R and T (slab_optics_from_measurement) gives the K and S
// below. A consequence worth knowing: K >> S, so R saturates within 0.1 mm (thicker veins
// barely reflect more) while T falls about 2.7x per extra 0.1 mm (a 0.5 mm midrib passes 1/20
// of the lamina's light).
#pragma once

#include <array>
#include <cmath>

namespace boreas::render {

// Kubelka-Munk coefficients of one wavelength band.
struct SlabOptics {
  double absorption_per_mm = 0.0;  // K
  double scattering_per_mm = 0.0;  // S
};

// A thin slab of fixed K and S, evaluated at any thickness.
class KubelkaMunkSlab {
 public:
  explicit KubelkaMunkSlab(SlabOptics optics);

  // Fraction of diffuse light that passes a slab d_mm thick (d_mm >= 0), in [0, 1]. Inline:
  // the HL2 fit calls it about 25 million times for the default leaf.
  double transmittance(double d_mm) const {
    double y = beta_ * d_mm;
    if (y < 1e-3) return 1.0 / ((s_ + k_) * d_mm * sinhc(y) + std::cosh(y));
    // With e = exp(-y), (S + K) d sinhc(y) + cosh(y) = ((A + 1) - (A - 1) e^2) / (2 e),
    // A = (S + K) / beta: one exponential.
    double e = std::exp(-y);
    return 2.0 * e / ((a_ + 1.0) - (a_ - 1.0) * e * e);
  }
  // Fraction of diffuse light that a slab d_mm thick reflects, over a black background.
  double reflectance(double d_mm) const;

 private:
  // sinh(y) / y, by its series near 0 (where the quotient is 0 / 0).
  static double sinhc(double y) {
    return std::abs(y) < 1e-3 ? 1.0 + y * y / 6.0 : std::sinh(y) / y;
  }

  double k_;
  double s_;
  double beta_;  // sqrt(K (K + 2 S)), 1/mm
  double a_;     // (S + K) / beta, when beta > 0
};

// K and S of a slab d_mm thick that reflects r and transmits t (r, t > 0, r + t < 1): the
// standard inversion a = (1 + r^2 - t^2) / (2 r), S = ln((1 - r (a - b)) / t) / (b d),
// K = S (a - 1). Throws TextureError for values no slab can have.
SlabOptics slab_optics_from_measurement(double r, double t, double d_mm);

// Per-channel (linear RGB) optics of a green leaf; see the file comment.
struct LeafOptics {
  std::array<SlabOptics, 3> rgb;
  // The channel whose optics give the HL2 coefficients: green, standing in for the paper's
  // single "dominant wavelength of green light (510 nm)".
  int coefficient_channel = 1;
};

// The reference lamina that default_leaf_optics reproduces.
inline constexpr double kReferenceLaminaMm = 0.2;
inline constexpr std::array<double, 3> kReferenceReflectance = {0.090, 0.150, 0.055};
inline constexpr std::array<double, 3> kReferenceTransmittance = {0.060, 0.130, 0.020};

LeafOptics default_leaf_optics();

}  // namespace boreas::render
