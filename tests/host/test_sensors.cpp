// Library tests: the sensors' own math, on hits the tests make analytically (a ground
// plane, a sphere around the sensor), so they hold without the world's ray structure:
// presets against their makers' tables, the firing schedule over steps, points on their
// rays, range noise and dropout measured, pose interpolation, intensity, the depth image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "sensors/depth_camera.h"
#include "sensors/lidar.h"
#include "sensors/lidar_params.h"
#include "sensors/lidar_presets.h"
#include "sensors/lidar_scan.h"
#include "sensors/lidar_sweep.h"
#include "support/expect_error.h"

namespace {

namespace impl = boreas::impl;
using boreas::test::expect_error;
constexpr double kPi = 3.14159265358979323846;
const boreas_object_id kGroundId = {3u, 1u, 0x54u};

double dot(const double* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The plane y = height seen from either side: a hit where the ray crosses it.
impl::RayCaster plane_caster(double height) {
  return [height](const boreas_ray* rays, int count, boreas_hit* hits) {
    for (int i = 0; i < count; ++i) {
      const boreas_ray& r = rays[i];
      boreas_hit h{};
      h.distance = INFINITY;
      h.part = -1;
      const double len = std::sqrt(double(r.direction[0]) * r.direction[0] +
                                   double(r.direction[1]) * r.direction[1] +
                                   double(r.direction[2]) * r.direction[2]);
      const double dy = r.direction[1] / len;
      const double t = dy != 0.0 ? (height - r.origin[1]) / dy : -1.0;
      if (t > 0.0 && t <= r.max_distance) {
        h.distance = float(t);
        h.kind = BOREAS_HIT_GROUND;
        h.object = kGroundId;
        h.part = 0;
        for (int a = 0; a < 3; ++a) h.point[a] = float(r.origin[a] + t * r.direction[a] / len);
        h.normal[1] = dy < 0.0 ? 1.0f : -1.0f;
      }
      hits[i] = h;
    }
  };
}

// Every ray hits at `radius` (a sphere around the sensor), head on.
impl::RayCaster sphere_caster(float radius, int32_t kind = BOREAS_HIT_LEAF) {
  return [radius, kind](const boreas_ray* rays, int count, boreas_hit* hits) {
    for (int i = 0; i < count; ++i) {
      boreas_hit h{};
      h.distance = radius;
      h.kind = kind;
      h.part = 0;
      for (int a = 0; a < 3; ++a) h.normal[a] = -rays[i].direction[a];
      hits[i] = h;
    }
  };
}

// A caster that keeps every ray it was handed, then asks `inner`.
struct Recorder {
  impl::RayCaster inner;
  std::vector<boreas_ray> rays;
  impl::RayCaster caster() {
    return [this](const boreas_ray* r, int count, boreas_hit* hits) {
      rays.insert(rays.end(), r, r + count);
      inner(r, count, hits);
    };
  }
};

impl::LidarParams params(boreas_lidar_def def = boreas_default_lidar_def()) {
  return impl::checked_lidar_def(def);
}

TEST(LidarPresets, AnglesAreTheMakersTables) {
  // The manuals' tables, from their stated first angle and spacing.
  auto check = [](const char* name, double lowest, double spacing, double tolerance) {
    std::vector<double> table = impl::lidar_preset_table_degrees(name);
    std::sort(table.begin(), table.end());
    for (size_t i = 0; i < table.size(); ++i)
      EXPECT_NEAR(table[i], lowest + spacing * double(i), tolerance) << name << " ring " << i;
  };
  check("VLP-16", -15.0, 2.0, 0.0);
  check("HDL-32E", -92.0 / 3.0, 4.0 / 3.0, 0.005);  // thirds of a degree, printed to two decimals
  check("OS1-128", -22.5, 45.0 / 127.0, 1e-9);
  std::vector<double> hdl64 = impl::lidar_preset_table_degrees("HDL-64E");
  ASSERT_EQ(hdl64.size(), 64u);
  EXPECT_DOUBLE_EQ(hdl64.front(), 2.0);  // the upper block's top laser
  EXPECT_NEAR(hdl64[31], -8.33, 0.005);
  EXPECT_NEAR(hdl64[32], -8.83, 1e-9);  // the lower block's
  EXPECT_NEAR(hdl64[63], -24.33, 1e-9);
  // The VLP-16 manual interleaves its lasers: id 0 at -15, id 1 at +1, ...
  const std::vector<double>& vlp = impl::lidar_preset_table_degrees("VLP-16");
  EXPECT_EQ(vlp[0], -15.0);
  EXPECT_EQ(vlp[1], 1.0);
  EXPECT_EQ(vlp[15], 15.0);
}

TEST(LidarPresets, DefsAreValidWithRingsFromLowestToHighest) {
  const std::map<std::string, int> channels = {
      {"VLP-16", 16}, {"HDL-32E", 32}, {"HDL-64E", 64}, {"OS1-128", 128}};
  std::set<std::string> seen;
  for (int i = 0; const char* name = impl::lidar_preset_name(i); ++i) {
    seen.insert(name);
    const boreas_lidar_def d = impl::lidar_preset(name);
    ASSERT_EQ(d.channels, channels.at(name));
    std::vector<double> table = impl::lidar_preset_table_degrees(name);
    std::sort(table.begin(), table.end());
    for (int r = 0; r < d.channels; ++r)
      EXPECT_NEAR(d.vertical_angles[r], table[size_t(r)] * kPi / 180.0, 1e-6) << name << r;
    const impl::LidarParams p = impl::checked_lidar_def(d);
    EXPECT_EQ(p.channels(), d.channels);
  }
  EXPECT_EQ(seen.size(), channels.size());
  EXPECT_EQ(impl::lidar_preset("vlp-16").channels, 16);  // names match in any case
  expect_error([] { impl::lidar_preset("VLP-17"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"VLP-17", "VLP-16", "HDL-32E", "HDL-64E", "OS1-128"});
}

TEST(LidarDef, FieldOfViewSpreadsEvenlyFromTheLowest) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.channels = 5;
  d.vertical_fov[0] = -0.4f;
  d.vertical_fov[1] = 0.4f;
  const impl::LidarParams p = params(d);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(p.elevations[size_t(i)], -0.4 + 0.2 * i, 1e-7);
  d.channels = 1;
  EXPECT_NEAR(params(d).elevations[0], 0.0, 1e-7);
}

TEST(LidarDef, BadFieldsAreRefusedByName) {
  struct Case {
    const char* names;
    void (*poke)(boreas_lidar_def&);
  };
  static const float kNan = NAN;
  const Case cases[] = {
      {"channels", [](boreas_lidar_def& d) { d.channels = 0; }},
      {"channels", [](boreas_lidar_def& d) { d.channels = BOREAS_LIDAR_MAX_CHANNELS + 1; }},
      {"vertical_angles[1]",
       [](boreas_lidar_def& d) {
         static const float angles[2] = {0.0f, 2.0f};
         d.channels = 2;
         d.vertical_angles = angles;
       }},
      {"vertical_angles[0]",
       [](boreas_lidar_def& d) {
         d.channels = 1;
         d.vertical_angles = &kNan;
       }},
      {"vertical_fov[0] must not exceed",
       [](boreas_lidar_def& d) { std::swap(d.vertical_fov[0], d.vertical_fov[1]); }},
      {"points_per_turn", [](boreas_lidar_def& d) { d.points_per_turn = 0; }},
      {"channels * points_per_turn", [](boreas_lidar_def& d) { d.points_per_turn = 1 << 20; }},
      {"rotation_rate", [](boreas_lidar_def& d) { d.rotation_rate = 0.0f; }},
      {"min_range must be below max_range", [](boreas_lidar_def& d) { d.min_range = 200.0f; }},
      {"max_range", [](boreas_lidar_def& d) { d.max_range = -1.0f; }},
      {"range_noise", [](boreas_lidar_def& d) { d.range_noise = -0.1f; }},
      {"dropout", [](boreas_lidar_def& d) { d.dropout = 1.5f; }},
      {"reflectivity[2]", [](boreas_lidar_def& d) { d.reflectivity[2] = NAN; }},
      {"pose.position[1]", [](boreas_lidar_def& d) { d.pose.position[1] = INFINITY; }},
      {"pose.orientation must be a unit quaternion",
       [](boreas_lidar_def& d) { d.pose.orientation[3] = 0.0f; }},
      {"pose.orientation[2]", [](boreas_lidar_def& d) { d.pose.orientation[2] = NAN; }},
  };
  for (const Case& c : cases) {
    boreas_lidar_def d = boreas_default_lidar_def();
    c.poke(d);
    expect_error([&] { impl::checked_lidar_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT, {c.names});
  }
}

TEST(LidarPose, NearUnitQuaternionsAreNormalizedOthersRefused) {
  boreas_pose pose = boreas_default_pose();
  pose.orientation[3] = 1.0009f;
  const impl::Pose p = impl::checked_pose(pose, "pose");
  EXPECT_NEAR(p.rotation[3], 1.0, 1e-15);
  pose.orientation[3] = 1.002f;
  expect_error([&] { impl::checked_pose(pose, "pose"); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {"pose.orientation", "unit quaternion"});
}

TEST(LidarPose, TurnAndInBetweenAgreeWithAnglesAboutUp) {
  // A turn by a about +Y takes +X to (cos a, 0, -sin a): azimuth a of the LiDAR's frame.
  auto about_y = [](double a) {
    impl::Pose p;
    p.rotation = {0.0, std::sin(a / 2), 0.0, std::cos(a / 2)};
    return p;
  };
  const impl::Vec3d x = about_y(0.7).turn({1.0, 0.0, 0.0});
  const impl::Vec3d az = impl::lidar_direction(0.0, 0.7);
  for (size_t a = 0; a < 3; ++a) EXPECT_NEAR(x[a], az[a], 1e-15);
  // Half way between turns by 0.2 and 1.0 rad is the turn by 0.6 (spherical, not linear).
  const impl::Pose mid = impl::between(about_y(0.2), about_y(1.0), 0.5);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(mid.rotation[i], about_y(0.6).rotation[i], 1e-12);
  // q and -q are the same turn: between them nothing moves.
  impl::Pose negated = about_y(0.2);
  for (double& c : negated.rotation) c = -c;
  const impl::Vec3d same = impl::between(about_y(0.2), negated, 0.5).turn({1.0, 0.0, 0.0});
  const impl::Vec3d want = about_y(0.2).turn({1.0, 0.0, 0.0});
  for (size_t a = 0; a < 3; ++a) EXPECT_NEAR(same[a], want[a], 1e-12);
}

TEST(LidarSweep, StepsOfAnyLengthCastEveryFiringOnceAndATurnPerPeriod) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.points_per_turn = 360;
  d.rotation_rate = 7.0f;
  const impl::LidarParams p = params(d);
  const double start = 0.25;
  double t = start;
  int64_t next = 0;
  std::vector<int64_t> cast;
  const double dts[] = {1.0 / 60, 0.013, 1.0 / 7, 0.0001, 0.05, 1.0 / 240};
  for (int s = 0; s < 600; ++s) {
    const double t1 = t + dts[s % 6];
    const impl::Firings f = impl::step_firings(next, t1, start, p);
    ASSERT_EQ(f.first, next);  // no step is longer than two turns here: nothing skipped
    for (int64_t k = f.first; k < f.end; ++k) {
      cast.push_back(k);
      const double when = impl::firing_time(k, start, p);
      EXPECT_GE(when, t - 1e-9) << k;  // inside its step
      EXPECT_LT(when, t1 + 1e-9) << k;
    }
    next = f.end;
    t = t1;
  }
  for (size_t i = 0; i < cast.size(); ++i) ASSERT_EQ(cast[i], int64_t(i));
  // Each period 1 / rate holds one turn: every azimuth once.
  const int64_t turns = int64_t((t - start) * 7.0) - 1;
  ASSERT_GT(turns, 10);
  for (int64_t turn = 0; turn < turns; ++turn) {
    std::set<double> azimuths;
    for (int64_t k = 0; k < int64_t(cast.size()); ++k) {
      const double when = impl::firing_time(k, start, p) - start;
      if (when >= turn / 7.0 - 1e-12 && when < (turn + 1) / 7.0 - 1e-12)
        azimuths.insert(impl::firing_azimuth(k, p));
    }
    ASSERT_EQ(azimuths.size(), 360u) << "turn " << turn;
    EXPECT_NEAR(*azimuths.begin(), 0.0, 1e-12);
    EXPECT_NEAR(*azimuths.rbegin(), 2 * kPi * 359 / 360, 1e-12);
  }
}

TEST(LidarSweep, AStepLongerThanATurnKeepsTheLastCompleteSweepAndTheOneUnderWay) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.points_per_turn = 100;
  const impl::LidarParams p = params(d);  // 10 Hz: 1000 firings a second
  const impl::Firings f = impl::step_firings(0, 3.55, 0.0, p);
  EXPECT_EQ(f.end, 3550);
  EXPECT_EQ(f.first, 3400);  // sweep 34 (complete) and sweep 35 (half)
}

TEST(Lidar, SweepsGatherOverStepsWithEveryRingAndAzimuth) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.points_per_turn = 200;
  d.range_noise = 0.0f;
  impl::Lidar lidar(params(d), 0.0);
  const impl::RayCaster sphere = sphere_caster(5.0f);
  double t = 0.0;
  for (int s = 0; s < 37; ++s) {  // 37 steps of 1/60 s: 0.6167 s, six sweeps done
    lidar.commit(lidar.cast(t, t + 1.0 / 60, sphere));
    t += 1.0 / 60;
  }
  const boreas_lidar_info info = lidar.info();
  EXPECT_EQ(info.sweeps, 6);
  EXPECT_NEAR(info.sweep_start, 0.5, 1e-12);
  EXPECT_NEAR(info.next_sweep_start, 0.6, 1e-12);
  EXPECT_EQ(info.firings, int64_t(std::ceil(t * 2000.0 - 1e-9)));
  const std::vector<boreas_lidar_point>& sweep = lidar.last_sweep();
  ASSERT_EQ(sweep.size(), 200u * 16u);
  std::set<std::pair<int, float>> seen;
  for (size_t i = 0; i < sweep.size(); ++i) {
    EXPECT_EQ(sweep[i].ring, i % 16);
    EXPECT_NEAR(sweep[i].time, double(i / 16) / 2000.0, 1e-7);  // since the sweep began
    seen.insert({sweep[i].ring, sweep[i].time});
  }
  EXPECT_EQ(seen.size(), sweep.size());
}

TEST(Lidar, PointsOfAStepLieOnThatStepsRaysAtTheNoisyRange) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.range_noise = 0.05f;
  d.pose.position[1] = 2.0f;
  impl::Lidar lidar(params(d), 0.0);
  boreas_pose moved = d.pose;
  moved.position[0] = 0.3f;  // driving along +x during the step
  moved.orientation[1] = float(std::sin(0.1));
  moved.orientation[3] = float(std::cos(0.1));
  lidar.set_pose(impl::checked_pose(moved, "pose"));
  Recorder rec{plane_caster(0.0)};
  lidar.commit(lidar.cast(0.0, 0.05, rec.caster()));
  const std::vector<boreas_lidar_point>& points = lidar.last_step();
  ASSERT_GT(points.size(), 1000u);              // the lower half of 16 channels x 900 azimuths
  const size_t firings = rec.rays.size() / 16;  // those in [0, 0.05 s) at 18000 a second
  ASSERT_GE(firings, 900u);
  ASSERT_LE(firings, 901u);
  // Point i comes from its ray: the next ray of its ring whose hit is on the ground.
  size_t ray = 0;
  double worst = 0.0;
  for (const boreas_lidar_point& pt : points) {
    while (ray < rec.rays.size() && (int(ray % 16) != pt.ring || rec.rays[ray].direction[1] >= 0))
      ++ray;
    ASSERT_LT(ray, rec.rays.size());
    const boreas_ray& r = rec.rays[ray++];
    const double rel[3] = {pt.x - double(r.origin[0]), pt.y - double(r.origin[1]),
                           pt.z - double(r.origin[2])};
    const double along = dot(rel, r.direction);
    const double cross[3] = {rel[1] * r.direction[2] - rel[2] * r.direction[1],
                             rel[2] * r.direction[0] - rel[0] * r.direction[2],
                             rel[0] * r.direction[1] - rel[1] * r.direction[0]};
    const double across =
        std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    worst = std::max(worst, across / along);
    EXPECT_EQ(pt.kind, BOREAS_HIT_GROUND);
    EXPECT_TRUE(boreas_object_id_equal(pt.object, kGroundId));
    const double true_range = -r.origin[1] / r.direction[1];
    EXPECT_LT(std::fabs(along - true_range), 6 * 0.05);  // within six sigma
    // Intensity: ground reflectivity times |cos| between the ray and the ground's normal.
    EXPECT_NEAR(pt.intensity, 0.3 * std::fabs(r.direction[1]), 1e-6);
  }
  EXPECT_LT(worst, 1e-6);  // on the ray, up to float rounding
  // The ray of a firing at time tk starts where the pose is at tk: moving linearly in x.
  for (size_t k = 0; k < 900; k += 100) {
    const double s = (double(k) / 18000.0) / 0.05;
    EXPECT_NEAR(rec.rays[k * 16].origin[0], 0.3 * s, 1e-6) << k;
    EXPECT_NEAR(rec.rays[k * 16].origin[1], 2.0, 1e-6) << k;
  }
}

