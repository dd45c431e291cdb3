// boreas tests: several trunks stand apart as Arbaro stands them (TreeImpl.make: each trunk
// translated by var(0BranchDist) along (sin a, cos a) of a = var(360), horizontally, not
// scaled by Scale; tree_generator.cpp, trunk_base). The grasses of the Arbaro species files
// (barley and wheat: 0BranchDist 0.1 m; rush: 0.05 m) grow as clumps, not from one point.
// The device side (every reader sees the trunk where it stands, the wind bends it about its
// own base) is in test_tree_kernels.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fstream>

#include "boreas/boreas.hpp"
#include "host/trees/arbaro_figures.h"
#include "support/temp_dir.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {
namespace {

Species arbaro_species(const std::string& name) {
  return load_species(
      (std::filesystem::path(BOREAS_TEST_DATA_DIR) / "arbaro" / (name + ".xml")).string());
}

// Where each trunk (a first piece on the root) stands at rest, by the double reference.
std::vector<glm::dvec3> trunk_bases(const TreeModel& m) {
  const std::vector<reference::Branch> rest = rest_branches(m);
  std::vector<glm::dvec3> bases;
  for (size_t b = 0; b < m.branches.size(); ++b)
    if (m.branches[b].parent < 0) bases.push_back(rest[b].curve.p[0]);
  return bases;
}

// Arbaro's rule: a distance uniform in (-d, d) along a uniform horizontal direction. So
// every base lies on the ground within d of the tree's origin; over n bases the mean
// distance is d / 2 (standard error d / sqrt(12 n)) and the mean offset is 0 (each
// component's standard error d / sqrt(6 n)), within 4 standard errors; and the farthest
// of hundreds comes within a tenth of d of the bound (missed with probability 0.9^n).
TEST(TrunksApart, EachTrunkStandsWithinBranchDistOfTheTreesBase) {
  for (const std::string name : {"barley", "rush", "wheat"}) {
    SCOPED_TRACE(name);
    const Species s = arbaro_species(name);
    const double d = s.level[0].branch_dist;
    ASSERT_GT(d, 0.0);
    ASSERT_GT(s.level[0].branches, 1.0);
    constexpr int kSeeds = 40;
    double sum_r = 0.0, far = 0.0;
    glm::dvec3 sum(0.0);
    int n = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
      for (const glm::dvec3& p : trunk_bases(grow_tree(s, uint64_t(seed)))) {
        EXPECT_NEAR(p.y, 0.0, 1e-12) << "seed " << seed;
        const double r = std::hypot(p.x, p.z);
        EXPECT_LT(r, d) << "seed " << seed;
        sum_r += r;
        sum += p;
        far = std::max(far, r);
        ++n;
      }
    }
    ASSERT_EQ(n, kSeeds * int(s.level[0].branches));
    EXPECT_NEAR(sum_r / n, 0.5 * d, 4.0 * d / std::sqrt(12.0 * n));
    EXPECT_NEAR(sum.x / n, 0.0, 4.0 * d / std::sqrt(6.0 * n));
    EXPECT_NEAR(sum.z / n, 0.0, 4.0 * d / std::sqrt(6.0 * n));
    EXPECT_GT(far, 0.9 * d);
    std::printf("    %-7s %d trunks: mean distance %.4f m (d/2 = %.4f), farthest %.4f m\n",
                name.c_str(), n, sum_r / n, 0.5 * d, far);
  }
}

