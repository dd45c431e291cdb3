// boreas tests: the underbrush's air damping and length scaling (cl/shared/underbrush_math.h,
// boreas_ub_air_step and boreas_ub_shape_load). The step against the equation it solves,
//   y'' = -(2/tau) y' - y/tau^2 + r (c |u - v| (u - v) - c |u| u),   y = X - X0(u),
// (r the part's air coupling, c its drag per unit mass), integrated in double by RK4 at a
// hundredth of the step (the kernel in a steady wind, the shared header at width 1 in calm
// air); against the closed form of its linearization about rest in a steady wind, and of
// the work the air takes from a swing kicked in calm air (first order in the drag); its
// spectral radius at the stiffest built-in part and dt 1/30 over
// wind speeds up to a storm; and a blade twice as long bending by the cantilever ratio.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <functional>

#include "underbrush_fixtures.h"
#include "shared/underbrush_math.h"
#include "underbrush/rest_shape.h"
#include "underbrush/frame_pack.h"

namespace boreas {
namespace {

using test::meadow_world;
using test::planting_grid;
using test::species_params;
using D3 = std::array<double, 3>;

double norm3(const D3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// One component's motion about a fixed X0: y = X - X0 and v.
struct Motion {
  D3 y{}, v{};
};

// The equation's right side for (y, v): the constraint plus the drag on the relative wind
// less the drag on the wind (which X0 holds). c per unit mass (1/m).
D3 accel(const D3& y, const D3& v, const D3& u, double c, double tau) {
  D3 w{u[0] - v[0], u[1] - v[1], u[2] - v[2]};
  const double ws = norm3(w), us = norm3(u);
  D3 a{};
  for (int i = 0; i < 3; ++i)
    a[i] = -2.0 / tau * v[i] - y[i] / (tau * tau) + c * ws * w[i] - c * us * u[i];
  return a;
}

// RK4 over dt in `sub` substeps.
Motion reference_step(Motion m, const D3& u, double c, double tau, double dt, int sub = 100) {
  const double h = dt / sub;
  for (int s = 0; s < sub; ++s) {
    auto add = [](const D3& a, const D3& b, double k) {
      return D3{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]};
    };
    const D3 k1y = m.v, k1v = accel(m.y, m.v, u, c, tau);
    const D3 k2y = add(m.v, k1v, h / 2), k2v = accel(add(m.y, k1y, h / 2), k2y, u, c, tau);
    const D3 k3y = add(m.v, k2v, h / 2), k3v = accel(add(m.y, k2y, h / 2), k3y, u, c, tau);
    const D3 k4y = add(m.v, k3v, h), k4v = accel(add(m.y, k3y, h), k4y, u, c, tau);
    for (int i = 0; i < 3; ++i) {
      m.y[i] += h / 6 * (k1y[i] + 2 * k2y[i] + 2 * k3y[i] + k4y[i]);
      m.v[i] += h / 6 * (k1v[i] + 2 * k2v[i] + 2 * k3v[i] + k4v[i]);
    }
  }
  return m;
}

// The shared header's step at width 1 (float), about X0 = 0, a root (base at rest).
Motion device_step(const Motion& m, const D3& u, double c, double tau, double dt) {
  BoreasV3 x = boreas_v3(float(m.y[0]), float(m.y[1]), float(m.y[2]));
  BoreasV3 v = boreas_v3(float(m.v[0]), float(m.v[1]), float(m.v[2]));
  boreas_ub_air_step(&x, &v, boreas_v3(0.0f, 0.0f, 0.0f), boreas_v3(float(u[0]), float(u[1]), float(u[2])),
                     boreas_v3(0.0f, 0.0f, 0.0f), float(c), float(tau), float(dt));
  Motion out;
  out.y = {x.x, x.y, x.z};
  out.v = {v.x, v.y, v.z};
  return out;
}

// Energy per unit mass of the constraint's oscillator: kinetic plus its spring's.
double energy(const Motion& m, double tau) {
  return 0.5 * (m.v[0] * m.v[0] + m.v[1] * m.v[1] + m.v[2] * m.v[2]) +
         0.5 * norm3(m.y) * norm3(m.y) / (tau * tau);
}

// The meadow grass's blade as the kernel sees it: drag per unit mass and tau.
struct PartConstants {
  double c, tau;
};
PartConstants part_constants(const std::string& species) {
  impl::Meadow m = impl::meadow_from_plantings(species_params({species}), planting_grid(1, 0.3));
  const BoreasGpuPart& g = m.parts[0].gpu;
  std::printf("    %s: air coupling %.3g\n", species.c_str(), g.air_coupling);
  return {double(g.drag_area) * g.inv_mass * g.air_coupling, g.tau};
}

// A swing in calm air, kicked at 1 m/s from rest (a footstep's push): with the air, the
// energy falls below the constraint's alone, step by step, and follows the equation; what
// the air takes is the equation's within 10 % (the drag's slope held over each step).
TEST(UnderbrushAir, CalmAirDrainsASwingAndFollowsTheEquation) {
  const PartConstants k = part_constants("meadow_grass");
  const double dt = 1.0 / 30.0;
  const D3 calm{0.0, 0.0, 0.0};
  Motion air, still, ref;
  air.v = still.v = ref.v = {1.0, 0.3, 0.0};
  double worst = 0.0, lost = 0.0, lost_ref = 0.0;
  for (int s = 1; s <= 30; ++s) {
    air = device_step(air, calm, k.c, k.tau, dt);
    still = device_step(still, calm, 0.0, k.tau, dt);
    ref = reference_step(ref, calm, k.c, k.tau, dt);
    const double e_air = energy(air, k.tau), e_still = energy(still, k.tau), e_ref = energy(ref, k.tau);
    EXPECT_LT(e_air, e_still) << "step " << s;
    worst = std::max(worst, std::fabs(e_air - e_ref) / energy(Motion{{}, {1.0, 0.3, 0.0}}, k.tau));
    lost += e_still - e_air;  // what the air took, summed over the swing
    lost_ref += e_still - e_ref;
    if (s % 5 == 0)
      std::printf("    t %.2f s: energy %.4g with air (equation %.4g), %.4g without (J/kg)\n", s * dt,
                  e_air, e_ref, e_still);
  }
  std::printf("    c %.3g 1/m, tau %.3g s: worst energy gap to the equation %.2g of the kick's\n", k.c,
              k.tau, worst);
  std::printf("    the air's share: %.4g (equation %.4g) J/kg s\n", lost * dt, lost_ref * dt);
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(lost, lost_ref, 0.1 * lost_ref) << "the air's take, as the equation's";
}

// The air's take in closed form. Kicked from rest at v0 in calm air, the constraint alone
// swings back critically damped, v(t) = v0 (1 - t/tau) e^(-t/tau) along the kick, and the
// drag on that motion dissipates, per unit mass and to first order in c v0 tau,
//   W = c v0^3 tau Int_0^inf |1 - s|^3 e^(-3s) ds = (4/27) (1 + e^-3) c v0^3 tau.
// The kernel's own velocities, stepped at tau/50 with the air, give the work the drag did
// (c |v|^3 summed by the trapezoid rule); it matches W within 1 % at c v0 tau = 0.01 (the
// next order and the step's rounding are each a few tenths of that), and a tenth of the
// kick gives a thousandth of the work (the cube law of a drag quadratic in the relative
// wind).
TEST(UnderbrushAir, CalmAirTakesWhatTheClosedFormSaysFromAKickedSwing) {
  const PartConstants k = part_constants("meadow_grass");
  const double dt = k.tau / 50.0;
  const D3 calm{0.0, 0.0, 0.0};
  auto air_work = [&](double v0) {
    Motion m;
    m.v = {v0 * 0.8, 0.0, v0 * 0.6};
    double work = 0.0, before = std::pow(norm3(m.v), 3);
    for (int s = 1; s <= 1000; ++s) {  // 20 tau: e^-20 of the swing is left
      m = device_step(m, calm, k.c, k.tau, dt);
      const double now = std::pow(norm3(m.v), 3);
      work += k.c * 0.5 * (before + now) * dt;
      before = now;
    }
    return work;
  };
  const double v0 = 0.01 / (k.c * k.tau);
  const double closed = 4.0 / 27.0 * (1.0 + std::exp(-3.0)) * k.c * v0 * v0 * v0 * k.tau;
  const double work = air_work(v0), small = air_work(0.1 * v0);
  std::printf("    c %.3g 1/m, tau %.3g s, kick %.3g m/s: the air took %.5g J/kg, closed form %.5g\n",
              k.c, k.tau, v0, work, closed);
  EXPECT_NEAR(work, closed, 0.01 * closed);
  EXPECT_NEAR(small, 1e-3 * closed, 0.01e-3 * closed) << "the take goes as the kick cubed";
}

// Linearized about rest in a steady wind u, a small swing obeys
// y'' + (2/tau + c|u| (1 + [along u])) y' + y/tau^2 = 0: over-damped, in closed form.
TEST(UnderbrushAir, SmallSwingInSteadyWindMatchesTheLinearizedClosedForm) {
  const PartConstants k = part_constants("meadow_grass");
  const double dt = 1.0 / 30.0, speed = 6.0, y0 = 1e-3;
  const D3 u{speed, 0.0, 0.0};
  for (int axis : {0, 2}) {  // along the wind, across it
    const double alpha = 1.0 / k.tau + k.c * speed * (axis == 0 ? 1.0 : 0.5);
    const double omega = 1.0 / k.tau, g = std::sqrt(alpha * alpha - omega * omega);
    Motion m;
    m.y[axis] = y0;
    double worst = 0.0;
    for (int s = 1; s <= 60; ++s) {
      m = device_step(m, u, k.c, k.tau, dt);
      const double t = s * dt;
      // y(t) = y0 e^(-alpha t) (cosh(g t) + alpha/g sinh(g t)) from rest
      const double closed = y0 * std::exp(-alpha * t) * (std::cosh(g * t) + alpha / g * std::sinh(g * t));
      worst = std::max(worst, std::fabs(m.y[axis] - closed) / y0);
    }
    std::printf("    axis %d: alpha %.3g 1/s (no air %.3g), worst gap to the closed form %.2g of y0\n", axis,
                alpha, omega, worst);
    EXPECT_LT(worst, 2e-3) << "axis " << axis;
  }
}

// The spectral radius of the step's (y_i, v_i) block about rest in a steady wind, by
// central differences of the float step: at most 1, and the exact linear step's.
using StepFn = std::function<Motion(const Motion&, const D3&, double, double, double)>;

double spectral_radius(const D3& u, double c, double tau, double dt, int axis, double h,
                       const StepFn& step = device_step) {
  double j[2][2];
  for (int col = 0; col < 2; ++col) {
    Motion out[2];
    for (int sign = 0; sign < 2; ++sign) {
      Motion m;
      (col == 0 ? m.y : m.v)[axis] = sign == 0 ? h : -h;
      out[sign] = step(m, u, c, tau, dt);
    }
    j[0][col] = (out[0].y[axis] - out[1].y[axis]) / (2 * h);
    j[1][col] = (out[0].v[axis] - out[1].v[axis]) / (2 * h);
  }
  const double tr = j[0][0] + j[1][1], det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr / 4.0 - det, 0.0));
  return std::max(std::abs(tr / 2.0 + root), std::abs(tr / 2.0 - root));
}

