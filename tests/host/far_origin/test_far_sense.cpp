// Far from the origin, what a simulator reads (issues 40 and 37): rays cast at a tree, a
// meadow and an imported tree standing 100 km out measure what the same rays measure at the
// world's 0, a collider placed there in double (its pose's origin) pushes a tree as one
// near 0 does, and a LiDAR and a depth camera there see what they see near 0. At 100 km a
// float is 8 mm apart: rays or poses kept in float world coordinates would miss the 1e-4 m
// asked here by millimetres (the collider's position 100000.2537 rounds 4 mm off), so each
// test also checks that its far scene is one a float world coordinate cannot hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "host/mesh_trees/tube_trees.h"
#include "support/temp_dir.h"
#include "support/test_support.h"

namespace boreas {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr double kTolerance = 1e-4;  // m
constexpr double kFar[3] = {1.0e5, 0.0, -1.0e5};

struct World {
  boreas_world w = nullptr;
  World() {
    boreas_world_def def = boreas_default_world_def();
    const boreas_wave wave = test::steady_wave(1.0f, 0.4f, 8.0f);
    def.grid = test::calm_grid();
    def.waves = &wave;
    def.wave_count = 1;
    EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_OK) << boreas_last_error();
  }
  ~World() { boreas_world_destroy(w); }
  World(const World&) = delete;
  World& operator=(const World&) = delete;
};

void step(boreas_world w, int steps) {
  for (int s = 0; s < steps; ++s) ASSERT_EQ(boreas_world_step(w, kDt), BOREAS_OK) << boreas_last_error();
}

void set_origin(boreas_world w, const double* origin) {
  ASSERT_EQ(boreas_world_set_output_origin(w, origin), BOREAS_OK) << boreas_last_error();
}

// A tree, a meadow beside it and an imported tree behind, all about `at` (m, world).
void plant_stand(boreas_world w, const double* at, const std::string& obj) {
  boreas_tree_def tree = boreas_default_tree_def();
  for (int a = 0; a < 3; ++a) tree.position[a] = float(at[a]);
  boreas_tree_id t;
  ASSERT_EQ(boreas_world_add_tree(w, &tree, &t), BOREAS_OK) << boreas_last_error();
  boreas_meadow_def meadow = boreas_default_meadow_def();
  meadow.center[0] = float(at[0] + 4.0);
  meadow.center[1] = float(at[1]);
  meadow.center[2] = float(at[2]);
  meadow.size[0] = meadow.size[1] = 2.0f;
  meadow.density = 200.0f;
  meadow.seed = 3;
  meadow.terrain_relief = 0.2f;
  boreas_meadow_id m;
  ASSERT_EQ(boreas_world_add_meadow(w, &meadow, &m), BOREAS_OK) << boreas_last_error();
  boreas_mesh_tree_def mesh = boreas_default_mesh_tree_def();
  mesh.model = obj.c_str();
  mesh.cache = 0;
  mesh.position[0] = float(at[0] - 4.0);
  mesh.position[1] = float(at[1]);
  mesh.position[2] = float(at[2]);
  boreas_mesh_tree_id mt;
  ASSERT_EQ(boreas_world_add_mesh_tree(w, &mesh, &mt), BOREAS_OK) << boreas_last_error();
}

// A fan of rays from 12 m in front of the stand (relative to the output origin), aimed at
// points of the plane z = 0 from the ground to a crown's height across the imported tree,
// the tree and the meadow.
std::vector<boreas_ray> fan() {
  const float from[3] = {0.0037f, 1.0f, 12.0f};  // 0.0037: off any far float grid
  std::vector<boreas_ray> rays;
  for (int row = 0; row < 24; ++row)
    for (int col = 0; col < 64; ++col) {
      boreas_ray r{};
      const float to[3] = {-6.0f + 12.0f * float(col) / 63.0f, -0.2f + 9.0f * float(row) / 23.0f,
                           0.0f};
      for (int c = 0; c < 3; ++c) {
        r.origin[c] = from[c];
        r.direction[c] = to[c] - from[c];
      }
      r.max_distance = 40.0f;
      rays.push_back(r);
    }
  // And straight down onto the meadow from 3 m up, between and onto its blades.
  for (int k = 0; k < 256; ++k) {
    boreas_ray r{};
    r.origin[0] = 3.2037f + 1.6f * float(k % 16) / 15.0f;
    r.origin[1] = 3.0f;
    r.origin[2] = -0.8f + 1.6f * float(k / 16) / 15.0f;
    r.direction[1] = -1.0f;
    r.max_distance = 10.0f;
    rays.push_back(r);
  }
  return rays;
}

