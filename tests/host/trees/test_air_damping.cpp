// boreas tests: the drag's aerodynamic damping in damped mode (cl/shared/tree_math.h,
// boreas_damped_step; host/src/reference/tree_reference.cpp, branch_step). The step's
// spectral radius (its amplification of a small perturbation about a steady bend, from the
// step functions themselves: the double reference by finite differences, the device's
// shared header at width 1 by its columns) stays below 1 at omega 100 rad/s, dt 1/30 s, over
// zeta_air omega dt from 0.01 to 100, where the explicit rate it replaced passes 1; the
// shared header agrees with the reference step by step; a stiff leafy twig in a storm at
// 30 Hz follows its gusts without jitter (step-to-step reversals of its bend's change).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <glm/glm.hpp>

// The device's math as a CPU device builds it (polynomial exp2, log2, sin).
#define BOREAS_FAST_MATH 1
#include "reference/tree_reference.h"
#include "shared/tree_math.h"

namespace boreas {
namespace {

namespace ref = impl::reference;
using glm::dvec3;

constexpr double kOmega = 100.0, kZeta = 0.1, kDt = 1.0 / 30.0, kW2 = 0.48;

// A straight 1 m twig on a vertical parent, damped, under the drag load whose compliance
// makes the across-wind air damping zeta_air omega dt = `air_dt` at wind speed `speed`
// (zeta_air omega = omega^2 (1 + w2) drag |u| R / 2; R = 1 below vogel_speed).
ref::BranchShape twig(double air_dt, double speed, double vogel_b = 0.0, double vogel_speed = 1e9) {
  ref::BranchShape s;
  for (int k = 0; k < 4; ++k) s.local[k] = dvec3(k / 3.0, 0.0, 0.0);
  s.v = 1.0;
  s.w2 = kW2;
  s.omega = kOmega;
  s.zeta = kZeta;
  s.vogel_b = vogel_b;
  s.vogel_speed = vogel_speed;
  const double r = speed > vogel_speed ? std::pow(speed / vogel_speed, vogel_b) : 1.0;
  s.drag = air_dt / (kDt * 0.5 * kOmega * kOmega * (1.0 + kW2) * speed * r);
  return s;
}

ref::Branch parent() {
  ref::Branch p;
  p.curve.p = {dvec3(0.0), dvec3(0.0, 1.0 / 3.0, 0.0), dvec3(0.0, 2.0 / 3.0, 0.0), dvec3(0.0, 1.0, 0.0)};
  p.o = dvec3(1.0, 0.0, 0.0);
  return p;
}

// (F, dF/dt) -> the same after one step, for one axis pair of a 6-state map.
using Step = std::function<void(dvec3* f, dvec3* df)>;

// The spectral radius of the step's 2x2 block (F_i, dF_i/dt) about (f0, 0), by central
// differences (the step is linear in the perturbation, so h only needs to stay small
// against the bend); also checks that axis i does not leak into the others.
double spectral_radius(const Step& step, const dvec3& f0, int axis, double h) {
  double j[2][2];
  for (int col = 0; col < 2; ++col) {
    dvec3 out[2][2];
    for (int sign = 0; sign < 2; ++sign) {
      dvec3 f = f0, df(0.0);
      (col == 0 ? f : df)[axis] += sign == 0 ? h : -h;
      step(&f, &df);
      out[sign][0] = f;
      out[sign][1] = df;
    }
    for (int row = 0; row < 2; ++row) {
      const dvec3 d = (out[0][row] - out[1][row]) / (2.0 * h);
      j[row][col] = d[axis];
      for (int other = 0; other < 3; ++other)
        if (other != axis) EXPECT_NEAR(d[other], 0.0, 1e-6 * (1.0 + std::abs(d[axis])));
    }
  }
  // Eigenvalues of a 2x2: tr/2 +- sqrt(tr^2/4 - det).
  const double tr = j[0][0] + j[1][1], det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr / 4.0 - det, 0.0));
  return std::max(std::abs(tr / 2.0 + root), std::abs(tr / 2.0 - root));
}

// The reference's step of one branch in a steady wind.
Step reference_step(const ref::BranchShape& shape, const dvec3& wind) {
  return [shape, wind](dvec3* f, dvec3* df) {
    ref::Motion m;
    m.f = *f;
    m.df = *df;
    ref::branch_step(parent(), shape, wind, ref::response_step(shape.omega, shape.zeta, kDt), &m, kDt);
    *f = m.f;
    *df = m.df;
  };
}

