// boreas scenes: planting a stand of trees (forest.h).
#include "scene/forest.h"

#include <cmath>
#include <cstdint>

#include "scene/leaf_choice.h"

namespace boreas::render {

namespace {

// SplitMix64: a small, well-mixed stream, the same on every machine.
struct Stream {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
};

}  // namespace

std::vector<SceneTree> plant_forest(const SceneForest& forest) {
  std::vector<SceneTree> trees;
  if (forest.count <= 0 || forest.species.empty()) return trees;
  trees.reserve(size_t(forest.count));
  const double aspect = double(forest.size[0]) / double(forest.size[1]);
  const int columns = std::max(1, int(std::ceil(std::sqrt(double(forest.count) * aspect))));
  const int rows = (forest.count + columns - 1) / columns;
  const double cell_x = double(forest.size[0]) / columns, cell_z = double(forest.size[1]) / rows;
  double weight_sum = 0.0;
  for (const auto& s : forest.species) weight_sum += s.second;
  Stream rng{forest.seed};
  for (int i = 0; i < forest.count; ++i) {
    SceneTree tree;
    tree.def = forest.def;
    tree.def.species = nullptr;  // set from tree.species when the tree is added
    double pick = rng.uniform() * weight_sum;
    size_t s = 0;
    while (s + 1 < forest.species.size() && pick >= forest.species[s].second)
      pick -= forest.species[s++].second;
    tree.species = forest.species[s].first;
    tree.leaf_kind = default_leaf_kind(tree.species);
    tree.def.seed = 1 + rng.next() % uint64_t(std::max(1, forest.templates));
    const int column = i % columns, row = i / columns;
    const double jitter_x = (rng.uniform() - 0.5) * 0.7, jitter_z = (rng.uniform() - 0.5) * 0.7;
    tree.def.position[0] =
        float(forest.center[0] - 0.5 * forest.size[0] + (column + 0.5 + jitter_x) * cell_x);
    tree.def.position[1] = forest.center[1];
    tree.def.position[2] =
        float(forest.center[2] - 0.5 * forest.size[1] + (row + 0.5 + jitter_z) * cell_z);
    tree.def.rotation = float(rng.uniform() * 6.283185307179586);
    tree.def.scale = float(forest.scale[0] + rng.uniform() * (forest.scale[1] - forest.scale[0]));
    trees.push_back(std::move(tree));
  }
  return trees;
}

}  // namespace boreas::render
