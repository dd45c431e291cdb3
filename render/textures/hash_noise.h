// boreas textures: integer hashing and value noise. Every random choice in the generated
// textures goes through these, so a seed fixes every texel on every machine (the standard
// library's distributions are free to differ between implementations).
#pragma once

#include <algorithm>

#include <cstdint>

namespace boreas::render::noise {

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32").
uint32_t hash(uint32_t x);
// Hash of three values (lattice x, lattice y, seed), in [0, 1).
double hash01(uint32_t a, uint32_t b, uint32_t c);

// Smooth value noise over the unit square, in [0, 1]: a lattice of cells_u x cells_v random
// values with quintic interpolation, repeating with period 1 in u and in v (so textures
// built from it tile).
double value_noise(double u, double v, int cells_u, int cells_v, uint32_t seed);

// Fractal sum of `octaves` value noises, each with twice the cells and half the amplitude of
// the one before, normalized to [0, 1]; repeats with period 1 like value_noise.
double fbm(double u, double v, int cells_u, int cells_v, int octaves, uint32_t seed);

// Distance from (u, v) to the nearest border between Worley cells (F2 - F1 of the distances
// to the jittered cell points, in cell units, about 0 on a border and up to about 1 inside),
// with cells_u x cells_v cells repeating with period 1.
double cell_border_distance(double u, double v, int cells_u, int cells_v, uint32_t seed);

// Hermite step from 0 at e0 to 1 at e1 (GLSL's smoothstep), clamped outside.
inline double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace boreas::render::noise
