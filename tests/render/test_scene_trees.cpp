// render tests: the scene's "trees" array: defaults, values, species files found next to the
// scene, and each kind of mistake caught with the file and the JSON path.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "scene/leaf_choice.h"
#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "scene_error_for.h"

namespace boreas::render {
namespace {

namespace fs = std::filesystem;

using testing::error_for;

TEST(SceneTrees, AbsentKeysTakeTheLibraryDefaults) {
  Scene scene = load_scene_text(R"({"trees": [{"species": "quaking_aspen"}]})", "s.json");
  ASSERT_EQ(scene.trees.size(), 1u);
  const SceneTree& tree = scene.trees[0];
  boreas_tree_def defaults = boreas_default_tree_def();
  EXPECT_EQ(tree.species, "quaking_aspen");
  EXPECT_EQ(tree.def.species, nullptr);  // set from tree.species when the tree is added
  EXPECT_EQ(tree.def.position[0], 0.0f);
  EXPECT_EQ(tree.def.scale, defaults.scale);
  EXPECT_EQ(tree.def.seed, defaults.seed);
  EXPECT_EQ(tree.def.mode, defaults.mode);
  EXPECT_EQ(tree.def.response, defaults.response);
  EXPECT_EQ(tree.def.load, BOREAS_TREE_LOAD_DRAG);
  EXPECT_EQ(tree.def.bend_exponent, defaults.bend_exponent);
  EXPECT_EQ(tree.def.levels[2].rings, defaults.levels[2].rings);
  EXPECT_TRUE(load_scene_text("{}", "s.json").trees.empty());
}

TEST(SceneTrees, ValuesAreRead) {
  Scene scene = load_scene_text(R"({"trees": [
    {"species": "ca_black_oak", "position": [1, 2, 3], "scale": 0.5, "seed": 18446744073709551615,
     "mode": "exact", "response": "damped", "load": "linear", "bend_exponent": 4.88},
    {"species": "black_tupelo", "seed": 1e3, "mode": "lagged", "response": "quasi_static",
     "load": "drag"}]})",
                                "s.json");
  ASSERT_EQ(scene.trees.size(), 2u);
  const boreas_tree_def& oak = scene.trees[0].def;
  EXPECT_EQ(scene.trees[0].species, "ca_black_oak");
  EXPECT_EQ(oak.position[2], 3.0f);
  EXPECT_EQ(oak.scale, 0.5f);
  EXPECT_EQ(oak.seed, UINT64_MAX);
  EXPECT_EQ(oak.mode, BOREAS_TREE_EXACT);
  EXPECT_EQ(oak.response, BOREAS_TREE_DAMPED);
  EXPECT_EQ(oak.load, BOREAS_TREE_LOAD_LINEAR);
  EXPECT_EQ(oak.bend_exponent, 4.88f);
  EXPECT_EQ(scene.trees[1].def.load, BOREAS_TREE_LOAD_DRAG);
  EXPECT_EQ(scene.trees[1].def.seed, 1000u);
  EXPECT_EQ(scene.trees[1].def.mode, BOREAS_TREE_LAGGED);
  EXPECT_EQ(scene.trees[1].def.response, BOREAS_TREE_QUASI_STATIC);
}

TEST(SceneTrees, SpeciesFilesAreFoundNextToTheScene) {
  Scene scene = load_scene_text(
      R"({"trees": [{"species": "my/oak.xml"}, {"species": "../shared/Aspen.JSON"},
                     {"species": "/abs/tree.json"}]})",
      "s.json", "/data/scenes");
  EXPECT_EQ(scene.trees[0].species, "/data/scenes/my/oak.xml");
  EXPECT_EQ(scene.trees[1].species, "/data/shared/Aspen.JSON");
  EXPECT_EQ(scene.trees[2].species, "/abs/tree.json");
  // Without a folder (text, the built-in scene) paths stay relative to the working folder.
  EXPECT_EQ(load_scene_text(R"({"trees": [{"species": "oak.xml"}]})", "s.json").trees[0].species,
            "oak.xml");
  // A file on disk: its folder.
  fs::path dir = fs::temp_directory_path() / ("boreas_scene_trees_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream(dir / "scene.json") << R"({"trees": [{"species": "species/oak.xml"}]})";
  }
  Scene from_file = load_scene_file((dir / "scene.json").string());
  EXPECT_EQ(from_file.trees[0].species, (dir / "species" / "oak.xml").string());
  EXPECT_EQ(from_file.source, (dir / "scene.json").string());
  fs::remove_all(dir);
}

