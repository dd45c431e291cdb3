// boreas tests: the C and C++ API contract — defaults, bad arguments that change nothing,
// stale ids, and the C++ layer's errors.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "boreas/boreas.h"
#include "boreas/boreas.hpp"

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

class Api : public ::testing::Test {
 protected:
  // world_ gets the refused calls; twin_ gets the same valid history and nothing else.
  void SetUp() override {
    for (boreas_world* w : {&world_, &twin_}) {
      boreas_world_def def = boreas_default_world_def();
      def.grid.resolution[0] = 8;
      def.grid.resolution[1] = 4;
      def.grid.resolution[2] = 8;
      ASSERT_EQ(boreas_world_create(&def, w), BOREAS_OK) << boreas_last_error();
      boreas_wave wave = boreas_default_wave();
      ASSERT_EQ(boreas_wind_set_waves(*w, &wave, 1, 0.0f), BOREAS_OK);
      boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
      p.radius = 6.0f;
      boreas_primitive_id id;
      ASSERT_EQ(boreas_wind_add_primitive(*w, &p, &id), BOREAS_OK);
      ASSERT_EQ(boreas_world_step(*w, 0.5f), BOREAS_OK);
    }
  }
  void TearDown() override {
    boreas_world_destroy(world_);
    boreas_world_destroy(twin_);
  }

  // The wind at a few points: a fingerprint of a world's state.
  static std::vector<float> fingerprint(boreas_world w) {
    std::vector<float> xyz = {0, 1, 0, 5, 2, -3, -20, 3, 17}, f(9);
    EXPECT_EQ(boreas_wind_sample(w, xyz.data(), 3, f.data()), BOREAS_OK);
    return f;
  }

  // A call that must be refused as an invalid argument, naming `mention`, and change
  // nothing: now, and after both worlds step on (a primitive or a wave set slipped in
  // would only show then), world_ must match its untouched twin bit for bit.
  template <typename Call>
  void expect_refused(Call call, const std::string& mention) {
    boreas_status s = call();
    EXPECT_EQ(s, BOREAS_ERROR_INVALID_ARGUMENT) << boreas_status_name(s);
    EXPECT_NE(std::string(boreas_last_error()).find(mention), std::string::npos)
        << "message: " << boreas_last_error();
    EXPECT_EQ(boreas_world_get_time(world_), boreas_world_get_time(twin_));
    EXPECT_EQ(fingerprint(world_), fingerprint(twin_));
    ASSERT_EQ(boreas_world_step(world_, 0.7f), BOREAS_OK);
    ASSERT_EQ(boreas_world_step(twin_, 0.7f), BOREAS_OK);
    EXPECT_EQ(fingerprint(world_), fingerprint(twin_)) << "after a step";
  }

  boreas_world world_ = nullptr;
  boreas_world twin_ = nullptr;
};

TEST_F(Api, DefaultWorldIsCalm) {
  boreas_world_def def = boreas_default_world_def();
  EXPECT_EQ(def.waves, nullptr);
  EXPECT_EQ(def.wave_count, 0);
  boreas::World calm(def);
  calm.step(1.0f);
  boreas::Vec3 f = calm.wind_sample(boreas::Vec3{3, 2, 1});
  EXPECT_EQ(f.x, 0.0f);
  EXPECT_EQ(f.y, 0.0f);
  EXPECT_EQ(f.z, 0.0f);
  EXPECT_DOUBLE_EQ(calm.get_time(), 1.0);
}

// The twin comparison can tell: accepted changes that do not show at once (a wave set
// blending in from weight 0, a new primitive) do show after the step.
TEST_F(Api, TwinComparisonSeesChangesThatShowOnlyLater) {
  boreas_wave other = boreas_default_wave();
  other.direction[1] = 1.0f;
  ASSERT_EQ(boreas_wind_set_waves(world_, &other, 1, 1.0f), BOREAS_OK);
  EXPECT_EQ(fingerprint(world_), fingerprint(twin_)) << "weight 0 at the change";
  ASSERT_EQ(boreas_world_step(world_, 0.7f), BOREAS_OK);
  ASSERT_EQ(boreas_world_step(twin_, 0.7f), BOREAS_OK);
  EXPECT_NE(fingerprint(world_), fingerprint(twin_));
  boreas_flow_primitive_def vortex = boreas_default_flow_primitive_def();
  vortex.type = BOREAS_FLOW_VORTEX;
  vortex.radius = 8.0f;
  vortex.direction[1] = 1.0f;
  boreas_primitive_id id;
  ASSERT_EQ(boreas_wind_add_primitive(twin_, &vortex, &id), BOREAS_OK);
  std::vector<float> before = fingerprint(twin_);
  ASSERT_EQ(boreas_world_step(twin_, 0.7f), BOREAS_OK);
  EXPECT_NE(fingerprint(twin_), before);
}

