// render tests: the default scene, built and run twice through the library as `boreas run`
// steps it, has bit-identical state after every step (boreas_world_get_state_hash).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {
namespace {

std::vector<uint64_t> run_default_scene(int steps) {
  const Scene scene = load_default_scene();
  SceneIds ids;
  boreas::World world = make_world(scene, std::nullopt, &ids);
  std::vector<uint64_t> hashes{world.get_state_hash()};
  for (int s = 0; s < steps; ++s) {
    step_scene(world, scene, 1, scene.run.dt);
    hashes.push_back(world.get_state_hash());
  }
  return hashes;
}

TEST(SceneDeterminism, DefaultSceneTwiceGivesTheSameStateEveryStep) {
  const std::vector<uint64_t> first = run_default_scene(6), second = run_default_scene(6);
  EXPECT_EQ(first, second);
  for (size_t s = 1; s < first.size(); ++s) EXPECT_NE(first[s], first[s - 1]) << "step " << s;
}

}  // namespace
}  // namespace boreas::render
