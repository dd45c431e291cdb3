// Library tests: the sensors through the C API on a world — ids, getters, refusals that
// leave the world as it was — LiDAR points and depth images of a flat meadow ground
// against their analytic values, and a scan that moves with the trees in the wind.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"
#include "support/small_world.h"

namespace {

uint64_t hash_of(boreas_world world) {
  uint64_t hash = 0;
  EXPECT_EQ(boreas_world_get_state_hash(world, &hash), BOREAS_OK) << boreas_last_error();
  return hash;
}

class SensorsApi : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(boreas::test::create_small_windy_world(&world_), BOREAS_OK) << boreas_last_error();
  }
  void TearDown() override { boreas_world_destroy(world_); }

  // A flat meadow with no plants: its ground is the plane y = height over 20 m x 20 m.
  boreas_meadow_id add_flat_ground(float height) {
    boreas_meadow_def m = boreas_default_meadow_def();
    m.size[0] = m.size[1] = 20.0f;
    m.center[1] = height;
    m.density = 0.0f;
    m.terrain_relief = 0.0f;
    boreas_meadow_id id{};
    EXPECT_EQ(boreas_world_add_meadow(world_, &m, &id), BOREAS_OK) << boreas_last_error();
    return id;
  }

  boreas_world world_ = nullptr;
};

TEST_F(SensorsApi, ALidarHasNoPointsBeforeItsFirstStepAndItsIdGoesStaleWhenRemoved) {
  boreas_lidar_def def = boreas_default_lidar_def();
  boreas_lidar_id id{};
  ASSERT_EQ(boreas_world_add_lidar(world_, &def, &id), BOREAS_OK) << boreas_last_error();
  int count = -1;
  for (boreas_lidar_points which : {BOREAS_LIDAR_LAST_STEP, BOREAS_LIDAR_LAST_SWEEP}) {
    ASSERT_EQ(boreas_lidar_get_points(world_, id, which, nullptr, 0, &count), BOREAS_OK);
    EXPECT_EQ(count, 0);
  }
  boreas_lidar_info info{};
  ASSERT_EQ(boreas_lidar_get_info(world_, id, &info), BOREAS_OK);
  EXPECT_EQ(info.sweeps, 0);
  EXPECT_EQ(info.firings, 0);
  EXPECT_EQ(info.next_sweep_start, boreas_world_get_time(world_));
  ASSERT_EQ(boreas_world_remove_lidar(world_, id), BOREAS_OK);
  EXPECT_EQ(boreas_lidar_get_info(world_, id, &info), BOREAS_ERROR_NOT_FOUND);
  EXPECT_NE(std::string(boreas_last_error()).find("no LiDAR with id"), std::string::npos);
}

TEST_F(SensorsApi, IdsOfAnotherWorldOrKindAreNotLidars) {
  boreas_world other = nullptr;
  ASSERT_EQ(boreas::test::create_small_windy_world(&other), BOREAS_OK);
  boreas_lidar_def def = boreas_default_lidar_def();
  boreas_lidar_id foreign{};
  ASSERT_EQ(boreas_world_add_lidar(other, &def, &foreign), BOREAS_OK);
  boreas_lidar_info info{};
  EXPECT_EQ(boreas_lidar_get_info(world_, foreign, &info), BOREAS_ERROR_NOT_FOUND);
  EXPECT_NE(std::string(boreas_last_error()).find("another world"), std::string::npos)
      << boreas_last_error();
  boreas_collider_def ball = boreas_default_collider_def();
  boreas_collider_id collider{};
  ASSERT_EQ(boreas_world_add_collider(world_, &ball, &collider), BOREAS_OK);
  const boreas_lidar_id cast = {collider.index, collider.generation, collider.tag};
  EXPECT_EQ(boreas_world_remove_lidar(world_, cast), BOREAS_ERROR_NOT_FOUND);
  EXPECT_NE(std::string(boreas_last_error()).find("is not a LiDAR id but a collider id"),
            std::string::npos)
      << boreas_last_error();
  boreas_world_destroy(other);
}