// The draws are the trunks' own (a stream of their own), so standing apart moves each trunk
// whole and changes nothing else: barley (no pruning, no LeafBend, no AttractionUp: nothing
// that looks at where a stem is) grown with 0BranchDist 0 is the same tree with every trunk
// at the origin, seed for seed. With 0BranchDist 0 every base is exactly the origin.
TEST(TrunksApart, StandingApartMovesEachTrunkWholeAndNothingElse) {
  Species apart = arbaro_species("barley");
  Species together = apart;
  together.level[0].branch_dist = 0.0;
  for (int seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const TreeModel a = grow_tree(apart, uint64_t(seed));
    const TreeModel t = grow_tree(together, uint64_t(seed));
    ASSERT_EQ(a.branches.size(), t.branches.size());
    ASSERT_EQ(a.leaves.size(), t.leaves.size());
    const double tol = 1e-12 * 10.0;  // the tree is under a metre tall
    for (size_t b = 0; b < a.branches.size(); ++b) {
      const BranchModel &x = a.branches[b], &y = t.branches[b];
      EXPECT_EQ(y.local[0], (std::array<double, 3>{0.0, 0.0, 0.0})) << b;
      EXPECT_EQ(x.parent, y.parent);
      EXPECT_EQ(x.v, y.v);
      EXPECT_EQ(x.theta, y.theta);
      EXPECT_EQ(x.alpha, y.alpha);
      EXPECT_EQ(x.length, y.length);
      EXPECT_EQ(x.radius, y.radius);
      if (x.parent >= 0) EXPECT_EQ(x.local[0], y.local[0]) << b;  // only trunks move
      for (size_t k = 1; k < 4; ++k)
        for (size_t c = 0; c < 3; ++c)
          EXPECT_NEAR(x.local[k][c] - x.local[0][c], y.local[k][c], tol) << b << " " << k;
    }
    for (size_t j = 0; j < a.leaves.size(); ++j) {
      EXPECT_EQ(a.leaves[j].parent, t.leaves[j].parent);
      EXPECT_EQ(a.leaves[j].v, t.leaves[j].v);
      EXPECT_NEAR(a.leaves[j].cos_theta, t.leaves[j].cos_theta, 1e-12);
      EXPECT_NEAR(a.leaves[j].cos_alpha, t.leaves[j].cos_alpha, 1e-12);
    }
    // Every branch of a standing-apart tree is its together twin moved by its trunk's base.
    const std::vector<reference::Branch> ra = rest_branches(a), rt = rest_branches(t);
    std::vector<glm::dvec3> moved(a.branches.size());
    for (size_t b = 0; b < a.branches.size(); ++b) {
      const int p = a.branches[b].parent;
      moved[b] = p < 0 ? ra[b].curve.p[0] - rt[b].curve.p[0] : moved[size_t(p)];
      for (size_t k = 0; k < 4; ++k)
        EXPECT_LT(glm::length(ra[b].curve.p[k] - rt[b].curve.p[k] - moved[b]), tol) << b;
    }
    for (const glm::dvec3& p : trunk_bases(t)) EXPECT_EQ(p, glm::dvec3(0.0));
  }
}

// A grown tree's scale multiplies the trunks' distances apart with every other length.
TEST(TrunksApart, DistancesApartScaleWithTheTree) {
  const Species s = arbaro_species("wheat");
  const std::vector<glm::dvec3> one = trunk_bases(grow_tree(s, 9, 1.0));
  const std::vector<glm::dvec3> three = trunk_bases(grow_tree(s, 9, 3.0));
  ASSERT_EQ(one.size(), three.size());
  for (size_t t = 0; t < one.size(); ++t)
    EXPECT_LT(glm::length(three[t] - 3.0 * one[t]), 1e-12) << t;
}

boreas_world_def small_world_def() {
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = def.grid.origin[2] = -16.0f;
  def.grid.origin[1] = 0.0f;
  def.grid.cell_size = 4.0f;
  def.grid.resolution[0] = def.grid.resolution[2] = 8;
  def.grid.resolution[1] = 6;
  return def;
}

