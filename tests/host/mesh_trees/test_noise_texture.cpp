// boreas tests: the tiling 1/f^beta noise texture — its spectrum slope, seamless tiling,
// two normalized uncorrelated channels, determinism, the bilinear lookup, bad arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "errors.h"
#include "mesh_trees/noise_texture.h"
#include "support/expect_error.h"

namespace boreas::test {
namespace {

using impl::NoiseTexture;

constexpr double kPi = 3.14159265358979323846;

double texel(const NoiseTexture& noise, int x, int y, int channel) {
  return noise.texels[2 * (size_t(y) * noise.size + x) + channel];
}

double mean(const std::vector<double>& a) {
  double s = 0.0;
  for (double x : a) s += x;
  return s / double(a.size());
}

double rms(const std::vector<double>& a) {
  double s = 0.0;
  for (double x : a) s += x * x;
  return std::sqrt(s / double(a.size()));
}

std::vector<double> channel_values(const NoiseTexture& noise, int channel) {
  std::vector<double> out;
  for (size_t i = 0; i < noise.texels.size() / 2; ++i) out.push_back(noise.texels[2 * i + channel]);
  return out;
}

// Pearson's r of the two channels over the whole tile.
double channel_correlation(const NoiseTexture& noise) {
  const std::vector<double> a = channel_values(noise, 0), b = channel_values(noise, 1);
  const double ma = mean(a), mb = mean(b);
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

// Least-squares slope of log power against log k over k = lo..hi.
double log_log_slope(const std::vector<double>& power, int lo, int hi) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const int n = hi - lo + 1;
  for (int k = lo; k <= hi; ++k) {
    const double x = std::log(double(k)), y = std::log(power[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// RMS of the neighbour differences of one channel across the seam (the last column to the
// first, or the last row to the first) over the RMS of those inside an n x n window of the
// texture whose corner is (0, 0), treated as if it were the whole tile.
double seam_to_interior_ratio(const NoiseTexture& noise, int n, int channel, bool across_x) {
  auto at = [&](int i, int j) {
    return across_x ? texel(noise, i, j, channel) : texel(noise, j, i, channel);
  };
  std::vector<double> seam, interior;
  for (int j = 0; j < n; ++j) {
    seam.push_back(at(0, j) - at(n - 1, j));
    for (int i = 0; i + 1 < n; ++i) interior.push_back(at(i + 1, j) - at(i, j));
  }
  return rms(seam) / rms(interior);
}

TEST(NoiseTexture, FieldSpectrumFallsWithSlopeMinusBetaMinusOne) {
  // The 2D field is made with radial power |k|^-(beta + 1), so that its lines have 1/f^beta
  // (next test). Tolerance 0.15: each frequency's power is A^2 (1 + cos psi) / 2 with psi
  // the sum of the random phases at k and -k, so annulus k (about 2 pi k frequencies)
  // scatters by roughly 1/sqrt(pi k), 28% at k = 2; over k = 2..64 the fitted slopes of many
  // seeds land within 0.08 of the exponent. A wrong amplitude exponent (|k|^-beta, or the
  // line's beta given to the field) is off by 0.5 at least here.
  for (double beta : {1.0, 2.0, 3.0}) {
    const NoiseTexture noise = impl::make_noise_texture(256, beta, 17);
    for (int channel = 0; channel < 2; ++channel) {
      const double slope = log_log_slope(impl::radial_power_spectrum(noise, channel), 2, 64);
      EXPECT_NEAR(slope, -(beta + 1.0), 0.15) << "beta " << beta << ", channel " << channel;
    }
  }
}

// The power spectrum of the lines a branch reads over time (x at fixed y: the kernel moves
// u, a branch's phase, by its level's clock), averaged over every line and both channels:
// the periodogram |DFT|^2 of each line, k = 0..n/2.
std::vector<double> line_power_spectrum(const NoiseTexture& noise) {
  const int n = noise.size;
  std::vector<double> power(size_t(n / 2 + 1), 0.0);
  for (int channel = 0; channel < 2; ++channel)
    for (int y = 0; y < n; ++y)
      for (int k = 0; k <= n / 2; ++k) {
        double re = 0.0, im = 0.0;
        for (int x = 0; x < n; ++x) {
          const double phase = -2.0 * kPi * k * x / n;
          re += texel(noise, x, y, channel) * std::cos(phase);
          im += texel(noise, x, y, channel) * std::sin(phase);
        }
        power[size_t(k)] += (re * re + im * im) / (2.0 * n);
      }
  return power;
}

TEST(NoiseTexture, EachBranchSwaysWithOneOverFToTheBeta) {
  // Kusternig's 1/f^beta is the spectrum of a branch's motion over time. A line of the
  // field is a sum over k_y of the field's columns, each of power (k_x^2 + k_y^2)^-(beta+1)/2,
  // which falls as k_x^-beta for k_x well inside the tile (k = 2..32 here; the sum over a
  // finite k_y range steepens it slightly near n/2). 256 lines of 2 channels average away
  // most of the scatter; 0.15 separates it from the field's beta + 1 and from beta - 1.
  for (double beta : {1.0, 2.0, 3.0}) {
    const NoiseTexture noise = impl::make_noise_texture(128, beta, 5);
    const double slope = log_log_slope(line_power_spectrum(noise), 2, 32);
    std::printf("    beta %.1f: a line's periodogram falls with slope %.3f\n", beta, slope);
    EXPECT_NEAR(slope, -beta, 0.15) << "beta " << beta;
  }
}

TEST(NoiseTexture, PowerSpectrumHasNoMeanAndSumsToTheMeanSquare) {
  const NoiseTexture noise = impl::make_noise_texture(64, 2.0, 3);
  const std::vector<double> power = impl::radial_power_spectrum(noise, 0);
  ASSERT_EQ(power.size(), 33u);
  EXPECT_LT(power[0], 1e-12);  // zero mean: nothing at |f| = 0
  // Parseval: the powers of all frequencies sum to the channel's mean square, 1, less what
  // lies in the corners beyond |f| = 32.5 (little, for a spectrum falling as 1/f^2). Each
  // frequency inside the annuli adds its annulus's mean: together, the annuli's total.
  double total = 0.0;
  for (int iy = 0; iy < 64; ++iy) {
    for (int ix = 0; ix < 64; ++ix) {
      const int kx = ix < 32 ? ix : ix - 64, ky = iy < 32 ? iy : iy - 64;
      const int k = int(std::floor(std::sqrt(double(kx * kx + ky * ky)) + 0.5));
      if (k <= 32) total += power[k];
    }
  }
  EXPECT_GT(total, 0.95);
  EXPECT_LE(total, 1.0 + 1e-6);
}

TEST(NoiseTexture, TilesSeamlessly) {
  const NoiseTexture noise = impl::make_noise_texture(64, 2.0, 5);
  for (auto [u, v] : {std::pair{0.37, 0.81}, {0.0, 0.0}, {0.999, 0.013}, {0.5, 0.25}}) {
    double base[2], moved[2];
    impl::sample_noise(noise, u, v, base);
    for (auto [du, dv] : {std::pair{1.0, 0.0}, {0.0, 1.0}, {3.0, -2.0}}) {
      impl::sample_noise(noise, u + du, v + dv, moved);
      for (int c = 0; c < 2; ++c) {
        // Not bit-equal: u + 3 - floor(u + 3) may differ from u in its last bit.
        EXPECT_NEAR(moved[c], base[c], 1e-12)
            << "(" << u << ", " << v << ") + (" << du << ", " << dv << "), channel " << c;
      }
    }
  }
}

TEST(NoiseTexture, SeamDifferencesMatchInteriorDifferences) {
  // 256 rows of seam differences give the seam RMS to about 1/sqrt(2 * 256), 4.4%: 25% is
  // more than five times that (100 seeds give 0.86..1.15). A 1/f^2 field that does not
  // tile jumps at the seam as if the two sides were far apart: a 128-texel window of the
  // tile fails the same bound (100 seeds give 1.47 and more).
  const NoiseTexture noise = impl::make_noise_texture(256, 2.0, 11);
  for (int channel = 0; channel < 2; ++channel) {
    for (bool across_x : {true, false}) {
      EXPECT_NEAR(seam_to_interior_ratio(noise, 256, channel, across_x), 1.0, 0.25)
          << "channel " << channel << (across_x ? ", last column to first" : ", last row to first");
      // Control: the same measure sees the jump in a window that does not tile.
      EXPECT_GT(seam_to_interior_ratio(noise, 128, channel, across_x), 1.25)
          << "channel " << channel << (across_x ? ", across x" : ", across y");
    }
  }
}

TEST(NoiseTexture, ChannelsHaveZeroMeanUnitRms) {
  for (double beta : {0.0, 2.0, 4.0}) {
    const NoiseTexture noise = impl::make_noise_texture(64, beta, 23);
    EXPECT_EQ(noise.size, 64);
    EXPECT_EQ(noise.beta, beta);
    ASSERT_EQ(noise.texels.size(), 2u * 64 * 64);
    for (int c = 0; c < 2; ++c) {
      // Normalized in double, stored as float: off by float rounding only.
      EXPECT_NEAR(mean(channel_values(noise, c)), 0.0, 1e-6) << "beta " << beta << ", " << c;
      EXPECT_NEAR(rms(channel_values(noise, c)), 1.0, 1e-6) << "beta " << beta << ", " << c;
    }
  }
}

TEST(NoiseTexture, ChannelsAreUncorrelated) {
  // The correlation on one tile is sum over the pairs (k, -k) of A_k^2 sin(2 psi_k) over
  // sum A_k^2 (psi_k the mean of the pair's phases): zero in expectation, but a steep
  // spectrum leaves few frequencies to average. Its scatter is 0.007 for a field of radial
  // exponent 1 (beta = 0), 0.07 for 2 (beta = 1) and 0.2 for 3 (beta = 2, the default:
  // one tree's two sway channels are that correlated by chance), size 256, where one tile
  // is no test: there the test takes many seeds.
  const NoiseTexture flat = impl::make_noise_texture(256, 0.0, 29);
  EXPECT_LT(std::fabs(channel_correlation(flat)), 0.05);

  const int seeds = 24;
  double sum = 0.0, squares = 0.0;
  for (int seed = 0; seed < seeds; ++seed) {
    const double r = channel_correlation(impl::make_noise_texture(256, 1.0, seed));
    sum += r;
    squares += r * r;
  }
  // The mean of 24 scatters by 0.07 / sqrt(24) = 0.014; channels sharing part of their
  // field would give a mean and an RMS of r well away from 0 (1 for copies).
  EXPECT_LT(std::fabs(sum / seeds), 0.05);
  EXPECT_LT(std::sqrt(squares / seeds), 0.1);
}

TEST(NoiseTexture, SameSeedGivesSameBytes) {
  const NoiseTexture a = impl::make_noise_texture(128, 2.0, 42);
  const NoiseTexture b = impl::make_noise_texture(128, 2.0, 42);
  const NoiseTexture c = impl::make_noise_texture(128, 2.0, 43);
  ASSERT_EQ(a.texels.size(), b.texels.size());
  ASSERT_EQ(a.texels.size(), c.texels.size());
  const size_t bytes = a.texels.size() * sizeof(float);
  EXPECT_EQ(std::memcmp(a.texels.data(), b.texels.data(), bytes), 0);
  EXPECT_NE(std::memcmp(a.texels.data(), c.texels.data(), bytes), 0);
}

TEST(NoiseTexture, BilinearLookupHitsTexelCentersAndBlendsBetween) {
  const int n = 16;
  const NoiseTexture noise = impl::make_noise_texture(n, 2.0, 7);
  double out[2];
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      impl::sample_noise(noise, (x + 0.5) / n, (y + 0.5) / n, out);
      for (int c = 0; c < 2; ++c) EXPECT_EQ(out[c], texel(noise, x, y, c)) << x << ", " << y;

      // Halfway to the next center in x, in y, and in both; the next of the last texel is
      // the first (u = 1, or v = 1, is the edge between them).
      const int x1 = (x + 1) % n, y1 = (y + 1) % n;
      for (int c = 0; c < 2; ++c) {
        impl::sample_noise(noise, (x + 1.0) / n, (y + 0.5) / n, out);
        EXPECT_NEAR(out[c], 0.5 * (texel(noise, x, y, c) + texel(noise, x1, y, c)), 1e-12);
        impl::sample_noise(noise, (x + 0.5) / n, (y + 1.0) / n, out);
        EXPECT_NEAR(out[c], 0.5 * (texel(noise, x, y, c) + texel(noise, x, y1, c)), 1e-12);
        impl::sample_noise(noise, (x + 1.0) / n, (y + 1.0) / n, out);
        const double corners = texel(noise, x, y, c) + texel(noise, x1, y, c) +
                               texel(noise, x, y1, c) + texel(noise, x1, y1, c);
        EXPECT_NEAR(out[c], 0.25 * corners, 1e-12);
      }
    }
  }
  // A quarter texel past the last center, before u wraps to 0: 3/4 of the last texel and
  // 1/4 of the first (the blend must wrap here too, not only below the first center).
  impl::sample_noise(noise, 1.0 - 0.25 / n, 1.0 - 0.25 / n, out);
  for (int c = 0; c < 2; ++c) {
    const double last_row = 0.75 * texel(noise, n - 1, n - 1, c) + 0.25 * texel(noise, 0, n - 1, c);
    const double first_row = 0.75 * texel(noise, n - 1, 0, c) + 0.25 * texel(noise, 0, 0, c);
    EXPECT_NEAR(out[c], 0.75 * last_row + 0.25 * first_row, 1e-12);
  }
}

TEST(NoiseTexture, BadArgumentsThrowNamingTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int size : {0, 4, 100, 2048}) {
    expect_error([&] { (void)impl::make_noise_texture(size, 2.0, 1); },
                 BOREAS_ERROR_INVALID_ARGUMENT, {"size", std::to_string(size)});
  }
  for (double beta : {-1.0, nan, 5.0}) {
    const std::string shown = std::isnan(beta) ? "nan" : beta < 0 ? "-1" : "5";
    expect_error([&] { (void)impl::make_noise_texture(64, beta, 1); },
                 BOREAS_ERROR_INVALID_ARGUMENT, {"beta", shown});
  }
  // The ends of the ranges are allowed.
  EXPECT_NO_THROW((void)impl::make_noise_texture(8, 0.0, 1));
  EXPECT_NO_THROW((void)impl::make_noise_texture(8, 4.0, 1));

  const NoiseTexture noise = impl::make_noise_texture(8, 2.0, 1);
  double out[2];
  expect_error([&] { impl::sample_noise(noise, nan, 0.5, out); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"u", "nan"});
  expect_error([&] { (void)impl::radial_power_spectrum(noise, 2); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"channel", "2"});
  expect_error([&] { impl::sample_noise(NoiseTexture{}, 0.5, 0.5, out); },
               BOREAS_ERROR_INVALID_ARGUMENT, {"size 0"});
}

}  // namespace
}  // namespace boreas::test
