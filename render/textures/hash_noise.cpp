// boreas textures: integer hashing, value noise and Worley cell borders.
#include "textures/hash_noise.h"

#include <algorithm>
#include <cmath>

namespace boreas::render::noise {
namespace {

// Lattice index i wrapped into [0, period); without a division in the common case of
// coordinates inside the unit square (divisions were most of value_noise's time).
uint32_t wrap(long long i, int period) {
  if (i >= 0 && i < period) return static_cast<uint32_t>(i);
  long long p = period;
  return static_cast<uint32_t>(((i % p) + p) % p);
}

double quintic(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

}  // namespace

uint32_t hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

double hash01(uint32_t a, uint32_t b, uint32_t c) {
  // One mix of a weighted sum (odd multipliers): distinct lattice points of a texture
  // (coordinates below 2^16) and seeds give distinct sums, and the mix decorrelates them.
  // Nesting three mixes looked the same and cost a fifth of the leaf's generation time.
  uint32_t h = hash(a * 0x8da6b343U + b * 0xd8163841U + c * 0xcb1ab31fU);
  return (h >> 8) * (1.0 / 16777216.0);
}

double value_noise(double u, double v, int cells_u, int cells_v, uint32_t seed) {
  double x = u * cells_u;
  double y = v * cells_v;
  double fx = std::floor(x);
  double fy = std::floor(y);
  long long ix = static_cast<long long>(fx);
  long long iy = static_cast<long long>(fy);
  double tx = quintic(x - fx);
  double ty = quintic(y - fy);
  uint32_t x0 = wrap(ix, cells_u), x1 = x0 + 1 == uint32_t(cells_u) ? 0 : x0 + 1;
  uint32_t y0 = wrap(iy, cells_v), y1 = y0 + 1 == uint32_t(cells_v) ? 0 : y0 + 1;
  double a = hash01(x0, y0, seed), b = hash01(x1, y0, seed);
  double c = hash01(x0, y1, seed), d = hash01(x1, y1, seed);
  double bottom = a + (b - a) * tx;
  double top = c + (d - c) * tx;
  return bottom + (top - bottom) * ty;
}

double fbm(double u, double v, int cells_u, int cells_v, int octaves, uint32_t seed) {
  double sum = 0.0;
  double norm = 0.0;
  double amplitude = 1.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(u, v, cells_u << o, cells_v << o, hash(seed + 977U * o));
    norm += amplitude;
    amplitude *= 0.5;
  }
  return sum / norm;
}

double cell_border_distance(double u, double v, int cells_u, int cells_v, uint32_t seed) {
  double x = u * cells_u;
  double y = v * cells_v;
  long long ix = static_cast<long long>(std::floor(x));
  long long iy = static_cast<long long>(std::floor(y));
  double f1 = 1e9, f2 = 1e9;
  for (long long j = iy - 1; j <= iy + 1; ++j) {
    for (long long i = ix - 1; i <= ix + 1; ++i) {
      uint32_t wi = wrap(i, cells_u), wj = wrap(j, cells_v);
      // The point sits in the middle 80% of its cell, so the 3x3 neighbourhood always
      // holds the two nearest points.
      double px = i + 0.1 + 0.8 * hash01(wi, wj, seed);
      double py = j + 0.1 + 0.8 * hash01(wi, wj, seed ^ 0x5bd1e995U);
      double d = (px - x) * (px - x) + (py - y) * (py - y);  // squared until the end
      if (d < f1) {
        f2 = f1;
        f1 = d;
      } else if (d < f2) {
        f2 = d;
      }
    }
  }
  return std::min(std::sqrt(f2) - std::sqrt(f1), 1.0);
}

}  // namespace boreas::render::noise
