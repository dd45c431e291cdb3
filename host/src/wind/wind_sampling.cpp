// boreas: the error bound of interpolated wind sampling.
//
// A wave's term is A g(theta), theta = w (d . (x, z)) + phase, w = 2 pi / L, d a unit
// vector, g = ((sin theta + 1) / 2)^k. Bilinear interpolation is linear interpolation along
// x, then along z: its error is at most (h^2 / 8) (max |u_xx| + max |u_zz|), and with
// u_xx = w^2 d_x^2 g'', u_zz = w^2 d_z^2 g'' that is (h^2 / 8) w^2 max |g''|, whatever the
// wave's direction.
//
// With b = (sin theta + 1) / 2: b' = cos theta / 2, b'^2 = b (1 - b), b'' = 1/2 - b, so
// g'' = k b^(k-1) (k - 1/2 - k b). For k >= 1 its largest magnitude on b in [0, 1] is k/2,
// at the crest (b = 1): the interior extremum, at b* = (k - 1)(k - 1/2) / k^2, is
// (k - 1/2) b*^(k-1) <= k/2. So the error is at most (h^2 / 8) w^2 k / 2 = (pi h / L)^2 k / 4.
//
// For 0 < k < 1, g'' is unbounded at the trough (b = 0), where g ~ b^k has a cusp; there a
// bilinear value, a convex combination of the four corners', is off by at most the largest
// change of g between the point and a corner. Theta changes by at most w h sqrt(2) over a
// cell's diagonal, b by half that, and b^k is Hoelder: |b1^k - b2^k| <= |b1 - b2|^k. So the
// error is at most min(1, (pi sqrt(2) h / L)^k). For k = 0 the term is constant: no error.
// And never more than 1 for any k: g and its bilinear value (a convex combination of its
// corners') both lie in [0, 1].
//
// In the outermost cell of column centers the kernels blend the bilinear sum into the
// exact one (a convex combination of the two), so the bound holds there as well.
#include "wind/wind_sampling.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

double interpolation_error(const WaveParams& wave, double cell_size) {
  const double k = wave.sharpness;
  if (k <= 0.0) return 0.0;
  const double x = M_PI * cell_size / wave.wavelength;
  if (k >= 1.0) return std::min(1.0, x * x * k / 4.0);
  return std::min(1.0, std::pow(std::sqrt(2.0) * x, k));
}

double interpolation_error_bound(const std::vector<WaveParams>& waves, double cell_size) {
  double bound = 0.0;
  for (const WaveParams& w : waves) bound += w.amplitude * interpolation_error(w, cell_size);
  return bound;
}

}  // namespace boreas::impl
