// boreas tests: the Weber-Penn tree generator — determinism, Weber-Penn's counts and lengths
// recomputed independently, the Bezier and hierarchy invariants the animation kernel relies
// on, leaves, parameter effects, refusals, and every Arbaro species in tests/data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace boreas::impl {
namespace {

// A three-level tree with no length variation, so every length and count follows from the
// model's offsets. Shape 4 (tapered cylindrical, 0.5 + 0.5 r) makes level-1 lengths differ.
Species test_species() {
  Species s;
  s.name = "test_tree";
  s.shape = 4;
  s.levels = 3;
  s.scale = 10.0;
  s.scale_v = 0.0;
  s.base_size = 0.2;
  s.ratio = 0.02;
  s.ratio_power = 1.2;
  s.flare = 0.5;
  s.lobes = 5;
  s.lobe_depth = 0.1;
  s.leaves = 10;
  s.leaf_scale = 0.2;
  s.leaf_scale_x = 0.5;
  s.leaf_quality = 1.0;
  s.leaf_stem_len = 0.25;
  s.leaf_distrib = 3;  // cylindrical: every last-level stem gets exactly Leaves
  s.leaf_bend = 0.0;   // leaves as placed (test_weber_penn_rules.cpp turns them)
  s.trunk_scale = 1.0;
  s.trunk_scale_v = 0.0;
  SpeciesLevel& l0 = s.level[0];
  l0.length = 1.0;
  l0.curve_res = 5;
  l0.curve_v = 10.0;
  l0.taper = 1.0;
  SpeciesLevel& l1 = s.level[1];
  l1.down_angle = 60.0;
  l1.down_angle_v = -40.0;
  l1.rotate = 140.0;
  l1.branches = 20;
  l1.branch_dist = 1.0;
  l1.length = 0.4;
  l1.curve = -30.0;
  l1.curve_v = 20.0;
  l1.taper = 1.0;
  SpeciesLevel& l2 = s.level[2];
  l2.down_angle = 45.0;
  l2.down_angle_v = 10.0;
  l2.rotate = -90.0;
  l2.branches = 8;
  l2.branch_dist = 1.0;
  l2.length = 0.5;
  l2.curve = 20.0;
  l2.curve_back = -10.0;
  l2.curve_v = 30.0;
  l2.curve_res = 3;  // Arbaro's default for levels 2 and 3 is 1 (straight)
  l2.taper = 1.0;
  SpeciesLevel& l3 = s.level[3];  // the leaf block
  l3.down_angle = 30.0;
  l3.rotate = 77.0;
  l3.branches = 4;
  l3.branch_dist = 1.0;
  l3.length = 0.5;
  return s;
}

bool same_branch(const BranchModel& a, const BranchModel& b) {
  return a.local == b.local && a.level == b.level && a.parent == b.parent && a.v == b.v &&
         a.theta == b.theta && a.alpha == b.alpha && a.length == b.length && a.radius == b.radius &&
         a.taper_depth == b.taper_depth && a.taper_exponent == b.taper_exponent &&
         a.flare == b.flare && a.bulge_count == b.bulge_count && a.bulge_depth == b.bulge_depth &&
         a.lobe_count == b.lobe_count && a.lobe_depth == b.lobe_depth &&
         a.lobe_taper == b.lobe_taper && a.tip_cap == b.tip_cap && a.bulge_phase == b.bulge_phase;
}

bool same_leaf(const LeafModel& a, const LeafModel& b) {
  return a.parent == b.parent && a.v == b.v && a.cos_theta == b.cos_theta &&
         a.sin_theta == b.sin_theta && a.cos_alpha == b.cos_alpha && a.sin_alpha == b.sin_alpha &&
         a.cos_roll == b.cos_roll && a.sin_roll == b.sin_roll && a.length == b.length &&
         a.width == b.width && a.stem == b.stem;
}

bool same_tree(const TreeModel& a, const TreeModel& b) {
  if (a.branches.size() != b.branches.size() || a.leaves.size() != b.leaves.size()) return false;
  if (a.levels != b.levels || a.level_begin != b.level_begin) return false;
  for (size_t i = 0; i < a.branches.size(); ++i)
    if (!same_branch(a.branches[i], b.branches[i])) return false;
  for (size_t i = 0; i < a.leaves.size(); ++i)
    if (!same_leaf(a.leaves[i], b.leaves[i])) return false;
  return true;
}

std::vector<int> children_per_branch(const TreeModel& t) {
  std::vector<int> n(t.branches.size(), 0);
  for (const BranchModel& b : t.branches)
    if (b.parent >= 0) ++n[size_t(b.parent)];
  return n;
}

std::vector<int> leaves_per_branch(const TreeModel& t) {
  std::vector<int> n(t.branches.size(), 0);
  for (const LeafModel& l : t.leaves) ++n[size_t(l.parent)];
  return n;
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(TreeGenerator, SameSeedGivesTheSameTreeAndAnotherSeedAnother) {
  const Species s = test_species();
  const TreeModel a = grow_tree(s, 7);
  const TreeModel b = grow_tree(s, 7);
  const TreeModel c = grow_tree(s, 8);
  EXPECT_TRUE(same_tree(a, b));
  EXPECT_FALSE(same_tree(a, c));
  EXPECT_EQ(a.species, "test_tree");
}

TEST(TreeGenerator, BranchCountsAndLengthsFollowWeberPenn) {
  const Species s = test_species();
  for (uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const TreeModel t = grow_tree(s, seed);
    const std::vector<int> children = children_per_branch(t);
    const BranchModel& trunk = t.branches[0];
    EXPECT_DOUBLE_EQ(trunk.length, 10.0);         // 0Length * Scale, no variation
    EXPECT_DOUBLE_EQ(trunk.radius, 10.0 * 0.02);  // L Ratio 0Scale
    EXPECT_EQ(children[0], 20);                   // the trunk: 1Branches in all
    for (int i = t.level_begin[1]; i < t.level_begin[2]; ++i) {
      const BranchModel& b = t.branches[size_t(i)];
      // Above BaseSize; length L0 1Length ShapeRatio4((L0 - offset) / (L0 - BaseSize L0)).
      EXPECT_GE(b.v, 0.2);
      const double r = (1.0 - b.v) / (1.0 - 0.2);
      EXPECT_NEAR(b.length, 10.0 * 0.4 * (0.5 + 0.5 * r), 1e-9);
      // Children: floor(2Branches (0.2 + 0.8 (L / L0) / 1Length_max)).
      const int expected = int(std::floor(8.0 * (0.2 + 0.8 * (b.length / 10.0) / 0.4)));
      EXPECT_EQ(children[size_t(i)], expected) << "level-1 stem " << i;
    }
    for (int i = t.level_begin[2]; i < t.level_begin[3]; ++i) {
      const BranchModel& b = t.branches[size_t(i)];
      const BranchModel& parent = t.branches[size_t(b.parent)];
      EXPECT_NEAR(b.length, 0.5 * (parent.length - 0.6 * b.v * parent.length), 1e-9);
      EXPECT_EQ(children[size_t(i)], 0);  // the last level
    }
    EXPECT_EQ(t.levels, 3);
  }
}

TEST(TreeGenerator, DeeperLevelsHaveFewerChildrenTowardTheirParentsTip) {
  Species s = test_species();
  s.levels = 4;
  const TreeModel t = grow_tree(s, 11);
  ASSERT_EQ(t.levels, 4);
  const std::vector<int> children = children_per_branch(t);
  for (int i = t.level_begin[2]; i < t.level_begin[3]; ++i) {
    // floor(3Branches (1 - 0.5 offset / L_parent)), offset / L_parent = v.
    const int expected = int(std::floor(4.0 * (1.0 - 0.5 * t.branches[size_t(i)].v)));
    EXPECT_EQ(children[size_t(i)], expected) << "level-2 stem " << i;
  }
  for (int i = t.level_begin[3]; i < t.level_begin[4]; ++i) {
    const BranchModel& b = t.branches[size_t(i)];
    const BranchModel& parent = t.branches[size_t(b.parent)];
    EXPECT_NEAR(b.length, 0.5 * (parent.length - 0.6 * b.v * parent.length), 1e-9);
  }
}

TEST(TreeGenerator, ControlPolygonStartsAtTheOriginAlongXWithTheStemsLength) {
  const TreeModel t = grow_tree(test_species(), 3);
  for (const BranchModel& b : t.branches) {
    EXPECT_EQ(b.local[0], (std::array<double, 3>{0.0, 0.0, 0.0}));
    EXPECT_NEAR(b.local[1][0], b.length / 3.0, 1e-12 * b.length);
    EXPECT_EQ(b.local[1][1], 0.0);
    EXPECT_EQ(b.local[1][2], 0.0);
    double polygon = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double segment = distance(b.local[size_t(i)], b.local[size_t(i) + 1]);
      EXPECT_NEAR(segment, b.length / 3.0, 1e-12 * b.length);
      polygon += segment;
    }
    EXPECT_NEAR(polygon, b.length, 1e-12 * b.length);
  }
}

TEST(TreeGenerator, CurvatureBendsInThePlaneWithoutVariation) {
  Species s = test_species();
  s.level[1].curve_v = 0.0;
  s.level[1].curve = 60.0;  // 20 degrees at each of the two joints, toward +y
  const TreeModel t = grow_tree(s, 5);
  const BranchModel& b = t.branches[size_t(t.level_begin[1])];
  const double seg = b.length / 3.0;
  const double a = 20.0 * 3.14159265358979323846 / 180.0;
  EXPECT_NEAR(b.local[2][0], seg + seg * std::cos(a), 1e-12 * b.length);
  EXPECT_NEAR(b.local[2][1], seg * std::sin(a), 1e-12 * b.length);
  EXPECT_NEAR(b.local[3][0], seg + seg * std::cos(a) + seg * std::cos(2 * a), 1e-12 * b.length);
  EXPECT_NEAR(b.local[3][1], seg * std::sin(a) + seg * std::sin(2 * a), 1e-12 * b.length);
  EXPECT_NEAR(b.local[3][2], 0.0, 1e-12 * b.length);  // placed through its rest frame
}

TEST(TreeGenerator, ChildrenAttachToTheLevelAboveContiguouslyInParentOrder) {
  const TreeModel t = grow_tree(test_species(), 4);
  const BranchModel& trunk = t.branches[0];
  EXPECT_EQ(trunk.level, 0);
  EXPECT_EQ(trunk.parent, -1);
  EXPECT_EQ(trunk.v, 0.0);
  EXPECT_EQ(trunk.theta, 0.0);
  EXPECT_EQ(trunk.alpha, 0.0);
  int previous_parent = 0;
  for (size_t i = 1; i < t.branches.size(); ++i) {
    const BranchModel& b = t.branches[i];
    ASSERT_GE(b.parent, 0);
    ASSERT_LT(size_t(b.parent), i);
    EXPECT_EQ(t.branches[size_t(b.parent)].level, b.level - 1);
    EXPECT_GE(b.v, 0.0);
    EXPECT_LE(b.v, 1.0);
    EXPECT_GE(b.parent, previous_parent) << "children of one parent must be contiguous";
    previous_parent = b.parent;
  }
}

TEST(TreeGenerator, LevelBeginBracketsEachLevel) {
  const TreeModel t = grow_tree(test_species(), 9);
  EXPECT_EQ(t.level_begin[0], 0);
  EXPECT_EQ(t.level_begin[1], 1);
  for (int n = 0; n < kMaxTreeLevels; ++n) {
    EXPECT_LE(t.level_begin[size_t(n)], t.level_begin[size_t(n) + 1]);
    for (int i = t.level_begin[size_t(n)]; i < t.level_begin[size_t(n) + 1]; ++i)
      EXPECT_EQ(t.branches[size_t(i)].level, n);
  }
  for (int n = t.levels; n <= kMaxTreeLevels; ++n)
    EXPECT_EQ(t.level_begin[size_t(n)], int32_t(t.branches.size()));
  EXPECT_LT(t.level_begin[size_t(t.levels) - 1], t.level_begin[size_t(t.levels)]);
}

TEST(TreeGenerator, RadiiShrinkWithLevelAndNeverExceedTheParent) {
  const TreeModel t = grow_tree(test_species(), 6);
  for (size_t i = 1; i < t.branches.size(); ++i) {
    const BranchModel& b = t.branches[i];
    EXPECT_GT(b.radius, 0.0);
    EXPECT_LE(b.radius, t.branches[size_t(b.parent)].radius);
  }
  double previous_max = t.branches[0].radius;
  for (int n = 1; n < t.levels; ++n) {
    double level_max = 0.0;
    for (int i = t.level_begin[size_t(n)]; i < t.level_begin[size_t(n) + 1]; ++i)
      level_max = std::max(level_max, t.branches[size_t(i)].radius);
    EXPECT_LT(level_max, previous_max) << "level " << n;
    previous_max = level_max;
  }
}

TEST(TreeGenerator, RadiusFunctionsFollowTheSpecies) {
  Species s = test_species();
  s.level[0].taper = 0.7;
  s.level[1].taper = 1.5;
  s.level[2].taper = 2.5;
  const TreeModel t = grow_tree(s, 2);
  const BranchModel& trunk = t.branches[0];
  EXPECT_EQ(trunk.taper_depth, 0.7);
  EXPECT_EQ(trunk.taper_exponent, 1.0);
  EXPECT_EQ(trunk.flare, 0.5);
  EXPECT_EQ(trunk.lobe_count, 5.0);
  EXPECT_EQ(trunk.lobe_depth, 0.1);
  EXPECT_EQ(trunk.lobe_taper, 1.0);
  EXPECT_EQ(trunk.bulge_depth, 0.0);
  const BranchModel& branch = t.branches[size_t(t.level_begin[1])];
  EXPECT_DOUBLE_EQ(branch.taper_depth, 0.5);  // Arbaro's unit taper 2 - nTaper
  EXPECT_EQ(branch.taper_exponent, 1.0);
  EXPECT_EQ(branch.flare, 0.0);
  EXPECT_EQ(branch.lobe_count, 0.0);
  EXPECT_EQ(branch.lobe_depth, 0.0);
  const BranchModel& twig = t.branches[size_t(t.level_begin[2])];
  // Arbaro's beads: no taper, beads one diameter long counted from the stem's tip, their
  // waists sunk by nTaper - 2 of the radius, the last radius the tip's hemisphere.
  ASSERT_EQ(twig.stem_from, 0.0);
  EXPECT_EQ(twig.taper_depth, 0.0);
  EXPECT_EQ(twig.bulge_depth, 0.5);
  EXPECT_NEAR(twig.bulge_count, twig.length / (2.0 * twig.radius), 1e-9 * twig.bulge_count);
  EXPECT_NEAR(twig.bulge_phase, (twig.stem_length - twig.length) / (2.0 * twig.radius),
              1e-9 * twig.stem_length / twig.radius);
  if (twig.length == twig.stem_length) EXPECT_DOUBLE_EQ(twig.tip_cap, twig.radius / twig.length);
}

TEST(TreeGenerator, LeavesGrowOnTheLastLevelOnly) {
  const Species s = test_species();
  const TreeModel t = grow_tree(s, 12);
  ASSERT_FALSE(t.leaves.empty());
  const std::vector<int> leaves = leaves_per_branch(t);
  for (size_t i = 0; i < t.branches.size(); ++i)
    EXPECT_EQ(leaves[i], t.branches[i].level == 2 ? 10 : 0) << "branch " << i;
  int previous_parent = 0;
  for (const LeafModel& l : t.leaves) {
    EXPECT_GE(l.parent, previous_parent) << "leaves must be grouped by parent";
    previous_parent = l.parent;
    EXPECT_GE(l.v, 0.0);
    EXPECT_LE(l.v, 1.0);
    EXPECT_DOUBLE_EQ(l.length, 0.2);
    EXPECT_DOUBLE_EQ(l.width, 0.1);
    EXPECT_DOUBLE_EQ(l.stem, 0.05);
    EXPECT_NEAR(l.alpha(), 30.0 * 3.14159265358979323846 / 180.0, 1e-12);
  }
}

TEST(TreeGenerator, LeafCountsFollowLeafDistribAndRoundByChance) {
  Species s = test_species();
  s.leaves = 5;
  s.leaf_quality = 0.5;  // 2.5 leaves per stem: 2 or 3
  const TreeModel t = grow_tree(s, 13);
  const std::vector<int> leaves = leaves_per_branch(t);
  int stems = 0, total = 0;
  for (int i = t.level_begin[2]; i < t.level_begin[3]; ++i) {
    EXPECT_TRUE(leaves[size_t(i)] == 2 || leaves[size_t(i)] == 3);
    total += leaves[size_t(i)];
    ++stems;
  }
  ASSERT_GT(stems, 50);
  EXPECT_NEAR(double(total) / stems, 2.5, 0.2);
  // Fewer, larger leaves: Weber-Penn's LeafScale / sqrt(LeafQuality).
  EXPECT_DOUBLE_EQ(t.leaves[0].length, 0.2 / std::sqrt(0.5));

  s.leaf_quality = 1.0;
  s.leaf_distrib = 4;  // 0.5 + 0.5 r, r = offset / L_parent
  const TreeModel u = grow_tree(s, 13);
  const std::vector<int> counts = leaves_per_branch(u);
  for (int i = u.level_begin[2]; i < u.level_begin[3]; ++i) {
    const double expected = 5.0 * (0.5 + 0.5 * u.branches[size_t(i)].v);
    EXPECT_GE(counts[size_t(i)], int(std::floor(expected)));
    EXPECT_LE(counts[size_t(i)], int(std::ceil(expected)));
  }
}

TEST(TreeGenerator, NoLeavesWhenLeavesIsZeroOrTheTreeIsATrunk) {
  Species s = test_species();
  s.leaves = 0;
  EXPECT_TRUE(grow_tree(s, 1).leaves.empty());
  s.leaves = 10;
  s.levels = 1;
  const TreeModel t = grow_tree(s, 1);
  EXPECT_EQ(t.branches.size(), 1u);
  EXPECT_EQ(t.levels, 1);
  EXPECT_TRUE(t.leaves.empty());
}

TEST(TreeGenerator, FanLeavesSitAtTheTip) {
  Species s = test_species();
  s.leaves = -5;
  s.level[3].rotate = 60.0;
  s.level[3].down_angle = 0.0;
  const TreeModel t = grow_tree(s, 3);
  const std::vector<int> leaves = leaves_per_branch(t);
  for (int i = t.level_begin[2]; i < t.level_begin[3]; ++i) EXPECT_EQ(leaves[size_t(i)], 5);
  for (const LeafModel& l : t.leaves) {
    EXPECT_EQ(l.v, 1.0);
    EXPECT_LE(l.alpha(), 3.14159265358979323846 / 180.0 * 25.0);  // 2.5 steps of 12 degrees
  }
}

TEST(TreeGenerator, MoreBranchesWithLargerBranchCounts) {
  Species s = test_species();
  s.level[1].branches = 10;
  const size_t few = grow_tree(s, 1).branches.size();
  s.level[1].branches = 40;
  const size_t many = grow_tree(s, 1).branches.size();
  EXPECT_GT(many, few);
  s.level[2].branches = 16;
  EXPECT_GT(grow_tree(s, 1).branches.size(), many);
}

TEST(TreeGenerator, ScaleMultipliesEveryLength) {
  const Species s = test_species();
  const TreeModel a = grow_tree(s, 21, 1.0);
  const TreeModel b = grow_tree(s, 21, 2.5);
  ASSERT_EQ(a.branches.size(), b.branches.size());
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  for (size_t i = 0; i < a.branches.size(); ++i) {
    const BranchModel& x = a.branches[i];
    const BranchModel& y = b.branches[i];
    EXPECT_NEAR(y.length, 2.5 * x.length, 1e-12 * y.length);
    EXPECT_NEAR(y.radius, 2.5 * x.radius, 1e-12 * y.radius);
    for (size_t p = 0; p < 4; ++p)
      for (size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(y.local[p][c], 2.5 * x.local[p][c], 1e-12 * y.length);
    EXPECT_EQ(x.parent, y.parent);
    // Angles agree to rounding (a negative nDownAngleV reads a ratio of scaled lengths).
    EXPECT_NEAR(x.v, y.v, 1e-12);
    EXPECT_NEAR(x.theta, y.theta, 1e-12);
    EXPECT_NEAR(x.alpha, y.alpha, 1e-12);
  }
  for (size_t i = 0; i < a.leaves.size(); ++i) {
    EXPECT_NEAR(b.leaves[i].length, 2.5 * a.leaves[i].length, 1e-12);
    EXPECT_DOUBLE_EQ(a.leaves[i].v, b.leaves[i].v);
  }
}

TEST(TreeGenerator, RefusesBadScalesAndExplodingSpecies) {
  const Species s = test_species();
  for (double scale : {-1.0, 0.0, std::nan(""), HUGE_VAL}) {
    try {
      (void)grow_tree(s, 1, scale);
      ADD_FAILURE() << "scale " << scale << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
      EXPECT_NE(std::string(e.what()).find("scale"), std::string::npos) << e.what();
    }
  }
  Species big = test_species();
  big.name = "jungle";
  big.levels = 4;
  for (int n = 1; n < 4; ++n) big.level[size_t(n)].branches = 10000;
  try {
    (void)grow_tree(big, 1);
    ADD_FAILURE() << "an exploding species was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT);
    const std::string what = e.what();
    EXPECT_NE(what.find("'jungle'"), std::string::npos) << what;
    EXPECT_NE(what.find("Levels = 4"), std::string::npos) << what;
  }
}

// ---- Every Arbaro species in tests/data ----

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

const char* const kArbaroFiles[] = {
    "barley",   "black_tupelo",   "ca_black_oak",  "desert_bush", "eastern_cottonwood",
    "fanpalm",  "palm",           "quaking_aspen", "rush",        "shave-grass",
    "tamarack", "weeping_willow", "wheat"};

bool finite_branch(const BranchModel& b) {
  for (const auto& p : b.local)
    for (double c : p)
      if (!std::isfinite(c)) return false;
  for (double x : {b.v, b.theta, b.alpha, b.length, b.radius, b.taper_depth, b.taper_exponent,
                   b.flare, b.bulge_count, b.bulge_depth, b.lobe_count, b.lobe_depth, b.lobe_taper, b.tip_cap,
                   b.bulge_phase})
    if (!std::isfinite(x)) return false;
  return true;
}

TEST(TreeGenerator, EveryArbaroSpeciesGrowsAPlausibleTree) {
  for (const char* name : kArbaroFiles) {
    SCOPED_TRACE(name);
    const std::string file = std::string(BOREAS_TEST_DATA_DIR) + "/arbaro/" + name + ".xml";
    const Species s = parse_arbaro_xml(read_text(file), file);
    for (uint64_t seed : {1u, 2u}) {
      const TreeModel t = grow_tree(s, seed);
      EXPECT_GE(t.levels, 1);
      EXPECT_LE(t.levels, s.levels);
      // Each factor is kept above a tenth of its value (shave-grass: Scale 0.5 +- 0.7).
      const double lo = std::max(s.level[0].length - s.level[0].length_v, 0.1 * s.level[0].length) *
                        std::max(s.scale - s.scale_v, 0.1 * s.scale);
      const double hi = (s.level[0].length + s.level[0].length_v) * (s.scale + s.scale_v);
      // The trunk's whole length (a split ends its first piece early).
      EXPECT_GE(t.branches[0].stem_length, lo - 1e-9);
      EXPECT_LE(t.branches[0].stem_length, hi + 1e-9);
      if (s.levels > 1 && s.level[1].branches >= 2) {
        EXPECT_GT(t.branches.size(), 1u);
        EXPECT_EQ(t.levels, s.levels);
      }
      for (const BranchModel& b : t.branches) {
        ASSERT_TRUE(finite_branch(b));
        EXPECT_GT(b.length, 0.0);
        EXPECT_GT(b.radius, 0.0);
      }
      for (const LeafModel& l : t.leaves) {
        ASSERT_TRUE(std::isfinite(l.v) && std::isfinite(l.theta()) && std::isfinite(l.alpha()));
        EXPECT_EQ(t.branches[size_t(l.parent)].level, s.levels - 1);
      }
      if (s.leaves != 0 && t.levels == s.levels && s.levels > 1) {
        EXPECT_FALSE(t.leaves.empty());
      }
    }
  }
}

}  // namespace
}  // namespace boreas::impl