std::vector<boreas_hit> cast(boreas_world w, const std::vector<boreas_ray>& rays) {
  std::vector<boreas_hit> hits(rays.size());
  EXPECT_EQ(boreas_world_cast_rays(w, rays.data(), int(rays.size()), hits.data()), BOREAS_OK)
      << boreas_last_error();
  return hits;
}

// Two stands in one world, one at 0 and one 100 km out, in the same wind: the same rays,
// relative to each stand's output origin, hit the same parts at the same distances.
TEST(FarSense, RaysAtAStandHundredKilometresOutMeasureAsAtTheOrigin) {
  World world;
  test::TempDir dir;
  const std::string obj = test::write_tube_tree_obj(dir.path());
  const double near[3] = {0.0, 0.0, 0.0};
  plant_stand(world.w, near, obj);
  plant_stand(world.w, kFar, obj);
  step(world.w, 30);
  const std::vector<boreas_ray> rays = fan();
  set_origin(world.w, near);
  const std::vector<boreas_hit> a = cast(world.w, rays);
  set_origin(world.w, kFar);
  const std::vector<boreas_hit> b = cast(world.w, rays);
  int kinds[9] = {};
  double largest = 0.0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_EQ(a[i].kind, b[i].kind) << "ray " << i;
    ASSERT_EQ(a[i].part, b[i].part) << "ray " << i;
    ++kinds[a[i].kind];
    if (a[i].kind == BOREAS_HIT_NONE) continue;
    largest = std::max(largest, std::fabs(double(a[i].distance) - double(b[i].distance)));
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, std::fabs(double(a[i].point[c]) - double(b[i].point[c])));
  }
  std::printf("rays 100 km out: %d branch, %d leaf, %d imported, %d underbrush, %d ground hits; "
              "distances and points differ by up to %.2g m\n",
              kinds[BOREAS_HIT_BRANCH], kinds[BOREAS_HIT_LEAF],
              kinds[BOREAS_HIT_MESH_TRUNK] + kinds[BOREAS_HIT_MESH_LEAF],
              kinds[BOREAS_HIT_UNDERBRUSH], kinds[BOREAS_HIT_GROUND], largest);
  EXPECT_GT(kinds[BOREAS_HIT_BRANCH], 0);
  EXPECT_GT(kinds[BOREAS_HIT_LEAF], 0);
  EXPECT_GT(kinds[BOREAS_HIT_MESH_TRUNK] + kinds[BOREAS_HIT_MESH_LEAF], 0);
  EXPECT_GT(kinds[BOREAS_HIT_UNDERBRUSH], 0);
  EXPECT_GT(kinds[BOREAS_HIT_GROUND], 0);
  EXPECT_LE(largest, kTolerance);
  // The same rays in float world coordinates (output origin 0) start millimetres off
  // (0.0037 m is no float 100 km out) and measure so: what the output origin is for.
  set_origin(world.w, nullptr);
  std::vector<boreas_ray> in_world = rays;
  for (boreas_ray& r : in_world)
    for (int c = 0; c < 3; ++c) r.origin[c] = float(kFar[c] + double(r.origin[c]));
  const std::vector<boreas_hit> w = cast(world.w, in_world);
  double world_largest = 0.0;
  for (size_t i = 0; i < rays.size(); ++i)
    if (w[i].kind == a[i].kind && w[i].part == a[i].part && a[i].kind != BOREAS_HIT_NONE)
      world_largest = std::max(world_largest, std::fabs(double(a[i].distance) - double(w[i].distance)));
  std::printf("the same rays in float world coordinates: distances differ by up to %.2g m\n",
              world_largest);
  EXPECT_GT(world_largest, 1e-3);
}