// Through the public API: each trunk's base in the world is where the grown model puts it
// (the distances between bases are the model's times the tree's scale, whatever its turn
// and place), before and after a storm (the wind bends each trunk about its own base);
// and a second tree of the same species and seed, whose rest pose comes from the device's
// copy of the kept template (TreeBatch::template_rest) and to which heal returns, stands
// its trunks where a fresh world's does, bit for bit.
TEST(TrunksApart, EveryTrunkOfAWorldsTreeStandsWhereTheModelPutsIt) {
  const std::string file =
      (std::filesystem::path(BOREAS_TEST_DATA_DIR) / "arbaro" / "barley.xml").string();
  const std::vector<glm::dvec3> model = trunk_bases(grow_tree(arbaro_species("barley"), 3));
  boreas_tree_def def = boreas_default_tree_def();
  def.species = file.c_str();
  def.seed = 3;
  def.position[0] = 5.0f;
  def.position[2] = -4.0f;
  def.rotation = 0.7f;
  def.scale = 1.5f;
  boreas::World kept(small_world_def()), fresh(small_world_def());
  boreas_tree_def first = def;
  first.position[0] = -6.0f;
  (void)kept.add_tree(first);
  const boreas_tree_id a = kept.add_tree(def);
  const boreas_tree_id b = fresh.add_tree(def);
  const auto bases = [](const std::vector<boreas_branch>& branches) {
    std::vector<glm::dvec3> out;
    for (const boreas_branch& br : branches)
      if (br.parent < 0)
        out.emplace_back(br.control_points[0][0], br.control_points[0][1], br.control_points[0][2]);
    return out;
  };
  const auto check = [&](const std::vector<glm::dvec3>& world, const char* when) {
    ASSERT_EQ(world.size(), model.size()) << when;
    double widest = 0.0;
    for (size_t i = 0; i < world.size(); ++i) {
      EXPECT_NEAR(world[i].y, 0.0, 1e-6) << when;
      for (size_t j = 0; j < i; ++j) {
        const double want = 1.5 * glm::length(model[i] - model[j]);
        EXPECT_NEAR(glm::length(world[i] - world[j]), want, 1e-5) << when << " " << i << " " << j;
        widest = std::max(widest, want);
      }
    }
    EXPECT_GT(widest, 0.1) << when;  // they do stand apart
  };
  check(bases(fresh.tree_get_branches(b)), "at rest");
  const auto same = [](const std::vector<boreas_branch>& x, const std::vector<boreas_branch>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
  };
  EXPECT_TRUE(same(kept.tree_get_branches(a), fresh.tree_get_branches(b)));
  boreas_wave storm = boreas_default_wave();
  storm.direction[0] = 1.0f;
  storm.amplitude = 11.0f;
  storm.wavelength = 25.0f;
  storm.speed = 7.0f;
  for (boreas::World* w : {&kept, &fresh}) {
    w->wind_set_waves({storm});
    for (int s = 0; s < 20; ++s) w->step(1.0f / 60.0f);
  }
  const std::vector<boreas_branch> stormed = fresh.tree_get_branches(b);
  check(bases(stormed), "in the storm");
  double tip = 0.0;
  kept.tree_heal(a);
  const std::vector<boreas_branch> healed = kept.tree_get_branches(a);
  for (size_t i = 0; i < stormed.size(); ++i)
    if (stormed[i].parent < 0)
      for (int c = 0; c < 3; ++c)
        tip = std::max(tip, double(std::fabs(stormed[i].control_points[3][c] - healed[i].control_points[3][c])));
  EXPECT_GT(tip, 1e-3);  // the storm bent the stalks
  boreas::World again(small_world_def());
  EXPECT_TRUE(same(healed, again.tree_get_branches(again.add_tree(def))));
}

// The clump of poles below: three straight, untapered trunks up to a metre apart.
std::string write_poles_species(const test::TempDir& dir) {
  const std::string path = (dir.path() / "poles.json").string();
  std::ofstream(path) << R"({"format": "boreas-species-1", "name": "poles", "params": {
    "Levels": 1, "Scale": 10, "ScaleV": 0, "Flare": 0, "Lobes": 0, "Leaves": 0,
    "0Branches": 3, "0BranchDist": 1.0, "0Taper": 0, "0Curve": 0, "0CurveV": 0,
    "0CurveBack": 0, "0SegSplits": 0}})";
  return path;
}

// Colliders meet each trunk where it stands: a sphere pressed into the side of the pole
// farthest from the tree's base pushes that pole (its tip moves, the collider feels the
// push) and leaves the others as they stood; the same sphere at the tree's base, where no
// pole stands, touches nothing.
TEST(TrunksApart, AColliderTouchesTheTrunkWhereItStands) {
  test::TempDir dir;
  const std::string path = write_poles_species(dir);
  boreas_world_def wd = boreas_default_world_def();
  wd.wave_count = 0;
  constexpr double kBall = 0.1;
  // The first seed whose poles all stand clear of the base (by the ball and 5 cm).
  const auto clearance = [&](uint64_t seed) {
    boreas::World world(wd);
    boreas_tree_def def = boreas_default_tree_def();
    def.species = path.c_str();
    def.seed = seed;
    double nearest = 1e9;
    for (const boreas_branch& b : world.tree_get_branches(world.add_tree(def)))
      nearest = std::min(nearest, double(std::hypot(b.control_points[0][0], b.control_points[0][2]) - b.radius));
    return nearest;
  };
  uint64_t seed = 1;
  while (seed < 100 && !(clearance(seed) > kBall + 0.05)) ++seed;
  ASSERT_LT(seed, 100u);
  for (bool at_pole : {true, false}) {
    SCOPED_TRACE(at_pole ? "at the pole" : "at the base");
    boreas::World world(wd);
    boreas_tree_def def = boreas_default_tree_def();
    def.species = path.c_str();
    def.seed = seed;
    const boreas::TreeId tree = world.add_tree(def);
    const std::vector<boreas_branch> rest = world.tree_get_branches(tree);
    ASSERT_EQ(rest.size(), 3u);
    size_t far = 0;
    double apart = 0.0;
    for (size_t i = 0; i < rest.size(); ++i) {
      const double r = std::hypot(rest[i].control_points[0][0], rest[i].control_points[0][2]);
      if (r > apart) apart = r, far = i;
    }
    const float* p0 = rest[far].control_points[0];
    const double ux = p0[0] / apart, uz = p0[2] / apart;
    // Into the pole's outer side by 2 cm, at a fifth of its height; or at the base.
    const double d = rest[far].radius + kBall - 0.02;
    boreas_collider_def c = boreas_default_collider_def();
    c.radius = float(kBall);
    c.pose.position[0] = at_pole ? float(p0[0] + d * ux) : 0.0f;
    c.pose.position[1] = float(rest[far].control_points[3][1] / 5.0);
    c.pose.position[2] = at_pole ? float(p0[2] + d * uz) : 0.0f;
    const boreas_collider_id ball = world.add_collider(c);
    for (int s = 0; s < 10; ++s) world.step(1.0f / 60.0f);
    const std::vector<boreas_branch> now = world.tree_get_branches(tree);
    const boreas_collider_contact contact = world.collider_get_contact(ball);
    const double push = std::hypot(contact.force[0], contact.force[1], contact.force[2]);
    for (size_t i = 0; i < now.size(); ++i) {
      double moved = 0.0;
      for (int k = 0; k < 3; ++k)
        moved = std::max(moved, double(std::fabs(now[i].control_points[3][k] - rest[i].control_points[3][k])));
      if (at_pole && i == far)
        EXPECT_GT(moved, 1e-4) << "the pushed pole " << i;
      else
        EXPECT_EQ(moved, 0.0) << "pole " << i;
    }
    if (at_pole)
      EXPECT_GT(push, 0.0);
    else
      EXPECT_EQ(push, 0.0);
  }
}

