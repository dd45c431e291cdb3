// boreas tests: a cast's hits do not depend on what was cast before. The ray structure keeps
// what earlier updates made where nothing since has moved it (a tree's branches emptied,
// its subtree runs and their wide nodes left as last made: ray_scene.h), so a cast after a
// history of other casts must find, bit for bit, what the same rays find in a world in the
// same state that never cast.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "ray_forest.h"

namespace boreas::reference {
namespace {

// A 16-channel LiDAR's slice: `columns` columns from azimuth `from` (radians) over `width`,
// channels from -20 to +20 degrees, from `origin`.
std::vector<boreas_ray> slice(const std::array<float, 3>& origin, double from, double width, int columns) {
  std::vector<boreas_ray> rays;
  for (int col = 0; col < columns; ++col)
    for (int ch = 0; ch < 16; ++ch) {
      const double az = from + width * col / (columns - 1), el = (-20.0 + 40.0 * ch / 15.0) * M_PI / 180.0;
      rays.push_back({{origin[0], origin[1], origin[2]},
                      {float(std::cos(el) * std::cos(az)), float(std::sin(el)), float(std::cos(el) * std::sin(az))},
                      60.0f});
    }
  return rays;
}

std::vector<boreas_hit> cast(boreas_world w, const std::vector<boreas_ray>& rays) {
  std::vector<boreas_hit> hits(rays.size());
  EXPECT_EQ(boreas_world_cast_rays(w, rays.data(), int(rays.size()), hits.data()), BOREAS_OK);
  return hits;
}

uint64_t state_hash(boreas_world w) {
  uint64_t h = 0;
  EXPECT_EQ(boreas_world_get_state_hash(w, &h), BOREAS_OK);
  return h;
}

// Two worlds made and stepped alike; one casts a LiDAR's slices as it turns (60 degrees a
// step, its origin moving), once rays across everything, and in the last step another
// slice first; then both cast the same rays (a slice that overlaps the ones before, and
// rays scattered through the stand): the same bits.
TEST(RayHistory, RaysCastAfterOtherCastsFindWhatAFreshWorldFinds) {
  RayForestDef def;
  def.trees = 9;
  def.components = 900;
  auto fresh = make_ray_forest(def), used = make_ray_forest(def);
  const float half = used->half_extent;
  for (int s = 0; s < 8; ++s) {
    ASSERT_EQ(boreas_world_step(fresh->world, 1.0f / 60.0f), BOREAS_OK);
    ASSERT_EQ(boreas_world_step(used->world, 1.0f / 60.0f), BOREAS_OK);
    const std::array<float, 3> at = {-half + 0.4f * float(s), 1.8f, 0.5f};
    cast(used->world, slice(at, M_PI / 3.0 * s, M_PI / 3.0, 96));
    if (s == 3)
      cast(used->world, {{{-600.0f, -600.0f, -600.0f}, {1.0f, 1.0f, 1.0f}, 2100.0f},
                         {{600.0f, 600.0f, 600.0f}, {-1.0f, -1.0f, -1.0f}, 2100.0f}});
  }
  ASSERT_EQ(state_hash(fresh->world), state_hash(used->world));
  std::vector<boreas_ray> rays = slice({0.0f, 1.8f, 0.5f}, 2.0, 2.5, 128);
  const std::vector<boreas_ray> scattered = forest_rays(*used, 4000, 23);
  rays.insert(rays.end(), scattered.begin(), scattered.end());
  const std::vector<boreas_hit> a = cast(fresh->world, rays), b = cast(used->world, rays);
  int hit = 0;
  for (const boreas_hit& h : a) hit += h.kind != BOREAS_HIT_NONE;
  EXPECT_GT(hit, int(rays.size()) / 10);
  // Every word but the object's tag, which names the world that issued it.
  int differ = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    boreas_hit x = a[i], y = b[i];
    x.object.tag = y.object.tag = 0;
    differ += std::memcmp(&x, &y, sizeof(boreas_hit)) != 0;
  }
  EXPECT_EQ(differ, 0) << "of " << rays.size() << " rays";
}

}  // namespace
}  // namespace boreas::reference
