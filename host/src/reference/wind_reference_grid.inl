// boreas: the double-precision grid step (template body of wind_reference.h).
#pragma once

#include <algorithm>
#include <cmath>

namespace boreas::impl::reference {

template <typename SineAt>
void grid_step(Grid& grid, const boreas_grid_def& def, double dt, SineAt sine_at,
               const std::vector<BoreasGpuForcing>& forcing) {
  const BoreasGpuGrid& g = grid.g;
  const double h = g.cell_size;
  const double mix_d = -std::expm1(-6.0 * def.diffusion * dt / (h * h));
  const double decay = std::exp(-def.decay_rate * dt);
  const double drive = dt / def.response_time;
  std::vector<std::array<double, 4>> out(grid.cells.size());
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const auto& self = grid.cells[grid.index(i, j, k)];
        double cx = g.origin_x + (i + 0.5) * h;
        double cy = g.origin_y + (j + 0.5) * h;
        double cz = g.origin_z + (k + 0.5) * h;
        std::array<double, 2> s2 = sine_at(cx, cz);
        Vec3 sine = {s2[0], 0.0, s2[1]};
        Vec3 back;
        for (int a = 0; a < 3; ++a) back[a] = (a == 0 ? i : a == 1 ? j : k) - (sine[a] + self[a]) * dt / h;
        Vec3 adv = grid.trilinear(back);
        auto at = [&](int ii, int jj, int kk) -> const std::array<double, 4>& {
          ii = std::clamp(ii, 0, g.nx - 1);
          jj = std::clamp(jj, 0, g.ny - 1);
          kk = std::clamp(kk, 0, g.nz - 1);
          return grid.cells[grid.index(ii, jj, kk)];
        };
        const auto& xm = at(i - 1, j, k);
        const auto& xp = at(i + 1, j, k);
        const auto& ym = at(i, j - 1, k);
        const auto& yp = at(i, j + 1, k);
        const auto& zm = at(i, j, k - 1);
        const auto& zp = at(i, j, k + 1);
        Vec3 v;
        for (int a = 0; a < 3; ++a) {
          double mean = (xm[a] + xp[a] + ym[a] + yp[a] + zm[a] + zp[a]) / 6.0;
          v[a] = (adv[a] + (mean - adv[a]) * mix_d) * decay;
        }
        if (!forcing.empty()) {
          Vec3 target = {0, 0, 0};
          double cmax = 0.0;
          for (const BoreasGpuForcing& f : forcing) {
            double c = 0.0;
            Vec3 fv = flow_velocity(f, {cx - f.pos_x, cy - f.pos_y, cz - f.pos_z}, &c);
            for (int a = 0; a < 3; ++a) target[a] += fv[a];
            cmax = std::max(cmax, c);
          }
          double keep = std::exp(-cmax * drive);
          for (int a = 0; a < 3; ++a) v[a] = target[a] + (v[a] - target[a]) * keep;
        }
        double solid = self[3];
        if (g.solid_count > 0) {
          Vec3 t = {sine[0] + v[0], sine[1] + v[1], sine[2] + v[2]};
          if (xp[3] != 0 || xm[3] != 0) t[0] = 0;
          if (yp[3] != 0 || ym[3] != 0) t[1] = 0;
          if (zp[3] != 0 || zm[3] != 0) t[2] = 0;
          for (int a = 0; a < 3; ++a) v[a] = solid != 0 ? -sine[a] : t[a] - sine[a];
        }
        out[grid.index(i, j, k)] = {v[0], v[1], v[2], solid};
      }
  grid.cells = std::move(out);
}

}  // namespace boreas::impl::reference
