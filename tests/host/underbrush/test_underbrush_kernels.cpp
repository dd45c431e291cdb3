// The underbrush step and vertex kernels: the dynamics against the closed-form critically
// damped solution, rest, colliders, impulses, breaking, robustness, shapes and LOD.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

// The fixtures (through meadow.h) choose the host's math before the shared header is read.
#include "underbrush_fixtures.h"
#include "shared/underbrush_math.h"
#include "underbrush/rest_shape.h"
#include "underbrush/frame_pack.h"

namespace boreas {
namespace {

using test::meadow_world;
using test::planting_grid;
using test::species_params;

struct Placed {
  std::unique_ptr<impl::World> world;
  boreas_meadow_id id;
};

Placed place(float wind, const std::vector<std::string>& species, int per_side, double spacing = 0.3) {
  Placed p;
  p.world = meadow_world(wind);
  p.id = p.world->add_meadow(impl::meadow_from_plantings(species_params(species), planting_grid(per_side, spacing)));
  return p;
}

double dist(const float a[3], const float b[3]) {
  return std::sqrt(double(a[0] - b[0]) * (a[0] - b[0]) + double(a[1] - b[1]) * (a[1] - b[1]) +
                   double(a[2] - b[2]) * (a[2] - b[2]));
}

// The load of a component under a uniform wind u (m/s along x), as the kernel forms it.
BoreasV3 wind_load(const impl::Meadow& m, int c, double u) {
  const BoreasGpuPart& g = m.parts[size_t(impl::part_of(m.index.data(), m.count, int(c)))].gpu;
  float drag = g.drag_area * g.inv_mass * float(u);
  return boreas_v3(float(u) * drag, -float(impl::kGravity), 0.0f);
}

TEST(UnderbrushKernel, CalmMeadowStaysAtRest) {
  Placed p = place(0.0f, {"meadow_grass", "daisy"}, 3);
  std::vector<boreas_component> before = p.world->meadow_components(p.id);
  for (int s = 0; s < 120; ++s) p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> after = p.world->meadow_components(p.id);
  ASSERT_EQ(before.size(), after.size());
  for (size_t c = 0; c < after.size(); ++c) {
    EXPECT_LT(dist(after[c].center_of_mass, after[c].rest_center_of_mass), 2e-6) << c;
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(after[c].velocity[a], 0.0f, 1e-5f);
  }
}

TEST(UnderbrushKernel, WindBendsDownwindAndReleasesToRest) {
  Placed p = place(8.0f, {"meadow_grass", "daisy", "clover"}, 3);
  for (int s = 0; s < 90; ++s) p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> windy = p.world->meadow_components(p.id);
  double mean_dx = 0.0;
  for (const boreas_component& c : windy) mean_dx += c.center_of_mass[0] - c.rest_center_of_mass[0];
  mean_dx /= double(windy.size());
  EXPECT_GT(mean_dx, 0.005) << "the wind blows along +x";
  p.world->wind().set_waves(nullptr, 0, 0.0f, p.world->time());
  for (int s = 0; s < 300; ++s) p.world->step(1.0f / 60.0f);
  for (const boreas_component& c : p.world->meadow_components(p.id)) {
    if (c.broken) continue;
    EXPECT_LT(dist(c.center_of_mass, c.rest_center_of_mass), 1e-4);
  }
}

TEST(UnderbrushKernel, BallPushesComponentsAwayFromItsCenter) {
  Placed p = place(0.0f, {"meadow_grass"}, 9, 0.1);
  boreas_collider_def ball = boreas_default_collider_def();  // r = 0.11 m at (0, 0.11, 0)
  p.world->add_collider(ball);
  for (int s = 0; s < 60; ++s) p.world->step(1.0f / 60.0f);
  int near = 0, pushed = 0, far_moved = 0;
  for (const boreas_component& c : p.world->meadow_components(p.id)) {
    double rx = c.rest_center_of_mass[0], rz = c.rest_center_of_mass[2];
    double dx = c.center_of_mass[0] - rx, dz = c.center_of_mass[2] - rz;
    double r = std::hypot(rx, rz);
    if (r < 0.15 && r > 0.02) {
      ++near;
      // Further from the ball's center (blades under it are pressed down and out).
      if (dist(c.center_of_mass, ball.pose.position) > dist(c.rest_center_of_mass, ball.pose.position) + 0.005) ++pushed;
    }
    if (r > 0.6 && std::hypot(dx, dz) > 1e-5) ++far_moved;
  }
  ASSERT_GT(near, 10);
  EXPECT_EQ(pushed, near) << "every blade near the ball moves away from it";
  EXPECT_EQ(far_moved, 0);
}

TEST(UnderbrushKernel, ImpulseKicksAndTheComponentsSettleAgain) {
  Placed p = place(0.0f, {"meadow_grass"}, 3, 0.2);
  boreas_emitter_def foot = boreas_default_emitter_def();
  foot.rate = 0.0f;  // one event
  foot.area_radius = 0.0f;
  foot.event_radius = 0.5f;
  foot.impulse[1] = -2e-3f;
  p.world->add_emitter(foot);
  p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> kicked = p.world->meadow_components(p.id);
  for (const boreas_component& c : kicked) EXPECT_LT(c.velocity[1], -0.01f);
  // 8 s: the longest blades (1.3 times the mean) have tau 1.7 times the mean's 0.25 s.
  for (int s = 0; s < 480; ++s) p.world->step(1.0f / 60.0f);
  for (const boreas_component& c : p.world->meadow_components(p.id))
    EXPECT_LT(dist(c.center_of_mass, c.rest_center_of_mass), 1e-4);
}

TEST(UnderbrushKernel, NoNaNUnderExtremeForcesAndLargeSteps) {
  boreas_world_def def = boreas_default_world_def();
  def.grid = test::calm_grid();
  boreas_wave storm[2] = {test::steady_wave(1.0f, 0.2f, 1000.0f), test::steady_wave(-0.3f, 1.0f, 700.0f)};
  storm[1].sharpness = 3.0f;
  storm[1].wavelength = 0.7f;
  storm[1].speed = 40.0f;
  def.waves = storm;
  def.wave_count = 2;
  impl::World world(def);
  boreas_meadow_id id = world.add_meadow(impl::meadow_from_plantings(
      species_params({"meadow_grass", "daisy", "clover", "fern"}), planting_grid(2, 0.3)));
  boreas_collider_def ball = boreas_default_collider_def();
  boreas_collider_id b = world.add_collider(ball);
  const float dts[] = {1e-4f, 1.0f / 60.0f, 0.5f, 30.0f, 3600.0f};
  for (int s = 0; s < 100000; ++s) {
    float c[3] = {float(std::sin(s * 0.01)) * 0.3f, 0.1f, 0.0f};
    world.set_collider_position(b, c);
    world.step(dts[s % 5]);
    if (s % 10000 == 9999) {
      for (const boreas_component& comp : world.meadow_components(id))
        for (int a = 0; a < 3; ++a) {
          ASSERT_TRUE(std::isfinite(comp.center_of_mass[a])) << "step " << s;
          ASSERT_TRUE(std::isfinite(comp.velocity[a])) << "step " << s;
          // Never further from its base than its own length.
          ASSERT_LT(dist(comp.center_of_mass, comp.base), 1.0);
        }
    }
  }
  std::vector<float> v;
  std::vector<int32_t> n;
  world.meadow_vertices(id, nullptr, &v, &n);
  for (float f : v) ASSERT_TRUE(std::isfinite(f));
}

TEST(UnderbrushKernel, StrongWindBreaksWeakBladesForGood) {
  impl::MeadowParams params = species_params({"meadow_grass"});
  params.species[0].tissue.break_stress = 2e6;  // weak: holds itself, not a gale
  auto world = meadow_world(45.0f);
  boreas_meadow_id id =
      world->add_meadow(impl::meadow_from_plantings(params, planting_grid(3, 0.3)));
  for (const boreas_component& c : world->meadow_components(id)) EXPECT_EQ(c.broken, 0);
  for (int s = 0; s < 30; ++s) world->step(1.0f / 60.0f);
  int broken = 0;
  for (const boreas_component& c : world->meadow_components(id)) broken += c.broken > 0;
  EXPECT_GT(broken, 0);
  world->wind().set_waves(nullptr, 0, 0.0f, world->time());
  for (int s = 0; s < 300; ++s) world->step(1.0f / 60.0f);
  int still = 0;
  for (const boreas_component& c : world->meadow_components(id)) still += c.broken > 0;
  EXPECT_EQ(still, broken) << "broken components stay broken";
}

TEST(UnderbrushKernel, TooHeavyToHoldItselfIsBrokenAtRest) {
  impl::MeadowParams params = species_params({"meadow_grass"});
  params.species[0].tissue.break_stress = 1e4;
  auto world = meadow_world(0.0f);
  boreas_meadow_id id =
      world->add_meadow(impl::meadow_from_plantings(params, planting_grid(3, 0.3)));
  int broken = 0;
  std::vector<boreas_component> comps = world->meadow_components(id);
  for (const boreas_component& c : comps) broken += c.broken > 0;
  EXPECT_GT(broken, int(comps.size()) / 2);
}

TEST(UnderbrushKernel, ChildBasesFollowTheirParents) {
  Placed p = place(10.0f, {"daisy"}, 2);
  std::vector<boreas_component> rest = p.world->meadow_components(p.id);
  for (int s = 0; s < 60; ++s) p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> comps = p.world->meadow_components(p.id);
  int children = 0;
  for (size_t i = 0; i < comps.size(); ++i) {
    const boreas_component& c = comps[i];
    if (c.parent < 0) continue;
    ++children;
    const boreas_component& parent = comps[size_t(c.parent)];
    // The petal's base moved the way its stalk's center of mass moved, and further (it
    // sits at the stalk's tip, beyond its center of mass).
    double along = 0.0, moved = 0.0, base_moved = 0.0;
    for (int a = 0; a < 3; ++a) {
      double dp = parent.center_of_mass[a] - parent.rest_center_of_mass[a];
      double db = c.base[a] - rest[i].base[a];
      along += dp * db;
      moved += dp * dp;
      base_moved += db * db;
    }
    ASSERT_GT(moved, 1e-8);
    EXPECT_GT(along / std::sqrt(moved * base_moved), 0.999);
    EXPECT_GT(std::sqrt(base_moved), std::sqrt(moved));
  }
  EXPECT_GT(children, 0);
}

// Petals and leaflets ride on their swaying stalk: the center of mass of a part never gets
// further from its base than the part reaches (it trailed by 2 tau v_base, up to 0.26 m,
// before the step carried X with the base), and in the wind it keeps near its rest arm.
TEST(UnderbrushKernel, AttachedPartsStayWithinReachOfTheirMovingBase) {
  const std::vector<std::string> species = {"daisy", "fern"};
  Placed p = place(12.0f, species, 3);
  const impl::Meadow m = impl::meadow_from_plantings(species_params(species), planting_grid(3, 0.3));
  std::vector<boreas_component> rest = p.world->meadow_components(p.id);
  ASSERT_EQ(rest.size(), size_t(m.count));
  double worst = 0.0, base_travel = 0.0;
  int children = 0;
  for (int s = 0; s < 90; ++s) {
    p.world->step(1.0f / 60.0f);
    std::vector<boreas_component> comps = p.world->meadow_components(p.id);
    for (int c = 0; c < m.count; ++c) {
      const boreas_component& k = comps[size_t(c)];
      if (k.parent < 0) continue;
      children += s == 0;
      const BoreasGpuPart& g = m.parts[size_t(impl::part_of(m.index.data(), m.count, int(c)))].gpu;
      const double reach = double(g.reach) * impl::unpack_frame(m.index.data(), m.count, int(c)).scale;
      worst = std::max(worst, dist(k.center_of_mass, k.base) / reach);
      base_travel = std::max(base_travel, dist(k.base, rest[size_t(c)].base));
    }
  }
  ASSERT_GT(children, 0);
  EXPECT_GT(base_travel, 0.02);  // the stalks did sway
  EXPECT_LE(worst, 1.0 + 1e-3);
}

// A rain drop's impulse gives a light part metres per second (the default 2e-4 N s gives a
// daisy's petal of ~15 mg about 13 m/s): its center of mass still stays within the part's
// reach of its base, where it flew over a metre from it, through the ground (found by
// tests/soak), and the meadow settles again.
TEST(UnderbrushKernel, ImpulsesNeverThrowAPartPastItsReach) {
  const std::vector<std::string> species = {"daisy", "clover", "fern", "meadow_grass"};
  Placed p = place(0.0f, species, 3);
  const impl::Meadow m = impl::meadow_from_plantings(species_params(species), planting_grid(3, 0.3));
  boreas_emitter_def drop = boreas_default_emitter_def();
  drop.rate = 0.0f;  // one event, at the center, reaching every component almost in full
  drop.area_radius = 0.0f;
  drop.event_radius = 50.0f;
  drop.impulse[0] = 1e-4f;
  drop.impulse[1] = -2e-4f;
  p.world->add_emitter(drop);
  // |X - base| over reach, past reach by more than the rounding of X's coordinates (a
  // petal's reach is ~8 mm, its X ~0.5 m from the origin: 6e-8 m ulps).
  double worst = 0.0, excess = 0.0;
  for (int s = 0; s < 300; ++s) {
    p.world->step(1.0f / 60.0f);
    std::vector<boreas_component> comps = p.world->meadow_components(p.id);
    ASSERT_EQ(comps.size(), size_t(m.count));
    for (int c = 0; c < m.count; ++c) {
      const boreas_component& k = comps[size_t(c)];
      const BoreasGpuPart& g = m.parts[size_t(impl::part_of(m.index.data(), m.count, int(c)))].gpu;
      const double reach = double(g.reach) * impl::unpack_frame(m.index.data(), m.count, int(c)).scale;
      const double d = dist(k.center_of_mass, k.base);
      worst = std::max(worst, d / reach);
      excess = std::max(excess, d - reach);
    }
  }
  // Without the limit the petals went to 370 times their reach.
  EXPECT_GT(worst, 0.99) << "the drop threw the light parts as far as they reach";
  EXPECT_LE(excess, 1e-6) << "m past reach; worst " << worst << " of reach";
  for (const boreas_component& c : p.world->meadow_components(p.id))
    EXPECT_LT(dist(c.center_of_mass, c.rest_center_of_mass), 1e-3);
}

TEST(UnderbrushKernel, SameInputsGiveBitIdenticalState) {
  auto run = [] {
    Placed p = place(7.0f, {"meadow_grass", "daisy"}, 3);
    boreas_emitter_def rain = boreas_default_emitter_def();
    p.world->add_emitter(rain);
    for (int s = 0; s < 40; ++s) p.world->step(1.0f / 60.0f);
    return p.world->underbrush().read_meadow_state(p.world->meadow(p.id).key);
  };
  std::vector<float> a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

// ---- Vertices ----------------------------------------------------------------------------

TEST(UnderbrushVertices, LevelOfDetailVertexCounts) {
  Placed p = place(0.0f, {"meadow_grass"}, 1);  // 7 blades of 6 sections at the origin
  std::vector<float> v;
  std::vector<int32_t> counts;
  // Default LOD distances 15, 40, 120 m.
  struct Case {
    float distance;
    int expected;
  } cases[] = {{1.0f, 14}, {20.0f, 8}, {60.0f, 4}, {200.0f, 0}};
  for (const Case& c : cases) {
    float cam[3] = {c.distance, 0.0f, 0.0f};
    p.world->meadow_vertices(p.id, cam, &v, &counts);
    for (int32_t n : counts) EXPECT_EQ(n, c.expected) << "at " << c.distance << " m";
  }
  p.world->meadow_vertices(p.id, nullptr, &v, &counts);
  for (int32_t n : counts) EXPECT_EQ(n, 14);
}

// The strip's own center of mass (section masses at the midpoints of its main axis) against
// the animated X: in direction from the base always (the inverse table's shapes are turned
// to X's polar angle), and in distance too once X has settled at an equilibrium. Mid-swing,
// X moves on the straight path of the point-mass constraint and may pass closer to the base
// than any bent shape's center of mass can be: the shape is then the most curled one.
void expect_strips_follow(int steps, double max_distance_error) {
  Placed p = place(9.0f, {"meadow_grass"}, 3);
  impl::Meadow m = impl::meadow_from_plantings(species_params({"meadow_grass"}), planting_grid(3, 0.3));
  for (int s = 0; s < steps; ++s) p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> comps = p.world->meadow_components(p.id);
  std::vector<float> v;
  std::vector<int32_t> counts;
  p.world->meadow_vertices(p.id, nullptr, &v, &counts);
  const impl::ComponentSpecies& sp = m.params.species[0];
  std::vector<impl::SectionPhysics> sec = impl::part_sections(sp.tissue, sp.parts[0]);
  double worst_com = 0.0, worst_angle = 0.0, worst_len = 0.0, worst_width = 0.0;
  std::vector<double> half = impl::part_half_widths(sp.parts[0]);
  for (size_t c = 0; c < comps.size(); ++c) {
    double scale = impl::unpack_frame(m.index.data(), m.count, int(c)).scale;
    std::vector<double> mid[3];
    for (int j = 0; j < 7; ++j) {
      const float* l = &v[(c * 18 + 2 * j) * 8];
      const float* r = &v[(c * 18 + 2 * j + 1) * 8];
      for (int a = 0; a < 3; ++a) mid[a].push_back(0.5 * (l[a] + r[a]));
      // length_variation keeps the width (underbrush_math.h, boreas_ub_shape_load)
      worst_width = std::max(worst_width, std::fabs(dist(l, r) - 2.0 * half[j]) / half[0]);
      // Unit normal, perpendicular to the border vector.
      double nn = 0.0, nd = 0.0;
      for (int a = 0; a < 3; ++a) {
        nn += double(l[3 + a]) * l[3 + a];
        nd += double(l[3 + a]) * (r[a] - l[a]);
      }
      EXPECT_NEAR(nn, 1.0, 1e-5);
      EXPECT_NEAR(nd, 0.0, 1e-6);
    }
    double com[3] = {0, 0, 0}, mass = 0.0;
    for (int j = 0; j < 6; ++j) {
      double len = 0.0;
      for (int a = 0; a < 3; ++a) {
        com[a] += sec[j].mass * 0.5 * (mid[a][j] + mid[a][j + 1]);
        len += (mid[a][j + 1] - mid[a][j]) * (mid[a][j + 1] - mid[a][j]);
      }
      mass += sec[j].mass;
      worst_len = std::max(worst_len, std::fabs(std::sqrt(len) - sec[j].length * scale) / (sec[j].length * scale));
    }
    double reach = m.parts[0].gpu.reach * scale, along = 0.0, d_com = 0.0, d_x = 0.0;
    for (int a = 0; a < 3; ++a) {
      double ec = com[a] / mass - comps[c].base[a], ex = comps[c].center_of_mass[a] - comps[c].base[a];
      along += ec * ex;
      d_com += ec * ec;
      d_x += ex * ex;
    }
    worst_angle = std::max(worst_angle, std::acos(std::min(1.0, along / std::sqrt(d_com * d_x))));
    worst_com = std::max(worst_com, std::fabs(std::sqrt(d_com) - std::sqrt(d_x)) / reach);
  }
  // The inverse table is a nearest-sample table read bilinearly: its shapes' centers of
  // mass land within a few percent of the part's reach of X; segment lengths and widths
  // are the part's to float precision (lengths: interpolated joints shorten chords a little).
  EXPECT_LT(worst_angle, 0.03);
  EXPECT_LT(worst_com, max_distance_error);
  EXPECT_LT(worst_len, 0.05);
  EXPECT_LT(worst_width, 1e-4);
  std::printf("after %d steps: strip center of mass vs X: direction %.2f deg, distance %.2f %% of reach; "
              "segment length worst %.2f %%\n", steps, worst_angle * 180 / M_PI, 100 * worst_com, 100 * worst_len);
}

TEST(UnderbrushVertices, StripsFollowTheCenterOfMassMidSwing) { expect_strips_follow(20, 0.35); }
TEST(UnderbrushVertices, StripsMatchTheCenterOfMassAtEquilibrium) { expect_strips_follow(300, 0.04); }

TEST(UnderbrushVertices, KernelMatchesTheHostPathOfTheSameTables) {
  Placed p = place(5.0f, {"daisy"}, 2);
  impl::Meadow m = impl::meadow_from_plantings(species_params({"daisy"}), planting_grid(2, 0.3));
  for (int s = 0; s < 15; ++s) p.world->step(1.0f / 60.0f);
  std::vector<boreas_component> comps = p.world->meadow_components(p.id);
  std::vector<float> v;
  std::vector<int32_t> counts;
  p.world->meadow_vertices(p.id, nullptr, &v, &counts);
  double worst = 0.0;
  for (size_t c = 0; c < comps.size(); ++c) {
    BoreasV3 base = boreas_v3(comps[c].base[0], comps[c].base[1], comps[c].base[2]);
    BoreasV3 x = boreas_v3(comps[c].center_of_mass[0], comps[c].center_of_mass[1], comps[c].center_of_mass[2]);
    int sections = m.parts[size_t(impl::part_of(m.index.data(), m.count, int(c)))].def.sections;
    for (int j = 0; j <= sections; ++j) {
      BoreasV3 joint = impl::meadow_shape_joint(m, int(c), base, x, comps[c].broken, j);
      const float* l = &v[(c * 18 + 2 * j) * 8];
      const float* r = &v[(c * 18 + 2 * j + 1) * 8];
      worst = std::max({worst, std::fabs(0.5 * (l[0] + r[0]) - joint.x), std::fabs(0.5 * (l[1] + r[1]) - joint.y),
                        std::fabs(0.5 * (l[2] + r[2]) - joint.z)});
    }
  }
  EXPECT_LT(worst, 2e-6);
}

}  // namespace
}  // namespace boreas
