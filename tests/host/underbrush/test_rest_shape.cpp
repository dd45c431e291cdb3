// Rest shapes (Endo et al. eq. 1) and the shape tables, against what they promise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "underbrush/component_species.h"
#include "underbrush/rest_shape.h"
#include "underbrush/shape_table.h"

// The kernels' table lookups (their C++ build).
#define BOREAS_FAST_MATH 1
#include "shared/underbrush_math.h"

namespace boreas::impl {
namespace {

// A uniform blade: every section alike.
std::vector<SectionPhysics> uniform_blade(int sections, double mass, double stiffness,
                                          double max_moment = 1e9) {
  std::vector<SectionPhysics> s(static_cast<size_t>(sections));
  for (SectionPhysics& p : s) {
    p.length = 0.05;
    p.mass = mass;
    p.stiffness = stiffness;
    p.max_moment = max_moment;
  }
  return s;
}

// Directions of the sections of a shape, from its joints.
std::vector<double> directions(const BentShape& s) {
  std::vector<double> phi;
  for (size_t j = 0; j + 1 < s.u.size(); ++j) phi.push_back(std::atan2(s.v[j + 1] - s.v[j], s.u[j + 1] - s.u[j]));
  return phi;
}

// The balance of eq. 1 at every joint, recomputed from the final joints alone: after
// joint j turned, the part above it lay straight along section j's final direction, so
// its arm r_j and mass M_j follow from the sections; the elastic moment kappa sin(alpha_j)
// (alpha_j = phi_j - phi_{j-1}) must equal r_j M_j |a| sin(beta_j), beta_j the angle from
// that direction to the load. Returns the largest residual relative to the load's moment.
double balance_residual(const std::vector<SectionPhysics>& sec, const BentShape& s, double theta, double norm) {
  std::vector<double> phi = directions(s);
  double worst = 0.0;
  for (size_t j = 0; j < sec.size(); ++j) {
    double m = 0.0, first = 0.0, along = 0.0;
    for (size_t k = j; k < sec.size(); ++k) {
      m += sec[k].mass;
      first += sec[k].mass * (along + 0.5 * sec[k].length);
      along += sec[k].length;
    }
    double r = first / m;
    double before = j == 0 ? 0.0 : phi[j - 1];
    double alpha = phi[j] - before;
    double beta = theta - phi[j];
    double elastic = sec[j].stiffness * std::sin(alpha);
    double load = r * m * norm * std::sin(beta);
    double scale = r * m * norm;
    worst = std::max(worst, std::fabs(elastic - load) / scale);
  }
  return worst;
}

TEST(RestShape, BalancesEquationOneAtEverySection) {
  for (double theta : {0.3, 1.0, 1.6, 2.5, 3.0}) {
    for (double stiffness : {2e-5, 2e-4, 2e-3}) {
      auto sec = uniform_blade(6, 5e-5, stiffness);
      BentShape s = bend_under_load(sec, theta, 9.81);
      EXPECT_LT(balance_residual(sec, s, theta, 9.81), 1e-12) << "theta " << theta << " stiffness " << stiffness;
      // Bent toward the load, never past it.
      std::vector<double> phi = directions(s);
      for (size_t j = 0; j < phi.size(); ++j) {
        EXPECT_GE(s.alpha[j], 0.0);
        EXPECT_LE(phi[j], theta + 1e-12);
      }
    }
  }
}

TEST(RestShape, GrassSpeciesBalancesWithTaper) {
  ComponentSpecies sp = load_component_species("meadow_grass");
  auto sec = part_sections(sp.tissue, sp.parts[0]);
  // An upright blade leaning 20 degrees: gravity at 160 degrees from its axis.
  double theta = M_PI * 160.0 / 180.0;
  BentShape s = bend_under_load(sec, theta, 9.80665);
  EXPECT_LT(balance_residual(sec, s, theta, 9.80665), 1e-12);
  std::vector<double> phi = directions(s);
  // The tapering blade droops more toward its tip (each joint turns by a positive angle).
  EXPECT_GT(phi.back(), phi.front());
  std::printf("meadow_grass leaning 20 deg: its tip turned %.1f deg from its axis\n", phi.back() * 180.0 / M_PI);
}

TEST(RestShape, HeavierComponentsBendMore) {
  double theta = 2.5;
  double last_tip_angle = -1.0;
  for (double mass : {1e-5, 3e-5, 1e-4, 3e-4}) {
    auto sec = uniform_blade(6, mass, 1e-4);
    BentShape s = bend_under_load(sec, theta, 9.81);
    double tip = directions(s).back();
    EXPECT_GT(tip, last_tip_angle) << "mass " << mass;
    last_tip_angle = tip;
  }
}

TEST(RestShape, NoLoadNoBend) {
  auto sec = uniform_blade(5, 1e-4, 1e-4);
  BentShape s = bend_under_load(sec, 2.0, 0.0);
  for (size_t j = 0; j < s.u.size(); ++j) {
    EXPECT_DOUBLE_EQ(s.v[j], 0.0);
    EXPECT_NEAR(s.u[j], 0.05 * j, 1e-15);
  }
}

TEST(RestShape, BreaksAtTheStatedThreshold) {
  // The base joint must carry kappa sin(alpha_0); set the limit just above and below it.
  auto sec = uniform_blade(4, 1e-4, 1e-4);
  double theta = 2.0;
  BentShape intact = bend_under_load(sec, theta, 9.81);
  double needed = sec[0].stiffness * std::sin(intact.alpha[0]);
  ASSERT_EQ(intact.broke_at, -1);
  for (SectionPhysics& p : sec) p.max_moment = needed * 1.001;
  EXPECT_EQ(bend_under_load(sec, theta, 9.81).broke_at, -1);
  sec[0].max_moment = needed * 0.999;
  BentShape broken = bend_under_load(sec, theta, 9.81);
  EXPECT_EQ(broken.broke_at, 0);
  // The broken part hangs along the load.
  std::vector<double> phi = directions(broken);
  for (double p : phi) EXPECT_NEAR(p, theta, 1e-9);
}

TEST(ShapeTable, ForwardMatchesTheSolverAtItsNodes) {
  auto sec = uniform_blade(6, 5e-5, 2e-4);
  ShapeTableSizes sizes;
  sizes.angles = 7;
  sizes.norms = 9;
  PartTables t = build_part_tables(sec, std::vector<double>(7, 0.002), sizes);
  for (int i = 0; i < sizes.angles; ++i)
    for (int j = 0; j < sizes.norms; ++j) {
      BentShape s = bend_under_load(sec, M_PI * i / (sizes.angles - 1), table_norm(t, j));
      EXPECT_NEAR(t.forward[(i * sizes.norms + j) * 2], s.com_u, 1e-7);
      EXPECT_NEAR(t.forward[(i * sizes.norms + j) * 2 + 1], s.com_v, 1e-7);
    }
  // The norm axis: each shape covers an interval; they increase and gravity is inside.
  for (int j = 1; j < sizes.norms; ++j) EXPECT_GT(table_norm(t, j), table_norm(t, j - 1));
  EXPECT_LT(table_norm(t, 0), 9.81);
  EXPECT_GT(table_norm(t, sizes.norms - 1), 9.81);
}

TEST(ShapeTable, InverseShapesHaveTheirCellsCenterOfMass) {
  ComponentSpecies sp = load_component_species("meadow_grass");
  auto sec = part_sections(sp.tissue, sp.parts[0]);
  PartTables t = build_part_tables(sec, part_half_widths(sp.parts[0]), ShapeTableSizes{});
  const int J = 9, R = t.sizes.rho_count;
  double worst_psi = 0.0;
  for (int k = 0; k < t.sizes.psi_count; ++k)
    for (int l = 0; l < R; ++l) {
      const float* joints = &t.inverse[(size_t(k) * R + l) * J * 2];
      std::vector<double> u, v;
      for (int j = 0; j <= t.sections; ++j) {
        u.push_back(joints[2 * j]);
        v.push_back(joints[2 * j + 1]);
      }
      double cu, cv;
      center_of_mass(sec, u, v, &cu, &cv);
      double psi = M_PI * k / (t.sizes.psi_count - 1);
      worst_psi = std::max(worst_psi, std::fabs(std::remainder(std::atan2(cv, cu) - psi, 2.0 * M_PI)));
      // Segment lengths are the part's.
      for (int j = 0; j < t.sections; ++j)
        EXPECT_NEAR(std::hypot(u[j + 1] - u[j], v[j + 1] - v[j]), sec[j].length, 1e-6);
    }
  EXPECT_LT(worst_psi, 1e-5);
}

TEST(ShapeTable, BreakThresholdSeparatesIntactFromBroken) {
  auto sec = uniform_blade(4, 1e-4, 1e-4, 2e-5);
  ShapeTableSizes sizes;
  sizes.angles = 5;
  PartTables t = build_part_tables(sec, std::vector<double>(5, 0.002), sizes);
  // (A load straight along the axis, either way, bends nothing and breaks nothing.)
  for (int i = 1; i < sizes.angles - 1; ++i) {
    double theta = M_PI * i / (sizes.angles - 1);
    double norm = t.breaking[2 * i];
    ASSERT_LT(norm, 1e30) << "angle " << i;
    EXPECT_EQ(bend_under_load(sec, theta, norm * 0.999).broke_at, -1);
    EXPECT_GE(bend_under_load(sec, theta, norm * 1.001).broke_at, 0);
  }
}

// A blade's drawn shape never snaps from one stored shape to the next: the load's angle
// and size are read bilinearly from the forward table, the center of mass that gives
// bilinearly from the inverse one, so sweeping the load across the tables' knots (every
// 10 degrees, every norm sample) moves every joint continuously. Measured as the largest
// joint move between neighbouring loads of a fine sweep against the median move: a snap
// would be a whole cell's change (a hundred sweep steps' worth) at a knot; piecewise-linear
// reading lets a step across a knot differ from its neighbours by the slopes' ratio only.
TEST(ShapeTable, ShapesFollowTheLoadWithoutSnapping) {
  ComponentSpecies sp = load_component_species("meadow_grass");
  auto sec = part_sections(sp.tissue, sp.parts[0]);
  PartTables t = build_part_tables(sec, part_half_widths(sp.parts[0]), ShapeTableSizes{});
  const ShapeTableSizes& z = t.sizes;
  // The joints for a load of size `norm` at angle `theta` from the blade's axis.
  auto joints = [&](double theta, double norm) {
    BoreasUbCell row = boreas_ub_cell(float(theta * (z.angles - 1) / M_PI), z.angles);
    BoreasUbCell col = boreas_ub_cell(
        boreas_ub_norm_position(float(norm), float(z.a_ref), float(t.q_max), z.norms), z.norms);
    float par, perp;
    boreas_ub_bilinear2(t.forward.data(), 0, z.norms, row, col, &par, &perp);
    BoreasUbCell psi, rho;
    boreas_ub_shape_cell(par, perp, float(t.reach), z.psi_count, z.rho_count, float(t.rho_min), &psi,
                         &rho);
    std::vector<double> out;
    for (int k = 0; k <= t.sections; ++k) {
      float u, v;
      boreas_ub_shape_joint(t.inverse.data(), 0, z.rho_count, psi, rho, k, &u, &v);
      out.push_back(u);
      out.push_back(v);
    }
    return out;
  };
  auto worst_over_median = [&](auto load_at, int steps) {
    std::vector<double> moves;
    std::vector<double> before = joints(load_at(0).first, load_at(0).second);
    for (int i = 1; i <= steps; ++i) {
      const auto [theta, norm] = load_at(double(i) / steps);
      std::vector<double> now = joints(theta, norm);
      double largest = 0.0;
      for (size_t k = 0; k + 1 < now.size(); k += 2)
        largest = std::max(largest, std::hypot(now[k] - before[k], now[k + 1] - before[k + 1]));
      moves.push_back(largest);
      before = now;
    }
    std::vector<double> sorted = moves;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    EXPECT_GT(median, 0.0);
    return *std::max_element(moves.begin(), moves.end()) / median;
  };
  // Gravity and a side wind of up to 3 g, turning: the load's angle sweeps 0..170 degrees
  // in 0.05 degree steps at 1.5 g, crossing 17 angle knots.
  const double g = 9.80665;
  const double by_angle = worst_over_median(
      [&](double f) { return std::make_pair(f * 170.0 * M_PI / 180.0, 1.5 * g); }, 3400);
  // The load's size from 0.2 g to 4 g at 60 degrees, crossing several norm knots.
  const double by_norm = worst_over_median(
      [&](double f) { return std::make_pair(M_PI / 3.0, (0.2 + 3.8 * f) * g); }, 3400);
  std::printf("    largest joint move over the median: %.2f sweeping the angle, %.2f the norm\n",
              by_angle, by_norm);
  EXPECT_LT(by_angle, 10.0);
  EXPECT_LT(by_norm, 10.0);
}

}  // namespace
}  // namespace boreas::impl
