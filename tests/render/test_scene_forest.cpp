// render tests: the scene's "forests" array (a stand of trees expanded by the loader), the
// trees' rotation and levels of detail, the camera's walk (view.eye_end), and more than
// the 1,024 trees scene files were once limited to.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "scene/forest.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "scene/scene_seed.h"
#include "scene_error_for.h"

namespace boreas::render {
namespace {

using testing::error_for;

const char* kStand = R"({"forests": [{"species": [{"species": "quaking_aspen", "weight": 3},
                                                   {"species": "ca_black_oak", "weight": 1}],
  "count": 2000, "center": [10, 1, -20], "size": [200, 100], "templates": 7, "seed": 5,
  "scale": [0.8, 1.2], "mode": "exact", "lod_distances": [10, 20, 40]}],
  "trees": [{"species": "black_tupelo", "rotation": 1.5, "lod_distances": [5, 6, 7]}]})";

TEST(SceneForest, AStandExpandsIntoItsTreesAfterTheSingleOnes) {
  Scene scene = load_scene_text(kStand, "s.json");
  ASSERT_EQ(scene.trees.size(), 2001u);
  EXPECT_EQ(scene.trees[0].species, "black_tupelo");
  EXPECT_EQ(scene.trees[0].def.rotation, 1.5f);
  EXPECT_EQ(scene.trees[0].def.lod_distances[2], 7.0f);
  std::map<std::string, int> species;
  std::set<uint64_t> seeds;
  for (size_t i = 1; i < scene.trees.size(); ++i) {
    const SceneTree& t = scene.trees[i];
    ++species[t.species];
    seeds.insert(t.def.seed);
    EXPECT_EQ(t.def.species, nullptr);
    EXPECT_EQ(t.def.mode, BOREAS_TREE_EXACT);
    EXPECT_EQ(t.def.lod_distances[1], 20.0f);
    EXPECT_GE(t.def.position[0], 10.0f - 100.0f);
    EXPECT_LE(t.def.position[0], 10.0f + 100.0f);
    EXPECT_GE(t.def.position[2], -20.0f - 50.0f);
    EXPECT_LE(t.def.position[2], -20.0f + 50.0f);
    EXPECT_EQ(t.def.position[1], 1.0f);
    EXPECT_GE(t.def.scale, 0.8f);
    EXPECT_LE(t.def.scale, 1.2f);
    EXPECT_GE(t.def.rotation, 0.0f);
    EXPECT_LT(t.def.rotation, 6.3f);
  }
  // The weights (3 : 1, within sampling error of 2,000 draws) and the templates (7 seeds).
  EXPECT_NEAR(double(species["quaking_aspen"]) / 2000.0, 0.75, 0.04);
  EXPECT_EQ(seeds.size(), 7u);
}

TEST(SceneForest, TreesKeepTheirDistanceAndTheSameSeedPlantsTheSameStand) {
  SceneForest f;
  f.species = {{"quaking_aspen", 1.0f}};
  f.count = 400;
  f.size[0] = f.size[1] = 100.0f;
  std::vector<SceneTree> a = plant_forest(f), b = plant_forest(f);
  ASSERT_EQ(a.size(), 400u);
  const double spacing = 100.0 / 20.0;  // 20 x 20 cells of 5 m
  double nearest = 1e9;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].def.position[0], b[i].def.position[0]);
    EXPECT_EQ(a[i].def.seed, b[i].def.seed);
    for (size_t j = i + 1; j < a.size(); ++j)
      nearest = std::min(nearest, std::hypot(double(a[i].def.position[0] - a[j].def.position[0]),
                                             double(a[i].def.position[2] - a[j].def.position[2])));
  }
  EXPECT_GE(nearest, 0.3 * spacing - 1e-3) << "jitter stays within 35 % of a cell";
  f.seed = 2;
  EXPECT_NE(plant_forest(f)[0].def.position[0], a[0].def.position[0]);
}

TEST(SceneForest, MistakesAreReportedWithTheirPath) {
  struct Case {
    const char* json;
    const char* where;
    const char* detail;
  };
  const Case cases[] = {
      {R"({"forests": [{"count": 10}]})", "/forests/0/species", "must list at least one species"},
      {R"({"forests": [{"species": [{"species": "baobab"}], "count": 10}]})",
       "/forests/0/species/0/species", "unknown species"},
      {R"({"forests": [{"species": [{"species": "quaking_aspen"}]}]})", "/forests/0/count", ""},
      {R"({"forests": [{"species": [{"species": "quaking_aspen"}], "count": 10, "scale": [2, 1]}]})",
       "/forests/0/scale/1", "must be >= scale/0"},
      {R"({"forests": [{"species": [{"species": "quaking_aspen", "weight": 0}], "count": 10}]})",
       "/forests/0/species/0/weight", ""},
      {R"({"trees": [{"species": "quaking_aspen", "lod_distances": [30, 20, 40]}]})",
       "/trees/0/lod_distances/1", "must be >= lod_distances/0"},
      {R"({"view": {"eye_end": [1, 2, 3]}})", "/view/eye_end", "needs eye"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.json);
    SceneError e = error_for(c.json, "scenes");
    EXPECT_EQ(e.where(), c.where) << e.what();
    EXPECT_NE(e.detail().find(c.detail), std::string::npos) << e.detail();
  }
}