TEST(SceneTrees, DefaultSceneHasAGroveOfTwoSpeciesInsideTheGrid) {
  Scene scene = load_default_scene();
  ASSERT_GE(scene.trees.size(), 10u) << "the issue asks for at least 10 trees";
  std::set<std::string> species;
  const boreas_grid_def& g = scene.grid;
  for (const SceneTree& tree : scene.trees) {
    species.insert(tree.species);
    for (int a : {0, 2}) {
      EXPECT_GT(tree.def.position[a], g.origin[a]) << tree.species;
      EXPECT_LT(tree.def.position[a], g.origin[a] + g.cell_size * float(g.resolution[a]))
          << tree.species;
    }
    EXPECT_EQ(tree.def.position[1], g.origin[1]) << "on the ground";
    // Not inside a building.
    for (const SolidBox& box : scene.obstacles) {
      bool inside = tree.def.position[0] >= box.min[0] && tree.def.position[0] <= box.max[0] &&
                    tree.def.position[2] >= box.min[2] && tree.def.position[2] <= box.max[2];
      EXPECT_FALSE(inside) << tree.species;
    }
  }
  EXPECT_GE(species.size(), 2u);
}

TEST(SceneTrees, LeafKindsFollowTheSpeciesUnlessTheSceneChooses) {
  Scene scene = load_scene_text(R"({"trees": [
    {"species": "quaking_aspen"},
    {"species": "weeping_willow", "leaf": "oak"},
    {"species": "black_tupelo", "leaf": "broadleaf"},
    {"species": "ca_black_oak"}
  ]})",
                                "s.json");
  ASSERT_EQ(scene.trees.size(), 4u);
  EXPECT_EQ(scene.trees[0].leaf_kind, "aspen");
  EXPECT_EQ(scene.trees[1].leaf_kind, "oak");
  EXPECT_EQ(scene.trees[2].leaf_kind, "broadleaf");
  EXPECT_EQ(scene.trees[3].leaf_kind, "oak");
}

TEST(SceneTrees, DefaultSceneHasAWeepingWillowAndEachTreeItsSpeciesLeaf) {
  Scene scene = load_default_scene();
  std::set<std::string> kinds;
  int willows = 0;
  for (const SceneTree& tree : scene.trees) {
    kinds.insert(tree.leaf_kind);
    willows += tree.species == "weeping_willow";
  }
  EXPECT_EQ(willows, 1);
  EXPECT_EQ(kinds, (std::set<std::string>{"aspen", "oak", "willow"}));
}

struct TreeMistake {
  const char* label;
  const char* trees;
  const char* where;
  const char* detail;  // the start of the message after the place
};