// For contrast: the drag on the relative wind taken explicitly (X0 moved by tau^2 r da(v_n),
// then the constraint's exact step).
Motion explicit_step(const Motion& m, const D3& u, double c, double tau, double dt) {
  const D3 w{u[0] - m.v[0], u[1] - m.v[1], u[2] - m.v[2]};
  const double ws = norm3(w), us = norm3(u), decay = std::exp(-dt / tau);
  Motion out;
  for (int i = 0; i < 3; ++i) {
    const double y = m.y[i] - tau * tau * c * (ws * w[i] - us * u[i]);
    const double k = m.v[i] + y / tau;
    out.y[i] = tau * tau * c * (ws * w[i] - us * u[i]) + (y + k * dt) * decay;
    out.v[i] = (m.v[i] - k * dt / tau) * decay;
  }
  return out;
}

TEST(UnderbrushAir, StepIsStableAtTheStiffestPartAndThirtyHertz) {
  // The stiffest built-in part: the smallest tau, at the shortest instance (tau s^2).
  double tau = 1e9, c = 0.0;
  std::string stiffest;
  for (const char* name : {"meadow_grass", "clover", "daisy", "fern"}) {
    impl::ComponentSpecies sp = impl::load_component_species(name);
    impl::Meadow m = impl::meadow_from_plantings(species_params({name}), planting_grid(1, 0.3));
    for (size_t p = 0; p < m.parts.size(); ++p) {
      const double s = 1.0 - m.parts[p].def.length_variation;
      if (m.parts[p].gpu.tau * s * s < tau) {
        tau = m.parts[p].gpu.tau * s * s;
        c = double(m.parts[p].gpu.drag_area) * m.parts[p].gpu.inv_mass * m.parts[p].gpu.air_coupling;
        stiffest = std::string(name) + " part " + std::to_string(p);
      }
    }
  }
  const double dt = 1.0 / 30.0;
  std::printf("    stiffest: %s, tau %.3g s, c %.3g 1/m\n", stiffest.c_str(), tau, c);
  // Its own air coupling, then couplings far past any built-in part's, up to an air
  // damping r c |u| dt of 100 at 40 m/s (where an explicit drag on the relative wind
  // would flip every step).
  for (double coupling : {c, 2.5 / 40.0, 25.0 / 40.0, 250.0 / 40.0, 2500.0 / 40.0}) {
    for (double speed : {0.0, 1.0, 5.0, 15.0, 40.0}) {
      const D3 u{speed, 0.0, 0.0};
      for (int axis : {0, 1}) {
        SCOPED_TRACE(testing::Message() << "r c " << coupling << ", speed " << speed << ", axis " << axis);
        // In calm air the drag is quadratic: a perturbation h adds r c h of damping, so h is
        // small there (and large enough elsewhere to stand out of the wind's float spacing).
        const double rho = spectral_radius(u, coupling, tau, dt, axis, speed == 0.0 ? 1e-7 : 1e-3);
        const double alpha = 1.0 / tau + coupling * speed * (axis == 0 ? 1.0 : 0.5), omega = 1.0 / tau;
        const std::complex<double> root = std::sqrt(std::complex<double>(alpha * alpha - omega * omega, 0.0));
        const double exact = std::abs(std::exp((-alpha + root) * dt));
        EXPECT_LE(rho, 1.0);
        EXPECT_NEAR(rho, exact, 2e-3);
      }
    }
  }
  const double explicit_rho = spectral_radius({40.0, 0.0, 0.0}, 250.0 / 40.0, tau, dt, 0, 1e-3, explicit_step);
  std::printf("    r c |u| dt 8.3 along a 40 m/s wind: spectral radius %.3f (explicit drag: %.3g)\n",
              spectral_radius({40.0, 0.0, 0.0}, 250.0 / 40.0, tau, dt, 0, 1e-3), explicit_rho);
  EXPECT_GT(explicit_rho, 1.0) << "the explicit drag this replaces";
}