TEST(SceneForest, MoreThanAThousandTreesAreAccepted) {
  std::string trees = "[";
  for (int i = 0; i < 3000; ++i)
    trees += std::string(i ? "," : "") + R"({"species": "quaking_aspen"})";
  trees += "]";
  EXPECT_EQ(load_scene_text(R"({"trees": )" + trees + "}", "s.json").trees.size(), 3000u);
}

// A 75-byte scene with "count": 10000000 made the loader ask for 1.8 GB at once, and any
// number of such forests was accepted; a scene now holds at most 2^20 trees in all, refused
// at the forest that passes the limit before it is planted.
TEST(SceneForest, AScenesTreesStopAtTwoToTheTwentiethInAll) {
  const std::string aspens = R"({"species": [{"species": "quaking_aspen"}], "count": )";
  SceneError e = error_for(R"({"forests": [)" + aspens + "10000000}]}");
  EXPECT_EQ(e.where(), "/forests/0/count") << e.what();
  EXPECT_NE(e.detail().find("<= 1048576"), std::string::npos) << e.detail();
  e = error_for(R"({"trees": [{"species": "quaking_aspen"}], "forests": [)" + aspens + "600000}, " +
                aspens + "448576}]}");
  EXPECT_EQ(e.where(), "/forests/1/count") << e.what();
  EXPECT_NE(e.detail().find("makes the scene's trees 1048577, more than the 1048576"),
            std::string::npos)
      << e.detail();
  // A smaller limit (the fuzzer's) is checked the same way.
  SceneLimits ten;
  ten.trees = 10;
  EXPECT_EQ(load_scene_text(R"({"forests": [)" + aspens + "10}]}", "s.json", "", ten).trees.size(),
            10u);
  try {
    (void)load_scene_text(R"({"forests": [)" + aspens + "11}]}", "s.json", "", ten);
    ADD_FAILURE() << "11 trees under a limit of 10";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.where(), "/forests/0/count") << error.what();
  }
}

TEST(SceneForest, TheCameraWalksFromEyeToEyeEnd) {
  Scene scene = load_scene_text(
      R"({"view": {"eye": [0, 2, 0], "eye_end": [10, 2, 0], "target": [0, 2, -5]}})", "s.json");
  ASSERT_TRUE(scene.view.eye_end.has_value());
  EXPECT_EQ((*scene.view.eye_end)[0], 10.0f);
}

// A run seed (boreas run --seed) over a scene: every seed changes, equal ones stay equal,
// the forest stands elsewhere; the same run seed gives the same scene, none the file's own.
TEST(SceneForest, ARunSeedReseedsEverySeedAndReplantsTheStand) {
  const std::string text = R"({"forests": [{"species": [{"species": "quaking_aspen", "weight": 1}],
    "count": 50, "size": [40, 40], "templates": 3, "seed": 5}],
    "trees": [{"species": "black_tupelo", "seed": 2}, {"species": "black_tupelo", "seed": 2},
              {"species": "quaking_aspen", "seed": 3}],
    "mesh_trees": [], "meadows": [{"size": [4, 4], "seed": 2}],
    "emitters": [{"center": [0, 1, 0], "seed": 9}]})";
  const Scene own = load_scene_text(text, "s.json");
  const Scene seeded = load_scene_text(text, "s.json", "", {}, uint64_t(11));
  const Scene again = load_scene_text(text, "s.json", "", {}, uint64_t(11));
  const Scene other = load_scene_text(text, "s.json", "", {}, uint64_t(12));
  ASSERT_EQ(seeded.trees.size(), own.trees.size());
  EXPECT_EQ(own.trees[0].def.seed, 2u);
  EXPECT_EQ(seeded.trees[0].def.seed, mix_seed(11, 2));
  EXPECT_EQ(seeded.trees[1].def.seed, seeded.trees[0].def.seed);
  EXPECT_NE(seeded.trees[2].def.seed, seeded.trees[0].def.seed);
  EXPECT_EQ(seeded.meadows[0].def.seed, mix_seed(11, 2));
  EXPECT_EQ(seeded.emitters[0].seed, mix_seed(11, 9));
  EXPECT_NE(mix_seed(11, 2), mix_seed(12, 2));
  // The stand: replanted (other spots), still from 3 templates, the same for the same seed.
  int moved = 0;
  std::set<uint64_t> templates;
  for (size_t i = 3; i < own.trees.size(); ++i) {
    moved += own.trees[i].def.position[0] != seeded.trees[i].def.position[0];
    templates.insert(seeded.trees[i].def.seed);
    EXPECT_EQ(seeded.trees[i].def.position[0], again.trees[i].def.position[0]);
    EXPECT_EQ(seeded.trees[i].def.seed, again.trees[i].def.seed);
  }
  EXPECT_EQ(moved, 50);
  EXPECT_LE(templates.size(), 3u);
  EXPECT_GE(templates.size(), 2u);
  for (uint64_t t : templates) EXPECT_GT(t, 3u);  // not the file's template seeds 1..3
  EXPECT_NE(other.trees[3].def.position[0], seeded.trees[3].def.position[0]);
}

}  // namespace
}  // namespace boreas::render
