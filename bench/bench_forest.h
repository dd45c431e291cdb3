// boreas benchmarks: the forest of BM_ForestStep (bench_forest.cpp), for the suites that
// step something else through it (BM_Colliders).
#pragma once

#include <cstdint>
#include <vector>

#include "bench_harness.h"
#include "boreas/boreas.h"

namespace boreas::bench {

// Trees stand on a square lattice this far apart (a closed canopy of aspens).
constexpr float kTreeSpacing = 5.0f;
// A step of the forest rows, s (one 60 Hz frame).
constexpr float kForestDt = 1.0f / 60.0f;
// The viewer of the forest rows, m: at the middle, an eye 1.8 m up. The fixture's forest is
// added with it as the focus (its far trees settle at add, as an engine that knows its
// camera first has them); the rows set it, or none, again before they step.
constexpr float kForestFocus[3] = {0.0f, 1.8f, 0.0f};

// Throws with the library's message unless status is BOREAS_OK.
void check(boreas_status status);

struct WorldHandle {
  boreas_world world = nullptr;
  ~WorldHandle() { boreas_world_destroy(world); }
};

// A world whose grid covers the middle of a forest `extent` m wide (its wind everywhere
// else is the sine sums), with the bench's waves.
boreas_world make_forest_world(float extent);
// `count` tree defs on the lattice centred on the origin: species by index from `species`,
// seeds from `templates` per species (0: every tree its own seed), each turned and scaled
// a little differently.
std::vector<boreas_tree_def> forest_defs(int count, int templates,
                                         const std::vector<const char*>& species);

// A forest world, kept across the rows of one size (the fixture slot): `trees` trees of
// `species` on the lattice (20 seeds per species), over a meadow of `components`.
struct ForestFixture : Fixture {
  WorldHandle world;
  int trees = 0;
  int64_t components = 0;
  double build_seconds = 0.0;
};
// (response: every tree's; damped rows measure the exact air damping's cost.)
ForestFixture& forest_fixture(int trees, int64_t components,
                              const std::vector<const char*>& species,
                              boreas_tree_response response = BOREAS_TREE_QUASI_STATIC);

}  // namespace boreas::bench
