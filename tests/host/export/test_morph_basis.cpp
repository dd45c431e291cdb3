// boreas tests: the morph basis of the animated glTF (host/gltf/morph_basis.h): Jacobi's
// eigenvectors against a matrix with known ones, a motion of two shapes kept in two
// targets, and every fit replayed as a viewer adds int16 targets: within the tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "morph_basis.h"

namespace boreas::gltf {
namespace {

// What a viewer draws from the fit at key k, minus the residual it was fitted to.
double replay_error(const std::vector<std::vector<float>>& keys, const MorphTargets& fit,
                    const std::array<double, 3>& extent) {
  double most = 0.0;
  for (size_t k = 0; k < keys.size(); ++k)
    for (size_t v = 0; v < keys[k].size() / 3; ++v) {
      double d2 = 0.0;
      for (size_t a = 0; a < 3; ++a) {
        double x = 0.0;
        for (size_t i = 0; i < fit.targets.size(); ++i)
          x += double(fit.weights[k][i]) * (fit.targets[i][3 * v + a] / double(fit.levels[i])) * extent[a];
        d2 += (x - keys[k][3 * v + a]) * (x - keys[k][3 * v + a]);
      }
      most = std::max(most, std::sqrt(d2));
    }
  return most;
}

TEST(MorphBasis, JacobiFindsKnownEigenvectorsLargestFirst) {
  // diag(1, 3, 2) turned by a rotation about z by 30 degrees: columns of R are the vectors.
  const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
  const double r[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  const double l[3] = {1, 3, 2};
  std::vector<double> a(9, 0.0);
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j)
      for (size_t k = 0; k < 3; ++k) a[i * 3 + j] += r[i][k] * l[k] * r[j][k];
  const std::vector<std::vector<double>> v = symmetric_eigenvectors(a, 3);
  const size_t order[3] = {1, 2, 0};  // eigenvalues 3, 2, 1
  for (size_t e = 0; e < 3; ++e) {
    double dot = 0.0;
    for (size_t i = 0; i < 3; ++i) dot += v[e][i] * r[i][order[e]];
    EXPECT_NEAR(std::abs(dot), 1.0, 1e-12) << "eigenvector " << e;
  }
}

TEST(MorphBasis, TwoShapesSwayingTakeTwoTargets) {
  // 500 vertices, 40 keys: two fixed shapes with incommensurate sways (rank 2).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<double> a(1500), b(1500);
  for (size_t i = 0; i < a.size(); ++i) a[i] = u(rng), b[i] = u(rng);
  std::vector<std::vector<float>> keys(40, std::vector<float>(1500));
  for (size_t k = 0; k < keys.size(); ++k)
    for (size_t i = 0; i < 1500; ++i)
      keys[k][i] = float(std::sin(0.37 * k) * a[i] + std::cos(1.3 * k + 0.2) * b[i]);
  const std::array<double, 3> extent{5.0, 2.0, 5.0};
  const MorphTargets fit = fit_morph_targets(keys, extent, 1e-3);
  EXPECT_EQ(fit.targets.size(), 2u);
  EXPECT_LE(fit.max_error, 1e-3);
  EXPECT_NEAR(replay_error(keys, fit, extent), fit.max_error, 1e-6) << "the error it reports is the replay's";
  for (int levels : fit.levels) EXPECT_EQ(levels, 32767) << "20 cm shapes need 16 bits for 1 mm";
  // At 5 cm they round finely enough at 8 bits (a step of 0.4 m / 127 = 3 mm).
  const MorphTargets loose = fit_morph_targets(keys, extent, 5e-2);
  EXPECT_LE(loose.max_error, 5e-2);
  EXPECT_NEAR(replay_error(keys, loose, extent), loose.max_error, 1e-6);
  EXPECT_GE(std::count(loose.levels.begin(), loose.levels.end(), 127), 1) << "int8 targets";
}

TEST(MorphBasis, ANoisyMotionMeetsTheToleranceWithAtMostATargetAKey) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.05);
  std::vector<std::vector<float>> keys(12, std::vector<float>(900));
  for (std::vector<float>& key : keys)
    for (float& x : key) x = float(n(rng));
  const std::array<double, 3> extent{1.0, 1.0, 1.0};
  const MorphTargets fit = fit_morph_targets(keys, extent, 1e-3);
  EXPECT_LE(fit.targets.size(), keys.size());
  EXPECT_LE(fit.max_error, 1e-3);
  EXPECT_LE(replay_error(keys, fit, extent), 1e-3 + 1e-6);
  const MorphTargets still = fit_morph_targets(std::vector<std::vector<float>>(5, std::vector<float>(9, 0.0f)),
                                               extent, 1e-3);
  EXPECT_TRUE(still.targets.empty()) << "no motion, no targets";
}

}  // namespace
}  // namespace boreas::gltf
