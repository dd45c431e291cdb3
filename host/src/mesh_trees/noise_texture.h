// boreas: the tiling 2D noise that sways imported trees (Kusternig sec. 5.2), made by
// spectral synthesis so that what one branch reads of it over time, a line through it,
// has the paper's 1/f^beta spectrum: the field's radial spectrum falls as 1/f^(beta + 1).
#pragma once

#include <cstdint>
#include <vector>

namespace boreas::impl {

struct NoiseTexture {
  int size = 0;               // texels per side, a power of two
  double beta = 2.0;          // a line's power spectrum ~ 1/f^beta (the field's 1/f^(beta+1))
  std::vector<float> texels;  // 2 channels per texel, x fastest; each channel zero mean, unit RMS
};

// size: a power of two in 8..1024; beta: finite, in [0, 4]. Channels 0 and 1 are the real
// and imaginary parts of one random-phase complex field: the same spectrum and zero
// expected correlation (one tile of a steep spectrum still shows some, by chance: about
// 0.07 RMS over seeds at beta 2, size 256). The same (size, beta, seed) gives the same
// bytes (boreas's own splitmix64 draws; libm supplies pow, cos and sin). Throws
// boreas::impl::Error (BOREAS_ERROR_INVALID_ARGUMENT) naming the bad parameter and value.
NoiseTexture make_noise_texture(int size, double beta, uint64_t seed);

// Bilinear lookup with wrap-around; u, v in texture periods (1.0 = one tile), any finite
// value. Texel i covers u in [i/size, (i+1)/size) and its value sits at its center,
// (i + 0.5)/size: between centers the lookup blends the two nearest, wrapping from the
// last texel to the first. A GPU sampler of this texture must copy this convention.
// Throws Error on a non-finite u or v, or a texture make_noise_texture did not make.
void sample_noise(const NoiseTexture& noise, double u, double v, double out[2]);

// The radially averaged power spectrum of one channel (0 or 1): element k is the mean
// |F|^2 over frequencies with k - 0.5 <= |f| < k + 0.5 (cycles per tile, signed wrapped
// frequencies), k = 0..size/2. F is the forward DFT divided by size^2, so the powers of all
// frequencies sum to the channel's mean square (1); the corners beyond size/2 + 0.5 are in
// no annulus.
std::vector<double> radial_power_spectrum(const NoiseTexture& noise, int channel);

}  // namespace boreas::impl
