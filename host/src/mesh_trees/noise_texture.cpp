// boreas: the tiling noise texture (Kusternig sec. 5.2), 1/f^beta along any line, by
// spectral synthesis: a random-phase spectrum, one inverse FFT, two channels.
#include "mesh_trees/noise_texture.h"

#include <charconv>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/tree_random.h"

namespace boreas::impl {
namespace {

using Complex = std::complex<double>;

constexpr int kMinSize = 8;
constexpr int kMaxSize = 1024;
constexpr double kMaxBeta = 4.0;
constexpr double kTwoPi = 6.283185307179586476925;

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

// The shortest form that reads back as the same double ("5", "-1", "nan", "4.0000001"),
// not std::to_string's fixed six decimals ("5.000000", and "4.000000" for 4.0000001).
std::string format_value(double v) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

void check_texture(const NoiseTexture& noise) {
  if (!is_power_of_two(noise.size) || noise.size < kMinSize || noise.size > kMaxSize ||
      noise.texels.size() != size_t(2) * noise.size * noise.size) {
    fail_argument("noise texture: size " + std::to_string(noise.size) + " with " +
                  std::to_string(noise.texels.size()) +
                  " floats is not one made by make_noise_texture (2 * size * size floats, "
                  "size a power of two in 8..1024)");
  }
}

// The phase of one frequency: its own splitmix64 draw keyed by (seed, texel index), so
// each phase depends only on the seed and where it sits, never on the order of the loop.
double random_phase(uint64_t seed_key, uint64_t index) {
  const uint64_t h = splitmix64_mix(seed_key + (index + 1) * 0x9e3779b97f4a7c15ull);
  return kTwoPi * (double(h >> 11) * 0x1.0p-53);
}

// An iterative radix-2 complex FFT of one power-of-two length, unscaled. The twiddles are
// computed once each from cos/sin rather than by repeated multiplication, which would
// drift by a few ulps per stage.
class Fft {
 public:
  // sign -1: forward, sum x e^{-2 pi i k n / N}; +1: inverse (without the 1/N).
  Fft(int n, int sign) : n_(n), twiddles_(n / 2), reversed_(n) {
    for (int j = 0; j < n / 2; ++j) twiddles_[j] = std::polar(1.0, sign * kTwoPi * j / n);
    int bits = 0;
    while ((1 << bits) < n) ++bits;
    for (int i = 0; i < n; ++i) {
      int r = 0;
      for (int b = 0; b < bits; ++b) r |= ((i >> b) & 1) << (bits - 1 - b);
      reversed_[i] = r;
    }
  }

  void transform(Complex* a) const {
    for (int i = 0; i < n_; ++i) {
      if (i < reversed_[i]) std::swap(a[i], a[reversed_[i]]);
    }
    for (int len = 2; len <= n_; len *= 2) {
      const int half = len / 2;
      const int step = n_ / len;  // stage len uses every step-th twiddle of the length-n table
      for (int start = 0; start < n_; start += len) {
        for (int j = 0; j < half; ++j) {
          const Complex t = twiddles_[j * step] * a[start + j + half];
          a[start + j + half] = a[start + j] - t;
          a[start + j] += t;
        }
      }
    }
  }

  // A size x size grid, x fastest: every row, then every column (gathered into a line).
  void transform_2d(std::vector<Complex>& grid) const {
    for (int y = 0; y < n_; ++y) transform(&grid[size_t(y) * n_]);
    std::vector<Complex> column(n_);
    for (int x = 0; x < n_; ++x) {
      for (int y = 0; y < n_; ++y) column[y] = grid[size_t(y) * n_ + x];
      transform(column.data());
      for (int y = 0; y < n_; ++y) grid[size_t(y) * n_ + x] = column[y];
    }
  }

