// Texture generator tests: the HL2 basis, the least-squares fit (exact for intensities
// linear in the light direction, optimal otherwise) and the back-lit leaf intensity it is
// fitted to.
#include "textures/hl2_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "textures/leaf_translucency.h"
#include "textures/texture_error.h"
#include "textures/thin_slab.h"

namespace boreas::render {
namespace {

const SlabOptics kGreen = default_leaf_optics().rgb[1];
const glm::dvec3 kUp(0.0, 0.0, 1.0);
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 direction(double polar_deg, double azimuth_deg) {
  double t = polar_deg * kPi / 180.0, p = azimuth_deg * kPi / 180.0;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

double rms(const Hl2Fitter& fitter, const LeafTranslucency& model, double d, glm::dvec3 n) {
  double sum = 0.0;
  for (const glm::dvec3& w : fitter.directions()) sum += std::pow(model.intensity(d, n, w), 2);
  return std::sqrt(sum / fitter.directions().size());
}

TEST(Hl2Basis, IsOrthonormalAndEvenlyAroundTheNormal) {
  const auto& b = hl2_basis();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(glm::dot(b[i], b[j]), i == j ? 1.0 : 0.0, 1e-15) << i << " " << j;
    }
    EXPECT_NEAR(glm::dot(b[i], kUp), 1.0 / std::sqrt(3.0), 1e-15) << i;
  }
  // The sum of the three is sqrt(3) z: a texel with equal coefficients c has I(w) = c sqrt3 w.z.
  glm::dvec3 sum = b[0] + b[1] + b[2];
  EXPECT_NEAR(glm::length(sum - std::sqrt(3.0) * kUp), 0.0, 1e-15);
}

TEST(Hl2Fit, RecoversAnIntensityLinearInTheDirectionExactly) {
  const glm::dvec3 g(0.31, -0.72, 1.4);
  const auto& b = hl2_basis();
  for (auto [rings, sectors] : {std::pair{1, 3}, std::pair{16, 6}, std::pair{9, 13}}) {
    Hl2Fitter fitter(rings, sectors);
    Hl2Coefficients c = fitter.fit([&](const glm::dvec3& w) { return glm::dot(g, w); });
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(c[i], glm::dot(b[i], g), 1e-12) << rings << "x" << sectors;
    EXPECT_LT(fitter.rms_residual(c, [&](const glm::dvec3& w) { return glm::dot(g, w); }), 1e-12);
    EXPECT_NEAR(hl2_evaluate(c, direction(30, 70)), glm::dot(g, direction(30, 70)), 1e-12);
  }
}

TEST(Hl2Fit, IsTheLeastSquaresOptimumForTheLeafIntensity) {
  Hl2Fitter fitter;
  LeafTranslucency model(kGreen);
  glm::dvec3 n = glm::normalize(glm::dvec3(0.2, -0.1, 1.0));
  auto intensity = [&](const glm::dvec3& w) { return model.intensity(0.25, n, w); };
  Hl2Coefficients best = fitter.fit(intensity);
  double best_residual = fitter.rms_residual(best, intensity);
  for (int i = 0; i < 3; ++i) {
    for (double step : {-1e-3, 1e-3}) {
      Hl2Coefficients moved = best;
      moved[i] += step;
      EXPECT_GT(fitter.rms_residual(moved, intensity), best_residual) << i << " " << step;
    }
  }
}

TEST(Hl2Fit, LeafResidualStaysUnderTheStatedBound) {
  // Three coefficients can only hold I(w) = dot(g, w), linear in w, while the leaf's
  // I = cos(theta) T(d / cos(theta)) falls off faster than cos(theta): the fit is a rough,
  // low-frequency one (the paper says as much). Measured relative RMS residuals with the
  // default sampling: 0.475 for the lamina, 0.664 for the midrib; 0.172 for the lamina with
  // refraction into the leaf (index 1.45), whose paths are shorter at grazing angles.
  Hl2Fitter fitter;
  LeafTranslucency plain(kGreen), refracting(kGreen, 1.45);
  struct Case {
    const LeafTranslucency* model;
    double d;
    glm::dvec3 n;
    double bound;
  };
  for (const Case& k : {Case{&plain, 0.2, kUp, 0.5}, Case{&plain, 0.5, kUp, 0.7},
                        Case{&plain, 0.2, glm::normalize(glm::dvec3(0.3, 0.1, 1.0)), 0.5},
                        Case{&refracting, 0.2, kUp, 0.2}}) {
    auto intensity = [&](const glm::dvec3& w) { return k.model->intensity(k.d, k.n, w); };
    Hl2Coefficients c = fitter.fit(intensity);
    double relative = fitter.rms_residual(c, intensity) / rms(fitter, *k.model, k.d, k.n);
    EXPECT_LT(relative, k.bound) << k.d;
    EXPECT_GT(relative, 0.5 * k.bound) << "the bound is stale: " << k.d;
  }
}

TEST(Hl2Fit, DefaultSamplingIsWithinOnePercentOfADenseFit) {
  Hl2Fitter coarse, dense(64, 128);
  LeafTranslucency model(kGreen);
  for (double d : {0.2, 0.3, 0.5}) {
    for (glm::dvec3 n : {kUp, glm::normalize(glm::dvec3(0.35, 0.0, 1.0)),
                         glm::normalize(glm::dvec3(-0.2, 0.5, 1.0))}) {
      Hl2Coefficients a = model.coefficients(coarse, d, n), b = model.coefficients(dense, d, n);
      double diff = 0.0, norm = 0.0;
      for (int i = 0; i < 3; ++i) {
        diff += (a[i] - b[i]) * (a[i] - b[i]);
        norm += b[i] * b[i];
      }
      EXPECT_LT(std::sqrt(diff / norm), 0.01) << d << " " << n.x << " " << n.y;
    }
  }
}

TEST(LeafTranslucency, LightStraightFromBehindIsBrightest) {
  Hl2Fitter fitter;
  LeafTranslucency model(kGreen);
  Hl2Coefficients c = model.coefficients(fitter, 0.2, kUp);
  double straight = model.intensity(0.2, kUp, kUp);
  double fitted_straight = hl2_evaluate(c, kUp);
  EXPECT_NEAR(straight, kReferenceTransmittance[1], 2e-6);
  for (double polar : {5.0, 20.0, 45.0, 70.0, 89.0}) {
    for (double azimuth : {0.0, 60.0, 135.0, 250.0}) {
      glm::dvec3 w = direction(polar, azimuth);
      EXPECT_LT(model.intensity(0.2, kUp, w), straight) << polar << " " << azimuth;
      EXPECT_LT(hl2_evaluate(c, w), fitted_straight) << polar << " " << azimuth;
    }
  }
}

TEST(LeafTranslucency, ThickerVeinsTransmitLessThanLamina) {
  Hl2Fitter fitter;
  LeafTranslucency model(kGreen);
  double previous = 1.0;
  for (double d : {0.2, 0.3, 0.5, 0.9}) {
    double straight = hl2_evaluate(model.coefficients(fitter, d, kUp), kUp);
    EXPECT_GT(straight, 0.0) << d;
    EXPECT_LT(straight, previous) << d;
    previous = straight;
  }
}

TEST(LeafTranslucency, TiltedNormalTiltsTheFittedLobe) {
  Hl2Fitter fitter;
  LeafTranslucency model(kGreen);
  glm::dvec3 n = glm::normalize(glm::dvec3(0.4, 0.0, 1.0));
  Hl2Coefficients c = model.coefficients(fitter, 0.2, n);
  EXPECT_GT(hl2_evaluate(c, direction(40, 0)), hl2_evaluate(c, direction(40, 180)));
  EXPECT_GT(hl2_evaluate(c, n), hl2_evaluate(c, kUp));
  // A flat texel's three coefficients are equal (its lobe is symmetric about +Z).
  Hl2Coefficients flat = model.coefficients(fitter, 0.2, kUp);
  EXPECT_NEAR(flat[0], flat[2], 1e-12);
  EXPECT_NEAR(flat[1], flat[2], 1e-12);
}

TEST(LeafTranslucency, LightGrazingOrBehindTheFacetPassesNothing) {
  LeafTranslucency model(kGreen);
  glm::dvec3 n = glm::normalize(glm::dvec3(0.5, 0.0, 1.0));
  EXPECT_EQ(model.intensity(0.2, n, direction(80, 180)), 0.0);
  EXPECT_GT(model.intensity(0.2, n, direction(80, 0)), 0.0);
  EXPECT_THROW(LeafTranslucency(kGreen, 0.5), TextureError);
  EXPECT_THROW(Hl2Fitter(4, 2), TextureError);
}

}  // namespace
}  // namespace boreas::render