TEST(Lidar, RangeNoiseAndDropoutHaveTheirSetStatistics) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.range_noise = 0.04f;
  d.dropout = 0.25f;
  impl::Lidar lidar(params(d), 0.0);
  lidar.commit(lidar.cast(0.0, 0.1, sphere_caster(10.0f)));  // one turn: 28800 rays
  const std::vector<boreas_lidar_point>& points = lidar.last_step();
  const double n_rays = lidar.info().last_step_rays, kept = double(points.size());
  ASSERT_GE(n_rays, 1800.0 * 16.0);
  const double drop = 1.0 - kept / n_rays;
  EXPECT_NEAR(drop, 0.25, 4.0 * std::sqrt(0.25 * 0.75 / n_rays));
  double sum = 0.0, sum2 = 0.0;
  for (const boreas_lidar_point& pt : points) {
    const double e =
        std::sqrt(double(pt.x) * pt.x + double(pt.y) * pt.y + double(pt.z) * pt.z) - 10.0;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / kept, sd = std::sqrt(sum2 / kept - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4.0 * 0.04 / std::sqrt(kept));
  EXPECT_NEAR(sd, 0.04, 4.0 * 0.04 / std::sqrt(2.0 * kept) + 2e-6);  // + float rounding of x, y, z
}

