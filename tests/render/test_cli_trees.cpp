// render tests: trees in `boreas run`: they sway in the side-view panel under the slice when
// the wind blows and stand still when it is calm; a bad species file stops the run with the
// library's message, naming the scene's tree and the species file's line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "command_runner.h"
#include "png_reader.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 64;         // the slice, in pixels
constexpr int kPanelHeight = 48;  // side_panel_height(64, 64)

// Pixels of the side-view panel (below the slice) that differ between two frames.
int panel_pixels_differing(const Png& a, const Png& b) {
  int differing = 0;
  for (int y = kSize; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      differing += !std::equal(a.at(x, y), a.at(x, y) + a.channels, b.at(x, y)) ? 1 : 0;
    }
  }
  return differing;
}

// The panel's pixels that are not sky or ground: the tree.
int panel_tree_pixels(const Png& png) {
  const uint8_t* sky = png.at(1, kSize + 1);
  const uint8_t* ground = png.at(1, png.height - 1);
  int tree = 0;
  for (int y = kSize; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      const uint8_t* p = png.at(x, y);
      bool background = std::equal(p, p + 3, sky) || std::equal(p, p + 3, ground);
      tree += background ? 0 : 1;
    }
  }
  return tree;
}

struct TreeRun {
  Png first;
  Png second;
  nlohmann::json summary;
};

TreeRun run_tree_scene(const std::string& wind) {
  TempDir dir;
  dir.write("trees.json", scene_with_trees(wind, aspen_in_the_middle()));
  CommandResult r = run_boreas("run --view slice trees.json --out out", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  TreeRun run;
  run.first = read_png((dir.path() / "out" / "frame_0000.png").string());
  run.second = read_png((dir.path() / "out" / "frame_0001.png").string());
  if (r.exit_code == 0) run.summary = nlohmann::json::parse(read_text(dir.path() / "out" / "summary.json"));
  return run;
}

TEST(CliTrees, TreesSwayInAGustyWind) {
  TreeRun run = run_tree_scene(gusty_wind());
  ASSERT_EQ(run.first.width, kSize);
  ASSERT_EQ(run.first.height, kSize + kPanelHeight);  // the side view under the slice
  ASSERT_EQ(run.second.height, run.first.height);
  EXPECT_GT(panel_tree_pixels(run.first), 100) << "the tree is drawn";
  // The panel holds nothing but the tree over a fixed background: any change is the tree.
  EXPECT_GT(panel_pixels_differing(run.first, run.second), 20);

  const nlohmann::json& s = run.summary;
  ASSERT_EQ(s["trees"].size(), 1u);
  EXPECT_EQ(s["trees"][0]["species"], "quaking_aspen");
  EXPECT_GT(s["trees"][0]["branches"].get<int>(), 100);
  EXPECT_GT(s["trees"][0]["leaves"].get<int>(), 1000);
  EXPECT_GT(s["frame_stats"][1]["max_sway"].get<double>(), 0.05);
  for (const char* stage : {"tree_readback", "tree_drawing"}) {
    EXPECT_GT(s["timings"][stage].get<double>(), 0.0) << stage;
  }
}

TEST(CliTrees, TreesStandStillWhenCalm) {
  TreeRun run = run_tree_scene("{}");
  ASSERT_EQ(run.first.height, kSize + kPanelHeight);
  EXPECT_GT(panel_tree_pixels(run.first), 100);
  EXPECT_EQ(panel_pixels_differing(run.first, run.second), 0);
  EXPECT_EQ(run.first.pixels, run.second.pixels);
  for (const nlohmann::json& frame : run.summary["frame_stats"]) {
    EXPECT_LT(frame["max_sway"].get<double>(), 1e-3);
  }
}

TEST(CliTrees, BadSpeciesFileStopsTheRunNamingTreeFileAndLine) {
  TempDir dir;
  fs::create_directories(dir.path() / "scenes");
  dir.write("scenes/bad.json", bad_species_json());
  // Relative to the scene's folder, not to where boreas runs.
  dir.write("scenes/trees.json",
            scene_with_trees("{}", R"([{"species": "quaking_aspen"}, {"species": "bad.json"}])"));
  CommandResult r = run_boreas("run --view slice scenes/trees.json --out out", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("boreas: error: scenes/trees.json: /trees/1: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("scenes/bad.json:5: parameter 'Levels'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace boreas::render::testing