TEST_F(SensorsApi, BadCallsAreRefusedNamingWhatAndTheWorldIsUnchanged) {
  boreas_lidar_def good = boreas_default_lidar_def();
  boreas_lidar_id id{};
  ASSERT_EQ(boreas_world_add_lidar(world_, &good, &id), BOREAS_OK);
  const uint64_t before = hash_of(world_);
  struct Row {
    const char* names;
    boreas_status expect;
    std::function<boreas_status()> call;
  };
  boreas_lidar_def bad = good;
  bad.dropout = -0.5f;
  boreas_pose unnormal = boreas_default_pose();
  unnormal.orientation[3] = 2.0f;
  boreas_depth_camera_def camera = boreas_default_depth_camera_def();
  camera.fx = NAN;
  float depth[4];
  boreas_lidar_point point;
  int count = 0;
  const std::vector<Row> rows = {
      {"def is NULL", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_world_add_lidar(world_, nullptr, nullptr); }},
      {"dropout", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_world_add_lidar(world_, &bad, nullptr); }},
      {"pose is NULL", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_lidar_set_pose(world_, id, nullptr); }},
      {"pose.orientation", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_lidar_set_pose(world_, id, &unnormal); }},
      {"which", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] {
         return boreas_lidar_get_points(world_, id, boreas_lidar_points(7), nullptr, 0, &count);
       }},
      {"count is NULL", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] {
         return boreas_lidar_get_points(world_, id, BOREAS_LIDAR_LAST_STEP, &point, 1, nullptr);
       }},
      {"null LiDAR id", BOREAS_ERROR_NOT_FOUND,
       [&] { return boreas_lidar_set_pose(world_, boreas_lidar_id{}, &unnormal); }},
      {"camera is NULL", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_world_capture_depth(world_, nullptr, depth, nullptr); }},
      {"fx", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_world_capture_depth(world_, &camera, depth, nullptr); }},
      {"no LiDAR preset named \"HDL-16\"", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_lidar_preset("HDL-16", &good); }},
      {"name is NULL", BOREAS_ERROR_INVALID_ARGUMENT,
       [&] { return boreas_lidar_preset(nullptr, &good); }},
  };
  for (const Row& row : rows) {
    const boreas_status got = row.call();
    EXPECT_EQ(got, row.expect) << row.names << ": " << boreas_last_error();
    EXPECT_NE(std::string(boreas_last_error()).find(row.names), std::string::npos)
        << row.names << " not in: " << boreas_last_error();
    EXPECT_EQ(hash_of(world_), before) << row.names;
  }
  EXPECT_EQ(good.channels, boreas_default_lidar_def().channels);  // a refused preset wrote nothing
}

TEST(SensorsPose, BetweenTwoPosesIsTheLidarsMotionAndRefusesBadPoses) {
  boreas_pose a = boreas_default_pose(), b = a;
  b.position[0] = 4.0f;
  b.orientation[1] = float(std::sin(M_PI / 4));  // a quarter turn about +Y
  b.orientation[3] = float(std::cos(M_PI / 4));
  const boreas_pose half = boreas::pose_between(a, b, 0.5f);
  EXPECT_FLOAT_EQ(half.position[0], 2.0f);
  EXPECT_NEAR(half.orientation[1], std::sin(M_PI / 8), 1e-6);  // an eighth turn
  EXPECT_NEAR(half.orientation[3], std::cos(M_PI / 8), 1e-6);
  const boreas_pose end = boreas::pose_between(a, b, 1.0f);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(end.orientation[i], b.orientation[i], 1e-6);
  boreas_pose out{}, bad = a;
  bad.orientation[3] = 2.0f;
  EXPECT_EQ(boreas_pose_between(&a, &bad, 0.5f, &out), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("b.orientation"), std::string::npos) << boreas_last_error();
  EXPECT_EQ(boreas_pose_between(&a, &b, 1.5f, &out), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("s must be in [0"), std::string::npos) << boreas_last_error();
  EXPECT_EQ(boreas_pose_between(nullptr, &b, 0.5f, &out), BOREAS_ERROR_INVALID_ARGUMENT);
}

TEST_F(SensorsApi, CppMirrorsPresetsAndDefaults) {
  const boreas_lidar_def d = boreas::lidar_preset("HDL-32E");
  EXPECT_EQ(d.channels, 32);
  EXPECT_NEAR(d.vertical_angles[0], -30.67 * M_PI / 180.0, 1e-6);
  EXPECT_NEAR(d.vertical_angles[31], 10.67 * M_PI / 180.0, 1e-6);
  EXPECT_STREQ(boreas::lidar_preset_name(0), "VLP-16");
  EXPECT_EQ(boreas::lidar_preset_name(4), nullptr);
  EXPECT_EQ(boreas::default_pose().orientation[3], 1.0f);
}

