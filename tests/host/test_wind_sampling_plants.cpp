// boreas tests: wind_sampling interpolated reaches the plants' kernels (trees, imported
// trees and underbrush): the same bits at every SIMD width, and plants that move like those
// of exact sampling within what the wind's error bound allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "host/mesh_trees/tube_trees.h"
#include "support/test_support.h"
#include "wind/wind_sampling.h"

namespace boreas::test {
namespace {

// Where the plants are, in float triples: every branch's control points, every imported
// trunk vertex, every component's center of mass.
struct Plants {
  std::vector<float> tree_points;
  std::vector<float> mesh_points;
  std::vector<float> meadow_points;
  std::vector<unsigned char> bytes;  // everything the world reports, for bit-for-bit checks
};

Plants grow_and_blow(boreas_wind_sampling sampling, int width, int steps) {
  ScopedEnv env("BOREAS_SIMD_WIDTH", std::to_string(width).c_str());
  boreas_grid_def g = boreas_default_grid_def();
  g.wind_sampling = sampling;
  auto world = make_world(&g);
  EXPECT_EQ(world->runtime().simd_width(), width);
  // One wave over the default grid (2 m cells): 25 m long, sharpness 2, so the
  // interpolated sum is off by at most (pi 2 / 25)^2 2 / 4 = 3.2 % of the amplitude.
  const boreas_wave w = windy_wave();
  EXPECT_EQ(g.cell_size, 2.0f);
  world->wind().set_waves(&w, 1, 0.0f, world->time());
  std::vector<boreas_tree_id> trees;
  for (int i = 0; i < 3; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    d.seed = uint64_t(1 + i);
    d.position[0] = -6.0f + 6.0f * float(i);
    d.position[2] = 3.0f * float(i);
    trees.push_back(world->add_tree(d));
  }
  boreas_meadow_def m = boreas_default_meadow_def();
  m.size[0] = 6.0f;
  m.size[1] = 4.0f;
  m.density = 60.0f;
  const boreas_meadow_id meadow = world->add_meadow(m);
  TempDir dir;
  const std::string obj = write_tube_tree_obj(dir.path());
  boreas_mesh_tree_def md = boreas_default_mesh_tree_def();
  md.model = obj.c_str();
  md.position[0] = 8.0f;
  md.position[2] = -5.0f;
  const boreas_mesh_tree_id mesh = world->add_mesh_tree(md);
  for (int s = 0; s < steps; ++s) world->step(1.0f / 60.0f);
  Plants p;
  for (boreas_tree_id id : trees) {
    for (const boreas_branch& b : world->tree_branches(id))
      p.tree_points.insert(p.tree_points.end(), &b.control_points[0][0],
                           &b.control_points[0][0] + 12);
  }
  for (const boreas_vertex& v : world->mesh_tree_vertices(mesh, BOREAS_MESH_TRUNK))
    p.mesh_points.insert(p.mesh_points.end(), v.position, v.position + 3);
  for (const boreas_component& c : world->meadow_components(meadow))
    p.meadow_points.insert(p.meadow_points.end(), c.center_of_mass, c.center_of_mass + 3);
  for (const auto* v : {&p.tree_points, &p.mesh_points, &p.meadow_points}) {
    const auto* b = reinterpret_cast<const unsigned char*>(v->data());
    p.bytes.insert(p.bytes.end(), b, b + v->size() * sizeof(float));
  }
  return p;
}

// The largest distance between corresponding points of a and b.
double max_distance(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
    worst = std::max(worst, std::hypot(double(a[i]) - b[i], double(a[i + 1]) - b[i + 1],
                                       double(a[i + 2]) - b[i + 2]));
  return worst;
}

TEST(WindSamplingPlants, InterpolatedIsTheSameAtEveryWidthAndMovesPlantsLikeExact) {
  constexpr int kSteps = 60;
  const Plants rest = grow_and_blow(BOREAS_WIND_SAMPLING_EXACT, 16, 0);
  const Plants exact = grow_and_blow(BOREAS_WIND_SAMPLING_EXACT, 16, kSteps);
  const Plants wide = grow_and_blow(BOREAS_WIND_SAMPLING_INTERPOLATED, 16, kSteps);
  const Plants scalar = grow_and_blow(BOREAS_WIND_SAMPLING_INTERPOLATED, 1, kSteps);
  ASSERT_FALSE(wide.tree_points.empty());
  ASSERT_FALSE(wide.meadow_points.empty());
  EXPECT_TRUE(wide.bytes == scalar.bytes) << "interpolated sampling differs between widths";

  // The wind's error, relative to its largest value (the wave's amplitude: the grid is
  // calm). The load is drag, quadratic in the wind: a relative wind error e changes the
  // load by up to 2 e of its largest value, and the plants' response to load is about
  // linear, so each point moves by up to ~2 e of the largest displacement; twice that
  // for what the linear picture leaves out (the constraints, the bend's nonlinearity).
  const boreas_wave w = windy_wave();
  const double e = impl::interpolation_error_bound(impl::checked_waves(&w, 1, "w", "count"),
                                                   boreas_default_grid_def().cell_size) /
                   w.amplitude;
  for (const auto& [name, got, want, at_rest] :
       {std::tuple{"trees", &wide.tree_points, &exact.tree_points, &rest.tree_points},
        std::tuple{"imported trees", &wide.mesh_points, &exact.mesh_points, &rest.mesh_points},
        std::tuple{"underbrush", &wide.meadow_points, &exact.meadow_points, &rest.meadow_points}}) {
    const double moved = max_distance(*want, *at_rest);
    const double apart = max_distance(*got, *want);
    ASSERT_GT(moved, 1e-3) << name << ": the wind moved nothing";
    EXPECT_GT(apart, 0.0) << name << ": interpolated sampling did not reach the kernels";
    EXPECT_LE(apart, 4.0 * e * moved) << name << ": moved " << moved << " m, apart " << apart;
    RecordProperty(std::string(name) + " apart over moved", testing::PrintToString(apart / moved));
  }
}

}  // namespace
}  // namespace boreas::test