TEST(Lidar, TheSameSeedGivesTheSamePointsHoweverStepsCutTheSweep) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.range_noise = 0.1f;
  d.dropout = 0.1f;
  auto sweep_with = [&](double dt, uint64_t seed) {
    d.seed = seed;
    impl::Lidar lidar(params(d), 0.0);
    double t = 0.0;
    while (lidar.info().sweeps < 2) {
      lidar.commit(lidar.cast(t, t + dt, sphere_caster(7.0f)));
      t += dt;
    }
    return lidar.last_sweep();
  };
  const auto a = sweep_with(1.0 / 60, 9), b = sweep_with(1.0 / 25, 9), c = sweep_with(1.0 / 60, 10);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])), 0);
  EXPECT_FALSE(a.size() == c.size() &&
               std::memcmp(a.data(), c.data(), a.size() * sizeof(a[0])) == 0);
}

TEST(Lidar, MissesAndHitsNearerThanMinRangeGiveNoPoint) {
  boreas_lidar_def d = boreas_default_lidar_def();
  d.pose.position[1] = 1.0f;
  d.min_range = 3.0f;
  impl::Lidar lidar(params(d), 0.0);
  lidar.commit(lidar.cast(0.0, 0.1, plane_caster(0.0)));
  ASSERT_FALSE(lidar.last_step().empty());
  for (const boreas_lidar_point& pt : lidar.last_step()) {
    const double range =
        std::sqrt(double(pt.x) * pt.x + (pt.y - 1.0) * (pt.y - 1.0) + double(pt.z) * pt.z);
    EXPECT_GE(range, 3.0 - 6 * 0.015);
    EXPECT_LT(pt.y, 0.1);  // upward rays miss: no point above the ground
  }
}

