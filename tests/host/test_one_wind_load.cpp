// boreas tests: one wind load for every kind of plant — doubling a steady wind quadruples
// the small-deflection response of underbrush blades and of imported trees (generated
// trees: trees/test_wind_load.cpp).
//
// The wind: one sine wave of sharpness 0 and speed 0 over a calm grid. base^0 = 1, so it
// blows `amplitude` along +x everywhere and for ever; each world samples it first, so a
// change to the sine sum cannot quietly turn this into a test of some other wind.
//
// Blades (cl/underbrush_step.cl): the load per unit mass is drag_area |u| u / m plus
// gravity, exactly 4 times the wind's part at 2u, and the equilibrium read from the shape
// table is a smooth function of the load, which the critically damped constraint reaches
// (3 s is 10 tau or more for the default mix: grass, clover, daisies). For a small load the
// equilibrium's move from rest is linear in the load, so the center of mass settles 4 times as far
// from rest at 2u. Asserted: the median ratio and the ratio of the sums over the meadow, and the
// median of every (species, part), within 5 % of 4; every median move far above the float noise
// floor (a meadow that did not move would give 0/0); a calm meadow stays at rest. Not asserted per
// component: single blades give 3.4 to 4.9 at 0.5 -> 1 m/s, because the default table (19 angles,
// 10 degrees apart) is bilinear and a blade whose load angle crosses a knot between u and 2u
// changes slope (181 angles: 3.65 to 4.43; 7 angles: 2.5 to 9.1). Measured at 0.5 -> 1 m/s:
// median 4.01, sums 3.96; grass 3.92 (its drag per unit mass is ~2.3 /m, so 1 m/s already turns its
// load 13 degrees; 2 m/s, about g, gives 1.9: no longer a small deflection), clover 4.01-4.02,
// daisies 3.99-4.01.
//
// Imported trees (cl/shared/mesh_tree_math.h): a trunk vertex moves by
// load * (bend along the wind + sway * noise), load = q / (1 + q / ceiling),
// q = |W|^2 / (10 m/s)^2. W, the wind a branch feels, starts at the wind on the tree's
// first step, and the noise clock runs on time alone, so in two worlds stepped alike the
// noise is the same and the whole move scales with the load: every vertex's ratio must be
// 4 (1 + q/c) / (1 + 4 q/c) within 1 % (measured: within 0.02 %), with the sway off (bend
// alone) and on (bend and sway at the same time). Leaves are left out: their flutter noise
// rolls downwind by W dt each step, so at u and 2u it is read at different places.
#include <gtest/gtest.h>

// The kernels' headers as a CPU device builds them (polynomial math).
#define BOREAS_FAST_MATH 1

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "boreas/boreas.h"
#include "host/mesh_trees/tube_trees.h"
#include "mesh_trees/mesh_tree_drag.h"
#include "shared/mesh_tree_math.h"
#include "shared/mesh_tree_types.h"
#include "support/temp_dir.h"
#include "support/test_support.h"
#include "trees/wind_load.h"
#include "wind/air.h"