// The kernel in a steady wind from rest, against the equation in double (each component
// with its own scale's tau), at 60 Hz and in long steps; and the rest it reaches is the
// tables' equilibrium under the wind (the relative wind of a resting blade is the wind).
void expect_equation(float dt, int steps, double tolerance) {
  const double speed = 6.0;
  auto world = meadow_world(float(speed));
  const auto plantings = planting_grid(2, 0.3);
  impl::Meadow m = impl::meadow_from_plantings(species_params({"meadow_grass"}), plantings);
  const boreas_meadow_id id = world->add_meadow(impl::meadow_from_plantings(species_params({"meadow_grass"}), plantings));
  std::vector<boreas_component> rest = world->meadow_components(id);
  const int n = m.count;
  const double c_load = double(m.parts[0].gpu.drag_area) * m.parts[0].gpu.inv_mass;
  const double c = c_load * m.parts[0].gpu.air_coupling;  // the equation's r c
  const double reach = m.parts[0].gpu.reach;
  std::vector<Motion> ref(rest.size());
  std::vector<D3> x0(rest.size());
  for (size_t i = 0; i < rest.size(); ++i) {
    BoreasV3 base = boreas_v3(rest[i].base[0], rest[i].base[1], rest[i].base[2]);
    BoreasV3 load = boreas_v3(float(c_load * speed * speed), -float(impl::kGravity), 0.0f);
    BoreasV3 t = impl::meadow_equilibrium(m, int(i), base, load, 0);
    x0[i] = {t.x, t.y, t.z};
    for (int a = 0; a < 3; ++a) ref[i].y[a] = rest[i].center_of_mass[a] - x0[i][a];
  }
  double worst = 0.0;
  for (int s = 1; s <= steps; ++s) {
    world->step(dt);
    std::vector<boreas_component> now = world->meadow_components(id);
    for (size_t i = 0; i < now.size(); ++i) {
      const double scale = impl::unpack_frame(m.index.data(), int(n), int(i)).scale;
      ref[i] = reference_step(ref[i], {speed, 0.0, 0.0}, c, m.parts[0].gpu.tau * scale * scale, dt);
      for (int a = 0; a < 3; ++a)
        worst = std::max(worst, std::fabs(now[i].center_of_mass[a] - (x0[i][a] + ref[i].y[a])) / reach);
    }
  }
  std::printf("    dt %.4g s: worst gap to the equation %.2g of the reach\n", double(dt), worst);
  EXPECT_LT(worst, tolerance);
  // Settled: at the tables' equilibrium under the wind itself.
  for (int s = 0; s < int(20.0 / dt); ++s) world->step(dt);
  std::vector<boreas_component> settled = world->meadow_components(id);
  for (size_t i = 0; i < settled.size(); ++i)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(settled[i].center_of_mass[a], x0[i][a], 1e-5 * reach) << i;
}