TEST(SceneTrees, MistakesAreReportedWithTheirPath) {
  const TreeMistake cases[] = {
      {"NotAnArray", R"({"species": "quaking_aspen"})", "/trees",
       "expected an array of objects, got an object"},
      {"NotAnObject", R"(["quaking_aspen"])", "/trees/0",
       "expected an object, got a string (\"quaking_aspen\")"},
      {"MissingSpecies", R"([{"species": "quaking_aspen"}, {"position": [0, 0, 0]}])",
       "/trees/1/species",
       "missing: a tree needs a species: a built-in name (black_tupelo, ca_black_oak, "
       "quaking_aspen"},
      {"SpeciesTypo", R"([{"species": "quaking_aspn"}])", "/trees/0/species",
       "unknown species \"quaking_aspn\"; did you mean \"quaking_aspen\"?"},
      {"UnknownSpecies", R"([{"species": "baobab"}])", "/trees/0/species",
       "unknown species \"baobab\"; the built-in species are black_tupelo, ca_black_oak"},
      {"SpeciesNotAString", R"([{"species": 3}])", "/trees/0/species",
       "expected a string, got a number (3)"},
      {"ShortPosition", R"([{"species": "quaking_aspen", "position": [1, 2]}])",
       "/trees/0/position", "expected an array of 3 numbers, got an array of 2"},
      {"PositionNotANumber", R"([{"species": "quaking_aspen", "position": [1, "2", 3]}])",
       "/trees/0/position/1", "expected a number, got a string (\"2\")"},
      {"ZeroScale", R"([{"species": "quaking_aspen", "scale": 0}])", "/trees/0/scale",
       "must be > 0 (got 0)"},
      {"HugeScale", R"([{"species": "quaking_aspen", "scale": 5000}])", "/trees/0/scale",
       "must be <= 1000 (got 5000)"},
      {"NegativeSeed", R"([{"species": "quaking_aspen", "seed": -1}])", "/trees/0/seed",
       "must be >= 0 (got -1)"},
      {"FractionalSeed", R"([{"species": "quaking_aspen", "seed": 1.5}])", "/trees/0/seed",
       "must be an integer (got 1.5)"},
      {"SeedAsString", R"([{"species": "quaking_aspen", "seed": "7"}])", "/trees/0/seed",
       "expected an integer, got a string (\"7\")"},
      {"UnknownMode", R"([{"species": "quaking_aspen", "mode": "fast"}])", "/trees/0/mode",
       "must be one of lagged, exact (got \"fast\")"},
      {"UnknownResponse", R"([{"species": "quaking_aspen", "response": "springy"}])",
       "/trees/0/response", "must be one of quasi_static, damped (got \"springy\")"},
      {"BendExponentOutOfRange", R"([{"species": "quaking_aspen", "bend_exponent": 0}])",
       "/trees/0/bend_exponent", "must be >= 0.1 (got 0)"},
      {"UnknownLoad", R"([{"species": "quaking_aspen", "load": "cubic"}])", "/trees/0/load",
       "must be one of drag, linear (got \"cubic\")"},
      {"UnknownKey", R"([{"species": "quaking_aspen", "sead": 2}])", "/trees/0/sead",
       "unknown key; did you mean \"seed\"?"},
      {"UnknownLeafKind", R"([{"species": "quaking_aspen", "leaf": "mapel"}])", "/trees/0/leaf",
       "unknown leaf kind \"mapel\" (the kinds are broadleaf, aspen, oak, willow, tupelo)"},
      {"LeafKindTypo", R"([{"species": "quaking_aspen", "leaf": "wilow"}])", "/trees/0/leaf",
       "unknown leaf kind \"wilow\"; did you mean \"willow\"?"},
      {"LeafKindNotAString", R"([{"species": "quaking_aspen", "leaf": 3}])", "/trees/0/leaf",
       "expected a string, got a number (3)"},
      {"DuplicateKey", R"([{"species": "quaking_aspen", "scale": 1, "scale": 2}])",
       "/trees/0/scale", "key given twice in the same object"},
  };
  for (const TreeMistake& m : cases) {
    SCOPED_TRACE(m.label);
    SceneError e = error_for(R"({"trees": )" + std::string(m.trees) + "}", "scenes");
    EXPECT_EQ(e.source(), "s.json");
    EXPECT_EQ(e.where(), m.where);
    EXPECT_EQ(e.detail().rfind(m.detail, 0), 0u) << e.detail();
  }
}

TEST(SceneTrees, TreesIsATopLevelKey) {
  // Suggested when misspelt, like every other key.
  try {
    load_scene_text(R"({"tress": []})", "s.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "/tress");
    EXPECT_EQ(e.detail(), "unknown key; did you mean \"trees\"?");
  }
}

TEST(SceneTrees, WearTheirSpeciesLeafKind) {
  EXPECT_EQ(default_leaf_kind("quaking_aspen"), "aspen");
  EXPECT_EQ(default_leaf_kind("ca_black_oak"), "oak");
  EXPECT_EQ(default_leaf_kind("weeping_willow"), "willow");
  EXPECT_EQ(default_leaf_kind("black_tupelo"), "tupelo");
  EXPECT_EQ(default_leaf_kind("/some/where/weeping_willow.xml"), "willow");
  EXPECT_EQ(default_leaf_kind("species/ca_black_oak.json"), "oak");
  EXPECT_EQ(default_leaf_kind("my_maple.json"), "broadleaf");
  EXPECT_EQ(default_leaf_kind(""), "broadleaf");
  // And the tree def gets the outline of the kind the scene chose.
  EXPECT_EQ(leaf_outline_of_kind("oak"), BOREAS_LEAF_OAK);
  EXPECT_EQ(leaf_outline_of_kind("broadleaf"), BOREAS_LEAF_BROADLEAF);
  EXPECT_THROW(leaf_outline_of_kind("maple"), std::invalid_argument);
}

}  // namespace
}  // namespace boreas::render