// The step it replaced, for contrast: the drag taken on the wind relative to the tip with
// the last step's rate (clamped to the wind's speed), then the structural exact step.
Step explicit_rate_step(const ref::BranchShape& shape, const dvec3& wind) {
  return [shape, wind](dvec3* f, dvec3* df) {
    dvec3 tip = (1.0 + shape.w2) * *df;
    const double ws = glm::length(wind), ts = glm::length(tip);
    if (ts > ws) tip *= ws / ts;
    const dvec3 w = wind - tip;
    const dvec3 target = shape.drag * glm::length(w) * w;
    const ref::Response r = ref::response_step(shape.omega, shape.zeta, kDt);
    const dvec3 x = *f - target, u = *df;
    *f = target + r.a * x + r.b * u;
    *df = r.c * x + r.d * u;
  };
}

// The device's step at width 1 (float), as tree_step.cl calls it.
struct DeviceStep {
  float ra, rb, rc, rd;
  ref::BranchShape shape;
  BoreasV3 wind;

  DeviceStep(const ref::BranchShape& s, const dvec3& w) : shape(s) {
    const ref::Response r = ref::response_step(s.omega, s.zeta, kDt);
    ra = float(r.a), rb = float(r.b), rc = float(r.c), rd = float(r.d);
    wind = boreas_v3(float(w.x), float(w.y), float(w.z));
  }
  void operator()(dvec3* f, dvec3* df) const {
    const BoreasV3 target = boreas_bend_target(wind, 0.0f, float(shape.drag), float(shape.vogel_b),
                                               float(1.0 / shape.vogel_speed));
    const BoreasV3 x = boreas_v3_sub(boreas_v3(float(f->x), float(f->y), float(f->z)), target);
    const BoreasV3 u = boreas_v3(float(df->x), float(df->y), float(df->z));
    BoreasV3 x_next, rate;
    boreas_damped_step(x, u, ra, rb, rc, rd, float(kZeta * kOmega * kDt), float(kOmega * kDt),
                       float(kDt), float(kOmega * kOmega * kDt), wind,
                       float((1.0 + shape.w2) * shape.drag), float(shape.vogel_b),
                       float(1.0 / shape.vogel_speed), &x_next, &rate);
    const BoreasV3 bend = boreas_v3_add(target, x_next);
    *f = dvec3(bend.x, bend.y, bend.z);
    *df = dvec3(rate.x, rate.y, rate.z);
  }
};

const double kSweep[] = {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 30.0, 100.0};

TEST(AirDamping, SpectralRadiusBelowOneAtOmega100Dt30OverTheWholeSweep) {
  const double speed = 20.0;
  const dvec3 wind(speed, 0.0, 0.0);
  for (double air_dt : kSweep) {
    for (double vogel_b : {0.0, -0.7}) {
      SCOPED_TRACE(testing::Message() << "zeta_air omega dt " << air_dt << ", Vogel " << vogel_b);
      const ref::BranchShape s = twig(air_dt, speed, vogel_b, vogel_b == 0.0 ? 1e9 : 5.0);
      const dvec3 steady = glm::length(wind) * s.drag *
                           (vogel_b == 0.0 ? 1.0 : std::pow(speed / 5.0, vogel_b)) * wind;
      const double h = 1e-6 * glm::length(steady);
      for (int axis : {0, 2}) {  // along the wind, across it
        const double rho = spectral_radius(reference_step(s, wind), steady, axis, h);
        EXPECT_LT(rho, 1.0) << "reference, axis " << axis;
        // The continuous oscillator's: max |e^(lambda dt)|, lambda = -alpha +- sqrt(alpha^2 -
        // omega^2), alpha = (zeta + zeta_air (2 + b' along the wind, 1 across)) omega.
        const double along = axis == 0 ? 2.0 + (vogel_b == 0.0 ? 0.0 : vogel_b) : 1.0;
        const double alpha = kZeta * kOmega + along * air_dt / kDt;
        const std::complex<double> root = std::sqrt(std::complex<double>(alpha * alpha - kOmega * kOmega, 0.0));
        EXPECT_NEAR(rho, std::abs(std::exp((-alpha + root) * kDt)), 1e-6 * (1.0 + rho)) << "axis " << axis;
        // The device's step is linear in (x, u): its columns from a unit perturbation.
        const double rho_device = spectral_radius(DeviceStep(s, wind), steady, axis, 1e-2 * glm::length(steady));
        EXPECT_LT(rho_device, 1.0) << "device, axis " << axis;
        EXPECT_NEAR(rho_device, rho, 2e-3) << "axis " << axis;
      }
      if (vogel_b != 0.0) continue;
      // The explicit rate it replaced, for contrast.
      const double rho_explicit = spectral_radius(explicit_rate_step(s, wind), steady, 0, h);
      std::printf("    zeta_air omega dt %g: spectral radius along the wind %.4f, across %.4f (explicit rate: %.4f)\n",
                  air_dt, spectral_radius(reference_step(s, wind), steady, 0, h),
                  spectral_radius(reference_step(s, wind), steady, 2, h), rho_explicit);
      if (air_dt >= 5.0) EXPECT_GT(rho_explicit, 1.0);
    }
  }
}