TEST(UnderbrushAir, KernelFollowsTheRelativeWindEquationInSteadyWind) { expect_equation(1.0f / 60.0f, 90, 2e-3); }
TEST(UnderbrushAir, KernelFollowsTheEquationInLongSteps) { expect_equation(0.4f, 6, 2e-2); }

// A blade twice as long (length_variation's scale 2: lengths doubled, width and thickness
// kept) under the same small load across it, per unit mass: its center of mass moves
// 2^4 = 16 times as far (a cantilever's deflection q L^4 / 8 E I with the load per length q
// the same, and the center of mass at a fixed share of it), by the kernel's lookup
// (boreas_ub_equilibrium at scale 2) and by the section solver for a part drawn twice as
// long, which the lookup matches.
TEST(UnderbrushLength, TwiceAsLongBendsByTheCantileverRatio) {
  impl::Meadow m = impl::meadow_from_plantings(species_params({"meadow_grass"}), planting_grid(1, 0.3));
  const impl::MeadowPart& part = m.parts[0];
  const BoreasGpuPart& g = part.gpu;
  // Small: 8 a stays in the tables' first norm cell, where the lookup is linear in a to
  // 0.4 % (the norm axis is linear in a / (a + a_ref)).
  const float a = 0.005f;
  auto lookup = [&](float scale) {
    BoreasUbPlane plane{0.0f, a, boreas_v3(1.0f, 0.0f, 0.0f)};
    return double(boreas_ub_equilibrium(m.tables.data(), g.forward, g.angles, g.norms, g.a_ref, g.q_max,
                                        boreas_v3(0.0f, 0.0f, 0.0f), boreas_v3(0.0f, 1.0f, 0.0f), plane,
                                        0.5f * BOREAS_UB_PI, a, scale)
                      .x);
  };
  const double d1 = lookup(1.0f), d2 = lookup(2.0f);
  const impl::ComponentSpecies& sp = m.params.species[0];
  impl::PartDef twice = part.def;
  twice.length *= 2.0;
  const impl::BentShape b1 = impl::bend_under_load(impl::part_sections(sp.tissue, part.def), M_PI / 2, a);
  const impl::BentShape b2 = impl::bend_under_load(impl::part_sections(sp.tissue, twice), M_PI / 2, a);
  std::printf("    deflection ratio: lookup %.3f, solver %.3f (16); scale 2: lookup %.4g m, solver %.4g m\n",
              d2 / d1, b2.com_v / b1.com_v, d2, b2.com_v);
  EXPECT_NEAR(d2 / d1, 16.0, 0.16);
  EXPECT_NEAR(b2.com_v / b1.com_v, 16.0, 0.16);
  // The lookup's own error (the table's first cell) is the same at both scales.
  std::printf("    lookup over solver: %.4f at scale 1, %.4f at scale 2\n", d1 / b1.com_v, d2 / b2.com_v);
  EXPECT_NEAR(d2 / b2.com_v, d1 / b1.com_v, 0.01);
  EXPECT_NEAR(d2, b2.com_v, 0.05 * b2.com_v);
}

}  // namespace
}  // namespace boreas
