// boreas scenes: a run's seed over the scene's seeds (scene_seed.h).
#include "scene/scene_seed.h"

namespace boreas::render {

namespace {

// SplitMix64's finalizer: every bit of the input reaches every bit of the output.
uint64_t finalize(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

uint64_t mix_seed(uint64_t run_seed, uint64_t scene_seed) {
  // The run seed is finalized before it meets the scene's, so that run seeds 0, 1, 2 ...
  // and scene seeds 1, 2, 3 ... never cancel in the xor.
  return finalize(finalize(run_seed + 0x9e3779b97f4a7c15ull) ^ scene_seed);
}

void apply_run_seed(Scene& scene, uint64_t run_seed) {
  for (SceneTree& t : scene.trees) t.def.seed = mix_seed(run_seed, t.def.seed);
  for (SceneMeshTree& t : scene.mesh_trees) t.def.seed = mix_seed(run_seed, t.def.seed);
  for (SceneMeadow& m : scene.meadows) m.def.seed = mix_seed(run_seed, m.def.seed);
  for (boreas_emitter_def& e : scene.emitters) e.seed = mix_seed(run_seed, e.seed);
  // A LiDAR's range noise and dropout.
  for (SceneSensor& s : scene.sensors) s.lidar.seed = mix_seed(run_seed, s.lidar.seed);
}

}  // namespace boreas::render