// Rays see each trunk where it stands: in the clump of poles (Levels 1, no leaves), each hit at its own surface by a level ray aimed at its
// axis from 5 m away, and the hit names that trunk.
TEST(TrunksApart, RaysHitEachTrunkWhereItStands) {
  test::TempDir dir;
  const std::string path = write_poles_species(dir);
  boreas_world_def wd = boreas_default_world_def();
  wd.wave_count = 0;
  boreas::World world(wd);
  boreas_tree_def def = boreas_default_tree_def();
  def.species = path.c_str();
  def.seed = 2;
  def.position[0] = 2.0f;
  const boreas::TreeId tree = world.add_tree(def);
  const std::vector<boreas_branch> trunks = world.tree_get_branches(tree);
  ASSERT_EQ(trunks.size(), 3u);
  double apart = 0.0;
  for (const boreas_branch& t : trunks) {
    apart = std::max(apart, std::hypot(t.control_points[0][0] - 2.0, t.control_points[0][2]));
    for (int c = 1; c < 4; ++c) {  // the premise: vertical poles
      EXPECT_NEAR(t.control_points[c][0], t.control_points[0][0], 1e-5);
      EXPECT_NEAR(t.control_points[c][2], t.control_points[0][2], 1e-5);
    }
  }
  EXPECT_GT(apart, 0.2);  // they stand apart
  constexpr double kFrom = 5.0;
  std::vector<boreas_ray> rays;
  for (size_t i = 0; i < trunks.size(); ++i) {
    const float* p0 = trunks[i].control_points[0];
    // Level, at a third of the height, from a side where no other pole stands in the way.
    double ux = 1.0, uz = 0.0;
    for (int k = 0; k < 36; ++k) {
      ux = std::cos(k * M_PI / 18.0), uz = std::sin(k * M_PI / 18.0);
      bool clear = true;
      for (size_t j = 0; j < trunks.size(); ++j) {
        const double dx = trunks[j].control_points[0][0] - p0[0];
        const double dz = trunks[j].control_points[0][2] - p0[2];
        const double along = dx * ux + dz * uz, across = std::fabs(dx * uz - dz * ux);
        if (j != i && along > 0.0 && across < 3.0 * trunks[j].radius) clear = false;
      }
      if (clear) break;
    }
    const float y = float(trunks[i].control_points[3][1] / 3.0);
    rays.push_back({{float(p0[0] + kFrom * ux), y, float(p0[2] + kFrom * uz)},
                    {float(-ux), 0.0f, float(-uz)}, std::numeric_limits<float>::infinity()});
  }
  const std::vector<boreas_hit> hits = world.cast_rays(rays);
  for (size_t i = 0; i < trunks.size(); ++i) {
    // A prism's surface lies between its inscribed and circumscribed circles.
    const double r = trunks[i].radius;
    EXPECT_EQ(hits[i].kind, BOREAS_HIT_BRANCH) << i;
    EXPECT_EQ(hits[i].part, int32_t(i)) << i;
    EXPECT_GE(hits[i].distance, kFrom - r - 1e-4) << i;
    EXPECT_LE(hits[i].distance, kFrom - r * std::cos(M_PI / def.levels[0].sides) + 1e-4) << i;
  }
}

}  // namespace
}  // namespace boreas::impl
