// boreas: where the plants of a meadow grow (Endo et al. sec. 5.2): propagation from seed
// points toward richer ground, with competition through consumption of the nutrients.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "underbrush/terrain.h"

namespace boreas::impl {

// What one kind of plant needs from the ground and takes from it.
struct PlantNeeds {
  double weight = 1.0;                     // share of the plants planted, > 0
  double need[kMaxNutrients] = {0, 0, 0};  // minimum concentration to grow, 0..1
  double consumption[kMaxNutrients] = {0, 0, 0};  // taken from the ground per plant, per m^2
                                                   // of its cell
  double spacing = 0.05;                   // m, least distance between plants of any kind
};

struct Planting {
  float position[3];  // on the terrain
  float normal[3];    // the terrain's unit normal there
  int32_t kind;       // index into the PlantNeeds list
  uint32_t seed;      // per-plant random seed (shape variation)
};

struct DistributionParams {
  int64_t target_count = 0;  // plants wanted (the result may be fewer where ground is poor)
  int seed_points = 8;       // propagation starts per kind
  uint64_t seed = 1;
  // Called now and then with the fraction done (0..1); may be empty.
  std::function<void(double)> progress;
};

// Deterministic: the same inputs give the same plantings in the same order.
std::vector<Planting> distribute(const Terrain& terrain, const NutrientMaps& nutrients,
                                 const std::vector<PlantNeeds>& kinds,
                                 const DistributionParams& params);

}  // namespace boreas::impl