// The header's version macros and the library's boreas_version() are one version, and
// BOREAS_VERSION orders them.
TEST(Version, HeaderAndLibraryAgree) {
  const std::string expected = std::to_string(BOREAS_VERSION_MAJOR) + "." +
                               std::to_string(BOREAS_VERSION_MINOR) + "." +
                               std::to_string(BOREAS_VERSION_PATCH);
  ASSERT_NE(boreas_version(), nullptr);
  EXPECT_EQ(std::string(boreas_version()), expected);
  EXPECT_EQ(BOREAS_VERSION,
            BOREAS_VERSION_MAJOR * 10000 + BOREAS_VERSION_MINOR * 100 + BOREAS_VERSION_PATCH);
  static_assert(BOREAS_VERSION_MINOR < 100 && BOREAS_VERSION_PATCH < 100,
                "BOREAS_VERSION packs minor and patch in two digits each");
}

// boreas_world_get_memory reports the bytes the runtime counts against its limit: they
// grow with what the world holds, stay under the limit, and the limit is the one
// BOREAS_DEVICE_MEMORY sets. Kernel variants appear once a step has built kernels.
TEST(WorldMemory, CountsDeviceBuffersAgainstTheLimitAndKernels) {
  const char* saved = std::getenv("BOREAS_DEVICE_MEMORY");
  const std::string saved_text = saved ? saved : "";
  ASSERT_EQ(setenv("BOREAS_DEVICE_MEMORY", "300M", 1), 0);
  boreas_world_def def = boreas_default_world_def();
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 4;
  boreas_world world = nullptr;
  const boreas_status created = boreas_world_create(&def, &world);
  if (saved)
    setenv("BOREAS_DEVICE_MEMORY", saved_text.c_str(), 1);
  else
    unsetenv("BOREAS_DEVICE_MEMORY");
  ASSERT_EQ(created, BOREAS_OK) << boreas_last_error();
  boreas_memory_info empty{};
  ASSERT_EQ(boreas_world_get_memory(world, &empty), BOREAS_OK) << boreas_last_error();
  EXPECT_EQ(empty.device_limit, 300ull << 20);
  // The grid's cells: two halves of 4 floats per cell, at least.
  EXPECT_GE(empty.device_bytes, 2ull * 8 * 4 * 8 * 4 * sizeof(float));
  EXPECT_LE(empty.device_bytes, empty.device_limit);
  boreas_tree_def tree = boreas_default_tree_def();
  ASSERT_EQ(boreas_world_add_tree(world, &tree, nullptr), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_world_step(world, 0.02f), BOREAS_OK) << boreas_last_error();
  boreas_memory_info with_tree{};
  ASSERT_EQ(boreas_world_get_memory(world, &with_tree), BOREAS_OK);
  // A tree of a few thousand branches: its state, motion and shape are well over 100 kB.
  EXPECT_GT(with_tree.device_bytes, empty.device_bytes + 100000);
  EXPECT_LE(with_tree.device_bytes, with_tree.device_limit);
  EXPECT_GT(with_tree.kernel_variants, 0);
  EXPECT_EQ(boreas_world_get_memory(world, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("out is NULL"), std::string::npos);
  boreas_world_destroy(world);
}

// The device bytes boreas_world_get_memory reports once PoCL has freed what the world let
// go (it may free on a thread of its own after the commands that used a buffer are done):
// the first reading at or under `at_most`, or the last after a second.
uint64_t device_bytes_falling_to(boreas_world world, uint64_t at_most) {
  boreas_memory_info info{};
  for (int k = 0; k < 100; ++k) {
    EXPECT_EQ(boreas_world_get_memory(world, &info), BOREAS_OK) << boreas_last_error();
    if (info.device_bytes <= at_most) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return info.device_bytes;
}

boreas_world small_grid_world() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 4;
  boreas_world world = nullptr;
  EXPECT_EQ(boreas_world_create(&def, &world), BOREAS_OK) << boreas_last_error();
  return world;
}

std::vector<boreas_tree_def> aspens_of_four_seeds(int count) {
  std::vector<boreas_tree_def> defs(size_t(count), boreas_default_tree_def());
  for (int i = 0; i < count; ++i) {
    defs[size_t(i)].seed = uint64_t(1 + i % 4);
    defs[size_t(i)].position[0] = float(i % 8) * 6.0f;
    defs[size_t(i)].position[2] = float(i / 8) * 6.0f;
  }
  return defs;
}

// The header's promise, read where a user reads it: once trees are removed, the device
// bytes a world holds fall to within 4 times what its present population needs. 64 aspens
// of 4 seeds, 60 removed: the trees' share (device bytes past the empty world's) must come
// within 4 times that of a fresh world holding the 4 that are left. At the peak it is far
// above that, so a world whose buffers only grow fails.
TEST(WorldMemory, FollowsThePopulationDownThroughTheCApi) {
  boreas_world fresh = small_grid_world(), churned = small_grid_world();
  ASSERT_TRUE(fresh && churned);
  boreas_memory_info empty{};
  ASSERT_EQ(boreas_world_get_memory(churned, &empty), BOREAS_OK);
  const std::vector<boreas_tree_def> defs = aspens_of_four_seeds(64);
  std::vector<boreas_tree_id> ids(defs.size());
  ASSERT_EQ(boreas_world_add_trees(churned, defs.data(), 64, ids.data()), BOREAS_OK)
      << boreas_last_error();
  ASSERT_EQ(boreas_world_add_trees(fresh, defs.data(), 4, nullptr), BOREAS_OK)
      << boreas_last_error();
  ASSERT_EQ(boreas_world_step(churned, 0.02f), BOREAS_OK);
  ASSERT_EQ(boreas_world_step(fresh, 0.02f), BOREAS_OK);
  boreas_memory_info peak{}, needed{};
  ASSERT_EQ(boreas_world_get_memory(churned, &peak), BOREAS_OK);
  ASSERT_EQ(boreas_world_get_memory(fresh, &needed), BOREAS_OK);
  const uint64_t need = needed.device_bytes - empty.device_bytes;
  ASSERT_GT(peak.device_bytes - empty.device_bytes, 4 * need)
      << "64 trees must hold more than 4 times what 4 of them need, or this test cannot fail";
  uint64_t last = peak.device_bytes;
  for (int i = 63; i >= 4; --i) {
    ASSERT_EQ(boreas_world_remove_tree(churned, ids[size_t(i)]), BOREAS_OK) << boreas_last_error();
    const uint64_t now = device_bytes_falling_to(churned, last);
    EXPECT_LE(now, last) << "removing tree " << i << " grew the world";
    last = now;
  }
  ASSERT_EQ(boreas_world_step(churned, 0.02f), BOREAS_OK);
  const uint64_t after = device_bytes_falling_to(churned, empty.device_bytes + 4 * need);
  EXPECT_LE(after - empty.device_bytes, 4 * need)
      << "after: " << after << " B, empty " << empty.device_bytes << " B, 4 trees alone "
      << needed.device_bytes << " B";
  boreas_world_destroy(fresh);
  boreas_world_destroy(churned);
}

TEST(StepStats, SplitTheLastStepByStage) {
  // A tree and a meadow give every stage work; the stages' device times are parts of the
  // step, so they are non-negative and together within the call's wall time.
  boreas_world_def def = boreas_default_world_def();
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 4;
  boreas_world world = nullptr;
  ASSERT_EQ(boreas_world_create(&def, &world), BOREAS_OK) << boreas_last_error();
  boreas_step_stats s{1.0, 1.0, 1.0, 1.0};
  ASSERT_EQ(boreas_world_get_step_stats(world, &s), BOREAS_OK);
  EXPECT_EQ(s.total, 0.0) << "before the first step";
  boreas_tree_def tree = boreas_default_tree_def();
  boreas_tree_id tree_id;
  ASSERT_EQ(boreas_world_add_tree(world, &tree, &tree_id), BOREAS_OK) << boreas_last_error();
  boreas_meadow_def meadow = boreas_default_meadow_def();
  meadow.size[0] = meadow.size[1] = 4.0f;
  boreas_meadow_id meadow_id;
  ASSERT_EQ(boreas_world_add_meadow(world, &meadow, &meadow_id), BOREAS_OK) << boreas_last_error();
  ASSERT_EQ(boreas_world_step(world, 0.1f), BOREAS_OK);
  ASSERT_EQ(boreas_world_get_step_stats(world, &s), BOREAS_OK);
  EXPECT_GT(s.total, 0.0);
  EXPECT_GE(s.wind, 0.0);
  EXPECT_GT(s.trees, 0.0);
  EXPECT_GT(s.underbrush, 0.0);
  EXPECT_LE(s.wind + s.trees + s.underbrush, s.total * 1.001 + 1e-6);
  EXPECT_EQ(boreas_world_get_step_stats(world, nullptr), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("out is NULL"), std::string::npos);
  boreas_world_destroy(world);
}

TEST_F(Api, StepAdvancesTimeAndRefusesBadDt) {
  EXPECT_DOUBLE_EQ(boreas_world_get_time(world_), 0.5);
  expect_refused([&] { return boreas_world_step(world_, 0.0f); }, "dt");
  expect_refused([&] { return boreas_world_step(world_, -1.0f); }, "dt");
  expect_refused([&] { return boreas_world_step(world_, kNaN); }, "dt");
  expect_refused([&] { return boreas_world_step(world_, kInf); }, "dt");
  expect_refused([&] { return boreas_world_step(world_, 4000.0f); }, "dt");
  expect_refused([&] { return boreas_world_step(nullptr, 0.1f); }, "world is NULL");
}

TEST_F(Api, SetWavesRefusesBadWaves) {
  boreas_wave good = boreas_default_wave();
  auto with = [&](auto change) {
    boreas_wave waves[2] = {good, good};
    change(waves[1]);
    return [this, waves]() mutable { return boreas_wind_set_waves(world_, waves, 2, 1.0f); };
  };
  expect_refused(with([](boreas_wave& w) { w.wavelength = 0.0f; }), "waves[1].wavelength");
  expect_refused(with([](boreas_wave& w) { w.wavelength = -3.0f; }), "waves[1].wavelength");
  expect_refused(with([](boreas_wave& w) { w.direction[0] = w.direction[1] = 0.0f; }),
                 "waves[1].direction");
  expect_refused(with([](boreas_wave& w) { w.amplitude = kNaN; }), "waves[1].amplitude");
  expect_refused(with([](boreas_wave& w) { w.speed = kInf; }), "waves[1].speed");
  expect_refused(with([](boreas_wave& w) { w.sharpness = -1.0f; }), "waves[1].sharpness");
  expect_refused(with([](boreas_wave& w) { w.amplitude = -2.0f; }), "waves[1].amplitude");
  expect_refused([&] { return boreas_wind_set_waves(world_, &good, -1, 0.0f); }, "count");
  expect_refused([&] { return boreas_wind_set_waves(world_, nullptr, 2, 0.0f); }, "NULL");
  expect_refused([&] { return boreas_wind_set_waves(world_, &good, 1, -1.0f); }, "blend_seconds");
  expect_refused([&] { return boreas_wind_set_waves(world_, &good, 1, kNaN); }, "blend_seconds");
}

TEST_F(Api, PrimitivesAndGustsRefuseBadValuesAndCatchStaleIds) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  boreas_primitive_id id{};
  boreas_flow_primitive_def bad = p;
  bad.direction[0] = bad.direction[1] = bad.direction[2] = 0.0f;
  expect_refused([&] { return boreas_wind_add_primitive(world_, &bad, &id); }, "direction");
  bad = p;
  bad.strength = kNaN;
  expect_refused([&] { return boreas_wind_add_primitive(world_, &bad, &id); }, "strength");
  bad = p;
  bad.type = BOREAS_FLOW_VORTEX;
  bad.radius = 0.0f;
  expect_refused([&] { return boreas_wind_add_primitive(world_, &bad, &id); }, "radius");
  bad = p;
  bad.radius = -1.0f;
  expect_refused([&] { return boreas_wind_add_primitive(world_, &bad, &id); }, "radius");
  bad = p;
  bad.type = static_cast<boreas_flow_type>(42);
  expect_refused([&] { return boreas_wind_add_primitive(world_, &bad, &id); }, "type");
  expect_refused([&] { return boreas_wind_add_primitive(world_, nullptr, &id); }, "NULL");

  boreas_gust_def g = boreas_default_gust_def();
  boreas_gust_def bad_gust = g;
  boreas_gust_id gust_id{};
  bad_gust.rise = -1.0f;
  expect_refused([&] { return boreas_wind_add_gust(world_, &bad_gust, &gust_id); }, "gust.rise");
  bad_gust = g;
  bad_gust.center[1] = kInf;
  expect_refused([&] { return boreas_wind_add_gust(world_, &bad_gust, &gust_id); },
                 "gust.center[1]");

  ASSERT_EQ(boreas_wind_add_primitive(world_, &p, &id), BOREAS_OK);
  EXPECT_EQ(boreas_wind_remove_primitive(world_, id), BOREAS_OK);
  EXPECT_EQ(boreas_wind_remove_primitive(world_, id), BOREAS_ERROR_NOT_FOUND);
  boreas_primitive_id reused{};
  ASSERT_EQ(boreas_wind_add_primitive(world_, &p, &reused), BOREAS_OK);
  EXPECT_EQ(reused.index, id.index) << "the slot is reused";
  EXPECT_EQ(boreas_wind_remove_primitive(world_, id), BOREAS_ERROR_NOT_FOUND)
      << "the old id's generation is stale";
  EXPECT_EQ(boreas_wind_remove_primitive(world_, boreas_primitive_id{~0u, 1, id.tag}),
            BOREAS_ERROR_NOT_FOUND);
}

