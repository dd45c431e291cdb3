// boreas: double-precision sine sums, trilinear sampling and flow primitives.
#include "reference/wind_reference.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl::reference {

std::array<double, 2> sine_sum(const std::vector<WaveParams>& waves, double x, double z, double t) {
  std::array<double, 2> f = {0.0, 0.0};
  for (const WaveParams& w : waves) {
    double theta = (w.dir_x * x + w.dir_z * z) * w.wavenumber() + t * w.phase_rate();
    double base = (std::sin(theta) + 1.0) / 2.0;
    double s = w.amplitude * (w.sharpness == 0.0 ? 1.0 : std::pow(base, w.sharpness));
    f[0] += w.dir_x * s;
    f[1] += w.dir_z * s;
  }
  return f;
}

std::array<double, 2> sine_sum(const WaveLayers& layers, double x, double z, double t) {
  std::array<double, 2> f = {0.0, 0.0};
  for (const WaveLayers::Layer& layer : layers.layers()) {
    double weight = WaveLayers::weight(layer, t);
    std::array<double, 2> part = sine_sum(layer.waves, x, z, t);
    f[0] += weight * part[0];
    f[1] += weight * part[1];
  }
  return f;
}

Vec3 Grid::trilinear(Vec3 c) const {
  int n[3] = {g.nx, g.ny, g.nz};
  int lo[3], hi[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    c[a] = std::clamp(c[a], 0.0, double(n[a] - 1));
    double fl = std::floor(c[a]);
    lo[a] = int(fl);
    hi[a] = std::min(lo[a] + 1, n[a] - 1);
    f[a] = c[a] - fl;
  }
  Vec3 out = {0, 0, 0};
  for (int corner = 0; corner < 8; ++corner) {
    int ii = corner & 1 ? hi[0] : lo[0];
    int jj = corner & 2 ? hi[1] : lo[1];
    int kk = corner & 4 ? hi[2] : lo[2];
    double w = (corner & 1 ? f[0] : 1 - f[0]) * (corner & 2 ? f[1] : 1 - f[1]) *
               (corner & 4 ? f[2] : 1 - f[2]);
    const auto& v = cells[index(ii, jj, kk)];
    for (int a = 0; a < 3; ++a) out[a] += w * v[a];
  }
  return out;
}

Vec3 flow_velocity(const BoreasGpuForcing& f, const Vec3& r, double* coverage) {
  double d2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  double c = 1.0;
  if (f.radius > 0) {
    double q = std::max(1.0 - d2 / (double(f.radius) * f.radius), 0.0);
    c = q * q;
  }
  *coverage = c;
  Vec3 dir = {f.dir_x, f.dir_y, f.dir_z};
  double d = std::sqrt(d2);
  double core = std::max(0.25 * f.radius, 1e-6);
  double ramp = std::min(d / core, 1.0) * c * f.strength;
  double inv_d = d > 1e-6 ? 1.0 / d : 0.0;
  double along = r[0] * dir[0] + r[1] * dir[1] + r[2] * dir[2];
  Vec3 rho = {r[0] - along * dir[0], r[1] - along * dir[1], r[2] - along * dir[2]};
  Vec3 a = {dir[1] * rho[2] - dir[2] * rho[1], dir[2] * rho[0] - dir[0] * rho[2],
            dir[0] * rho[1] - dir[1] * rho[0]};
  double len = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  double inv_len = len > 1e-6 ? 1.0 / len : 0.0;
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    v[i] = f.uniform_weight * dir[i] * f.strength * c + f.radial_weight * ramp * r[i] * inv_d +
           f.swirl_weight * ramp * a[i] * inv_len;
  }
  return v;
}

}  // namespace boreas::impl::reference