namespace boreas {
namespace {

// The constraint step works in world coordinates, so a component settles only to within a
// few float ulps of its coordinates: within a meter of the origin it ends about 0.5 um
// short of the equilibrium (the host's float equilibrium stays linear down to 0.03 m/s).
// That biases the ratio of tiny moves upward: clover petioles, which move 4 um at
// 0.125 m/s, give 4.3 at 0.125 -> 0.25 m/s and 6.5 at 0.0625 -> 0.125 m/s. Hence moves
// are required to be 50 times this floor.
constexpr double kNoiseFloor = 1e-6;  // m

// A world whose wind is `speed` m/s along +x everywhere (see the top of the file).
struct SteadyWorld {
  boreas_world w = nullptr;
  explicit SteadyWorld(float speed) {
    boreas_world_def def = boreas_default_world_def();
    def.grid = test::calm_grid();
    boreas_wave wave = test::steady_wave(1.0f, 0.0f, speed);
    wave.speed = 0.0f;
    def.waves = &wave;
    def.wave_count = 1;
    EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_OK) << boreas_last_error();
  }
  ~SteadyWorld() { boreas_world_destroy(w); }
  void step(double seconds) {
    const float dt = 1.0f / 60.0f;
    for (long s = 0; s < std::lround(seconds / dt); ++s)
      ASSERT_EQ(boreas_world_step(w, dt), BOREAS_OK);
  }
};

// The wind at points spread over where the plants stand is (speed, 0, 0).
void expect_uniform_wind(boreas_world w, float speed) {
  const std::vector<float> at = {0.0f, 0.1f, 0.0f, 0.7f,  0.3f, -0.4f, -0.9f, 0.05f, 0.8f,
                                 1.0f, 4.0f, 2.0f, -2.0f, 7.5f, -1.0f, 3.3f,  1.1f,  -2.7f};
  std::vector<float> wind(at.size());
  ASSERT_EQ(boreas_wind_sample(w, at.data(), int(at.size() / 3), wind.data()), BOREAS_OK);
  for (size_t p = 0; p < at.size() / 3; ++p) {
    EXPECT_NEAR(wind[3 * p + 0], speed, 1e-5f * speed) << "point " << p;
    EXPECT_EQ(wind[3 * p + 1], 0.0f) << "point " << p;
    EXPECT_EQ(wind[3 * p + 2], 0.0f) << "point " << p;
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double distance(const float* a, const float* b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// ---- Underbrush blades --------------------------------------------------------------

struct Move {
  std::pair<int, int> kind;  // species, part
  double distance;           // m, center of mass from rest
};

// Every component of the default meadow mix (grass, clover, daisies) after 3 s in a
// steady wind: how far its center of mass is from rest.
std::vector<Move> meadow_moves(float speed) {
  SteadyWorld sw(speed);
  expect_uniform_wind(sw.w, speed);
  boreas_meadow_def def = boreas_default_meadow_def();
  def.size[0] = def.size[1] = 2.0f;
  def.density = 100.0f;
  boreas_meadow_id m{};
  EXPECT_EQ(boreas_world_add_meadow(sw.w, &def, &m), BOREAS_OK) << boreas_last_error();
  sw.step(3.0);
  int n = 0;
  EXPECT_EQ(boreas_meadow_get_components(sw.w, m, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_component> c(size_t(n), boreas_component{});
  EXPECT_EQ(boreas_meadow_get_components(sw.w, m, c.data(), n, &n), BOREAS_OK);
  std::vector<Move> out;
  for (const boreas_component& x : c) {
    EXPECT_EQ(x.broken, 0) << "a small load broke a component";
    out.push_back({{x.species, x.part}, distance(x.center_of_mass, x.rest_center_of_mass)});
  }
  return out;
}

TEST(OneWindLoad, DoublingASteadyWindQuadruplesABladesDeflection) {
  const float u = 0.5f;  // m/s; grass, the most pliant, turns its load by 3.4 degrees
  const std::vector<Move> calm = meadow_moves(0.0f), slow = meadow_moves(u),
                          fast = meadow_moves(2.0f * u);
  ASSERT_EQ(slow.size(), fast.size());
  ASSERT_EQ(slow.size(), calm.size());
  ASSERT_GT(slow.size(), 100u);

  double calm_largest = 0.0, sum_slow = 0.0, sum_fast = 0.0;
  std::vector<double> moves, ratios;
  std::map<std::pair<int, int>, std::vector<double>> kind_moves, kind_ratios;
  for (size_t i = 0; i < slow.size(); ++i) {
    calm_largest = std::max(calm_largest, calm[i].distance);
    sum_slow += slow[i].distance;
    sum_fast += fast[i].distance;
    moves.push_back(slow[i].distance);
    kind_moves[slow[i].kind].push_back(slow[i].distance);
    if (slow[i].distance > 0.0) {
      ratios.push_back(fast[i].distance / slow[i].distance);
      kind_ratios[slow[i].kind].push_back(fast[i].distance / slow[i].distance);
    }
  }
  std::printf(
      "    %zu components: median move %.3g m at %.2g m/s; ratio at %.2g m/s: median %.4f, "
      "of sums %.4f; calm moves at most %.3g m\n",
      slow.size(), median(moves), u, 2 * u, median(ratios), sum_fast / sum_slow, calm_largest);
  // Rest is the calm equilibrium, so a move from rest is the wind's doing.
  EXPECT_LT(calm_largest, kNoiseFloor);
  EXPECT_NEAR(median(ratios), 4.0, 0.2);
  EXPECT_NEAR(sum_fast / sum_slow, 4.0, 0.2);
  for (const auto& [kind, r] : kind_ratios) {
    const double m = median(kind_moves[kind]);
    std::printf("    species %d part %d: %zu components, median move %.3g m, median ratio %.4f\n",
                kind.first, kind.second, r.size(), m, median(r));
    // Noise n on moves m and 4m shifts their ratio by at most about 5 n / m: at 40 n that is
    // 0.125 of the 0.2 allowed. (Clover's leaves, scaled by their length since issue 40's
    // dynamics, move about 49 n at 0.5 m/s.)
    EXPECT_GT(m, 40.0 * kNoiseFloor) << "species " << kind.first << " part " << kind.second;
    EXPECT_NEAR(median(r), 4.0, 0.2) << "species " << kind.first << " part " << kind.second;
  }
}

// ---- Imported trees ------------------------------------------------------------------

// Each trunk vertex's distance from rest after 2 s in a steady wind; with `sway` false,
// every level's sway is 0 (bend alone), else the default.
std::vector<double> mesh_tree_moves(const std::string& model, float speed, bool sway) {
  SteadyWorld sw(speed);
  expect_uniform_wind(sw.w, speed);
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
  def.model = model.c_str();
  def.cache = 0;
  if (!sway)
    for (boreas_mesh_level_def& l : def.levels) l.sway = 0.0f;
  boreas_mesh_tree_id id{};
  EXPECT_EQ(boreas_world_add_mesh_tree(sw.w, &def, &id), BOREAS_OK) << boreas_last_error();
  int n = 0;
  EXPECT_EQ(boreas_mesh_tree_get_vertices(sw.w, id, BOREAS_MESH_TRUNK, nullptr, 0, &n), BOREAS_OK);
  std::vector<boreas_vertex> rest(size_t(n), boreas_vertex{}), moved(rest.size(), boreas_vertex{});
  EXPECT_EQ(boreas_mesh_tree_get_vertices(sw.w, id, BOREAS_MESH_TRUNK, rest.data(), n, &n),
            BOREAS_OK);
  sw.step(2.0);
  EXPECT_EQ(boreas_mesh_tree_get_vertices(sw.w, id, BOREAS_MESH_TRUNK, moved.data(), n, &n),
            BOREAS_OK);
  std::vector<double> out;
  for (size_t v = 0; v < rest.size(); ++v)
    out.push_back(distance(moved[v].position, rest[v].position));
  return out;
}

void expect_mesh_tree_load_law(bool sway) {
  test::TempDir dir;
  const std::string model = test::write_tube_tree_obj(dir.path());
  const float u = 1.0f;  // m/s: q = 0.01, crown tips move ~4 mm
  const std::vector<double> slow = mesh_tree_moves(model, u, sway),
                            fast = mesh_tree_moves(model, 2.0f * u, sway);
  ASSERT_EQ(slow.size(), fast.size());
  // Both winds below Vogel's reference speed (mesh_trees/mesh_tree_drag.h): the plain drag
  // law, four times the load for twice the wind.
  static_assert(2.0 < boreas::impl::kMeshTreeVogelSpeed, "both winds below U_r");
  const double expected = 4.0;
  // Vertices near the ground barely move (their weights are ~0); a ratio needs a move
  // well above the float noise of coordinates up to 8 m (ulp 1e-6 m).
  const double measurable = 100.0 * kNoiseFloor;
  double sum_slow = 0.0, sum_fast = 0.0, largest = 0.0, worst = expected;
  std::vector<double> ratios;
  for (size_t i = 0; i < slow.size(); ++i) {
    sum_slow += slow[i];
    sum_fast += fast[i];
    largest = std::max(largest, slow[i]);
    if (slow[i] < measurable) continue;
    const double r = fast[i] / slow[i];
    ratios.push_back(r);
    if (std::abs(r - expected) > std::abs(worst - expected)) worst = r;
    EXPECT_NEAR(r, expected, 0.01 * expected) << "vertex " << i;
  }
  std::printf(
      "    %zu of %zu vertices moved > %.2g m (largest %.3g m) at %.2g m/s; ratio at %.2g m/s: "
      "median %.5f, of sums %.5f, worst %.5f; expected %.5f\n",
      ratios.size(), slow.size(), measurable, largest, u, 2 * u, median(ratios),
      sum_fast / sum_slow, worst, expected);
  EXPECT_GT(ratios.size(), slow.size() / 2) << "the crown did not move";
  EXPECT_NEAR(sum_fast / sum_slow, 4.0, 0.2);
}

TEST(OneWindLoad, DoublingASteadyWindQuadruplesAnImportedTreesBend) {
  expect_mesh_tree_load_law(false);
}

TEST(OneWindLoad, DoublingASteadyWindQuadruplesAnImportedTreesBendAndSway) {
  expect_mesh_tree_load_law(true);
}

// An imported tree's load is the drag law's, 1/2 rho C_d A |u|^2 R(|u|) of its leaves' and
// stems' areas, normalized to 0.8 at 10 m/s (mesh_trees/mesh_tree_drag.h): the double
// formula from the tube tree's mesh against the device's load (the kernels' header built
// here, polynomial exp2 and log2) and against the bend the kernels give its vertices at 5,
// 20 and 40 m/s (bend alone: moves proportional to the load).
TEST(OneWindLoad, ImportedTreeLoadFollowsTheDragLawAt5And20And40) {
  const impl::MeshModel model = test::make_tube_tree().model;
  const impl::MeshTreeDrag drag = impl::mesh_tree_drag(model);
  ASSERT_GT(drag.leaf_area, 0.0);
  ASSERT_GT(drag.stem_area, 0.0);
  const double phi = drag.vogel_b / impl::kMeshTreeVogelExponent;
  EXPECT_GT(phi, 0.0);
  EXPECT_LT(phi, 1.0);
  auto formula = [&](double u) {
    const double cd_a = impl::kLeafDragCoefficient * drag.leaf_area +
                        impl::kWoodDragCoefficient * drag.stem_area;
    auto d = [&](double s) {
      const double r = s > impl::kMeshTreeVogelSpeed
                           ? std::pow(s / impl::kMeshTreeVogelSpeed, phi * impl::kMeshTreeVogelExponent)
                           : 1.0;
      return 0.5 * impl::kAirDensity * cd_a * s * s * r;
    };
    return 0.8 * d(u) / d(10.0);
  };
  EXPECT_NEAR(impl::mesh_tree_load(drag, 10.0), 0.8, 1e-12);
  float trees[BOREAS_MESH_TREE_TREE_FLOATS] = {};  // one tree's planes
  trees[BOREAS_MESH_TREE_TREE_DRAG] = float(drag.load_per_speed2);
  trees[BOREAS_MESH_TREE_TREE_VOGEL_B] = float(drag.vogel_b);
  trees[BOREAS_MESH_TREE_TREE_VOGEL_SPEED] = float(1.0 / impl::kMeshTreeVogelSpeed);
  test::TempDir dir;
  const std::string path = test::write_tube_tree_obj(dir.path());
  const std::vector<double> at5 = mesh_tree_moves(path, 5.0f, false);
  for (double u : {5.0, 20.0, 40.0}) {
    SCOPED_TRACE(u);
    EXPECT_NEAR(impl::mesh_tree_load(drag, u), formula(u), 1e-12 * formula(u));
    EXPECT_NEAR(boreas_mesh_tree_load(float(u * u), trees, 1, 0), formula(u), 2e-6 * formula(u));
    // The tube tree's leaves are few: the device's Vogel factor for a leafy crown too.
    float leafy[BOREAS_MESH_TREE_TREE_FLOATS] = {};
    leafy[BOREAS_MESH_TREE_TREE_DRAG] = 1.0f;
    leafy[BOREAS_MESH_TREE_TREE_VOGEL_B] = -0.8f;
    leafy[BOREAS_MESH_TREE_TREE_VOGEL_SPEED] = float(1.0 / impl::kMeshTreeVogelSpeed);
    const double vogel = u * u * impl::reconfiguration(u, -0.8, impl::kMeshTreeVogelSpeed);
    EXPECT_NEAR(boreas_mesh_tree_load(float(u * u), leafy, 1, 0), vogel, 2e-6 * vogel);
    const std::vector<double> moves = mesh_tree_moves(path, float(u), false);
    const double want = formula(u) / formula(5.0);
    int measured = 0;
    for (size_t v = 0; v < moves.size(); ++v) {
      if (at5[v] < 100.0 * kNoiseFloor) continue;
      EXPECT_NEAR(moves[v] / at5[v], want, 1e-3 * want) << "vertex " << v;
      ++measured;
    }
    EXPECT_GT(measured, int(moves.size() / 2));
  }
  // The artist's ceiling is gone: at 40 m/s the load no longer falls to a fifth of the u^2
  // law's, only by the reconfiguration of its leafy share (this tube tree's is small).
  const double storm = formula(40.0) / (0.8 * 16.0);
  std::printf("    tube tree: leafy share %.3f, load at 40 m/s %.3f of the u^2 law's\n", phi, storm);
  EXPECT_GT(storm, 0.4);
  EXPECT_LE(storm, 1.0);
}

}  // namespace
}  // namespace boreas