// Moving the output origin moves where the rays count from at the next cast (the structure
// is rebuilt in the new frame): a ray from world point P hits the same as one from P - O.
TEST(FarSense, RaysFollowTheOutputOriginWhenItMoves) {
  World world;
  test::TempDir dir;
  const std::string obj = test::write_tube_tree_obj(dir.path());
  const double near[3] = {0.0, 0.0, 0.0};
  plant_stand(world.w, near, obj);
  step(world.w, 5);
  const std::vector<boreas_ray> rays = fan();
  const std::vector<boreas_hit> a = cast(world.w, rays);
  const double shifted[3] = {2.0, 0.5, -3.0};
  set_origin(world.w, shifted);
  std::vector<boreas_ray> moved = rays;
  for (boreas_ray& r : moved)
    for (int c = 0; c < 3; ++c) r.origin[c] = float(double(r.origin[c]) - shifted[c]);
  const std::vector<boreas_hit> b = cast(world.w, moved);
  int hit = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_EQ(a[i].kind, b[i].kind) << "ray " << i;
    ASSERT_EQ(a[i].part, b[i].part) << "ray " << i;
    if (a[i].kind == BOREAS_HIT_NONE) continue;
    ++hit;
    EXPECT_NEAR(a[i].distance, b[i].distance, kTolerance) << "ray " << i;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(double(a[i].point[c]) - shifted[c], b[i].point[c], kTolerance) << "ray " << i;
  }
  EXPECT_GT(hit, 100);
}

// A sphere pressed into a tree's trunk at 0.2537 m from its base (and rolling on at 0.3 m/s)
// pushes a tree 100 km out, placed by its pose's origin in double, as it pushes one at 0.
TEST(FarSense, ColliderPlacedInDoublePushesATreeFarOutAsAtTheOrigin) {
  World world;
  const double near[3] = {0.0, 0.0, 0.0};
  boreas_tree_id ids[2];
  boreas_collider_id colliders[2];
  const float offset[3] = {0.2537f, 1.5f, -0.0411f};
  for (int k = 0; k < 2; ++k) {
    const double* at = k == 0 ? near : kFar;
    boreas_tree_def def = boreas_default_tree_def();
    for (int a = 0; a < 3; ++a) def.position[a] = float(at[a]);
    ASSERT_EQ(boreas_world_add_tree(world.w, &def, &ids[k]), BOREAS_OK) << boreas_last_error();
    boreas_collider_def c = boreas_default_collider_def();
    c.radius = 0.25f;
    c.velocity[2] = 0.3f;
    for (int a = 0; a < 3; ++a) {
      c.pose.origin[a] = at[a];
      c.pose.position[a] = offset[a];
    }
    ASSERT_EQ(boreas_world_add_collider(world.w, &c, &colliders[k]), BOREAS_OK) << boreas_last_error();
  }
  // What a float world position would have put there instead.
  EXPECT_GT(std::fabs(double(float(kFar[0] + offset[0])) - (kFar[0] + double(offset[0]))), 1e-3);
  double largest = 0.0, pushed = 0.0;
  std::vector<boreas_branch> a, b;
  for (int s = 1; s <= 90; ++s) {
    ASSERT_EQ(boreas_world_step(world.w, kDt), BOREAS_OK) << boreas_last_error();
    boreas_collider_contact ca{}, cb{};
    ASSERT_EQ(boreas_collider_get_contact(world.w, colliders[0], &ca), BOREAS_OK);
    ASSERT_EQ(boreas_collider_get_contact(world.w, colliders[1], &cb), BOREAS_OK);
    EXPECT_EQ(ca.contacts, cb.contacts) << "step " << s;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(ca.force[c], cb.force[c], 1e-3 * (1.0 + std::fabs(ca.force[c]))) << "step " << s;
      EXPECT_NEAR(ca.torque[c], cb.torque[c], 1e-3 * (1.0 + std::fabs(ca.torque[c]))) << "step " << s;
    }
    pushed = std::max(pushed, double(ca.contacts));
  }
  for (int k = 0; k < 2; ++k) {
    set_origin(world.w, k == 0 ? near : kFar);
    int count = 0;
    ASSERT_EQ(boreas_tree_get_branches(world.w, ids[k], nullptr, 0, &count), BOREAS_OK);
    (k == 0 ? a : b).resize(size_t(count));
    ASSERT_EQ(boreas_tree_get_branches(world.w, ids[k], (k == 0 ? a : b).data(), count, &count),
              BOREAS_OK);
  }
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
    for (int p = 0; p < 4; ++p)
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::fabs(double(a[i].control_points[p][c]) -
                                              double(b[i].control_points[p][c])));
  // The pose moved on from its origin: the same offset from each origin.
  boreas_pose pa{}, pb{};
  ASSERT_EQ(boreas_collider_get_pose(world.w, colliders[0], &pa), BOREAS_OK);
  ASSERT_EQ(boreas_collider_get_pose(world.w, colliders[1], &pb), BOREAS_OK);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(pb.origin[c], kFar[c]);
    EXPECT_EQ(pa.position[c], pb.position[c]);
  }
  EXPECT_NEAR(pb.position[2], offset[2] + 90 * kDt * 0.3, 1e-5) << "it rolled on";
  std::printf("collider 100 km out: %g contacts at most; branches differ by up to %.2g m\n", pushed,
              largest);
  EXPECT_GT(pushed, 0.0) << "the sphere should touch the tree";
  EXPECT_LE(largest, kTolerance);
}