TEST_F(SensorsApi, LidarOverFlatGroundSeesTheGroundWhereTheRaysMeetIt) {
  const boreas_meadow_id ground = add_flat_ground(0.0f);
  boreas_lidar_def def = boreas_default_lidar_def();
  def.pose.position[1] = 1.5f;
  def.range_noise = 0.0f;
  def.max_range = 9.0f;  // within the ground's 10 m half-width
  boreas_lidar_id id{};
  ASSERT_EQ(boreas_world_add_lidar(world_, &def, &id), BOREAS_OK) << boreas_last_error();
  for (int s = 0; s < 7; ++s) ASSERT_EQ(boreas_world_step(world_, 1.0f / 60.0f), BOREAS_OK);
  int count = 0;
  ASSERT_EQ(boreas_lidar_get_points(world_, id, BOREAS_LIDAR_LAST_SWEEP, nullptr, 0, &count),
            BOREAS_OK);
  std::vector<boreas_lidar_point> points(static_cast<size_t>(count));
  ASSERT_EQ(
      boreas_lidar_get_points(world_, id, BOREAS_LIDAR_LAST_SWEEP, points.data(), count, &count),
      BOREAS_OK);
  // Rings whose ray meets the ground within 9 m: elevation below -asin(1.5 / 9).
  int expected_rings = 0;
  for (int r = 0; r < 16; ++r) {
    const double e = -15.0 + 2.0 * r;  // degrees, the default field of view
    if (e < 0 && 1.5 / std::sin(-e * M_PI / 180.0) <= 9.0) ++expected_rings;
  }
  EXPECT_EQ(count, expected_rings * def.points_per_turn);
  for (const boreas_lidar_point& p : points) {
    EXPECT_NEAR(p.y, 0.0f, 1e-3);
    EXPECT_EQ(p.kind, BOREAS_HIT_GROUND);
    boreas_hit as_hit{};
    as_hit.kind = p.kind;
    as_hit.object = p.object;
    EXPECT_TRUE(boreas_meadow_id_equal(boreas_hit_meadow(&as_hit), ground));
  }
}

TEST_F(SensorsApi, DepthOfFlatGroundFromAboveIsTheHeightInEveryPixel) {
  const boreas_meadow_id ground = add_flat_ground(0.25f);
  ASSERT_EQ(boreas_world_step(world_, 1.0f / 60.0f), BOREAS_OK);
  boreas_depth_camera_def camera = boreas_default_depth_camera_def();
  camera.width = 32;
  camera.height = 24;
  camera.fx = camera.fy = 20.0f;
  camera.cx = 15.5f;
  camera.cy = 11.5f;
  camera.pose.position[1] = 2.25f;
  camera.pose.orientation[0] = -float(std::sqrt(0.5));  // looking straight down
  camera.pose.orientation[3] = float(std::sqrt(0.5));
  std::vector<float> depth(32 * 24);
  std::vector<boreas_pixel_label> labels(32 * 24);
  ASSERT_EQ(boreas_world_capture_depth(world_, &camera, depth.data(), labels.data()), BOREAS_OK)
      << boreas_last_error();
  for (size_t i = 0; i < depth.size(); ++i) {
    EXPECT_NEAR(depth[i], 2.0f, 1e-3)
        << i;  // depth along the axis: the height, h / cos / (1 / cos)
    EXPECT_EQ(labels[i].kind, BOREAS_HIT_GROUND);
    boreas_hit as_hit{};
    as_hit.kind = labels[i].kind;
    as_hit.object = labels[i].object;
    EXPECT_TRUE(boreas_meadow_id_equal(boreas_hit_meadow(&as_hit), ground));
  }
}

