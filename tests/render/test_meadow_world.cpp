// render tests: a scene's underbrush in a world, through the library: what make_world plants
// and adds, a rolling ball pushing the components it passes aside while the rest of a calm
// meadow stays at rest, and a bad species file reported with the meadow's JSON path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {
namespace {

// A calm 8 m grid with a 4 m meadow of grass in the middle and a ball rolling along +x
// through it: at x = -1.5 m at time 0, at x = 0 at 1 s.
std::string rolling_ball_scene() {
  return R"({
    "world": {"grid": {"origin": [-4, 0, -4], "cell_size": 1, "resolution": [8, 4, 8]}},
    "meadows": [{"species": [{"species": "meadow_grass"}], "size": [4, 4], "density": 1200,
                 "seed_points": 256, "seed": 2}],
    "colliders": [{"center": [-1.5, 0.15, 0], "radius": 0.15, "velocity": [1.5, 0, 0]}]
  })";
}

std::vector<boreas_component> components(const boreas::World& world, boreas_meadow_id meadow) {
  int n = 0;
  EXPECT_EQ(boreas_meadow_get_components(world.handle(), meadow, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_component> out(static_cast<size_t>(n));
  EXPECT_EQ(boreas_meadow_get_components(world.handle(), meadow, out.data(), n, &n), BOREAS_OK);
  return out;
}

TEST(MeadowWorld, CollidersMoveAlongTheirVelocity) {
  SceneCollider ball;
  ball.def.pose.position[0] = -1.5f;
  ball.def.pose.position[1] = 0.15f;
  ball.def.velocity[0] = 1.5f;
  ball.def.velocity[2] = -0.5f;
  float at[3];
  collider_position(ball, 2.0, at);
  EXPECT_FLOAT_EQ(at[0], 1.5f);
  EXPECT_FLOAT_EQ(at[1], 0.15f);
  EXPECT_FLOAT_EQ(at[2], -1.0f);
  // Held within the library's bounds however long it rolls.
  ball.def.velocity[0] = 1000.0f;
  collider_position(ball, 1e6, at);
  EXPECT_EQ(at[0], 1e7f);
}

TEST(MeadowWorld, RollingBallPushesComponentsAsideAndTheRestStayStill) {
  Scene scene = load_scene_text(rolling_ball_scene(), "ball.json");
  SceneIds ids;
  boreas::World world = make_world(scene, std::nullopt, &ids);
  ASSERT_EQ(ids.meadows.size(), 1u);
  ASSERT_EQ(ids.colliders.size(), 1u);
  std::vector<boreas_component> rest = components(world, ids.meadows[0]);
  ASSERT_GT(rest.size(), 2000u);

  // Each component's farthest horizontal excursion from rest during the run, and how much
  // of it pointed away from the ball's path (the line z = 0).
  std::vector<float> peak(rest.size(), 0.0f);
  std::vector<float> outward(rest.size(), 0.0f);
  const float dt = 1.0f / 30.0f;
  for (int i = 0; i < 30; ++i) {
    world.step(dt);
    std::vector<boreas_component> now = components(world, ids.meadows[0]);
    ASSERT_EQ(now.size(), rest.size());
    for (size_t k = 0; k < now.size(); ++k) {
      float dx = now[k].center_of_mass[0] - rest[k].center_of_mass[0];
      float dz = now[k].center_of_mass[2] - rest[k].center_of_mass[2];
      float moved = std::hypot(dx, dz, now[k].center_of_mass[1] - rest[k].center_of_mass[1]);
      if (moved > peak[k]) {
        peak[k] = moved;
        outward[k] = now[k].base[2] > 0.0f ? dz : -dz;
      }
    }
  }
  float ball[3];
  collider_position(scene.colliders[0], world.get_time(), ball);
  EXPECT_NEAR(ball[0], 0.0f, 1e-4f);

  // The ball's path so far: x in [-1.5, 0], |z| under its radius (ends left out).
  std::vector<float> swept;
  double away = 0.0;
  int off_axis = 0;
  float far_moved = 0.0f;
  for (size_t k = 0; k < rest.size(); ++k) {
    float x = rest[k].base[0];
    float z = rest[k].base[2];
    if (x > -1.4f && x < -0.1f && std::fabs(z) < 0.15f) {
      swept.push_back(peak[k]);
      if (std::fabs(z) > 0.03f) {
        away += outward[k];
        ++off_axis;
      }
    }
    if (std::fabs(z) > 1.0f) far_moved = std::max(far_moved, peak[k]);
  }
  ASSERT_GT(swept.size(), 20u);
  std::sort(swept.begin(), swept.end());
  EXPECT_GT(swept[swept.size() / 2], 0.01f) << "most components the ball met moved over 1 cm";
  ASSERT_GT(off_axis, 10);
  EXPECT_GT(away / off_axis, 0.005) << "pushed away from the path, not toward it";
  EXPECT_LT(far_moved, 1e-3f) << "a calm meadow away from the ball stays at rest";
}

TEST(MeadowWorld, BadSpeciesFileNamesTheMeadow) {
  Scene scene = load_scene_text(R"({
    "world": {"grid": {"origin": [-4, 0, -4], "cell_size": 1, "resolution": [8, 4, 8]}},
    "meadows": [{"size": [1, 1], "density": 10},
                {"species": [{"species": "no/such/moss.json"}], "size": [1, 1]}]})",
                                "bad.json");
  try {
    (void)make_world(scene, std::nullopt);
    FAIL() << "no error";
  } catch (const boreas::Error& e) {
    std::string message = e.what();
    EXPECT_EQ(message.rfind("bad.json: /meadows/1: ", 0), 0u) << message;
    EXPECT_NE(message.find("no/such/moss.json"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace boreas::render
