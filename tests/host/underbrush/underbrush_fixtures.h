// boreas tests: small meadows placed by hand, in worlds whose wind is a steady sine sum
// over a calm grid (its part of the wind stays exactly zero).
#pragma once

#include <memory>
#include <vector>

#include "support/test_support.h"
#include "underbrush/meadow.h"
#include "world.h"

namespace boreas::test {

// A world with one steady wave of `speed` m/s along x (none for 0).
inline std::unique_ptr<impl::World> meadow_world(float speed) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = calm_grid();
  boreas_wave w = steady_wave(1.0f, 0.0f, speed);
  def.waves = speed > 0.0f ? &w : nullptr;
  def.wave_count = speed > 0.0f ? 1 : 0;
  return std::make_unique<impl::World>(def);
}

inline impl::MeadowParams species_params(const std::vector<std::string>& species) {
  impl::MeadowParams p;
  for (const std::string& s : species) {
    p.species.push_back(impl::load_component_species(s));
    p.weights.push_back(1.0);
  }
  return p;
}

// Plants of species `kind` on flat ground at y = 0 on a grid of the given spacing.
inline std::vector<impl::Planting> planting_grid(int per_side, double spacing, int kind = 0, uint32_t seed = 7) {
  std::vector<impl::Planting> out;
  for (int i = 0; i < per_side; ++i)
    for (int k = 0; k < per_side; ++k) {
      impl::Planting p{};
      p.position[0] = float((i - 0.5 * (per_side - 1)) * spacing);
      p.position[2] = float((k - 0.5 * (per_side - 1)) * spacing);
      p.normal[1] = 1.0f;
      p.kind = kind;
      p.seed = seed + uint32_t(i * per_side + k);
      out.push_back(p);
    }
  return out;
}

}  // namespace boreas::test
