// boreas tests and benchmarks: the windy forest the ray agreement test and BM_Rays cast
// into, built through the public C API (a stand of trees of several species on a lattice,
// a meadow under it on flat ground, imported trees beside it), its triangles handed to an
// EmbreeWorld, and rays that mostly hit something.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "embree_world.h"

namespace boreas::reference {

struct RayForestDef {
  int trees = 6;  // on a square lattice centred on the origin, species in turn
  std::vector<std::string> species{"quaking_aspen", "black_tupelo", "ca_black_oak"};
  int templates = 2;          // seeds per species (trees of one (species, seed) share a model)
  float spacing = 6.0f;       // m between neighbouring trees
  float scale = 0.6f;         // of every tree (each varies by up to 30 % about it)
  int64_t components = 0;     // underbrush under the stand (0: no meadow, no ground)
  std::vector<std::string> mesh_tree_models;  // imported trees, one each, beside the stand
  float wind = 8.0f;          // m/s: the amplitude of the main wave
};

struct RayForest {
  RayForest() = default;
  RayForest(const RayForest&) = delete;
  RayForest& operator=(const RayForest&) = delete;
  ~RayForest() { boreas_world_destroy(world); }

  boreas_world world = nullptr;
  std::vector<boreas_tree_def> tree_defs;  // species strings point into RayForestDef's
  std::vector<boreas_tree_id> trees;
  boreas_meadow_id meadow{0, 0, 0};
  boreas_meadow_def meadow_def{};
  std::vector<boreas_mesh_tree_id> mesh_trees;
  float half_extent = 0.0f;  // m: the stand (and the meadow) span [-half, half] in x and z
  float top = 0.0f;          // m: the highest branch point at rest
};

// Builds the forest (throws with boreas_last_error on a failure). def must outlive it.
std::unique_ptr<RayForest> make_ray_forest(const RayForestDef& def);

// Every object of the forest into `embree`: trees (with their defs' levels), the meadow,
// imported trees, and (flat_ground) the meadow's flat ground as two triangles
// (BOREAS_HIT_GROUND; boreas.h has no getter for the ground, so its parts are these two
// triangles, not boreas's grid: a test that compares ground parts adds the grid itself).
void add_to_embree(const RayForest& forest, EmbreeWorld* embree, bool flat_ground = true);

// The ground's two triangles' corners, as add_to_embree gives them (for callers that
// refresh Embree without a world).
std::vector<float> ground_positions(const RayForest& forest);

// `count` rays into the forest as of its last step, from a fixed seed: a third from random
// points in and around the stand in random directions (unbounded), a third aimed at random
// leaves' blades and a third at random points on random branches' curves (to 1.5 times
// the target's distance), so that most hit something.
std::vector<boreas_ray> forest_rays(const RayForest& forest, int count, uint64_t seed);

}  // namespace boreas::reference
