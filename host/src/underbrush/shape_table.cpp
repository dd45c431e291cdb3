// boreas: building a part's shape tables from the section-by-section solver.
#include "underbrush/shape_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "shared/underbrush_types.h"

namespace boreas::impl {

namespace {

constexpr int kJoints = BOREAS_UB_JOINTS;

// Joints padded to BOREAS_UB_JOINTS by repeating the tip, rotated by `turn` about the base.
void store_joints(const BentShape& s, double turn, float* out) {
  double c = std::cos(turn), d = std::sin(turn);
  for (int k = 0; k < kJoints; ++k) {
    size_t j = std::min<size_t>(static_cast<size_t>(k), s.u.size() - 1);
    out[2 * k] = static_cast<float>(c * s.u[j] - d * s.v[j]);
    out[2 * k + 1] = static_cast<float>(d * s.u[j] + c * s.v[j]);
  }
}

struct Sample {
  BentShape shape;
  double psi, rho;
};

}  // namespace

double table_norm(const PartTables& t, double j) {
  double q = t.q_max * j / (t.sizes.norms - 1);
  return t.sizes.a_ref * q / (1.0 - q);
}

namespace {

// The i-th of `count` angles spread evenly over [0, pi].
double table_angle(int i, int count) { return M_PI * i / (count - 1); }

// Forward: the equilibrium center of mass per angle and norm, per broken state.
void fill_forward(const std::vector<SectionPhysics>& sections, PartTables& t) {
  const ShapeTableSizes& sizes = t.sizes;
  const int states = t.sections + 1;
  for (int b = 0; b < states; ++b)
    for (int i = 0; i < sizes.angles; ++i)
      for (int j = 0; j < sizes.norms; ++j) {
        BentShape s =
            bend_under_load(sections, table_angle(i, sizes.angles), table_norm(t, j), b - 1);
        float* out = &t.forward[static_cast<size_t>(b) * t.forward_size + (static_cast<size_t>(i) * sizes.norms + j) * 2];
        out[0] = static_cast<float>(s.com_u);
        out[1] = static_cast<float>(s.com_v);
      }
}

// Breaking: the least norm at which the intact part breaks, per angle (bisection on a
// bracket found by a scan of the norm axis).
void fill_breaking(const std::vector<SectionPhysics>& sections, PartTables& t) {
  const ShapeTableSizes& sizes = t.sizes;
  for (int i = 0; i < sizes.angles; ++i) {
    double theta = table_angle(i, sizes.angles);
    double lo = 0.0, hi = -1.0;
    int joint = 0;
    const int scan = 256;
    for (int s = 1; s <= scan; ++s) {
      double norm = table_norm(t, double(s) * (sizes.norms - 1) / scan);
      BentShape shape = bend_under_load(sections, theta, norm);
      if (shape.broke_at >= 0) {
        hi = norm;
        joint = shape.broke_at;
        break;
      }
      lo = norm;
    }
    if (hi > 0.0) {
      for (int it = 0; it < 40; ++it) {
        double mid = 0.5 * (lo + hi);
        BentShape shape = bend_under_load(sections, theta, mid);
        if (shape.broke_at >= 0) {
          hi = mid;
          joint = shape.broke_at;
        } else {
          lo = mid;
        }
      }
    }
    t.breaking.push_back(hi > 0.0 ? static_cast<float>(hi) : std::numeric_limits<float>::max());
    t.breaking.push_back(static_cast<float>(joint));
  }
}

// The inverse table's samples: the shapes over angle and norm, densely, per broken state;
// sets t.rho_min from their centers of mass.
std::vector<std::vector<Sample>> sample_shapes(const std::vector<SectionPhysics>& sections,
                                               PartTables& t) {
  const ShapeTableSizes& sizes = t.sizes;
  const int states = t.sections + 1;
  const int sample_angles = 61, sample_norms = 49;
  std::vector<std::vector<Sample>> per_state(static_cast<size_t>(states));
  double rho_min = 1.0;
  for (int b = 0; b < states; ++b) {
    for (int i = 0; i < sample_angles; ++i)
      for (int j = 0; j < sample_norms; ++j) {
        Sample s;
        s.shape =
            bend_under_load(sections, table_angle(i, sample_angles),
                            table_norm(t, (sizes.norms - 1.0) * j / (sample_norms - 1)), b - 1);
        s.psi = std::atan2(s.shape.com_v, s.shape.com_u);
        s.rho = std::hypot(s.shape.com_u, s.shape.com_v) / t.reach;
        rho_min = std::min(rho_min, s.rho);
        per_state[b].push_back(std::move(s));
      }
  }
  t.rho_min = std::max(0.02, std::min(rho_min, 0.98));
  return per_state;
}

// Every cell of the (psi, rho) grid gets the sample whose center of mass is nearest,
// turned about the base so its center of mass has the cell's psi exactly.
void fill_inverse(const std::vector<std::vector<Sample>>& per_state, PartTables& t) {
  const ShapeTableSizes& sizes = t.sizes;
  const int states = t.sections + 1;
  for (int b = 0; b < states; ++b)
    for (int k = 0; k < sizes.psi_count; ++k)
      for (int l = 0; l < sizes.rho_count; ++l) {
        double psi = table_angle(k, sizes.psi_count);
        double rho = t.rho_min + (1.0 - t.rho_min) * l / (sizes.rho_count - 1);
        const Sample* best = nullptr;
        double best_d = std::numeric_limits<double>::max();
        for (const Sample& s : per_state[b]) {
          double dp = (s.psi - psi) / M_PI, dr = (s.rho - rho) / (1.0 - t.rho_min);
          double d = dp * dp + dr * dr;
          if (d < best_d) {
            best_d = d;
            best = &s;
          }
        }
        float* out = &t.inverse[static_cast<size_t>(b) * t.inverse_size +
                                (static_cast<size_t>(k) * sizes.rho_count + l) * kJoints * 2];
        store_joints(best->shape, psi - best->psi, out);
      }
}

}  // namespace

PartTables build_part_tables(const std::vector<SectionPhysics>& sections,
                             const std::vector<double>& half_widths, const ShapeTableSizes& sizes) {
  PartTables t;
  t.sizes = sizes;
  t.sections = static_cast<int>(sections.size());
  t.reach = straight_reach(sections);
  t.q_max = sizes.a_max / (sizes.a_max + sizes.a_ref);
  t.forward_size = sizes.angles * sizes.norms * 2;
  t.inverse_size = sizes.psi_count * sizes.rho_count * kJoints * 2;
  const int states = t.sections + 1;
  t.forward.assign(static_cast<size_t>(states) * t.forward_size, 0.0f);
  t.inverse.assign(static_cast<size_t>(states) * t.inverse_size, 0.0f);

  for (int k = 0; k < kJoints; ++k)
    t.widths.push_back(static_cast<float>(
        half_widths[std::min<size_t>(static_cast<size_t>(k), half_widths.size() - 1)]));

  fill_forward(sections, t);
  fill_breaking(sections, t);
  // Inverse: the shapes sampled densely over angle and norm, the nearest to each cell.
  fill_inverse(sample_shapes(sections, t), t);
  return t;
}

}  // namespace boreas::impl