// A LiDAR and a depth camera 100 km out, placed in double, see what they see near 0: the
// same points relative to the output origin at the stand (so relative to themselves).
TEST(FarSense, SensorsHundredKilometresOutSeeAsAtTheOrigin) {
  test::TempDir dir;
  const std::string obj = test::write_tube_tree_obj(dir.path());
  const double near[3] = {0.0, 0.0, 0.0};
  const float mount[3] = {0.0037f, 1.2f, 9.0041f};
  std::vector<boreas_lidar_point> points[2];
  std::vector<float> depth[2];
  boreas_depth_camera_def cam = boreas_default_depth_camera_def();
  cam.width = 64;
  cam.height = 48;
  cam.fx = cam.fy = 40.0f;
  cam.cx = 31.5f;
  cam.cy = 23.5f;
  for (int k = 0; k < 2; ++k) {
    const double* at = k == 0 ? near : kFar;
    World world;
    plant_stand(world.w, at, obj);
    set_origin(world.w, at);
    boreas_lidar_def lidar = boreas_default_lidar_def();
    lidar.range_noise = 0.0f;
    lidar.max_range = 30.0f;
    for (int a = 0; a < 3; ++a) {
      lidar.pose.origin[a] = at[a];
      lidar.pose.position[a] = mount[a];
    }
    boreas_lidar_id id;
    ASSERT_EQ(boreas_world_add_lidar(world.w, &lidar, &id), BOREAS_OK) << boreas_last_error();
    step(world.w, 7);  // past one turn at 10 Hz
    int count = 0;
    ASSERT_EQ(boreas_lidar_get_points(world.w, id, BOREAS_LIDAR_LAST_SWEEP, nullptr, 0, &count),
              BOREAS_OK);
    points[k].resize(size_t(count));
    ASSERT_EQ(boreas_lidar_get_points(world.w, id, BOREAS_LIDAR_LAST_SWEEP, points[k].data(), count,
                                      &count),
              BOREAS_OK);
    cam.pose = boreas_default_pose();
    for (int a = 0; a < 3; ++a) {
      cam.pose.origin[a] = at[a];
      cam.pose.position[a] = mount[a];
    }
    depth[k].resize(size_t(cam.width * cam.height));
    ASSERT_EQ(boreas_world_capture_depth(world.w, &cam, depth[k].data(), nullptr), BOREAS_OK)
        << boreas_last_error();
  }
  ASSERT_EQ(points[0].size(), points[1].size());
  ASSERT_GT(points[0].size(), 100u);
  double largest = 0.0;
  for (size_t i = 0; i < points[0].size(); ++i) {
    const boreas_lidar_point &p = points[0][i], &q = points[1][i];
    ASSERT_EQ(p.kind, q.kind) << "point " << i;
    ASSERT_EQ(p.part, q.part) << "point " << i;
    largest = std::max({largest, std::fabs(double(p.x) - q.x), std::fabs(double(p.y) - q.y),
                        std::fabs(double(p.z) - q.z)});
  }
  int seen = 0;
  double depth_largest = 0.0;
  for (size_t i = 0; i < depth[0].size(); ++i) {
    ASSERT_EQ(std::isinf(depth[0][i]), std::isinf(depth[1][i])) << "pixel " << i;
    if (std::isinf(depth[0][i])) continue;
    ++seen;
    depth_largest = std::max(depth_largest, std::fabs(double(depth[0][i]) - depth[1][i]));
  }
  std::printf("sensors 100 km out: %zu LiDAR points differ by up to %.2g m; %d pixels' depths by "
              "up to %.2g m\n",
              points[0].size(), largest, seen, depth_largest);
  EXPECT_GT(seen, 100);
  EXPECT_LE(largest, kTolerance);
  EXPECT_LE(depth_largest, kTolerance);
}