TEST(DepthCamera, FlatGroundSeenFromAboveIsAtTheCamerasHeight) {
  boreas_depth_camera_def def = boreas_default_depth_camera_def();
  def.width = 64;
  def.height = 48;
  def.fx = def.fy = 40.0f;
  def.cx = 31.5f;
  def.cy = 23.5f;
  def.pose.position[1] = 1.7f;
  def.pose.orientation[0] = float(-std::sqrt(0.5));  // -90 degrees about +X: looking down
  def.pose.orientation[3] = float(std::sqrt(0.5));
  const impl::DepthCamera camera = impl::checked_depth_camera_def(def);
  std::vector<float> depth(64 * 48);
  std::vector<boreas_pixel_label> labels(64 * 48);
  impl::capture_depth(camera, plane_caster(0.0), depth.data(), labels.data());
  // Depth along the optical axis is the height everywhere; the distance along each pixel's
  // ray is h / cos of its angle to the axis.
  const std::vector<boreas_ray> rays = impl::depth_rays(camera);
  for (int v = 0; v < 48; ++v) {
    for (int u = 0; u < 64; ++u) {
      const size_t i = size_t(v) * 64 + size_t(u);
      EXPECT_NEAR(depth[i], 1.7, 2e-6) << u << "," << v;
      EXPECT_EQ(labels[i].kind, BOREAS_HIT_GROUND);
      EXPECT_TRUE(boreas_object_id_equal(labels[i].object, kGroundId));
      const double du = (u - 31.5) / 40.0, dv = (v - 23.5) / 40.0;
      const double cosine = 1.0 / std::sqrt(1.0 + du * du + dv * dv);
      EXPECT_NEAR(-rays[i].direction[1], cosine, 1e-6);
      // Image right is world +x; image down is world +z (the camera's +Y, its top, is -z).
      EXPECT_NEAR(rays[i].direction[0], du * cosine, 1e-6);
      EXPECT_NEAR(rays[i].direction[2], dv * cosine, 1e-6);
    }
  }
  // Beyond max_depth: nothing.
  def.max_depth = 1.5f;
  impl::capture_depth(impl::checked_depth_camera_def(def), plane_caster(0.0), depth.data(),
                      labels.data());
  for (size_t i = 0; i < depth.size(); ++i) {
    EXPECT_EQ(depth[i], INFINITY);
    EXPECT_EQ(labels[i].kind, BOREAS_HIT_NONE);
    EXPECT_EQ(labels[i].part, -1);
  }
}