// A LiDAR's state is part of the world's, so equal worlds with
// equal LiDARs hash equal and another seed's noise shows.
TEST_F(SensorsApi, StateHashFollowsTheLidarsSeed) {
  add_flat_ground(0.0f);
  auto run = [&](uint64_t seed) {
    boreas_world w = nullptr;
    EXPECT_EQ(boreas::test::create_small_windy_world(&w), BOREAS_OK);
    boreas_meadow_def m = boreas_default_meadow_def();
    m.size[0] = m.size[1] = 20.0f;
    m.density = 0.0f;
    EXPECT_EQ(boreas_world_add_meadow(w, &m, nullptr), BOREAS_OK);
    boreas_lidar_def def = boreas_default_lidar_def();
    def.pose.position[1] = 1.5f;
    def.seed = seed;
    EXPECT_EQ(boreas_world_add_lidar(w, &def, nullptr), BOREAS_OK);
    for (int s = 0; s < 3; ++s) EXPECT_EQ(boreas_world_step(w, 1.0f / 60.0f), BOREAS_OK);
    const uint64_t h = hash_of(w);
    boreas_world_destroy(w);
    return h;
  };
  EXPECT_EQ(run(5), run(5));
  EXPECT_NE(run(5), run(6));
}

// A LiDAR point's ray: its ring and its firing within the turn (its time since the sweep
// began, in firings, rounded: the times of one firing agree to far better than half one).
// The default def's firings per second.
std::pair<int, int64_t> ray_key(const boreas_lidar_point& p) {
  const boreas_lidar_def d = boreas_default_lidar_def();
  const double firings_per_second = double(d.points_per_turn) * double(d.rotation_rate);
  return {int(p.ring), int64_t(std::llround(double(p.time) * firings_per_second))};
}

std::map<std::pair<int, int64_t>, boreas_lidar_point> keyed_by_ray(
    const std::vector<boreas_lidar_point>& points) {
  std::map<std::pair<int, int64_t>, boreas_lidar_point> out;
  for (const boreas_lidar_point& p : points) out[ray_key(p)] = p;
  return out;
}

