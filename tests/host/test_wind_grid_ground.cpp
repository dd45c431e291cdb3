// boreas tests: the force-field grid on ground larger than itself — its wind fades out
// beyond its sides without a seam (edge_fade), and a grid that follows the focus moves in
// whole cells, keeps its wind where old and new extents overlap and lays primitives and
// solid boxes into the cells that come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "support/test_support.h"

namespace boreas::test {
namespace {

boreas_grid_def ground_grid(int nx, int ny, int nz, float cell) {
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -0.5f * float(nx) * cell;
  g.origin[1] = 0.0f;
  g.origin[2] = -0.5f * float(nz) * cell;
  g.cell_size = cell;
  g.resolution[0] = nx;
  g.resolution[1] = ny;
  g.resolution[2] = nz;
  g.decay_rate = 0.0f;  // the grid reaches its primitives' velocity
  return g;
}

// smoothstep(1 - outside / fade), the fade's double-precision form; outside: cells beyond
// the extent in the max norm.
double fade_reference(double outside_cells, double fade_cells) {
  if (outside_cells <= 0.0) return 1.0;
  if (fade_cells <= 0.0) return 0.0;
  const double s = std::clamp(1.0 - outside_cells / fade_cells, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

std::vector<float> sample(impl::World& world, const std::vector<float>& points) {
  std::vector<float> out(points.size());
  world.wind().sample(points.data(), int(points.size() / 3), out.data());
  return out;
}

// A uniform primitive everywhere on the grid, along +x at 5 m/s, stepped to steady state.
void fill_uniform(impl::World& world) {
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.direction[0] = 1.0f;
  p.direction[1] = 0.0f;
  p.direction[2] = 0.0f;
  p.strength = 5.0f;
  p.radius = 0.0f;
  world.wind().add_primitive(p, world.time());
  for (int s = 0; s < 200; ++s) world.step(0.1f);
}

TEST(WindGridGround, GridWindFadesOutBeyondTheSidesAsTheSmoothstepSays) {
  for (float fade : {2.0f, 5.0f}) {
    boreas_grid_def g = ground_grid(12, 4, 10, 2.0f);  // x in [-12, 12), z in [-10, 10)
    g.edge_fade = fade;
    auto world = make_world(&g);  // calm: no waves, so all the wind is the grid's
    fill_uniform(*world);
    const double inside = sample(*world, {0.0f, 3.0f, 0.0f})[0];
    ASSERT_NEAR(inside, 5.0, 1e-3);
    for (double out_cells : {0.0, 0.25, 0.5, 1.0, 1.5, 1.99, 2.5, 4.0, 4.9, 5.0, 7.0, 1e4}) {
      const float d = float(out_cells * 2.0);
      // Beyond +x, -x, +z and -z; the y and the other coordinate inside.
      // Beyond a corner, the distance outside is the larger of the two (the max norm).
      const std::vector<float> points = {
          12.0f + d, 3.0f, 1.0f, -12.0f - d, 3.0f,      -3.0f, -5.0f,           1.0f,
          10.0f + d, 7.0f, 5.0f, -10.0f - d, 12.0f + d, 3.0f,  10.0f + 0.5f * d};
      const std::vector<float> w = sample(*world, points);
      const double want = inside * fade_reference(out_cells, fade);
      for (int p = 0; p < 5; ++p) {
        EXPECT_NEAR(w[size_t(3 * p)], want, 1e-4)
            << "edge_fade " << fade << ", " << out_cells << " cells beyond side " << p;
        EXPECT_NEAR(w[size_t(3 * p + 2)], 0.0, 1e-5);
      }
    }
    // Above the top and below the bottom the grid's wind goes on as in its outermost cells.
    const std::vector<float> w = sample(*world, {1.0f, 50.0f, 1.0f, 1.0f, -3.0f, 1.0f});
    EXPECT_NEAR(w[0], inside, 1e-4);
    EXPECT_NEAR(w[3], inside, 1e-4);
  }
}

TEST(WindGridGround, NoSeamAtTheSideAndAHardEdgeWhenFadeIsZero) {
  boreas_grid_def g = ground_grid(12, 4, 10, 2.0f);
  auto faded = make_world(&g);
  g.edge_fade = 0.0f;
  auto hard = make_world(&g);
  for (impl::World* world : {faded.get(), hard.get()}) {
    boreas_wave wave = steady_wave(0.0f, 1.0f, 2.0f);  // sine-sum wind along z everywhere
    world->wind().set_waves(&wave, 1, 0.0f, world->time());
    fill_uniform(*world);
  }
  // Either side of x = 12 m by 1 mm: with the fade the wind is continuous.
  const std::vector<float> across = {12.0f - 1e-3f, 3.0f, 0.0f, 12.0f + 1e-3f, 3.0f, 0.0f};
  const std::vector<float> f = sample(*faded, across);
  EXPECT_NEAR(f[0], f[3], 1e-3) << "the grid's wind jumps at its side";
  EXPECT_NEAR(f[0], 5.0f, 1e-3);
  // Past the fade only the sine sum is left, on both worlds.
  const std::vector<float> far = {40.0f, 3.0f, 0.0f};
  for (impl::World* world : {faded.get(), hard.get()}) {
    const std::vector<float> w = sample(*world, far);
    EXPECT_EQ(w[0], 0.0f);
    EXPECT_NEAR(w[2], 2.0f, 1e-5);
  }
  // edge_fade 0: the grid's wind stops at the side itself.
  const std::vector<float> h = sample(*hard, across);
  EXPECT_NEAR(h[0], 5.0f, 1e-3);
  EXPECT_EQ(h[3], 0.0f);
}

TEST(WindGridGround, EdgeFadeOutOfRangeIsRefusedNamingTheField) {
  for (float bad : {-1.0f, 2e6f, std::nanf("")}) {
    boreas_world_def def = boreas_default_world_def();
    def.grid.edge_fade = bad;
    boreas_world world = nullptr;
    EXPECT_NE(boreas_world_create(&def, &world), BOREAS_OK);
    EXPECT_EQ(world, nullptr);
    EXPECT_NE(std::strstr(boreas_last_error(), "grid.edge_fade"), nullptr) << boreas_last_error();
  }
  boreas_world_def def = boreas_default_world_def();
  def.grid.follow_focus = 2;
  boreas_world world = nullptr;
  EXPECT_NE(boreas_world_create(&def, &world), BOREAS_OK);
  EXPECT_NE(std::strstr(boreas_last_error(), "grid.follow_focus"), nullptr) << boreas_last_error();
}

TEST(WindGridGround, FollowMovesInWholeCellsAndKeepsTheWindWhereExtentsOverlap) {
  boreas_grid_def g = ground_grid(16, 4, 16, 1.0f);
  g.follow_focus = 1;
  auto world = make_world(&g);
  // A source off the middle: a field that differs from cell to cell.
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.type = BOREAS_FLOW_SOURCE;
  p.position[0] = 2.5f;
  p.position[1] = 1.5f;
  p.position[2] = -1.5f;
  p.strength = 4.0f;
  p.radius = 5.0f;
  world->wind().add_primitive(p, world->time());
  for (int s = 0; s < 30; ++s) world->step(0.1f);
  impl::WindGrid& grid = world->wind().grid();
  const std::vector<float> before = grid.read();
  // Within an eighth of the width (2 cells) of the middle: no move.
  EXPECT_FALSE(grid.follow(1.9, -1.9));
  EXPECT_EQ(grid.def().origin[0], -8.0f);
  // 5 cells along +x and 3 along -z from the middle: the grid moves by exactly that.
  ASSERT_TRUE(grid.follow(5.2, -3.3));
  EXPECT_EQ(grid.def().origin[0], -3.0f);
  EXPECT_EQ(grid.def().origin[2], -11.0f);
  EXPECT_EQ(grid.gpu().origin_x, -3.0f);
  const std::vector<float> after = grid.read();
  int kept = 0;
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 16; ++i) {
        const int si = i + 5, sk = k - 3;
        const size_t at = size_t((k * 4 + j) * 16 + i);
        for (int a = 0; a < 4; ++a) {
          const float want =
              (si < 16 && sk >= 0) ? before[4 * size_t((sk * 4 + j) * 16 + si) + size_t(a)] : 0.0f;
          ASSERT_EQ(after[4 * at + size_t(a)], want) << "cell " << i << "," << j << "," << k;
        }
        kept += (si < 16 && sk >= 0) && after[4 * at] != 0.0f;
      }
  EXPECT_GT(kept, 20) << "the source's field should lie in the overlap";
  // Past the whole width: nothing overlaps, every cell starts calm.
  ASSERT_TRUE(grid.follow(200.0, -3.0));
  for (float v : grid.read()) ASSERT_EQ(v, 0.0f);
}

TEST(WindGridGround, FollowingGridBringsGridWindWhereverTheFocusGoes) {
  boreas_grid_def g = ground_grid(16, 4, 16, 2.0f);  // 32 m wide
  g.follow_focus = 1;
  auto world = make_world(&g);
  // A uniform primitive of radius 6 m, 300 m from where the grid begins.
  const float spot[3] = {300.0f, 2.0f, -120.0f};
  boreas_flow_primitive_def p = boreas_default_flow_primitive_def();
  p.direction[0] = 0.0f;
  p.direction[1] = 0.0f;
  p.direction[2] = 1.0f;
  p.strength = 3.0f;
  p.radius = 6.0f;
  std::memcpy(p.position, spot, sizeof spot);
  world->wind().add_primitive(p, world->time());
  const float start[3] = {0.0f, 1.8f, 0.0f};
  world->set_focus(start, 1);
  for (int s = 0; s < 20; ++s) world->step(0.1f);
  const std::vector<float> at_spot(spot, spot + 3);
  EXPECT_EQ(sample(*world, at_spot)[2], 0.0f) << "the primitive lies far beyond the grid";
  // The camera goes there; the grid follows and the primitive drives its cells.
  world->set_focus(spot, 1);
  const int steps = 100;
  for (int s = 0; s < steps; ++s) world->step(0.1f);
  const boreas_grid_def now = world->wind().grid().def();
  EXPECT_EQ(now.origin[0] + 16.0f, spot[0]) << "the focus in the middle";
  EXPECT_EQ(now.origin[2] + 16.0f, spot[2]);
  EXPECT_EQ(now.origin[1], g.origin[1]) << "never vertically";
  EXPECT_GT(sample(*world, at_spot)[2], 1.5f);
  // It arrived calm (nothing of the old extent overlaps), so its wind is that of a grid
  // placed there from the start and stepped as often, bit for bit.
  boreas_grid_def placed = g;
  placed.follow_focus = 0;
  placed.origin[0] = now.origin[0];
  placed.origin[2] = now.origin[2];
  auto reference = make_world(&placed);
  reference->wind().add_primitive(p, reference->time());
  for (int s = 0; s < steps; ++s) reference->step(0.1f);
  const std::vector<float> a = world->wind().grid().read(), b = reference->wind().grid().read();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
  // Back home: the way back is whole cells too, the origin exactly the first.
  world->set_focus(start, 1);
  world->step(0.1f);
  EXPECT_EQ(world->wind().grid().def().origin[0], g.origin[0]);
  EXPECT_EQ(world->wind().grid().def().origin[2], g.origin[2]);
}

TEST(WindGridGround, SolidBoxesAreLaidIntoTheCellsAFollowingGridReaches) {
  boreas_grid_def g = ground_grid(16, 6, 16, 1.0f);
  g.follow_focus = 1;
  auto world = make_world(&g);
  boreas_wave wave = steady_wave(1.0f, 0.0f, 4.0f);
  world->wind().set_waves(&wave, 1, 0.0f, world->time());
  // A wall 60 m away: beyond the grid, so no cell is solid yet.
  const float lo[3] = {59.0f, 0.0f, -2.0f}, hi[3] = {61.0f, 3.0f, 2.0f};
  world->wind().add_solid_box(lo, hi);
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 0);
  const std::vector<float> in_wall = {60.0f, 1.5f, 0.0f};
  EXPECT_NEAR(sample(*world, in_wall)[0], 4.0f, 1e-5);
  const float there[3] = {60.0f, 1.8f, 4.0f};
  world->set_focus(there, 1);
  world->step(0.1f);
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 2 * 3 * 4)
      << "2 x 3 x 4 cell centers in the box";
  EXPECT_EQ(sample(*world, in_wall)[0], 0.0f) << "inside a solid cell the wind is zero";
  // Away and back: the box leaves the grid and is laid in again.
  const float home[3] = {0.0f, 1.8f, 0.0f};
  world->set_focus(home, 1);
  world->step(0.1f);
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 0);
  world->set_focus(there, 1);
  world->step(0.1f);
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 24);

  // A cell mask has no place in a moving grid: refused, the solids as they were.
  std::vector<uint8_t> mask(size_t(world->wind().grid().cell_count()), 1);
  try {
    world->wind().set_solid_mask(mask.data(), int64_t(mask.size()));
    FAIL() << "a mask on a following grid was taken";
  } catch (const impl::Error& e) {
    EXPECT_NE(std::string(e.what()).find("follow"), std::string::npos) << e.what();
  }
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 24);
  // Clearing is taken, and clears the boxes too: the wall is not laid in again.
  world->wind().set_solid_mask(nullptr, 0);
  world->set_focus(home, 1);
  world->step(0.1f);
  world->set_focus(there, 1);
  world->step(0.1f);
  EXPECT_EQ(world->wind().grid().gpu().solid_count, 0);
}

TEST(WindGridGround, FollowingIsDeterministic) {
  boreas_grid_def g = ground_grid(16, 4, 16, 1.0f);
  g.follow_focus = 1;
  std::vector<float> cells[2];
  for (int run = 0; run < 2; ++run) {
    auto world = make_world(&g);
    boreas_wave wave = steady_wave(1.0f, 0.5f, 3.0f);
    world->wind().set_waves(&wave, 1, 0.0f, world->time());
    boreas_gust_def gust = boreas_default_gust_def();
    gust.strength = 4.0f;
    gust.hold = 100.0f;
    world->wind().add_gust(gust, world->time());
    const float lo[3] = {3.0f, 0.0f, 3.0f}, hi[3] = {5.0f, 2.0f, 5.0f};
    world->wind().add_solid_box(lo, hi);
    for (int s = 0; s < 60; ++s) {
      const float focus[3] = {0.7f * float(s), 1.8f, -0.3f * float(s)};
      world->set_focus(focus, 1);
      world->step(0.05f);
    }
    cells[run] = world->wind().grid().read();
  }
  ASSERT_EQ(cells[0].size(), cells[1].size());
  EXPECT_EQ(std::memcmp(cells[0].data(), cells[1].data(), cells[0].size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace boreas::test