 private:
  int n_;
  std::vector<Complex> twiddles_;
  std::vector<int> reversed_;
};

// The signed frequency of FFT bin i, in cycles per tile: 0..n/2-1, then -n/2..-1.
int signed_frequency(int i, int n) { return i < n / 2 ? i : i - n; }

}  // namespace

NoiseTexture make_noise_texture(int size, double beta, uint64_t seed) {
  if (!is_power_of_two(size) || size < kMinSize || size > kMaxSize) {
    fail_argument("noise texture size must be a power of two in 8..1024 (got " +
                  std::to_string(size) + ")");
  }
  if (!std::isfinite(beta) || beta < 0.0 || beta > kMaxBeta) {
    fail_argument("noise texture beta must be a finite number in [0, 4] (got " +
                  format_value(beta) + ")");
  }

  // A branch reads the texture along a line (its phase moved by its level's clock), and a
  // line through an isotropic 2D field of radial power |k|^-a has the 1D power
  // integral dk_y (k_x^2 + k_y^2)^(-a/2) ~ k_x^(1 - a). So the field gets a = beta + 1:
  // amplitude |k|^(-(beta + 1)/2), and every branch sways with the 1/f^beta that Kusternig
  // names. Only integer frequencies (whole cycles per tile) exist, so the field tiles by
  // construction. F(0,0) = 0: no mean to remove.
  const uint64_t seed_key = splitmix64_mix(seed ^ 0x510e527fade682d1ull);
  std::vector<Complex> spectrum(size_t(size) * size);
  for (int iy = 0; iy < size; ++iy) {
    const int ky = signed_frequency(iy, size);
    for (int ix = 0; ix < size; ++ix) {
      const int kx = signed_frequency(ix, size);
      if (kx == 0 && ky == 0) continue;
      const size_t index = size_t(iy) * size + ix;
      const double k = std::sqrt(double(kx) * kx + double(ky) * ky);
      spectrum[index] = std::polar(std::pow(k, -0.5 * (beta + 1.0)), random_phase(seed_key, index));
    }
  }
  Fft(size, +1).transform_2d(spectrum);

  // Without Hermitian symmetry the field is complex. F(k) and F(-k) have independent
  // phases, so the real and imaginary parts are two real fields with the same spectrum
  // shape and zero expected correlation: one FFT gives both channels. (Each pair (k, -k)
  // adds the same cosine wave to both parts, weighted by the cosine and the sine of the
  // pair's mean phase, uniform in angle: uncorrelated, not independent; for swaying
  // trees only the correlation shows.)
  NoiseTexture noise;
  noise.size = size;
  noise.beta = beta;
  noise.texels.resize(size_t(2) * size * size);
  const double count = double(size) * size;
  for (int channel = 0; channel < 2; ++channel) {
    auto part = [&](size_t i) { return channel == 0 ? spectrum[i].real() : spectrum[i].imag(); };
    double sum = 0.0;
    for (size_t i = 0; i < spectrum.size(); ++i) sum += part(i);
    const double mean = sum / count;  // zero up to rounding, since F(0,0) = 0
    double squares = 0.0;
    for (size_t i = 0; i < spectrum.size(); ++i) squares += (part(i) - mean) * (part(i) - mean);
    const double scale = 1.0 / std::sqrt(squares / count);
    for (size_t i = 0; i < spectrum.size(); ++i) {
      noise.texels[2 * i + channel] = float((part(i) - mean) * scale);
    }
  }
  return noise;
}

void sample_noise(const NoiseTexture& noise, double u, double v, double out[2]) {
  check_texture(noise);
  if (!std::isfinite(u) || !std::isfinite(v)) {
    fail_argument("sample_noise: u and v must be finite (got u = " + format_value(u) +
                  ", v = " + format_value(v) + ")");
  }
  // Reduce to one period first, so u and u + 1 land on the same texels. Texel centers sit
  // at (i + 0.5) / size; x in [-0.5, size - 0.5] puts i0 in [-1, size - 1], and the mask
  // wraps -1 and size (the power-of-two size makes it a modulo).
  const int n = noise.size;
  const int mask = n - 1;
  const double x = (u - std::floor(u)) * n - 0.5;
  const double y = (v - std::floor(v)) * n - 0.5;
  const double fx0 = std::floor(x), fy0 = std::floor(y);
  const double wx = x - fx0, wy = y - fy0;
  const int x0 = int(fx0) & mask, x1 = (int(fx0) + 1) & mask;
  const int y0 = int(fy0) & mask, y1 = (int(fy0) + 1) & mask;
  const float* t = noise.texels.data();
  for (int c = 0; c < 2; ++c) {
    const double a = t[2 * (size_t(y0) * n + x0) + c], b = t[2 * (size_t(y0) * n + x1) + c];
    const double d = t[2 * (size_t(y1) * n + x0) + c], e = t[2 * (size_t(y1) * n + x1) + c];
    out[c] = (1.0 - wy) * ((1.0 - wx) * a + wx * b) + wy * ((1.0 - wx) * d + wx * e);
  }
}

std::vector<double> radial_power_spectrum(const NoiseTexture& noise, int channel) {
  check_texture(noise);
  if (channel != 0 && channel != 1) {
    fail_argument("radial_power_spectrum: channel must be 0 or 1 (got " + std::to_string(channel) +
                  ")");
  }
  const int n = noise.size;
  std::vector<Complex> grid(size_t(n) * n);
  for (size_t i = 0; i < grid.size(); ++i) grid[i] = noise.texels[2 * i + channel];
  Fft(n, -1).transform_2d(grid);

  // F scaled by 1/size^2, so that by Parseval the powers of all bins sum to the channel's
  // mean square. Bins beyond |f| = size/2 + 0.5 (the corners) fall in no annulus.
  const double scale = 1.0 / (double(n) * n);
  const int last = n / 2;
  std::vector<double> power(last + 1, 0.0);
  std::vector<int> bins(last + 1, 0);
  for (int iy = 0; iy < n; ++iy) {
    const int ky = signed_frequency(iy, n);
    for (int ix = 0; ix < n; ++ix) {
      const int kx = signed_frequency(ix, n);
      const int k = int(std::floor(std::sqrt(double(kx) * kx + double(ky) * ky) + 0.5));
      if (k > last) continue;
      power[k] += std::norm(grid[size_t(iy) * n + ix] * scale);
      ++bins[k];
    }
  }
  for (int k = 0; k <= last; ++k) power[k] /= bins[k];  // every annulus holds (k, 0)
  return power;
}

}  // namespace boreas::impl