// Halfway up a tree's crown: between its lowest first-level branch's base and its top.
float crown_middle(boreas_world w, boreas_tree_id tree) {
  int n = 0;
  EXPECT_EQ(boreas_tree_get_branches(w, tree, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_branch> b(static_cast<size_t>(n));
  EXPECT_EQ(boreas_tree_get_branches(w, tree, b.data(), n, &n), BOREAS_OK);
  float low = INFINITY, top = 0.0f;
  for (const boreas_branch& br : b) {
    if (br.level == 1) low = std::fmin(low, br.control_points[0][1]);
    for (int c = 0; c < 4; ++c) top = std::fmax(top, br.control_points[c][1]);
  }
  return 0.5f * (low + top);
}

// The points of a LiDAR on a tree's branches and leaves.
std::vector<boreas_lidar_point> tree_points_of(boreas_world w, boreas_lidar_id id,
                                               boreas_lidar_points which) {
  int n = 0;
  EXPECT_EQ(boreas_lidar_get_points(w, id, which, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_lidar_point> p(static_cast<size_t>(n)), out;
  EXPECT_EQ(boreas_lidar_get_points(w, id, which, p.data(), n, &n), BOREAS_OK);
  for (const boreas_lidar_point& q : p)
    if (q.kind == BOREAS_HIT_BRANCH || q.kind == BOREAS_HIT_LEAF) out.push_back(q);
  return out;
}

// How far (m) each point lies from what a ray cast now from `origin` through it meets first
// (infinity where it meets nothing): 0 for a point on the world's surfaces as they stand.
std::vector<float> off_surface(boreas_world w, const float origin[3],
                               const std::vector<boreas_lidar_point>& points) {
  std::vector<boreas_ray> rays;
  std::vector<float> range;
  for (const boreas_lidar_point& p : points) {
    const float d[3] = {p.x - origin[0], p.y - origin[1], p.z - origin[2]};
    rays.push_back({{origin[0], origin[1], origin[2]}, {d[0], d[1], d[2]}, INFINITY});
    range.push_back(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
  }
  std::vector<boreas_hit> hits(rays.size());
  if (!rays.empty())
    EXPECT_EQ(boreas_world_cast_rays(w, rays.data(), int(rays.size()), hits.data()), BOREAS_OK)
        << boreas_last_error();
  std::vector<float> off(points.size());
  for (size_t i = 0; i < points.size(); ++i) off[i] = std::fabs(hits[i].distance - range[i]);
  return off;
}

// The scan moves with the trees: without noise, in still air two sweeps of a tree are the
// same bits, and in wind the points on the tree move between sweeps while the ground's
// stay.
TEST(SensorsScan, PointsOnATreeMoveWithTheWindAndStayInStillAir) {
  auto sweeps = [](float amplitude) {
    boreas_world_def wd = boreas_default_world_def();
    boreas_world w = nullptr;
    EXPECT_EQ(boreas_world_create(&wd, &w), BOREAS_OK);
    boreas_wave wave = boreas_default_wave();
    wave.amplitude = amplitude;
    EXPECT_EQ(boreas_wind_set_waves(w, &wave, amplitude > 0.0f ? 1 : 0, 0.0f), BOREAS_OK);
    boreas_tree_def t = boreas_default_tree_def();
    t.position[0] = 6.0f;
    EXPECT_EQ(boreas_world_add_tree(w, &t, nullptr), BOREAS_OK);
    boreas_lidar_def def = boreas_default_lidar_def();
    def.pose.position[1] = 2.0f;
    def.range_noise = 0.0f;
    def.dropout = 0.0f;
    boreas_lidar_id id{};
    EXPECT_EQ(boreas_world_add_lidar(w, &def, &id), BOREAS_OK) << boreas_last_error();
    std::vector<std::vector<boreas_lidar_point>> out;
    const int steps_per_turn = int(std::lround(60.0 / def.rotation_rate));
    for (int s = 1; s <= 3 * steps_per_turn; ++s) {
      EXPECT_EQ(boreas_world_step(w, 1.0f / 60.0f), BOREAS_OK);
      if (s % steps_per_turn != 0 || s == steps_per_turn) continue;
      int n = 0;
      EXPECT_EQ(boreas_lidar_get_points(w, id, BOREAS_LIDAR_LAST_SWEEP, nullptr, 0, &n), BOREAS_OK);
      std::vector<boreas_lidar_point> p(static_cast<size_t>(n));
      EXPECT_EQ(boreas_lidar_get_points(w, id, BOREAS_LIDAR_LAST_SWEEP, p.data(), n, &n), BOREAS_OK);
      out.push_back(p);
    }
    boreas_world_destroy(w);
    return out;
  };
  auto tree_points = [](const std::vector<boreas_lidar_point>& p) {
    std::vector<boreas_lidar_point> t;
    for (const boreas_lidar_point& q : p)
      if (q.kind == BOREAS_HIT_BRANCH || q.kind == BOREAS_HIT_LEAF) t.push_back(q);
    return t;
  };
  const auto still = sweeps(0.0f), windy = sweeps(12.0f);
  ASSERT_EQ(still.size(), 2u);
  ASSERT_EQ(windy.size(), 2u);
  const auto s0 = tree_points(still[0]), s1 = tree_points(still[1]);
  ASSERT_GT(s0.size(), 100u) << "the LiDAR must see the tree";
  ASSERT_EQ(s0.size(), s1.size());
  for (size_t i = 0; i < s0.size(); ++i) {
    EXPECT_EQ(s0[i].x, s1[i].x);
    EXPECT_EQ(s0[i].y, s1[i].y);
    EXPECT_EQ(s0[i].z, s1[i].z);
  }
  // In wind: a share of the tree's points is elsewhere a sweep later. The scan sees the
  // trunk below the crown, which sways by tenths of a millimetre there (its tip by about a
  // centimetre between the sweeps: crowns reconfigure in a 12 m/s wind, README "Storms");
  // a float at 6 m resolves a micrometre.
  // The two sweeps' points are paired by their ray (ring and firing), not by their order:
  // a point the wind took off the tree in one sweep and onto it in the other has no pair.
  const auto w0 = tree_points(windy[0]), w1 = tree_points(windy[1]);
  ASSERT_GT(w0.size(), 100u);
  const std::map<std::pair<int, int64_t>, boreas_lidar_point> by_ray = keyed_by_ray(w1);
  size_t paired = 0, moved = 0;
  for (const boreas_lidar_point& p : w0) {
    auto q = by_ray.find(ray_key(p));
    if (q == by_ray.end()) continue;
    ++paired;
    moved += std::fabs(p.x - q->second.x) + std::fabs(p.y - q->second.y) +
                 std::fabs(p.z - q->second.z) > 5e-5f;
  }
  ASSERT_GT(paired, w0.size() / 2) << "the two sweeps must see mostly the same rays' hits";
  EXPECT_GT(moved, paired / 10) << moved << " of " << paired;
}

// A sweep is gathered over steps, each casting its slice against the plants as they stand
// then, so a sweep of a swaying tree holds it at several moments (a real unit's smear). On a
// world: every step's points lie on the surfaces of that step (a ray cast then along the
// point's ray meets them at its range); the sweep is those points, from several steps; and
// cast again after the sweep, many of the earlier steps' points on the tree are off it.
TEST(SensorsScan, ASweepHoldsTheSwayingTreeAsEachStepLeftIt) {
  boreas_world_def wd = boreas_default_world_def();
  boreas_world w = nullptr;
  ASSERT_EQ(boreas_world_create(&wd, &w), BOREAS_OK);
  boreas_wave wave = boreas_default_wave();
  wave.amplitude = 12.0f;
  ASSERT_EQ(boreas_wind_set_waves(w, &wave, 1, 0.0f), BOREAS_OK);
  boreas_tree_def t = boreas_default_tree_def();
  t.position[0] = 5.0f;
  boreas_tree_id tree{};
  ASSERT_EQ(boreas_world_add_tree(w, &t, &tree), BOREAS_OK);
  boreas_lidar_def def = boreas_default_lidar_def();
  def.pose.position[1] = crown_middle(w, tree);
  def.range_noise = 0.0f;
  def.dropout = 0.0f;
  boreas_lidar_id id{};
  ASSERT_EQ(boreas_world_add_lidar(w, &def, &id), BOREAS_OK) << boreas_last_error();
  const int steps_per_turn = int(std::lround(60.0 / def.rotation_rate));
  // Each tree point as its step left it, and the step that cast it.
  std::vector<std::pair<boreas_lidar_point, int>> cast_at;
  size_t on_own = 0, cast_count = 0;
  for (int s = 1; s <= 2 * steps_per_turn + 1; ++s) {
    ASSERT_EQ(boreas_world_step(w, 1.0f / 60.0f), BOREAS_OK);
    const std::vector<boreas_lidar_point> step_points =
        tree_points_of(w, id, BOREAS_LIDAR_LAST_STEP);
    const std::vector<float> offs = off_surface(w, def.pose.position, step_points);
    for (size_t i = 0; i < step_points.size(); ++i) {
      on_own += offs[i] < 2e-5f;
      ++cast_count;
      cast_at.push_back({step_points[i], s});
    }
  }
  ASSERT_GT(cast_count, 500u) << "the LiDAR must see the tree";
  EXPECT_GE(on_own, cast_count * 99 / 100) << "a step's points lie on that step's surfaces";
  // The last complete sweep: each of its tree points is one a step cast, bit for bit.
  const std::vector<boreas_lidar_point> sweep = tree_points_of(w, id, BOREAS_LIDAR_LAST_SWEEP);
  ASSERT_GT(sweep.size(), 100u);
  std::map<int, size_t> from_step;
  std::vector<boreas_lidar_point> earlier;
  for (const boreas_lidar_point& p : sweep) {
    int step = 0;
    for (const auto& [q, cast_step] : cast_at)
      if (q.ring == p.ring && q.x == p.x && q.y == p.y && q.z == p.z && q.time == p.time)
        step = cast_step;
    ASSERT_NE(step, 0) << "a sweep point no step cast";
    ++from_step[step];
    if (step < 2 * steps_per_turn + 1) earlier.push_back(p);
  }
  // The tree spans some 70 degrees of the turn's 360: two or three of its six steps.
  EXPECT_GE(from_step.size(), 2u) << "a sweep's points on the tree come from several steps";
  // Against the tree as it stands now the earlier points are off it: the sweep is smeared.
  const std::vector<float> offs = off_surface(w, def.pose.position, earlier);
  size_t off = 0;
  for (float o : offs) off += o > 1e-4f;
  EXPECT_GT(off, earlier.size() / 10) << off << " of " << earlier.size();
  std::printf("sweep: %zu tree points from %zu steps, %zu of the %zu from earlier steps off the "
              "tree as it stands; %zu of %zu step points on their step's surfaces\n",
              sweep.size(), from_step.size(), off, earlier.size(), on_own, cast_count);
  boreas_world_destroy(w);
}

}  // namespace