TEST_F(Api, SampleAndObstaclesRefuseBadInput) {
  float xyz[6] = {0, 0, 0, 1, kNaN, 2};
  float out[6];
  expect_refused([&] { return boreas_wind_sample(world_, xyz, 2, out); }, "xyz[4]");
  expect_refused([&] { return boreas_wind_sample(world_, xyz, -1, out); }, "count");
  expect_refused([&] { return boreas_wind_sample(world_, nullptr, 1, out); }, "NULL");
  expect_refused([&] { return boreas_wind_sample(world_, xyz, 1, nullptr); }, "NULL");
  float lo[3] = {0, 0, 0}, hi[3] = {-1, 1, 1};
  expect_refused([&] { return boreas_wind_add_solid_box(world_, lo, hi); }, "min[0]");
  uint8_t mask[3] = {1, 1, 1};
  expect_refused([&] { return boreas_wind_set_solid_mask(world_, mask, 3); }, "count");
  float grid[4];
  expect_refused([&] { return boreas_wind_get_grid_values(world_, grid, 4); }, "capacity");
}

TEST(ApiWorld, CreateRefusesBadGridAndLeavesOutputNull) {
  boreas_world_def def = boreas_default_world_def();
  def.grid.cell_size = -1.0f;
  boreas_world w = reinterpret_cast<boreas_world>(0x1);
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(w, nullptr);
  EXPECT_NE(std::string(boreas_last_error()).find("grid.cell_size"), std::string::npos);
  def = boreas_default_world_def();
  def.grid.resolution[1] = 1;
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(boreas_last_error()).find("grid.resolution[1]"), std::string::npos);
  def = boreas_default_world_def();
  boreas_wave bad = boreas_default_wave();
  bad.wavelength = 0.0f;
  def.waves = &bad;
  def.wave_count = 1;
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(boreas_world_create(nullptr, &w), BOREAS_ERROR_INVALID_ARGUMENT);
}

TEST(ApiWorld, UnknownDeviceRequestIsNoDevice) {
  boreas_world_def def = boreas_default_world_def();
  def.device = "no-such-device-anywhere";
  boreas_world w = nullptr;
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_ERROR_NO_DEVICE);
  std::string message = boreas_last_error();
  EXPECT_NE(message.find("no-such-device-anywhere"), std::string::npos) << message;
  EXPECT_NE(message.find("available"), std::string::npos) << message;
}

TEST(ApiCpp, ErrorsThrowWithStatusAndMessage) {
  boreas::World world;
  try {
    world.step(-1.0f);
    FAIL() << "step(-1) must throw";
  } catch (const boreas::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(e.what()).find("dt"), std::string::npos);
  }
  boreas::World moved = std::move(world);
  moved.step(0.1f);
  EXPECT_NEAR(moved.get_time(), 0.1, 1e-7);
  std::vector<boreas_device_info> devices = boreas::list_devices();
  ASSERT_FALSE(devices.empty());
  EXPECT_GT(std::string(moved.get_device().device_name).size(), 0u);
}

}  // namespace