TEST(DepthCamera, BadFieldsAreRefusedByName) {
  struct Case {
    const char* names;
    void (*poke)(boreas_depth_camera_def&);
  };
  const Case cases[] = {
      {"width", [](boreas_depth_camera_def& d) { d.width = 0; }},
      {"height", [](boreas_depth_camera_def& d) { d.height = -3; }},
      {"width * height", [](boreas_depth_camera_def& d) { d.width = d.height = 5000; }},
      {"fx", [](boreas_depth_camera_def& d) { d.fx = 0.0f; }},
      {"fy", [](boreas_depth_camera_def& d) { d.fy = NAN; }},
      {"cx", [](boreas_depth_camera_def& d) { d.cx = INFINITY; }},
      {"cy", [](boreas_depth_camera_def& d) { d.cy = NAN; }},
      {"max_depth", [](boreas_depth_camera_def& d) { d.max_depth = 0.0f; }},
      {"pose.orientation", [](boreas_depth_camera_def& d) { d.pose.orientation[0] = 1.0f; }},
  };
  for (const Case& c : cases) {
    boreas_depth_camera_def d = boreas_default_depth_camera_def();
    c.poke(d);
    expect_error([&] { impl::checked_depth_camera_def(d); }, BOREAS_ERROR_INVALID_ARGUMENT,
                 {c.names});
  }
}

}  // namespace