// Heavy air damping makes the twig creep toward its load, a real eigenvalue near 1 that no
// step flips: the radius is set by the slow mode e^-(omega^2 / 2 alpha) dt, not by the
// spring's phase over the step.
TEST(AirDamping, HeavilyDampedTwigCreepsWithoutFlipping) {
  const dvec3 wind(20.0, 0.0, 0.0);
  const ref::BranchShape s = twig(100.0, 20.0);
  ref::Motion m;  // from rest toward its load
  const dvec3 target = 20.0 * s.drag * wind;
  double last = 0.0;
  for (int step = 0; step < 30; ++step) {
    ref::branch_step(parent(), s, wind, ref::response_step(s.omega, s.zeta, kDt), &m, kDt);
    ASSERT_GE(m.f.x, last) << "step " << step;  // monotone: no flip
    ASSERT_LE(m.f.x, target.x * (1.0 + 1e-12)) << "step " << step;
    last = m.f.x;
  }
}

// Step-to-step reversals of the along-wind bend's change over `steps` at 30 Hz, in a storm
// of 25 m/s gusting by 8 m/s at 0.5 Hz (about two reversals a gust).
int reversals(const Step& step, int steps) {
  dvec3 f(0.0), df(0.0);
  double last_change = 0.0;
  int count = 0;
  for (int i = 0; i < steps; ++i) {
    const double before = f.x;
    step(&f, &df);
    const double change = f.x - before;
    if (i > 0 && change * last_change < 0.0) ++count;
    last_change = change;
    if (!std::isfinite(f.x)) return 1 << 20;
  }
  return count;
}

TEST(AirDamping, StiffLeafyTwigInAStormAt30HzDoesNotJitter) {
  const int steps = 300;  // 10 s, 5 gusts
  for (double air_dt : {1.0, 5.0, 30.0}) {
    SCOPED_TRACE(testing::Message() << "zeta_air omega dt at 25 m/s " << air_dt);
    const ref::BranchShape s = twig(air_dt, 25.0);
    int t = 0;
    auto gusty = [&](const std::function<Step(const dvec3&)>& make) -> Step {
      return [&, make](dvec3* f, dvec3* df) {
        const dvec3 wind(25.0 + 8.0 * std::sin(2.0 * 3.14159265358979 * 0.5 * t * kDt), 0.0, 3.0);
        ++t;
        make(wind)(f, df);
      };
    };
    t = 0;
    const int ref_count = reversals(gusty([&](const dvec3& w) { return reference_step(s, w); }), steps);
    t = 0;
    const int device_count = reversals(gusty([&](const dvec3& w) { return Step(DeviceStep(s, w)); }), steps);
    t = 0;
    const int explicit_count = reversals(gusty([&](const dvec3& w) { return explicit_rate_step(s, w); }), steps);
    std::printf("    zeta_air omega dt %g: reversals %d (reference), %d (device), %d (explicit rate)\n", air_dt,
                ref_count, device_count, explicit_count);
    EXPECT_LE(ref_count, 12);
    EXPECT_LE(device_count, 12);
    if (air_dt >= 5.0) EXPECT_GT(explicit_count, 100);  // the jitter this replaced
  }
}

// The device's step against the reference's, step by step, in a turning wind.
TEST(AirDamping, SharedHeaderMatchesReferenceStepByStep) {
  for (double air_dt : kSweep) {
    SCOPED_TRACE(air_dt);
    const ref::BranchShape s = twig(air_dt, 15.0, -0.6, 8.0);
    dvec3 f_ref(0.0), df_ref(0.0), f_dev(0.0), df_dev(0.0);
    for (int i = 0; i < 60; ++i) {
      const double a = 0.2 * i;
      const dvec3 wind(15.0 * std::cos(a), 1.0, 15.0 * std::sin(a) + 3.0);
      reference_step(s, wind)(&f_ref, &df_ref);
      DeviceStep(s, wind)(&f_dev, &df_dev);
      const double size = glm::length(s.drag * 15.0 * wind) + 1e-12;
      ASSERT_LT(glm::length(f_dev - f_ref), 2e-4 * size) << "step " << i;
      // Carry on from the reference's state so that errors do not compound.
      f_dev = f_ref;
      df_dev = df_ref;
    }
  }
}

}  // namespace
}  // namespace boreas