// A pose's origin is checked like its position, and boreas_pose_between goes from origin to
// origin in double; boreas_collider_set_position takes a world position (origin 0).
TEST(FarSense, PoseOriginIsCheckedAndKeptInDouble) {
  World world;
  boreas_collider_def c = boreas_default_collider_def();
  c.pose.origin[1] = NAN;
  boreas_collider_id id;
  EXPECT_EQ(boreas_world_add_collider(world.w, &c, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("pose.origin[1]"), std::string::npos)
      << boreas_last_error();
  c.pose.origin[1] = 2e7;
  EXPECT_EQ(boreas_world_add_collider(world.w, &c, &id), BOREAS_ERROR_INVALID_ARGUMENT);
  c.pose.origin[1] = 0.0;
  c.pose.origin[0] = 100000.0037;
  ASSERT_EQ(boreas_world_add_collider(world.w, &c, &id), BOREAS_OK) << boreas_last_error();
  boreas_pose now{};
  ASSERT_EQ(boreas_collider_get_pose(world.w, id, &now), BOREAS_OK);
  EXPECT_EQ(now.origin[0], 100000.0037);
  const float center[3] = {1.0f, 2.0f, 3.0f};
  ASSERT_EQ(boreas_collider_set_position(world.w, id, center), BOREAS_OK);
  ASSERT_EQ(boreas_collider_get_pose(world.w, id, &now), BOREAS_OK);
  EXPECT_EQ(now.origin[0], 0.0);
  EXPECT_EQ(now.position[0], 1.0f);

  boreas_pose a = boreas_default_pose(), b = boreas_default_pose(), mid{};
  a.origin[0] = 100000.0037;
  b.origin[0] = 100002.0037;
  a.position[1] = 1.0f;
  b.position[1] = 3.0f;
  ASSERT_EQ(boreas_pose_between(&a, &b, 0.5f, &mid), BOREAS_OK) << boreas_last_error();
  EXPECT_NEAR(mid.origin[0] + mid.position[0], 100001.0037, 1e-9);
  EXPECT_NEAR(mid.origin[1] + mid.position[1], 2.0, 1e-6);
  b.origin[2] = INFINITY;
  EXPECT_EQ(boreas_pose_between(&a, &b, 0.5f, &mid), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("b.origin[2]"), std::string::npos)
      << boreas_last_error();
}

}  // namespace
}  // namespace boreas
