// render tests: make_world's focus (the scene's eye, set before anything is added: what
// `boreas run` gives it). Trees that the eye sees from past their nearest distance settle as
// they are added: the world holds less right after the add than one given the same focus
// only after it, and once that one's trees have settled (kSettleTime, 3 s) both step to the
// same bits.
#include <gtest/gtest.h>

#include <cstdint>

#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {
namespace {

// 24 aspens over 120 m x 120 m, the eye at one corner: most of them far from it.
const char* kEyeOnAStand = R"({"forests": [{"species": [{"species": "quaking_aspen"}],
  "count": 24, "center": [0, 0, 0], "size": [120, 120], "templates": 3, "seed": 9,
  "lod_distances": [8, 16, 30]}],
  "view": {"eye": [-55, 1.8, -55], "target": [0, 5, 0]},
  "wind": {"waves": [{"direction": [1, 0.3], "amplitude": 3, "wavelength": 40, "speed": 6}]}})";

uint64_t device_bytes(boreas::World& world) {
  boreas_memory_info memory{};
  boreas::check(boreas_world_get_memory(world.handle(), &memory));
  return memory.device_bytes;
}

TEST(SceneFocus, AWorldFocusedBeforeTheAddSettlesThereAndStepsToTheSameBits) {
  const Scene scene = load_scene_text(kEyeOnAStand, "focus.json");
  ASSERT_TRUE(scene.view.eye.has_value());
  const float* eye = scene.view.eye->data();
  boreas::World before = make_world(scene, std::nullopt, nullptr, nullptr, eye);
  boreas::World after = make_world(scene, std::nullopt);
  boreas::check(boreas_world_set_focus(after.handle(), eye, 1));
  // Settled at add: the far trees' finest levels hold 28 B an entry, not their whole state.
  EXPECT_LT(device_bytes(before), device_bytes(after));
  // 3.5 s of steps: `after` has carried its far trees from rest and settled them.
  const int settle_steps = int(3.5f / scene.run.dt) + 1;
  step_scene(before, scene, settle_steps, scene.run.dt);
  step_scene(after, scene, settle_steps, scene.run.dt);
  uint64_t last = 0;
  for (int s = 0; s < 4; ++s) {
    step_scene(before, scene, 1, scene.run.dt);
    step_scene(after, scene, 1, scene.run.dt);
    const uint64_t hash = before.get_state_hash();
    EXPECT_EQ(hash, after.get_state_hash()) << "step " << s;
    EXPECT_NE(hash, last) << "step " << s;  // the wind moves them: a hash that can differ
    last = hash;
  }
}

}  // namespace
}  // namespace boreas::render
